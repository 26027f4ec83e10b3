using System;
using System.Linq;
using FsCheck.Fluent;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// The solver's bottom-up order (<see cref="HeightOrder"/>): a permutation of the items in which no item comes
/// after one lower than it by more than one slice, (highest − lowest) / (n − 1); ties, equal heights and a single
/// item keep their order.
/// </summary>
public class HeightOrderLaws
{
    [Fact]
    public void Order_is_a_permutation_from_the_lowest_to_the_highest_within_one_slice() =>
        PropertyCheck.Run(
            from count in Gen.Choose(0, 200)
            from heights in Gen.OneOf(Generators.UniformF(-50, 50), Gen.Elements(-1f, 0f, 2.5f)).ArrayOf(count)
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

                float slice = (heights.Max() - heights.Min()) / (heights.Length - 1);
                float highestSoFar = float.NegativeInfinity;
                for (int k = 0; k < order.Length; k++)
                {
                    float h = heights[order[k]];
                    Law.Holds(h >= highestSoFar - slice * 1.0001f, $"item {order[k]} at {h} comes after one at {highestSoFar}");
                    highestSoFar = Math.Max(highestSoFar, h);
                }

                for (int k = 1; k < order.Length; k++)
                {
                    if (heights[order[k]] == heights[order[k - 1]])
                    {
                        Law.Holds(order[k] > order[k - 1], "equal heights keep their order");
                    }
                }
            }, seed: 701);
}
