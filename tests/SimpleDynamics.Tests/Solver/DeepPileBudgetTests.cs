using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The extra sweeps a deep pile may spend: <see cref="SequentialImpulseSolver.ExtraIterations"/> up to
/// <see cref="SequentialImpulseSolver.DeepPileLayers"/> bodies deep, more with the square of the depth beyond (the measurements
/// behind the rule are in the constant's documentation and in benchmarks/README.md).
/// </summary>
public class DeepPileBudgetTests
{
    private const float Radius = 0.1f;
    private readonly ITestOutputHelper _output;

    public DeepPileBudgetTests(ITestOutputHelper output) => _output = output;

    /// <summary>
    /// 2,000 discs poured into a box 20 wide, where they pile up 100 deep, with sleeping on at its defaults. With a
    /// fixed budget of 8 extra sweeps this pile still moved 12 s after the pour began (every step spent its whole
    /// budget, none asleep, overlaps up to 10.6 mm); with the budget scaled to its depth every disc is asleep after
    /// 277 steps (4.6 s). The test stops at 12 s.
    /// </summary>
    [Fact]
    public void A_pour_a_hundred_discs_deep_comes_to_rest_and_falls_asleep_at_the_default_threshold()
    {
        const int wide = 20, deep = 100;
        var world = new World(Scenes.EarthGravity);
        world.AddPlanes(StaticPlane.Box(Vector3.Zero, new Vector3(wide * 2.2f * Radius, 9 * deep * Radius, 0), planar: true));
        var random = new Random(1);
        for (int row = 0; row < deep; row++)
        {
            for (int column = 0; column < wide; column++)
            {
                float jitter = (float)(random.NextDouble() - 0.5) * 0.02f;
                var position = new Vector3((column + 0.5f) * 2.2f * Radius + jitter, (row + 0.5f) * 4.4f * Radius, 0);
                world.Add(new RigidBody(Radius * Radius, Radius, position, Inertia.Disc(Radius * Radius, Radius)));
            }
        }

        int steps = 0;
        while (steps < 720 && world.SleepingBodyCount < wide * deep)
        {
            world.Step(1f / 60f);
            steps++;
        }

        _output.WriteLine($"{world.SleepingBodyCount} of {wide * deep} asleep after {steps} steps");
        Assert.Equal(wide * deep, world.SleepingBodyCount);
    }

    /// <summary>A column of <paramref name="count"/> discs standing on the ground, each on the one below.</summary>
    private static World Column(int count, Vector3 gravity, SequentialImpulseSolver solver)
    {
        var world = new World(gravity, solver) { SleepingEnabled = false };
        world.AddPlanes(new[] { StaticPlane.Ground() });
        for (int i = 0; i < count; i++)
        {
            world.Add(new RigidBody(1f, Radius, new Vector3(0, Radius + i * 2 * Radius, 0), Inertia.Disc(1f, Radius)));
        }

        return world;
    }

    // A column of N discs has contacts from the ground up to N − 1 diameters: N − 1 layers, so 8 × ((N − 1) / 24)²
    // extra sweeps beyond 24 layers, at most 28 × 8 (rounded up; these depths keep the product off whole numbers and
    // float rounding). The budget is asserted in the second step, after the contacts have held the column once: a
    // resting pile stays slower than g dt, so it still counts.
    [Theory]
    [InlineData(10, 8)] // 9 layers: within 24
    [InlineData(26, 9)] // 25 layers: 8.68
    [InlineData(42, 24)] // 41 layers: 23.35
    [InlineData(122, 204)] // 121 layers: 203.35, within the cap
    [InlineData(166, 224)] // 165 layers: 378.13, capped at 28 × 8
    public void A_pile_deeper_than_the_deep_pile_layers_may_spend_more_extra_sweeps_with_the_square_of_its_depth(int discs, int expected)
    {
        var solver = new SequentialImpulseSolver();
        World world = Column(discs, Scenes.EarthGravity, solver);
        world.Step(1f / 60f);
        world.Step(1f / 60f);
        Assert.Equal(expected, solver.ExtraSweepBudget);
    }

    /// <summary>
    /// A crowd that falls packed together touches all through but rests on nothing: it is no pile, whatever its
    /// height, once it falls faster than g dt. (Measured from every contact, the 16,000-disc pit's falling lattice
    /// was given the deepest pile's budget before it landed.)
    /// </summary>
    [Fact]
    public void A_packed_column_in_free_fall_is_no_pile_and_keeps_the_setting()
    {
        var solver = new SequentialImpulseSolver();
        var world = new World(Scenes.EarthGravity, solver) { SleepingEnabled = false };
        for (int i = 0; i < 166; i++)
        {
            world.Add(new RigidBody(1f, Radius, new Vector3(0, 100 + i * 2 * Radius, 0), Inertia.Disc(1f, Radius)));
        }

        for (int step = 0; step < 3; step++)
        {
            world.Step(1f / 60f); // the third step begins at 2 g dt, clear of the threshold g dt
        }

        Assert.True(world.Diagnostics.ContactCount >= 165, $"the column should touch all through ({world.Diagnostics.ContactCount} contacts)");
        Assert.Equal(solver.ExtraIterations, solver.ExtraSweepBudget);
    }

    [Fact]
    public void Without_gravity_or_with_no_extra_sweeps_the_budget_is_the_setting()
    {
        var free = new SequentialImpulseSolver();
        World world = Column(161, Vector3.Zero, free);
        world.Step(1f / 60f);
        Assert.Equal(free.ExtraIterations, free.ExtraSweepBudget);

        var fixedWork = new SequentialImpulseSolver { ExtraIterations = 0 };
        World deep = Column(161, Scenes.EarthGravity, fixedWork);
        deep.Step(1f / 60f);
        Assert.Equal(0, fixedWork.ExtraSweepBudget);
    }
}
