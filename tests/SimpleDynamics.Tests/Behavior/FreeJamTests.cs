using System;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Response;
using SimpleDynamics.Tests.Properties;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Behavior;

/// <summary>
/// Jams that touch nothing immovable (ImpactStepper.Lumps.cs): a light disc squeezed between two far heavier ones in
/// free space or in free fall, whose inelastic collapse the impact pass's sweeps cannot settle, moves on as one lump.
/// </summary>
public class FreeJamTests
{
    private const float Dt = 1f / 60f;
    private readonly ITestOutputHelper _output;

    public FreeJamTests(ITestOutputHelper output) => _output = output;

    /// <summary>
    /// Without gravity, two 1,000 kg discs close at 10 m/s on a 0.01 kg disc between them, off their line of centres
    /// so that the three also turn (ε = 0). Each impact passes on the light disc's share of the heavy ones' approach,
    /// so they jam, and the lump they make keeps the momentum and the angular momentum about any point (eq. 2 for the
    /// lump; momentum to 1e-6 of Σ m |v|, angular momentum to 1e-5 of Σ m |r| |v|), loses kinetic energy, and stops
    /// closing on itself (no impacts a step later on). Without gravity the solver's sweeps also settle these three,
    /// more slowly, so this checks what the lump keeps (without its turn Ω the angular momentum fell from −750 to
    /// 0 kg m²/s in the first step); the falling sandwich below is what lumps fix.
    /// </summary>
    [Fact]
    public void Without_gravity_a_light_disc_squeezed_between_two_heavy_ones_moves_on_with_them_as_one_lump()
    {
        var world = new World(Vector3.Zero, new SequentialImpulseSolver(restitution: 0f, friction: 0f)) { Substeps = 4 };
        RigidBody left = world.Add(Disc(1000f, 0.3f, new Vector3(-0.5f, 0.05f, 0), new Vector3(5, 0, 0)));
        RigidBody light = world.Add(Disc(0.01f, 0.1f, new Vector3(0f, 0f, 0), Vector3.Zero));
        RigidBody right = world.Add(Disc(1000f, 0.3f, new Vector3(0.5f, -0.1f, 0), new Vector3(-5, 0, 0)));
        RigidBody[] bodies = { left, light, right };
        var origin = new D3(0.7, -1.3, 0);
        D3 p0 = Measure.Momentum(bodies), l0 = Measure.AngularMomentum(origin, bodies);
        double e0 = Measure.KineticEnergy(bodies);
        double pScale = Measure.MomentumScale(bodies), lScale = Measure.AngularMomentumScale(origin, bodies);

        int lateImpacts = 0;
        for (int step = 0; step < 60; step++)
        {
            world.Step(Dt);
            lateImpacts += step >= 30 ? world.ImpactCount : 0;
            Law.Near(p0, Measure.Momentum(bodies), 1e-6 * pScale, $"step {step}: momentum");
            Law.Near(l0, Measure.AngularMomentum(origin, bodies), 1e-5 * lScale, $"step {step}: angular momentum about {origin}");
            Assert.True(Measure.KineticEnergy(bodies) <= e0 * (1 + 1e-6), $"step {step}: kinetic energy rose from {e0} to {Measure.KineticEnergy(bodies)} J");
        }

        _output.WriteLine($"kinetic energy {e0:F1} -> {Measure.KineticEnergy(bodies):F1} J; {lateImpacts / 30.0:F1} impacts a step over steps 30-59");
        Assert.True(Measure.KineticEnergy(bodies) < 0.5 * e0, "the heavy discs did not stop each other");
        Assert.True(lateImpacts < 30 * 5, $"{lateImpacts / 30.0} impacts a step over steps 30-59: the lump still closes on itself");
    }

    /// <summary>
    /// Generated world 669 of 2,000 (seed 807): free space under gravity, where a 124 kg disc falls onto a 0.013 kg one
    /// lying on a 948 kg one, all three at 8–10 m/s. Jammed at the start of every substep and held still while gravity
    /// sped them up, the three hovered and the world gained 198 J in step 25. As one lump they fall: from two steps after
    /// they meet, their centre of mass gains g·dt a step, and the world's mechanical energy never rises.
    /// </summary>
    [Fact]
    public void Under_gravity_a_falling_sandwich_of_heavy_and_light_discs_falls_on_as_one_lump()
    {
        var world = new World(Scenes.EarthGravity, new SequentialImpulseSolver(restitution: 0f, friction: 0.3f) { RestitutionThreshold = 0.5f }) { Substeps = 4 };
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (1.7047164f, 0.12805048f, new(3.26968f, 1.225331f, 0), new(-0.3016532f, -1.4039319f, 0), 0.8291978f),
            (15.750677f, 0.056547005f, new(1.0613482f, 3.905999f, 0), new(4.142979f, 2.4225695f, 0), -1.2682031f),
            (124.67639f, 0.15858144f, new(1.7858412f, 3.197311f, 0), new(1.4755342f, -1.8673886f, 0), -1.7569724f),
            (948.5198f, 0.06493266f, new(2.243815f, 1.002021f, 0), new(0.35793865f, -0.3862963f, 0), 1.2632244f),
            (4.9715724f, 0.111244805f, new(2.3343015f, 0.39687154f, 0), new(-0.9963394f, -1.8812292f, 0), -3.856092f),
            (0.013455902f, 0.4321094f, new(2.565842f, 2.3184502f, 0), new(0.20765981f, -1.5069414f, 0), -3.3644488f),
        };
        RigidBody[] bodies = discs.Select(d => world.Add(Disc(d.Mass, d.Radius, d.Position, d.Velocity, d.Spin))).ToArray();
        RigidBody[] sandwich = { bodies[2], bodies[5], bodies[3] };
        double energy = MechanicalEnergy(world, bodies);
        float dt = 1f / 30f;
        for (int step = 0; step < 40; step++)
        {
            double before = CentreOfMassVelocityY(sandwich);
            world.Step(dt);
            double now = MechanicalEnergy(world, bodies);
            Assert.True(now <= energy + 1e-5 * Math.Abs(energy) + 1e-3, $"step {step}: mechanical energy rose from {energy} to {now} J");
            energy = now;
            if (step >= 26)
            {
                double gain = CentreOfMassVelocityY(sandwich) - before;
                Assert.True(Math.Abs(gain + 9.81 * dt) <= 1e-3, $"step {step}: the sandwich's centre of mass gained {gain} m/s, not {-9.81 * dt}");
            }
        }
    }

    private static RigidBody Disc(float mass, float radius, Vector3 position, Vector3 velocity, float spin = 0f) =>
        new(mass, radius, position, Inertia.Disc(mass, radius)) { LinearVelocity = velocity, AngularVelocity = new Vector3(0, 0, spin) };

    private static double CentreOfMassVelocityY(RigidBody[] bodies) => Measure.Momentum(bodies).Y / bodies.Sum(b => (double)b.Mass);

    private static double MechanicalEnergy(World world, RigidBody[] bodies) =>
        Measure.KineticEnergy(bodies) - bodies.Sum(b => b.Mass * (double)Vector3.Dot(world.Gravity, b.Position));
}
