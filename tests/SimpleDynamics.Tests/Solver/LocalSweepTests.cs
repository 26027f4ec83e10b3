using System;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Response;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The extra sweeps under gravity visit only the contacts of bodies that still change (SequentialImpulseSolver.LocalSweeps.cs):
/// they must converge as a sweep over every contact would, and visit much less.
/// </summary>
public class LocalSweepTests
{
    private const float Dt = 1f / 60f;
    private readonly ITestOutputHelper _output;

    public LocalSweepTests(ITestOutputHelper output) => _output = output;

    /// <summary>
    /// A deep pit poured and landing: once most of it rests, the few contacts that still press or let go keep the
    /// sweeps going while the rest of the pile is solved. Whenever the local sweeps end converged, a full sweep would
    /// change no contact's normal velocity by more than a few times the tolerance either: the last local sweep changed
    /// none by more than half of it, and a body with several contacts sums what they did to it, as after a last full
    /// sweep (measured: 1.7× the tolerance in the 2-D pit, 0.6× in the 3-D one, over all 480 steps; local sweeps that let
    /// bodies drift 16 times as far before revisiting their contacts leave 9.2× and 6.8×).
    /// </summary>
    [Theory]
    [InlineData(true, 2500)]
    [InlineData(false, 2744)]
    public void Extra_sweeps_visit_the_contacts_still_changing_and_converge_as_a_full_sweep_would(bool planar, int count)
    {
        var solver = new SequentialImpulseSolver { MeasureResidualAfterLocalSweeps = true };
        World world = Scenes.BallPit(count, planar, seed: 3, responder: solver);
        long localSolves = 0, fullSweepSolves = 0;
        int localSweeps = 0, sweeps = 0;
        for (int i = 0; i < 480; i++)
        {
            world.Step(Dt);
            sweeps += solver.SweepsThisStep;
            localSweeps += solver.LocalSweepsThisStep;
            localSolves += solver.LocalSolvesThisStep;
            fullSweepSolves += (long)solver.LocalSweepsThisStep * world.Collisions.Count;
        }

        float residual = solver.LargestResidualAfterLocalSweeps / solver.ConvergenceTolerance; // both in units of g h
        _output.WriteLine($"{sweeps} sweeps, {localSweeps} of them local, which solved {localSolves} contacts, {(double)localSolves / fullSweepSolves:P1} " +
            $"of full sweeps; largest residual after them {residual:F2}× the tolerance");
        Assert.True(localSweeps > 100, $"only {localSweeps} local sweeps: the landing must leave regions unsolved");
        Assert.True(localSolves < fullSweepSolves / 4, $"{localSolves} contacts solved, against {fullSweepSolves} by full sweeps");
        Assert.InRange(residual, 0f, 4f);
    }
}
