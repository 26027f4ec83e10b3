using System;
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
}
