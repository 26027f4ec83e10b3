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

    /// <summary>
    /// A settled pile of spheres goes on turning slowly (nothing resists rolling), so each substep's first sweep finds
    /// a little to change: within the tolerance the later sweeps converge to, not within the quarter of it that ends
    /// the substep at once. The fixed sweeps after it then visit only the contacts of the bodies it changed. Stepped
    /// beside a twin that finishes them over every contact, from the same poured pile, the pile must spend fewer sweeps
    /// and stay as the twin does: as deep in overlap, as still, and a full sweep after the local ones would change no
    /// contact by more than a few times the tolerance.
    /// </summary>
    [Fact]
    public void A_settled_pile_of_spheres_finishes_its_fixed_sweeps_where_bodies_change()
    {
        World localWorld = PitOfSpheres(finishesLocally: true);
        World fullWorld = PitOfSpheres(finishesLocally: false);
        var local = (SequentialImpulseSolver)localWorld.Responder;
        var full = (SequentialImpulseSolver)fullWorld.Responder;
        int finishedLocally = 0, sweepsWithLocal = 0, sweepsWithFull = 0;
        float localDepth = 0, fullDepth = 0;
        for (int step = 1; step <= 420; step++)
        {
            localWorld.Step(Dt);
            fullWorld.Step(Dt);
            if (step > 300) // poured and settled (5 s): the next two seconds
            {
                sweepsWithLocal += local.SweepsThisStep;
                finishedLocally += local.SubstepsFinishedLocallyThisStep;
                sweepsWithFull += full.SweepsThisStep;
                localDepth = MathF.Max(localDepth, localWorld.Diagnostics.MaxPenetration);
                fullDepth = MathF.Max(fullDepth, fullWorld.Diagnostics.MaxPenetration);
            }
        }

        double localSpeed = RmsSpeed(localWorld), fullSpeed = RmsSpeed(fullWorld);
        float residual = local.LargestResidualAfterLocalSweeps / local.ConvergenceTolerance;
        _output.WriteLine($"sweeps in 120 steps: {sweepsWithLocal} against {sweepsWithFull}, {finishedLocally} of 480 substeps finished locally; deepest overlap " +
            $"{localDepth * 1e3:F3} mm against {fullDepth * 1e3:F3} mm; rms speed {localSpeed:E2} against {fullSpeed:E2} m/s; " +
            $"largest residual after local sweeps {residual:F2}× the tolerance");
        Assert.True(finishedLocally > 120, $"only {finishedLocally} of 480 substeps were finished locally");
        Assert.True(sweepsWithLocal < 0.8 * sweepsWithFull, $"{sweepsWithLocal} sweeps against {sweepsWithFull}");
        Assert.InRange(localDepth, 0f, fullDepth + 1e-4f);
        Assert.InRange(localSpeed, 0, 2 * fullSpeed + 1e-3);
        Assert.InRange(residual, 0f, 4f);
    }

    /// <summary>
    /// The same finish on two threads: a pile of spheres cut into two strips (64 contacts a strip, so that a small pile
    /// is cut), stepped on one thread and on two, must move every body alike, every step, every bit, while its
    /// substeps are finished locally (the local sweeps in strips: SweepMarkedRange).
    /// </summary>
    [Fact]
    public void A_pile_of_spheres_finished_locally_steps_bit_for_bit_alike_on_two_threads()
    {
        World[] worlds = { PitInStrips(threads: 1), PitInStrips(threads: 2) };
        var solver = (SequentialImpulseSolver)worlds[0].Responder;
        int finishedLocally = 0, cutSteps = 0;
        try
        {
            for (int step = 1; step <= 600; step++)
            {
                worlds[0].Step(Dt);
                worlds[1].Step(Dt);
                finishedLocally += solver.SubstepsFinishedLocallyThisStep;
                cutSteps += solver.Cut.Count > 1 ? 1 : 0;
                Assert.True(WorldMeasure.FirstDifference(worlds[0], worlds[1]) is null,
                    $"step {step}, two threads: {WorldMeasure.FirstDifference(worlds[0], worlds[1])}");
            }
        }
        finally
        {
            worlds[1].ThreadCount = 1;
        }

        _output.WriteLine($"{finishedLocally} substeps finished locally, {cutSteps} of 600 steps cut into strips");
        Assert.True(cutSteps > 300, $"only {cutSteps} steps were cut into strips");
        Assert.True(finishedLocally > 200, $"only {finishedLocally} substeps were finished locally");
    }

    private static World PitInStrips(int threads)
    {
        var solver = new SequentialImpulseSolver { Strips = 2 };
        solver.Cut.ContactsPerStrip = 64;
        World world = Scenes.BallPit(Count3D, planar: false, seed: 2, responder: solver);
        world.SleepingEnabled = false;
        world.ThreadCount = threads;
        return world;
    }

    private static World PitOfSpheres(bool finishesLocally)
    {
        var solver = new SequentialImpulseSolver { FinishesFirstSweepLocally = finishesLocally, MeasureResidualAfterLocalSweeps = finishesLocally };
        return Scenes.BallPit(Count3D, planar: false, seed: 1, responder: solver);
    }

    private const int Count3D = 1000;

    /// <summary>√(2 KE / Σm): the bodies' root-mean-square speed, translation and spin together.</summary>
    private static double RmsSpeed(World world) =>
        Math.Sqrt(2 * world.Diagnostics.KineticEnergy / world.Bodies.Sum(b => (double)b.Mass));
}
