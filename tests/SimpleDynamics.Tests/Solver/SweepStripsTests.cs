using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The order in which the solver sweeps a pile cut into strips (SweepStrips.cs): the strips one after another, then the
/// seam contacts, each group in the height order it was given; and strips that share no moving body, which is what lets
/// threads sweep them at once with exactly one thread's result.
/// </summary>
public class SweepStripsTests
{
    [Theory]
    [InlineData(2)]
    [InlineData(8)]
    public void A_cut_pile_is_swept_strip_by_strip_then_the_seams_and_no_two_strips_move_one_body(int most)
    {
        World world = Scenes.BallPit(600, planar: true, seed: 3, radiusSpread: 1.5f);
        world.SleepingEnabled = false;
        for (int step = 0; step < 120; step++)
        {
            world.Step(1f / 60f);
        }

        RigidBody[] bodies = world.Bodies.ToArray();
        Contact[] contacts = world.Collisions.Contacts.ToArray();
        int n = contacts.Length;
        var strips = new SweepStrips { Most = most, ContactsPerStrip = 64 };
        strips.Cut(bodies, contacts, world.Gravity);
        Assert.Equal(most, strips.Count);

        // The solver's order before grouping: by height along gravity (ties by index here).
        float[] heights = contacts.Select(c => -Vector3.Dot(c.Point, world.Gravity)).ToArray();
        int[] order = Enumerable.Range(0, n).OrderBy(i => heights[i]).ThenBy(i => i).ToArray();
        var rank = new int[n];
        for (int place = 0; place < n; place++)
        {
            rank[order[place]] = place;
        }

        int[] grouped = (int[])order.Clone();
        var starts = new int[SweepStrips.MaxStrips + 2];
        strips.Group(grouped, bodies: false, new int[n], starts);

        Assert.Equal(Enumerable.Range(0, n), grouped.OrderBy(i => i));
        Assert.Equal(0, starts[0]);
        Assert.Equal(n, starts[strips.Count + 1]);
        var stripOfBody = new Dictionary<RigidBody, int>();
        for (int group = 0; group <= strips.Count; group++)
        {
            Assert.True(starts[group] <= starts[group + 1], $"group {group} ends before it begins");
            int previousRank = -1;
            foreach (int k in grouped.AsSpan(starts[group], starts[group + 1] - starts[group]))
            {
                Assert.True(rank[k] > previousRank, $"group {group}: contact {k} out of height order");
                previousRank = rank[k];
                if (group == strips.Count)
                {
                    continue; // the seams, checked below
                }

                foreach (RigidBody body in new[] { contacts[k].BodyA, contacts[k].BodyB }.Where(b => b.IsDynamic))
                {
                    Assert.True(stripOfBody.TryAdd(body, group) || stripOfBody[body] == group,
                        $"body {body.Id} moves in strips {stripOfBody[body]} and {group}");
                }
            }
        }

        // A seam contact joins two strips: both its bodies move, and not in the same strip.
        for (int place = starts[strips.Count]; place < n; place++)
        {
            Contact seam = contacts[grouped[place]];
            Assert.True(seam.BodyA.IsDynamic && seam.BodyB.IsDynamic, "a seam contact with a body that nothing moves");
            int a = stripOfBody.GetValueOrDefault(seam.BodyA, -1), b = stripOfBody.GetValueOrDefault(seam.BodyB, -2);
            Assert.True(a != b, $"seam contact of bodies {seam.BodyA.Id} and {seam.BodyB.Id}, both in strip {a}");
        }

        // Cut at equal shares of the contacts: no strip holds more than twice its share, and few contacts are seams.
        for (int strip = 0; strip < strips.Count; strip++)
        {
            Assert.InRange(starts[strip + 1] - starts[strip], 1, 2 * n / strips.Count);
        }

        Assert.InRange(n - starts[strips.Count], 1, n / 4);
    }
}
