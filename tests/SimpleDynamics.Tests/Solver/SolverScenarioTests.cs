using System;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The iterative solver in the scenes that break pair-by-pair response: resting contact, piles, a closed box,
/// a dense elastic gas, a free cluster, and rolling friction with its closed form.
/// </summary>
public class SolverScenarioTests
{
    private const float Dt = 1f / 60f;
    private readonly ITestOutputHelper _output;

    public SolverScenarioTests(ITestOutputHelper output) => _output = output;

    [Fact]
    public void Dropped_ball_with_restitution_half_comes_to_rest_and_stays_there_for_ten_seconds()
    {
        World world = Scenes.DroppedBall(restitution: 0.5f);
        var solver = (SequentialImpulseSolver)world.Responder;
        RigidBody ball = world.Bodies[0];
        int bounces = 0;
        float previousVy = 0;
        for (int i = 0; i < 300; i++)
        {
            world.Step(Dt);
            if (previousVy < 0 && ball.LinearVelocity.Y > 0)
            {
                bounces++;
            }

            previousVy = ball.LinearVelocity.Y;
        }

        Assert.InRange(bounces, 2, 10); // it bounces a few times, then lies still

        float maxSpeed = 0, maxPenetration = 0;
        for (int i = 0; i < 600; i++)
        {
            world.Step(Dt);
            maxSpeed = MathF.Max(maxSpeed, ball.LinearVelocity.Length());
            maxPenetration = MathF.Max(maxPenetration, world.Diagnostics.MaxPenetration);
        }

        _output.WriteLine($"bounces {bounces}, over the next 10 s: max speed {maxSpeed:E2} m/s, max penetration {maxPenetration:E2} m (slop {solver.Slop})");
        Assert.True(maxSpeed < 1e-3f, $"speed {maxSpeed} m/s");
        Assert.True(maxPenetration <= solver.Slop, $"penetration {maxPenetration} m > slop {solver.Slop} m");
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Pile_of_a_thousand_balls_poured_into_a_closed_box_settles(bool planar)
    {
        const float radius = 0.1f;
        World world = Scenes.BallPit(1000, planar, seed: 7, radius: radius);
        (Vector3 min, Vector3 max) = BoxOf(world);
        double startEnergy = world.Diagnostics.MechanicalEnergy;
        for (int i = 0; i < 600; i++)
        {
            world.Step(Dt);
            Assert.False(WorldMeasure.AnyNaN(world), $"NaN at step {i}");
            Assert.True(WorldMeasure.InsideBox(world, min, max, 0), $"a ball left the box at step {i}");
        }

        WorldDiagnostics settled = world.Diagnostics;
        _output.WriteLine($"{(planar ? "2-D" : "3-D")}: KE {settled.KineticEnergy:E2} J of {startEnergy:F1} J at start, max penetration {settled.MaxPenetration:E2} m, {settled.ContactCount} contacts");
        Assert.True(settled.KineticEnergy < 1e-4 * startEnergy, $"kinetic energy {settled.KineticEnergy} J");
        Assert.True(settled.MaxPenetration < 0.01f * radius, $"penetration {settled.MaxPenetration} m ≥ 1% of r");
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(0.5f)]
    [InlineData(1f)]
    public void In_a_closed_box_energy_never_rises_above_its_start(float restitution)
    {
        var solver = new SequentialImpulseSolver(restitution, friction: 0.3f);
        World world = Scenes.BallPit(300, planar: true, seed: 3, radius: 0.1f, responder: solver);
        double start = world.Diagnostics.MechanicalEnergy; // the floor is at y = 0, so this is positive
        double highest = start;
        for (int i = 0; i < 600; i++)
        {
            world.Step(Dt);
            highest = Math.Max(highest, world.Diagnostics.MechanicalEnergy);
        }

        _output.WriteLine($"ε = {restitution}: start {start:F6} J, highest {highest:F6} J, end {world.Diagnostics.MechanicalEnergy:F6} J");
        Assert.True(highest <= start * (1 + 1e-5), $"energy rose from {start} J to {highest} J");
    }

    /// <summary>
    /// ε = 1, μ = 0, no gravity: a dense gas (a third of the box filled) colliding many at once. Each collision the
    /// solver answers is a whole two-body elastic collision, which keeps kinetic energy exactly, so only float
    /// rounding may change it. Issue 3 asks for 1% over 10,000 steps.
    /// </summary>
    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Dense_elastic_gas_keeps_its_kinetic_energy_within_one_percent_over_10000_steps(bool planar)
    {
        World world = Scenes.ElasticGas(300, planar, seed: 5);
        double start = world.Diagnostics.KineticEnergy;
        double highest = start, lowest = start;
        int contacts = 0;
        for (int i = 0; i < 10_000; i++)
        {
            world.Step(Dt);
            double kinetic = world.Diagnostics.KineticEnergy;
            highest = Math.Max(highest, kinetic);
            lowest = Math.Min(lowest, kinetic);
            contacts += world.Diagnostics.ContactCount;
        }

        _output.WriteLine($"{(planar ? "2-D" : "3-D")}: KE over 10,000 steps: start {start:F6} J, highest {highest:F6} J, lowest {lowest:F6} J; {contacts} contacts");
        Assert.True(contacts > 100_000, "the gas should be dense enough to collide all the time");
        Assert.True(highest <= start * 1.01, $"kinetic energy rose from {start} to {highest}");
        Assert.True(lowest >= start * 0.99, $"kinetic energy fell {100 * (1 - lowest / start):F3}%");
    }

    /// <summary>
    /// Newton's cradle on a table: a ball strikes a row of equal touching balls head-on with ε = 1, μ = 0. Momentum
    /// and energy conservation leave one answer for sequential collisions: the striker and the row stop and the
    /// ball at the far end leaves with the striker's speed. (Solving the row's contacts simultaneously would set
    /// every ball moving instead.)
    /// </summary>
    [Fact]
    public void Struck_row_of_touching_balls_passes_the_blow_to_the_far_end_like_newtons_cradle()
    {
        const float speed = 3f;
        World world = Scenes.StruckRow(5, speed, restitution: 1f);
        for (int i = 0; i < 120; i++)
        {
            world.Step(Dt);
        }

        float[] velocities = world.Bodies.Select(b => b.LinearVelocity.X).ToArray(); // the row 0–4, then the striker
        _output.WriteLine(string.Join(", ", velocities.Select(v => v.ToString("F5"))));
        Assert.InRange(velocities[4], speed * 0.999f, speed * 1.001f);
        foreach (int i in new[] { 0, 1, 2, 3, 5 })
        {
            Assert.InRange(velocities[i], -1e-3f * speed, 1e-3f * speed);
        }
    }

    [Fact]
    public void Free_cluster_keeps_its_linear_and_angular_momentum_for_ten_thousand_steps()
    {
        var random = new Random(11);
        var world = new World(Vector3.Zero, new SequentialImpulseSolver(restitution: 0.5f, friction: 0.4f));
        for (int i = 0; i < 60; i++)
        {
            var position = new Vector3((float)random.NextDouble() * 3, (float)random.NextDouble() * 3, (float)random.NextDouble() * 3);
            float mass = 0.5f + (float)random.NextDouble() * 4;
            float r = 0.15f + (float)random.NextDouble() * 0.2f;
            world.Add(new RigidBody(mass, r, position)
            {
                LinearVelocity = (new Vector3(1.5f) - position) * 0.8f + new Vector3((float)random.NextDouble() - 0.5f, 0, 0),
                AngularVelocity = new Vector3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, 0),
            });
        }

        var point = new Vector3(0.3f, -0.2f, 0.5f);
        WorldDiagnostics start = world.MeasureDiagnostics(point);
        int contacts = 0;
        for (int i = 0; i < 10_000; i++)
        {
            world.Step(Dt);
            contacts += world.Collisions.Count;
        }

        WorldDiagnostics end = world.MeasureDiagnostics(point);
        // Impulses come in equal and opposite pairs along the line of centres or at the contact point, so they
        // conserve both exactly but for float rounding. The position correction (listing 2) moves two bodies
        // apart with Σ m Δx = 0, which keeps linear momentum and the centre of mass, but changes the orbital
        // angular momentum by Σ Δx × m v: a small drift, bounded here at 1% of |L|.
        double momentumScale = world.Bodies.Sum(b => b.Mass * b.LinearVelocity.Length());
        double linearDrift = (end.LinearMomentum - start.LinearMomentum).Length();
        double angularDrift = (end.AngularMomentum - start.AngularMomentum).Length() / start.AngularMomentum.Length();
        _output.WriteLine($"{contacts} contacts; p {start.LinearMomentum} -> {end.LinearMomentum}; L {start.AngularMomentum} -> {end.AngularMomentum} ({100 * angularDrift:F3}%)");
        Assert.True(contacts > 1000, "the cluster should collide many times");
        Assert.True(linearDrift < 1e-5 * momentumScale, $"linear momentum drifted by {linearDrift}");
        Assert.True(angularDrift < 0.01, $"angular momentum drifted by {100 * angularDrift:F3}%");
    }

