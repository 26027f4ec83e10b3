using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The extra sweeps a deep pile may spend: <see cref="SequentialImpulseSolver.ExtraIterations"/> up to
/// <see cref="SequentialImpulseSolver.DeepPileLayers"/> bodies deep, proportionally more beyond (the measurements
/// behind the rule are in the constant's documentation and in benchmarks/README.md).
/// </summary>
public class DeepPileBudgetTests
{
    private const float Radius = 0.1f;

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

    // A column of N discs has contacts from the ground up to N − 1 diameters: N − 1 layers, so 8 × (N − 1) / 16
    // extra sweeps beyond 16 layers (rounded up; odd depths keep the product off whole numbers and float rounding).
    [Theory]
    [InlineData(10, 8)] // 9 layers: within 16
    [InlineData(26, 13)] // 25 layers: 12.5
    [InlineData(42, 21)] // 41 layers: 20.5
    [InlineData(166, 83)] // 165 layers: 82.5
    public void A_pile_deeper_than_the_deep_pile_layers_may_spend_proportionally_more_extra_sweeps(int discs, int expected)
    {
        var solver = new SequentialImpulseSolver();
        World world = Column(discs, Scenes.EarthGravity, solver);
        world.Step(1f / 60f);
        Assert.Equal(expected, solver.ExtraSweepBudget);
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
