using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// Detection with a margin and a lookahead (what <see cref="World.Step"/> asks for): no pair that may meet is missed,
/// and a crowd moving as one reports fewer neighbours it never approaches than spheres around its starts would.
/// </summary>
/// <remarks>
/// The safety law: if two bodies moving along straight lines at their velocities come within the margin of touching at
/// some time in [0, lookahead], the detector reports them. The oracle works that closest approach out in double
/// precision: for d = c_A − c_B and w = v_A − v_B, the distance |d + w t| is least at t = −d·w / |w|², clamped to the
/// interval. Pairs within float rounding of the bound are not generated, as in <see cref="DetectionLaws"/>.
/// </remarks>
public class LookaheadDetectionLaws
{
    private sealed record Body(Vector3 Position, Vector3 Velocity, float Radius);

    private sealed record Scene(Body[] Bodies, float Margin, float Lookahead);

    /// <summary>
    /// Scenes of 2–24 bodies in a 4 m box, about half of them moving with one shared velocity (a crowd, each component
    /// up to 20 m/s) plus up to 0.5 m/s of their own, the rest with any velocity (each component up to 30 m/s); margins
    /// up to 5 cm, lookaheads up to 1/30 s.
    /// </summary>
    private static Gen<Scene> Scenes { get; } =
        from count in Gen.Choose(2, 24)
        from crowd in Generators.Vector(20)
        from bodies in Gen.ListOf(
            from position in Generators.Vector(2)
            from radius in Generators.UniformF(0.02, 0.5)
            from own in Generators.Vector(30)
            from jitter in Generators.Vector(0.5)
            from inCrowd in Gen.Elements(true, false)
            select new Body(position, inCrowd ? crowd + jitter : own, radius), count)
        from margin in Generators.UniformF(0, 0.05)
        from lookahead in Generators.UniformF(0, 1.0 / 30)
        select new Scene(bodies.ToArray(), margin, lookahead);

    [Fact]
    public void BruteForceDetector_reports_every_pair_whose_paths_come_within_the_margin() =>
        Check(new BruteForceDetector(), seed: 411);

    [Fact]
    public void SpatialHashDetector_reports_every_pair_whose_paths_come_within_the_margin() =>
        Check(new SpatialHashDetector(), seed: 412);

    /// <summary>
    /// A 10 × 10 lattice of discs 0.1 m across, 0.11 m apart, falling together at 20 m/s, detected with the world's
    /// margin over a step of 1/60 s: the spheres around the middles of the paths are those around the centres, moved
    /// alike, so a pair is reported when its centres are closer than 2r + margin + |v| dt (1,654 pairs, those within
    /// 0.446 m). Spheres around the starts would reach twice as far along the path (2r + margin + 2 |v| dt, 0.779 m),
    /// taking in 3,782 pairs of discs that never approach each other.
    /// </summary>
    [Fact]
    public void A_crowd_falling_as_one_reports_half_the_reach_of_spheres_around_its_starts()
    {
        const float Radius = 0.05f, Spacing = 0.11f, Dt = 1f / 60f, Margin = 0.01f + 9.81f * Dt * Dt;
        var bodies = new List<RigidBody>();
        for (int row = 0; row < 10; row++)
        {
            for (int column = 0; column < 10; column++)
            {
                bodies.Add(new RigidBody(1f, Radius, new Vector3(column * Spacing, row * Spacing, 0)) { LinearVelocity = new Vector3(0, -20, 0) });
            }
        }

        foreach (ICollisionDetector detector in new ICollisionDetector[] { new BruteForceDetector(), new SpatialHashDetector() })
        {
            var collisions = new CollisionData();
            detector.FindContacts(bodies.ToArray(), collisions, Margin, Dt);
            Assert.Equal(1654, collisions.Count);
        }
    }