    /// <summary>
    /// A solid ball (I = 2/5 m r²) set sliding at v0 with no spin on a floor of friction μ: friction μ m g slows it
    /// and spins it up until v = ω r, at t = 2 v0 / (7 μ g), after which it rolls at 5/7 v0.
    /// </summary>
    [Fact]
    public void Sliding_ball_starts_rolling_when_and_as_fast_as_classical_mechanics_says()
    {
        const float v0 = 5f, mu = 0.3f, g = 9.81f;
        World world = Scenes.SlidingBall(v0, mu);
        RigidBody ball = world.Bodies[0];
        double rollingTime = double.NaN;
        for (int i = 0; i < 120; i++)
        {
            world.Step(Dt);
            float slip = ball.LinearVelocity.X + ball.AngularVelocity.Z * ball.Radius; // v − ω r, ω about −z rolls +x
            if (double.IsNaN(rollingTime) && MathF.Abs(slip) < 1e-3f)
            {
                rollingTime = world.Time;
            }
        }

        double expectedTime = 2 * v0 / (7 * mu * g);
        _output.WriteLine($"rolls from t = {rollingTime:F4} s (theory {expectedTime:F4} s) at {ball.LinearVelocity.X:F5} m/s (theory {5 * v0 / 7:F5})");
        Assert.InRange(rollingTime, expectedTime - Dt, expectedTime + Dt);
        Assert.InRange(ball.LinearVelocity.X, 5 * v0 / 7 * 0.999, 5 * v0 / 7 * 1.001);
        Assert.InRange(-ball.AngularVelocity.Z * ball.Radius, 5 * v0 / 7 * 0.999, 5 * v0 / 7 * 1.001);
    }

