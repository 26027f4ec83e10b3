using System;
using SimpleDynamics.Response;
using SimpleDynamics.Tests.Robustness;
using Xunit;
using Xunit.Abstractions;
using DeepPile = SimpleDynamics.Tests.Solver.LayerCorrectionTests.DeepPile;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The layer correction (SequentialImpulseSolver.Layers.cs) on several threads: bit for bit what one thread does, and
/// no allocation once warm.
/// </summary>
/// <remarks>
/// It runs in the collection of the tests that weigh the heap, alone after the parallel tests: with other tests
/// allocating at the same time, this thread's count of allocated bytes once rose by 8,160 B in a window where, run
/// alone, it never did (ten runs out of ten passed).
/// </remarks>
[Collection(nameof(MemoryMeasurements))]
public class LayerCorrectionThreadTests
{
    private const float Dt = 1f / 60f;
    private readonly ITestOutputHelper _output;

    public LayerCorrectionThreadTests(ITestOutputHelper output) => _output = output;

    /// <summary>
    /// A deep pile of mixed masses, solved to a tight tolerance so that its substeps need corrections, cut into strips
    /// (64 contacts a strip, so that it is cut) on one and on two threads: the corrections run between the threads'
    /// sweeps, and every body, every step, every bit is alike; once warm, stepping either allocates nothing on any
    /// thread.
    /// </summary>
    [Fact]
    public void A_deep_pile_in_strips_is_corrected_bit_for_bit_alike_on_two_threads_and_allocates_nothing_once_warm()
    {
        var pile = new DeepPile(Planar: true, Wide: 8, Deep: 48, RadiusSpread: 1f, MassSpread: 3f,
            Friction: 0.3f, Restitution: 0.2f, Substeps: 1, ExtraIterations: 2, Tolerance: 1e-5f, Seed: 5);
        World[] worlds = { InStrips(pile, threads: 1), InStrips(pile, threads: 2) };
        var solver = (SequentialImpulseSolver)worlds[0].Responder;
        int corrections = 0, measuredCorrections = 0, cutSteps = 0;
        long allocated = 0, workersBefore = 0;
        try
        {
            for (int step = 1; step <= 420; step++)
            {
                bool measured = step > 30 && step <= 90; // warm: every array has grown in the first 30 steps
                if (step == 31)
                {
                    workersBefore = worlds[1].Workers!.WorkerAllocatedBytes;
                }

                long before = GC.GetAllocatedBytesForCurrentThread();
                foreach (World world in worlds)
                {
                    world.Step(Dt);
                }

                allocated += measured ? GC.GetAllocatedBytesForCurrentThread() - before : 0;
                corrections += solver.LayerCorrectionsThisStep;
                measuredCorrections += measured ? solver.LayerCorrectionsThisStep : 0;
                cutSteps += solver.Cut.Count > 1 ? 1 : 0;
                Assert.True(WorldMeasure.FirstDifference(worlds[0], worlds[1]) is null, $"step {step}: {WorldMeasure.FirstDifference(worlds[0], worlds[1])}");
                if (step == 90)
                {
                    long workers = worlds[1].Workers!.WorkerAllocatedBytes - workersBefore;
                    Assert.True(allocated == 0 && workers == 0, $"{allocated} B allocated in steps 31–90 on the stepping thread, {workers} B on the worker");
                }
            }

            _output.WriteLine($"{corrections} corrections in 420 steps ({measuredCorrections} in steps 31–90, whose allocations were measured), {cutSteps} steps cut");
            Assert.True(cutSteps > 400, $"only {cutSteps} steps were cut into strips");
            Assert.True(corrections > 100, $"only {corrections} layer corrections: the pile did not need them");
            Assert.True(measuredCorrections > 0, "no layer correction in the steps whose allocations were measured");
        }
        finally
        {
            foreach (World world in worlds)
            {
                world.ThreadCount = 1;
            }
        }
    }

    private static World InStrips(DeepPile pile, int threads)
    {
        var solver = new SequentialImpulseSolver(pile.Restitution, pile.Friction) { Strips = 8 };
        solver.Cut.ContactsPerStrip = 64;
        World world = pile.Build(solver);
        world.ThreadCount = threads;
        return world;
    }
}
