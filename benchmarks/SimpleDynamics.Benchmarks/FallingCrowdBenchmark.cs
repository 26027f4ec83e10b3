using System;
using System.Collections.Generic;
using System.Linq;
using BenchmarkDotNet.Attributes;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// A falling crowd: the lattice of <c>Scenes.BallPit(N, planar: true)</c> 40 steps after it was let go, falling
/// together at about 6.5 m/s, well above the floor. Every iteration replays the same window of
/// <see cref="Window"/> steps, with the pairs of the crowd left out (<c>LeaveOut</c> = true, the default) or every pair
/// detection reports kept (false), to show what leaving them out saves (ImpactStepper.Crowd.cs). The time reported is
/// per step, averaged over the window.
/// </summary>
[InvocationCount(Window, 1)]
[MemoryDiagnoser]
public class FallingCrowd
{
    /// <summary>Steps per iteration: the lattice falls from 6.5 to 9.2 m/s, and at 1,000 discs its lowest row stays above the floor.</summary>
    public const int Window = 16;

    /// <summary>Steps before the window: 0.67 s of free fall.</summary>
    private const int Fall = 40;

    private readonly ReplayedWindow _window = new();
    private World _world = new();

    [ParamsSource(nameof(Counts))]
    public int N { get; set; }

    /// <summary>Whether the crowd's pairs are left out (the library's behaviour) or all kept (as before it did so).</summary>
    [Params(false, true)]
    public bool LeaveOut { get; set; }

    public static IEnumerable<int> Counts => Sizes.Scenes;

    [GlobalSetup]
    public void Setup()
    {
        _world = Scenes.BallPit(N, planar: true);
        _world.LeaveOutCrowdPairs = LeaveOut;
        for (int i = 0; i < Fall; i++)
        {
            _world.Step(Warm.Dt);
        }

        _window.TakeSnapshot(_world);

        // One reference run of the window: the contacts at its end, for the table, and the arrays grown to it.
        for (int i = 0; i < Window; i++)
        {
            _world.Step(Warm.Dt);
        }

        if (_world.Collisions.Contacts.ToArray().Any(c => c.IsPlaneContact && c.Penetration > 0))
        {
            throw new InvalidOperationException("The falling crowd must not reach the floor within its window.");
        }

        string key = SceneRecord.Key(nameof(FallingCrowd), new[] { new KeyValuePair<string, object>("N", N), new KeyValuePair<string, object>("LeaveOut", LeaveOut) });
        SceneRecord.Write(key, SceneRecord.Count(_world.Collisions.Count), SceneRecord.Metres(_world.Diagnostics.MaxPenetration));
        Rewind();
    }

    /// <summary>Puts every body back to the start of the window; the solver forgets its warm-start impulses.</summary>
    [IterationSetup]
    public void Rewind() => _window.Rewind(_world);

    [Benchmark]
    public void Step() => _world.Step(Warm.Dt);
}
