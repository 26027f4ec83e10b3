using System;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The default solver puts the contacts in its own order (bottom-up; equal heights by their bodies' places in the
/// world), so a world's motion is the same, bit for bit, whichever detector found the contacts and in whatever order
/// it reported them. A detector is then free to report them in the order that is fastest for it.
/// </summary>
public class ContactOrderTests
{
    private const float Dt = 1f / 60f;

    /// <summary>
    /// Identical discs in an exact grid, dropped together onto the floor: whole rows of contacts at exactly the same
    /// height, whose order the heights alone leave open, and Gauss–Seidel results depend on that order.
    /// </summary>
    [Fact]
    public void A_grid_of_identical_discs_lands_the_same_whatever_the_detector_or_its_order()
    {
        static World Grid(ICollisionDetector detector)
        {
            var world = new World(Scenes.EarthGravity) { Detector = detector };
            world.AddPlanes(StaticPlane.Box(Vector3.Zero, new Vector3(2.4f, 4f, 0), planar: true));
            for (int row = 0; row < 4; row++)
            {
                for (int column = 0; column < 10; column++)
                {
                    var position = new Vector3(0.3f + column * 0.2f + (row % 2) * 0.1f, 0.5f + row * 0.2f, 0);
                    world.Add(new RigidBody(1f, 0.1f, position, Inertia.Disc(1f, 0.1f)));
                }
            }

            return world;
        }

        AssertSameMotion(Grid, steps: 120);
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void A_pit_of_mixed_discs_or_balls_pours_the_same_whatever_the_detector_or_its_order(bool planar) =>
        AssertSameMotion(detector =>
        {
            World world = Scenes.BallPit(planar ? 300 : 343, planar, seed: 7, radiusSpread: 1.5f);
            world.Detector = detector;
            return world;
        }, steps: 150);

    private static void AssertSameMotion(Func<ICollisionDetector, World> scene, int steps)
    {
        World reference = scene(new SpatialHashDetector());
        World[] others =
        {
            scene(new BruteForceDetector()),
            scene(new Reordered(new SpatialHashDetector(), reverse: true)),
            scene(new Reordered(new BruteForceDetector(), reverse: false)),
        };
        int pressed = 0;
        for (int step = 0; step < steps; step++)
        {
            reference.Step(Dt);
            pressed = Math.Max(pressed, reference.Collisions.Contacts.ToArray().Count(c => c.NormalImpulse > 0));
            foreach (World other in others)
            {
                other.Step(Dt);
                Assert.Equal(reference.Collisions.Count, other.Collisions.Count);
                if (WorldMeasure.FirstDifference(reference, other) is string difference)
                {
                    Assert.Fail($"step {step + 1}, {other.Detector}: {difference}");
                }
            }
        }

        Assert.True(pressed > 10, $"the scene must press contacts (at most {pressed} in a step)");
    }

    /// <summary>Another detector's contacts, reported reversed or shuffled (with a fixed seed).</summary>
    private sealed class Reordered(ICollisionDetector inner, bool reverse) : ICollisionDetector
    {
        private readonly Random _random = new(3);

        public void FindContacts(ReadOnlySpan<RigidBody> bodies, CollisionData collisions, float margin = 0f, float lookahead = 0f)
        {
            int start = collisions.Count;
            inner.FindContacts(bodies, collisions, margin, lookahead);
            Span<Contact> found = collisions.Contacts[start..];
            if (reverse)
            {
                found.Reverse();
            }
            else
            {
                for (int k = found.Length - 1; k > 0; k--)
                {
                    int j = _random.Next(k + 1);
                    (found[k], found[j]) = (found[j], found[k]);
                }
            }
        }

        public override string ToString() => $"{inner.GetType().Name}, {(reverse ? "reversed" : "shuffled")}";
    }
}
