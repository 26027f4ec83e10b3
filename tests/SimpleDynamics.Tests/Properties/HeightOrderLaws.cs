using System;
using System.Collections.Generic;
using System.Linq;
using FsCheck.Fluent;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// The solver's bottom-up order (<see cref="HeightOrder"/>): a permutation of the items from the lowest to the
/// highest; equal heights and a single item keep their order, or go by their tie keys when given. Drawn from anywhere
/// in a range, crowded into a small part of it below one far outlier (most items then share one slice of the counting
/// sort, sorted on their own), and few distinct values (ties).
/// </summary>
public class HeightOrderLaws
{
    [Fact]
    public void Applying_the_order_in_place_puts_each_item_where_the_order_says_once() =>
        PropertyCheck.Run(
            from count in Gen.Choose(0, 300)
            from heights in Gen.OneOf(Generators.UniformF(-50, 50), Gen.Elements(-1f, 0f, 2.5f)).ArrayOf(count)
            select heights,
            heights =>
            {
                var order = new int[heights.Length];
                new HeightOrder().Sort(heights, order);
                int[] expected = order.ToArray();
                string[] items = Enumerable.Range(0, heights.Length).Select(i => $"item {i}").ToArray();

                HeightOrder.Apply(items.AsSpan(), order);

                for (int k = 0; k < items.Length; k++)
                {
                    Law.Holds(items[k] == $"item {expected[k]}", $"position {k} holds {items[k]}, not item {expected[k]}");
                }
            }, seed: 703);

    [Fact]
    public void Order_is_a_stable_permutation_from_the_lowest_to_the_highest() =>
        PropertyCheck.Run(
            from count in Gen.Choose(0, 200)
            from crowded in Gen.Elements(false, true)
            from heights in (crowded
                ? Gen.OneOf(Generators.UniformF(-0.5f, 0.5f), Generators.UniformF(-0.5f, 0.5f), Generators.UniformF(-0.5f, 0.5f), Gen.Constant(1e4f))
                : Gen.OneOf(Generators.UniformF(-50, 50), Gen.Elements(-1f, 0f, 2.5f))).ArrayOf(count)
            select heights,
            heights =>
            {
                var order = new int[heights.Length];
                new HeightOrder().Sort(heights, order);

                Law.Holds(order.OrderBy(i => i).SequenceEqual(Enumerable.Range(0, heights.Length)), "a permutation of 0 … n − 1");
                if (heights.Length < 2)
                {
                    return;
                }

                for (int k = 1; k < order.Length; k++)
                {
                    float lower = heights[order[k - 1]], h = heights[order[k]];
                    Law.Holds(h >= lower, $"item {order[k]} at {h} comes after item {order[k - 1]} at {lower}");
                    if (h == lower)
                    {
                        Law.Holds(order[k] > order[k - 1], "equal heights keep their order");
                    }
                }
            }, seed: 701);

    [Fact]
    public void With_tie_keys_the_order_is_by_height_then_key_whatever_order_the_items_come_in() =>
        PropertyCheck.Run(
            from count in Gen.Choose(0, 200)
            from crowded in Gen.Elements(false, true)
            from heights in (crowded
                ? Gen.OneOf(Gen.Elements(0f, 0.25f), Gen.Elements(0f, 0.25f), Gen.Elements(0f, 0.25f), Gen.Constant(1e4f))
                : Gen.OneOf(Generators.UniformF(-50, 50), Gen.Elements(-1f, 0f, 2.5f))).ArrayOf(count)
            from shuffle in Gen.Choose(0, int.MaxValue)
            select (heights, shuffle),
            input =>
            {
                float[] heights = input.heights;
                ulong[] ties = Enumerable.Range(0, heights.Length).Select(i => ((ulong)(uint)(i * 7919 % 1009) << 20) | (uint)i).ToArray();
                int[] permutation = Enumerable.Range(0, heights.Length).OrderBy(i => (i * 31L + input.shuffle) % 1013).ThenBy(i => i).ToArray();
                (float, ulong)[] Sorted(int[] items)
                {
                    var order = new int[items.Length];
                    new HeightOrder().Sort(items.Select(i => heights[i]).ToArray(), items.Select(i => ties[i]).ToArray(), order);
                    return order.Select(k => (heights[items[k]], ties[items[k]])).ToArray();
                }

                (float, ulong)[] inOrder = Sorted(Enumerable.Range(0, heights.Length).ToArray());
                (float, ulong)[] expected = inOrder.OrderBy(item => item.Item1).ThenBy(item => item.Item2).ToArray();
                Law.Holds(inOrder.SequenceEqual(expected), "by height, then by tie key");
                Law.Holds(Sorted(permutation).SequenceEqual(expected), "the same order from the items permuted");
            }, seed: 705);

