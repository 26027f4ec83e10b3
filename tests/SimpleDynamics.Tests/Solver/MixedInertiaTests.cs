using System.Numerics;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Response;
using SimpleDynamics.Tests.Properties;
using Xunit;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The solver keeps each body's world inverse inertia as a scalar where it is k·1 (a sphere) and as a matrix where it
/// turns with the body; a contact between one of each must still turn both by its friction (eq. 15).
/// </summary>
public class MixedInertiaTests
{
    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void A_sphere_rubbing_on_a_box_turns_both_and_keeps_angular_momentum(bool sphereFirst)
    {
        // No gravity; the two overlap by 0.2 mm (within the slop, so the position pass moves neither) and rub
        // sideways at 1 m/s while closing at 1 cm/s: a resting contact of the solver, with friction, in 3-D. The normal
        // impulse is about 7 mN s, so friction (μ = 0.5) turns the sphere at about 0.017 rad/s.
        var world = new World(Vector3.Zero, new SequentialImpulseSolver(restitution: 0f, friction: 0.5f)) { SleepingEnabled = false };
        var sphere = new RigidBody(1f, 0.5f, Vector3.Zero, Inertia.SolidSphere(1f, 0.5f)) { LinearVelocity = new Vector3(0.01f, 1f, 0.3f) };
        var box = new RigidBody(2f, 0.5f, new Vector3(0.9998f, 0, 0), Inertia.Box(2f, 1f, 0.6f, 0.3f));
        if (sphereFirst)
        {
            world.Add(sphere);
            world.Add(box);
        }
        else
        {
            world.Add(box);
            world.Add(sphere);
        }

        D3 about = new(0.3, -0.2, 0.1);
        D3 before = Measure.AngularMomentum(about, sphere, box);
        double scale = Measure.AngularMomentumScale(about, sphere, box);
        world.Step(1f / 60f);
        D3 after = Measure.AngularMomentum(about, sphere, box);

        Assert.True(sphere.AngularVelocity.Length() > 1e-3f, $"the sphere should be turned by the friction, ω = {sphere.AngularVelocity}");
        Assert.True(box.AngularVelocity.Length() > 1e-3f, $"the box should be turned by the friction, ω = {box.AngularVelocity}");
        Assert.True((after - before).Length <= 1e-5 * scale, $"angular momentum changed by {(after - before).Length} (scale {scale})");
    }

    /// <summary>
    /// The same over generated pairs: a sphere and a body of any inertia tensor (principal moments in a ratio up to 25,
    /// any orientation), in any direction from each other, overlapping by 0–0.4 mm, rubbing at up to 3 m/s and
    /// closing at up to 5 cm/s, μ of 0.3 or 1, masses 1e-2–1e3 kg; neither spins at first, so the gyroscopic term
    /// that World.Step leaves out is negligible within the step. One step must keep the pair's angular momentum
    /// about any point.
    /// </summary>
    [Fact]
    public void Contacts_between_spheres_and_bodies_of_any_inertia_keep_angular_momentum() =>
        PropertyCheck.Run(
            from massA in Generators.Mass
            from massB in Generators.Mass
            from radiusA in Generators.LogUniform(0.05, 0.5)
            from radiusB in Generators.LogUniform(0.05, 0.5)
            from direction in Generators.UnitVector
            from overlap in Generators.UniformF(0, 4e-4)
            from rubbing in Generators.Vector(3)
            from closing in Generators.UniformF(0, 0.05)
            from friction in Gen.Elements(0.3f, 1f)
            from about in Generators.Vector(2)
            from tensorB in Generators.InertiaTensor(massB, radiusB)
            select (massA, massB, radiusA, radiusB, direction, overlap, rubbing, closing, friction, about, tensorB),
            c =>
            {
                var world = new World(Vector3.Zero, new SequentialImpulseSolver(restitution: 0f, friction: c.friction)) { SleepingEnabled = false };
                var sphere = world.Add(new RigidBody(c.massA, c.radiusA, Vector3.Zero, Inertia.SolidSphere(c.massA, c.radiusA)));
                Vector3 centreB = c.direction * (c.radiusA + c.radiusB - c.overlap);
                var other = world.Add(new RigidBody(c.massB, c.radiusB, centreB, c.tensorB));
                Vector3 sideways = c.rubbing - Vector3.Dot(c.rubbing, c.direction) * c.direction;
                sphere.LinearVelocity = sideways + c.closing * c.direction;
                D3 about = D3.From(c.about);
                D3 before = Measure.AngularMomentum(about, sphere, other);
                world.Step(1f / 60f);
                D3 after = Measure.AngularMomentum(about, sphere, other);
                double scale = Measure.AngularMomentumScale(about, sphere, other) + 1e-12;
                Law.Holds((after - before).Length <= 1e-5 * scale, $"angular momentum changed by {(after - before).Length:E3} of scale {scale:E3}; sphere ω = {sphere.AngularVelocity}, other ω = {other.AngularVelocity}");
            }, seed: 1311, maxTest: 300);
}