    [Fact]
    public void Warm_starting_makes_a_pile_penetrate_less()
    {
        double Penetration(bool warm)
        {
            var solver = new SequentialImpulseSolver { WarmStarting = warm };
            World world = Scenes.BallPit(400, planar: true, seed: 9, radius: 0.1f, responder: solver);
            float worst = 0;
            for (int i = 0; i < 400; i++)
            {
                world.Step(Dt);
                if (i >= 300)
                {
                    worst = MathF.Max(worst, world.Diagnostics.MaxPenetration);
                }
            }

            return worst;
        }

        double warm = Penetration(true), cold = Penetration(false);
        _output.WriteLine($"largest penetration once settled: warm {warm:E3} m, cold {cold:E3} m");
        Assert.True(warm < 0.5 * cold, $"warm {warm} m, cold {cold} m");
    }

    private static (Vector3 Min, Vector3 Max) BoxOf(World world)
    {
        var min = new Vector3(float.NegativeInfinity);
        var max = new Vector3(float.PositiveInfinity);
        foreach (StaticPlane plane in world.Planes)
        {
            if (plane.Normal == Vector3.UnitX) min.X = plane.Offset;
            if (plane.Normal == -Vector3.UnitX) max.X = -plane.Offset;
            if (plane.Normal == Vector3.UnitY) min.Y = plane.Offset;
            if (plane.Normal == -Vector3.UnitY) max.Y = -plane.Offset;
            if (plane.Normal == Vector3.UnitZ) min.Z = plane.Offset;
            if (plane.Normal == -Vector3.UnitZ) max.Z = -plane.Offset;
        }

        return (min, max);
    }

