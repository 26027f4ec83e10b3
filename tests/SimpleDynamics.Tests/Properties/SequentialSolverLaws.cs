using System;
using System.Linq;
using System.Numerics;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// The laws that apply to <see cref="SequentialImpulseSolver"/>: every impulse it applies is equal and opposite
/// at one point, so momentum and angular momentum are conserved for any set of contacts, friction and warm
/// starting included; infinite-mass bodies never change; and a single frictionless contact (threshold 0, no
/// warm start) is answered exactly like eq. 16 (v_n' = −ε v_n, the same impulse as the pairwise responder).
/// Tolerances as in <see cref="ImpulseResponderLaws"/>.
/// </summary>
public class SequentialSolverLaws
{
    private static World WorldOf(RigidBody a, RigidBody b)
    {
        var world = new World(Vector3.Zero, new SequentialImpulseSolver());
        world.Add(a);
        world.Add(b);
        return world;
    }

    [Theory]
    [InlineData(Generators.RandomRestitution)]
    [InlineData(0f)]
    [InlineData(0.25f)]
    [InlineData(0.5f)]
    [InlineData(0.75f)]
    [InlineData(1f)]
    public void Single_frictionless_contact_matches_eq_16(float restitution) =>
        PropertyCheck.Run(Generators.Contact(restitution, friction: false, InfiniteMass.Any), c =>
        {
            (RigidBody a, RigidBody b) = c.BuildBodies();
            var solver = new SequentialImpulseSolver(c.Restitution, 0f) { RestitutionThreshold = 0f, WarmStarting = false };
            World world = WorldOf(a, b);
            var collisions = new CollisionData();
            collisions.Add(c.BuildContact(a, b));
            solver.ResolveVelocities(world, collisions, 1f / 60f);

            (RigidBody a1, RigidBody b1) = c.BuildBodies();
            Contact reference = c.BuildContact(a1, b1);
            new ImpulseCollisionResponder(c.Restitution, 0f).ResolveVelocity(ref reference);

            D3 p = D3.From(c.Point), n = D3.From(c.Normal);
            double after = D3.Dot(Measure.VelocityAt(a, p) - Measure.VelocityAt(b, p), n);
            double scale = Measure.SpeedScaleAt(a, p) + Measure.SpeedScaleAt(b, p) + Math.Abs(c.NormalVelocity());
            Law.Near(-c.Restitution * c.NormalVelocity(), after, 1e-4 * scale, "relative normal velocity after");
            (RigidBody a2, RigidBody b2) = c.BuildBodies(); // untouched, for the error scale of J (see Measure.ImpulseScale)
            Law.Near(reference.NormalImpulse, collisions[0].NormalImpulse, 1e-4 * Measure.ImpulseScale(a2, b2, p, n, c.Restitution), "normal impulse as eq. 16");
        }, seed: 501);

    /// <summary>
    /// Several bodies, random contacts among them (any pairs, any normals), friction, warm starting, two calls.
    /// Momentum is conserved when no contact touches an infinite-mass body (which takes impulses without
    /// moving: an external impulse on the system); with <see cref="InfiniteMass.None"/> that is every case.
    /// </summary>
    [Theory]
    [InlineData(InfiniteMass.None)]
    [InlineData(InfiniteMass.Any)]
    public void Momentum_and_angular_momentum_are_conserved_and_infinite_masses_never_change(InfiniteMass infinite) =>
        PropertyCheck.Run(
            from count in Gen.Choose(2, 6)
            from cases in Generators.Contact(friction: true, infinite: infinite).ArrayOf(count)
            from pairs in Gen.Choose(0, 2 * count - 1).Two().ArrayOf(count + 2)
            from restitution in Generators.UniformF(0, 1)
            from friction in Generators.UniformF(0, 1.5)
            from origin in Generators.Vector(10)
            select (cases, pairs, restitution, friction, origin),
            x =>
            {
                // Bodies: the A and B of each generated case; contacts: pairs of them with the case's normal and point.
                BodySpec[] specs = x.cases.SelectMany(c => new[] { c.A, c.B }).ToArray();
                RigidBody[] bodies = specs.Select(s => s.Build()).ToArray();
                var world = new World(Vector3.Zero, new SequentialImpulseSolver(x.restitution, x.friction));
                foreach (RigidBody body in bodies)
                {
                    world.Add(body);
                }

                var collisions = new CollisionData();
                bool external = false;
                for (int k = 0; k < x.pairs.Length; k++)
                {
                    (int i, int j) = x.pairs[k];
                    ContactCase c = x.cases[k % x.cases.Length];
                    if (i != j && (bodies[i].IsDynamic || bodies[j].IsDynamic))
                    {
                        collisions.Add(new Contact(bodies[i], bodies[j], c.Point, c.Normal, c.Penetration));
                        external |= !bodies[i].IsDynamic || !bodies[j].IsDynamic;
                    }
                }

                D3 o = D3.From(x.origin);
                D3 p0 = Measure.Momentum(bodies), l0 = Measure.AngularMomentum(o, bodies);
                double pScale = Measure.MomentumScale(bodies), lScale = Measure.AngularMomentumScale(o, bodies);
                var solver = (SequentialImpulseSolver)world.Responder;
                for (int step = 0; step < 2; step++)
                {
                    solver.ResolveVelocities(world, collisions, 1f / 60f); // the second call is warm started
                    pScale += Measure.MomentumScale(bodies);
                    lScale += Measure.AngularMomentumScale(o, bodies);
                }

                Law.Holds(infinite != InfiniteMass.None || !external, "with InfiniteMass.None every contact is between dynamic bodies");
                if (!external)
                {
                    // The same relative tolerances as for one pairwise impulse, although up to 2 × 8 × 14 impulses are applied.
                    Law.Near(p0, Measure.Momentum(bodies), 1e-5 * pScale, "total linear momentum");
                    Law.Near(l0, Measure.AngularMomentum(o, bodies), 1e-4 * lScale, $"angular momentum about {o}");
                }

                for (int i = 0; i < bodies.Length; i++)
                {
                    if (!bodies[i].IsDynamic)
                    {
                        ImpulseResponderLaws.AssertUnchanged(specs[i], bodies[i]);
                    }
                }
            }, seed: 502, maxTest: 300);
}
