using System;
using System.Collections.Generic;
using System.Linq;
using FsCheck.Fluent;
using SimpleDynamics.Collision;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// Last step's pairs in order (<see cref="PairOrder"/>), behind the warm start and the contact events: whatever order
/// this step meets its pairs in, each is found exactly where last step's list holds it, or not at all. Steps are drawn
/// as a pile's are (last step's pairs in the same order, some gone, some new, a few neighbours swapped) and as a
/// shaken crowd's (any order), several in a row through one list, so that both the in-order look-up and the table
/// behind it are used, and the list is refilled over and over.
/// </summary>
public class PairOrderLaws
{
    private static readonly FsCheck.Gen<ulong[]> FirstStep =
        from count in Gen.Choose(0, 150)
        from keys in Gen.Choose(0, 400).ArrayOf(count)
        select keys.Distinct().Select(k => (ulong)k).ToArray();

    /// <summary>The next step's pairs from this step's: kept (each with probability 3/4), a few new, maybe reordered.</summary>
    private static FsCheck.Gen<ulong[]> NextStep(ulong[] previous) =>
        from kept in Gen.Elements(true, true, true, false).ArrayOf(previous.Length)
        from added in Gen.Choose(0, 400).ArrayOf(12)
        from places in Gen.Choose(0, 1000).ArrayOf(12)
        from shaken in Gen.Elements(false, false, true)
        from swaps in Gen.Choose(0, 1000).ArrayOf(6)
        from shuffle in Gen.Choose(0, int.MaxValue)
        select Reorder(previous, kept, added, places, shaken, swaps, shuffle);

    private static ulong[] Reorder(ulong[] previous, bool[] kept, int[] added, int[] places, bool shaken, int[] swaps, int shuffle)
    {
        var keys = previous.Where((_, i) => kept[i]).ToList();
        for (int i = 0; i < added.Length; i++)
        {
            ulong key = (ulong)added[i];
            if (!keys.Contains(key))
            {
                keys.Insert(places[i] % (keys.Count + 1), key);
            }
        }

        if (shaken)
        {
            var random = new Random(shuffle);
            return keys.OrderBy(_ => random.Next()).ToArray();
        }

        foreach (int swap in swaps.Where(_ => keys.Count > 1))
        {
            int at = swap % (keys.Count - 1);
            (keys[at], keys[at + 1]) = (keys[at + 1], keys[at]);
        }

        return keys.ToArray();
    }

    [Fact]
    public void Each_pair_is_found_where_last_step_listed_it_or_not_at_all() =>
        PropertyCheck.Run(
            from first in FirstStep
            from second in NextStep(first)
            from third in NextStep(second)
            from fourth in NextStep(third)
            select new[] { first, second, third, fourth },
            steps =>
            {
                var order = new PairOrder();
                ulong[] listed = Array.Empty<ulong>();
                for (int step = 0; step < steps.Length; step++)
                {
                    ulong[] keys = steps[step];
                    for (int i = 0; i < keys.Length; i++)
                    {
                        int expected = Array.IndexOf(listed, keys[i]);
                        int found = order.Find(i, keys[i]);
                        Law.Holds(found == expected, $"step {step}: pair {keys[i]} met at {i} was found at {found}, listed at {expected}");
                    }

                    order.Begin(keys.Length);
                    foreach (ulong key in keys)
                    {
                        order.Add(key);
                    }

                    Law.Holds(order.Count == keys.Length, $"step {step}: {order.Count} listed, not {keys.Length}");
                    listed = keys;
                }
            }, seed: 1207);

    [Fact]
    public void A_pair_listed_twice_is_found_at_one_of_its_places()
    {
        // A detector may report a pair twice; either entry is last step's impulse of that pair.
        var order = new PairOrder();
        ulong[] listed = { 5, 9, 5, 7 };
        order.Begin(listed.Length);
        foreach (ulong key in listed)
        {
            order.Add(key);
        }

        Assert.Equal(0, order.Find(0, 5)); // where order puts it
        Assert.Equal(1, order.Find(1, 9));
        Assert.Equal(2, order.Find(2, 5));
        Assert.Equal(2, order.Find(3, 5)); // out of order: by key, the last place listed
        Assert.Equal(-1, order.Find(0, 11));
        Assert.Equal(3, order.Find(1, 7));
    }
}