    /// <summary>
    /// A sort tries the order the last one gave before sorting anew (a resting pile keeps its order). Over generated
    /// runs of sorts by one instance (heights left alone, nudged, swapped; tie keys swapped; items added or dropped;
    /// NaN and infinite heights), every sort must give exactly what a new instance gives, and the runs must take the
    /// reuse often enough for that to be tested.
    /// </summary>
    [Fact]
    public void A_sort_that_reuses_the_last_order_gives_exactly_what_a_fresh_sort_gives()
    {
        int sorts = 0, reused = 0;
        PropertyCheck.Run(
            from count in Gen.Choose(0, 120)
            from withTies in Gen.Elements(false, true)
            from heights in Gen.OneOf(Generators.UniformF(-5, 5), Gen.Elements(-1f, 0f, 2.5f)).ArrayOf(count)
            from changes in Gen.Choose(0, 5).Zip(Gen.Choose(0, int.MaxValue)).ArrayOf(8)
            select (withTies, heights, changes),
            run =>
            {
                var heights = run.heights.ToList();
                var ties = Enumerable.Range(0, heights.Count).Select(i => (ulong)(i * 7919 % 1009) << 20 | (uint)i).ToList();
                var reusing = new HeightOrder();
                foreach ((int change, int draw) in run.changes)
                {
                    Change(heights, ties, change, draw);
                    float[] h = heights.ToArray();
                    ulong[] t = run.withTies ? ties.ToArray() : Array.Empty<ulong>();
                    var order = new int[h.Length];
                    var expected = new int[h.Length];
                    reusing.Sort(h, t, order);
                    new HeightOrder().Sort(h, t, expected);
                    Law.Holds(order.SequenceEqual(expected), $"after change {change}: [{string.Join(", ", order)}], not [{string.Join(", ", expected)}]");
                    sorts++;
                    reused += reusing.ReusedLastOrder ? 1 : 0;
                }
            }, seed: 707, maxTest: 300);

        Law.Holds(reused > sorts / 5, $"only {reused} of {sorts} sorts reused the last order: the law above hardly tested it");
    }

    private static void Change(List<float> heights, List<ulong> ties, int change, int draw)
    {
        int n = heights.Count, i = n == 0 ? 0 : draw % n, j = n == 0 ? 0 : (draw / 7) % n;
        switch (change)
        {
            case not 4 when n == 0:
                break; // nothing to change but the count
            case 0:
                break; // left alone: the last order holds
            case 1:
                heights[i] += (draw % 3 - 1) * 1e-4f; // nudged: the order may or may not still hold
                break;
            case 2:
                (heights[i], heights[j]) = (heights[j], heights[i]);
                break;
            case 3:
                (ties[i], ties[j]) = (ties[j], ties[i]); // the same heights, other tie keys (another pair in that place)
                break;
            case 4:
                if (draw % 2 == 0 && n > 0)
                {
                    heights.RemoveAt(n - 1);
                    ties.RemoveAt(n - 1);
                }
                else
                {
                    heights.Add(n == 0 ? 0f : heights[i]);
                    ties.Add((ulong)(n + 1) << 40 | (uint)n);
                }

                break;
            default:
                heights[i] = draw % 3 == 0 ? float.NaN : draw % 3 == 1 ? float.PositiveInfinity : heights[j];
                break;
        }
    }
}
