using System;
using System.Linq;
using System.Numerics;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// Laws over whole <see cref="World.Step"/>s with the pairwise impulse responder and no gravity: random crowds
/// of dynamic bodies (so several contacts per step) keep their total momentum and angular momentum, and their
/// kinetic energy never increases (each contact's impulse loses energy on its own, eq. 16 with ε ≤ 1 and
/// friction that never reverses sliding). Tolerances as in <see cref="ImpulseResponderLaws"/>, per step.
/// </summary>
/// <remarks>
/// The bodies here are solid spheres (isotropic inertia). World.Step leaves out the gyroscopic term ω × I ω
/// (documented on its velocity integration: zero for spheres and discs, the shapes it collides), so a freely
/// spinning body with a non-isotropic tensor keeps ω, not L = I_w ω, and angular momentum would drift between
/// collisions for reasons unrelated to collision response. With full tensors the laws of a single impulse
/// are tested directly in <see cref="ImpulseResponderLaws"/>.
/// </remarks>
public class WorldLaws
{
    private static FsCheck.Gen<(BodySpec[] Bodies, float Restitution, float Friction)> Crowds { get; } =
        from count in Gen.Choose(2, 12)
        from bodies in (
            from radius in Generators.UniformF(0.2, 1)
            from position in Generators.Vector(2)
            from body in Generators.Body(BodyType.Dynamic, position, radius)
            select body with { Inertia = Inertia.SolidSphere(body.Mass, radius) }).ArrayOf(count)
        from restitution in Gen.OneOf(Generators.UniformF(0, 1), Gen.Elements(0f, 0.25f, 0.5f, 0.75f, 1f))
        from friction in Gen.OneOf(Gen.Constant(0f), Generators.UniformF(0, 1.5))
        select (bodies, restitution, friction);

    [Fact]
    public void Momentum_is_conserved_and_kinetic_energy_never_increases_over_steps() =>
        PropertyCheck.Run(Crowds, x =>
        {
            var world = new World(Vector3.Zero, new ImpulseCollisionResponder(x.Restitution, x.Friction));
            RigidBody[] bodies = x.Bodies.Select(b => world.Add(b.Build())).ToArray();
            D3 origin = new(0.5, -1, 2);
            D3 p0 = Measure.Momentum(bodies), l0 = Measure.AngularMomentum(origin, bodies);
            double energy = Measure.KineticEnergy(bodies);
            double pScale = Measure.MomentumScale(bodies), lScale = Measure.AngularMomentumScale(origin, bodies);
            for (int step = 0; step < 20; step++)
            {
                world.Step(1f / 60f);
                double next = Measure.KineticEnergy(bodies);
                Law.Holds(next <= energy * (1 + 1e-5), $"step {step}: kinetic energy rose from {energy:R} to {next:R} ({world.Collisions.Count} contacts)");
                energy = next;
                pScale += Measure.MomentumScale(bodies);
                lScale += Measure.AngularMomentumScale(origin, bodies);
            }

            Law.Near(p0, Measure.Momentum(bodies), 1e-5 * pScale, "total linear momentum after 20 steps");
            Law.Near(l0, Measure.AngularMomentum(origin, bodies), 1e-4 * lScale, "angular momentum after 20 steps");
        }, seed: 601, maxTest: 200);
}
