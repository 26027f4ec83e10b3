using System;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Api;

/// <summary>
/// Once warm, a step allocates nothing: contacts, pairs, solver data and the contact cache live in arrays that
/// are kept and only grow. Measured on this thread, which is where the whole step runs.
/// </summary>
public class ZeroAllocationTests
{
    private readonly ITestOutputHelper _output;

    public ZeroAllocationTests(ITestOutputHelper output) => _output = output;

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void A_warm_thousand_ball_pile_steps_a_hundred_times_without_allocating(bool planar)
    {
        World world = Scenes.BallPit(1000, planar, seed: 4);
        world.SleepingEnabled = false; // an awake pile; a sleeping world's steps are checked in SleepingTests
        for (int i = 0; i < 300; i++)
        {
            world.Step(1f / 60f);
        }

        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            world.Step(1f / 60f);
        }

        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        _output.WriteLine($"{allocated} bytes over 100 steps, {world.Collisions.Count} contacts");
        Assert.True(world.Collisions.Count > 1000, "the pile should be in contact");
        Assert.Equal(0, allocated);
    }

    [Fact]
    public void Reading_the_diagnostics_allocates_nothing()
    {
        World world = Scenes.BallPit(200, planar: true, seed: 4);
        world.Step(1f / 60f);
        _ = world.Diagnostics;
        long before = GC.GetAllocatedBytesForCurrentThread();
        WorldDiagnostics diagnostics = world.Diagnostics;
        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
        Assert.True(diagnostics.KineticEnergy >= 0);
    }
}