    /// <summary>The same two discs 1 m apart meet within the step when they close at 40 m/s, and not when they move as one.</summary>
    [Fact]
    public void Approaching_pairs_are_reported_and_pairs_moving_together_are_not()
    {
        var a = new RigidBody(1f, 0.05f, new Vector3(1, 0, 0));
        var b = new RigidBody(1f, 0.05f, Vector3.Zero);
        a.LinearVelocity = new Vector3(-20, 0, 0);
        b.LinearVelocity = new Vector3(20, 0, 0);
        Assert.True(ContactGeometry.TryCollide(a, b, 0.01f, 1f / 30f, out _));
        b.LinearVelocity = new Vector3(-20, 0, 0);
        Assert.False(ContactGeometry.TryCollide(a, b, 0.01f, 1f / 30f, out _));
    }

    private static void Check(ICollisionDetector detector, ulong seed, [System.Runtime.CompilerServices.CallerMemberName] string name = "") =>
        PropertyCheck.Run(Scenes.Where(NoBorderlinePair), scene =>
        {
            RigidBody[] bodies = scene.Bodies.Select(b => new RigidBody(1f, b.Radius, b.Position) { LinearVelocity = b.Velocity }).ToArray();
            var collisions = new CollisionData(capacity: 1);
            detector.FindContacts(bodies, collisions, scene.Margin, scene.Lookahead);
            var index = new Dictionary<RigidBody, int>(ReferenceEqualityComparer.Instance);
            for (int i = 0; i < bodies.Length; i++)
            {
                index[bodies[i]] = i;
            }

            var found = new HashSet<(int, int)>();
            foreach (Contact contact in collisions.Contacts)
            {
                Law.Holds(found.Add((index[contact.BodyA], index[contact.BodyB])), "a pair reported twice");
            }

            for (int i = 0; i < bodies.Length; i++)
            {
                for (int j = i + 1; j < bodies.Length; j++)
                {
                    double gap = ClosestApproach(scene.Bodies[i], scene.Bodies[j], scene.Lookahead) - scene.Bodies[i].Radius - scene.Bodies[j].Radius;
                    Law.Holds(gap >= scene.Margin || found.Contains((i, j)),
                        $"bodies {i} and {j} come within {gap:E3} m of touching in the lookahead (margin {scene.Margin}), but are not reported");
                }
            }
        }, seed, maxTest: 300, name: name);

    /// <summary>The least distance between the centres of two bodies moving straight at their velocities over [0, lookahead], in double.</summary>
    private static double ClosestApproach(Body a, Body b, float lookahead)
    {
        double dx = (double)a.Position.X - b.Position.X, dy = (double)a.Position.Y - b.Position.Y, dz = (double)a.Position.Z - b.Position.Z;
        double wx = (double)a.Velocity.X - b.Velocity.X, wy = (double)a.Velocity.Y - b.Velocity.Y, wz = (double)a.Velocity.Z - b.Velocity.Z;
        double ww = wx * wx + wy * wy + wz * wz;
        double t = ww > 0 ? Math.Clamp(-(dx * wx + dy * wy + dz * wz) / ww, 0, lookahead) : 0;
        return Math.Sqrt(Sq(dx + wx * t) + Sq(dy + wy * t) + Sq(dz + wz * t));
    }

    private static double Sq(double x) => x * x;

    /// <summary>No pair's closest approach lies within float rounding of the margin's bound.</summary>
    private static bool NoBorderlinePair(Scene scene)
    {
        for (int i = 0; i < scene.Bodies.Length; i++)
        {
            for (int j = i + 1; j < scene.Bodies.Length; j++)
            {
                Body a = scene.Bodies[i], b = scene.Bodies[j];
                double bound = (double)a.Radius + b.Radius + scene.Margin;
                double allowance = 1e-4 * bound + 1e-5 * (a.Position.Length() + b.Position.Length() + scene.Lookahead * (a.Velocity.Length() + b.Velocity.Length()));
                if (Math.Abs(ClosestApproach(a, b, scene.Lookahead) - bound) < allowance)
                {
                    return false;
                }
            }
        }

        return true;
    }
}
