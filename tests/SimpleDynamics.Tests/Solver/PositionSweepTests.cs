using System;
using System.Linq;
using SimpleDynamics.Bodies;
using SimpleDynamics.Response;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The position sweeps after the first visit only the contacts that can still change (SequentialImpulseSolver.Positions.cs):
/// without any drift allowed they must do exactly what full sweeps do; with the default they must visit far fewer
/// contacts and still end every step within the slop.
/// </summary>
public class PositionSweepTests
{
    private const float Dt = 1f / 60f;
    private readonly ITestOutputHelper _output;

    public PositionSweepTests(ITestOutputHelper output) => _output = output;

    /// <summary>A pour of mixed sizes, from the first contacts to a landed pile: every body, every step, bit for bit.</summary>
    [Theory]
    [InlineData(true, 600)]
    [InlineData(false, 729)]
    public void Without_drift_the_marked_sweeps_move_every_body_as_full_sweeps_do(bool planar, int count)
    {
        var marked = new SequentialImpulseSolver { PositionDrift = 0 };
        var full = new SequentialImpulseSolver { FullPositionSweeps = true };
        World world = Scenes.BallPit(count, planar, seed: 5, radiusSpread: 1.5f, responder: marked);
        World reference = Scenes.BallPit(count, planar, seed: 5, radiusSpread: 1.5f, responder: full);
        long markedVisits = 0, fullVisits = 0;
        for (int step = 1; step <= 240; step++)
        {
            world.Step(Dt);
            reference.Step(Dt);
            markedVisits += marked.PositionVisitsThisStep;
            fullVisits += full.PositionVisitsThisStep;
            if (WorldMeasure.FirstDifference(reference, world) is string difference)
            {
                Assert.Fail($"step {step}, against full sweeps: {difference}");
            }
        }

        _output.WriteLine($"marked sweeps visited {markedVisits} contacts, full sweeps {fullVisits} ({(double)markedVisits / fullVisits:P1})");
        Assert.True(markedVisits < 0.9 * fullVisits, $"{markedVisits} visits against {fullVisits}: the marks were hardly used");
    }

    /// <summary>
    /// A settled pit with the default drift (1 % of the slop): the sweeps after the first visit a fraction of the
    /// contacts, and every step still ends with no contact deeper than the slop (up to float rounding of where the
    /// bodies end, 1e-5 of their size, as the world laws allow), as with full sweeps.
    /// </summary>
    [Theory]
    [InlineData(true, 1000)]
    [InlineData(false, 1000)]
    public void With_the_default_drift_a_settled_pile_is_visited_far_less_and_ends_each_step_within_the_slop(bool planar, int count)
    {
        var marked = new SequentialImpulseSolver();
        var full = new SequentialImpulseSolver { FullPositionSweeps = true };
        World world = Scenes.BallPit(count, planar, seed: 2, responder: marked);
        World reference = Scenes.BallPit(count, planar, seed: 2, responder: full);
        world.SleepingEnabled = reference.SleepingEnabled = false;
        long markedVisits = 0, fullVisits = 0;
        float deepest = 0, deepestFull = 0;
        for (int step = 1; step <= 600; step++)
        {
            world.Step(Dt);
            reference.Step(Dt);
            if (step <= 420)
            {
                continue; // the pour lands in the first seven seconds
            }

            markedVisits += marked.PositionVisitsThisStep;
            fullVisits += full.PositionVisitsThisStep;
            deepest = MathF.Max(deepest, Deepest(world));
            deepestFull = MathF.Max(deepestFull, Deepest(reference));
        }

        _output.WriteLine($"settled: marked sweeps visited {(double)markedVisits / fullVisits:P1} of what full sweeps did; " +
            $"deepest contact {deepest * 1e3:F4} mm (full sweeps {deepestFull * 1e3:F4} mm), slop {marked.Slop * 1e3:F4} mm");
        Assert.True(markedVisits < 0.6 * fullVisits, $"{markedVisits} visits against {fullVisits}");
        float reach = 2 * world.Bodies.Max(b => b.Radius);
        Assert.True(deepest <= marked.Slop + 1e-5f * reach, $"a contact {deepest:R} m deep, beyond the slop"); // as WorldLaws allows
    }

    private static float Deepest(World world) =>
        world.Collisions.Contacts.ToArray().Max(c => c.Penetration);
}