    /// <summary>
    /// A settled pile, warm-started, is solved before its first sweep: that sweep changes nothing beyond a quarter of
    /// the tolerance, and the substep spends no other.
    /// </summary>
    [Fact]
    public void A_settled_pile_spends_one_sweep_a_substep()
    {
        var solver = new SequentialImpulseSolver();
        World world = Scenes.BallPit(100, planar: true, responder: solver);
        world.SleepingEnabled = false;
        for (int i = 0; i < 300; i++)
        {
            world.Step(Dt);
        }

        world.Step(Dt);
        Assert.Equal(world.Substeps, solver.SweepsThisStep);
    }

    /// <summary>
    /// A column that has just been set down has no impulses to start from: its first sweep is far from converged, so
    /// every substep does all of its <see cref="SequentialImpulseSolver.VelocityIterations"/> and then spends extra
    /// sweeps; without warm starting, every step starts that way.
    /// </summary>
    [Fact]
    public void A_pile_that_is_not_yet_solved_spends_every_fixed_sweep_and_more()
    {
        var solver = new SequentialImpulseSolver { WarmStarting = false };
        var world = new World(Scenes.EarthGravity, solver) { SleepingEnabled = false };
        world.AddPlanes(new[] { StaticPlane.Ground() });
        for (int i = 0; i < 10; i++)
        {
            world.Add(new RigidBody(1f, 0.1f, new Vector3(0, 0.1f + 0.2f * i, 0), Inertia.Disc(1f, 0.1f)));
        }

        for (int step = 0; step < 30; step++)
        {
            world.Step(Dt);
            Assert.True(solver.SweepsThisStep > solver.VelocityIterations * world.Substeps, $"step {step}: {solver.SweepsThisStep} sweeps");
        }
    }

    /// <summary>
    /// A pit 45 discs deep comes to rest after its pour and then falls asleep at the default threshold. Before the
    /// sweeps' convergence was measured in velocity (against g h), the top of such a pile counted as converged while
    /// it still sank, and the pile crept at 1–3 cm/s for ever, with bursts of 0.4 m/s and dozens of impacts a step.
    /// </summary>
    [Fact]
    public void A_deep_pit_comes_to_rest_and_falls_asleep_at_the_default_threshold()
    {
        World world = Scenes.BallPit(2000, planar: true);
        world.SleepingEnabled = false;
        for (int i = 0; i < 600; i++)
        {
            world.Step(Dt);
        }

        float fastest = world.Bodies.Max(b => b.LinearVelocity.Length());
        _output.WriteLine($"after 10 s: fastest ball {fastest} m/s, {world.ImpactCount} impacts in the last step");
        Assert.True(fastest < 5e-3f, $"the pile still moves: fastest ball {fastest} m/s");
        Assert.Equal(0, world.ImpactCount);

        world.SleepingEnabled = true;
        for (int i = 0; i < 60 && world.SleepingBodyCount < 2000; i++)
        {
            world.Step(Dt);
        }

        Assert.Equal(2000, world.SleepingBodyCount);
    }
}
