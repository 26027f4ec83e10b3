using System.Collections.Generic;
using BenchmarkDotNet.Attributes;
using SimpleDynamics.Response;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// The first <see cref="Seconds"/> s of a 2-D ball pit's pour (<see cref="Scenes.BallPit"/>), spawn to landed pile, on
/// one and on two threads (<see cref="World.ThreadCount"/>), its pile cut into two strips
/// (<see cref="SequentialImpulseSolver.Strips"/> = 2) on both. Each iteration pours a fresh pit, so both thread counts
/// do the same work: the bodies move bit for bit alike on any number of threads. This is where threads pay: a
/// landing pile needs tens to hundreds of sweeps a step, which run in strips on every thread, while a settled pile
/// needs one a substep, which stays on one (see SequentialImpulseSolver.Strips.cs).
/// </summary>
[WarmupCount(0)]
[IterationCount(3)]
[InvocationCount(1, 1)]
public class Pour2D
{
    /// <summary>Simulated seconds per iteration: the 4,000-disc pit lands and mostly settles in them.</summary>
    public const int Seconds = 8;

    private World _world = new();

    [ParamsSource(nameof(Counts))]
    public int N { get; set; }

    [Params(1, 2)]
    public int Threads { get; set; }

    public static IEnumerable<int> Counts => Sizes.Pours;

    [IterationSetup]
    public void Spawn()
    {
        _world.ThreadCount = 1;
        _world = Scenes.BallPit(N, planar: true, responder: new SequentialImpulseSolver { Strips = 2 });
        _world.SleepingEnabled = false;
        _world.ThreadCount = Threads;
    }

    [Benchmark]
    public void Pour()
    {
        for (int step = 0; step < Seconds * 60; step++)
        {
            _world.Step(Warm.Dt);
        }
    }

    [GlobalCleanup]
    public void Cleanup() => _world.ThreadCount = 1;
}
