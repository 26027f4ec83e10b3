using System;
using System.Linq;
using System.Collections.Generic;
using BenchmarkDotNet.Attributes;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// Smash (<see cref="Scenes.Smash"/>): a dense grid of N discs at rest, no gravity, hit by one heavy disc at
/// 20 m/s. The interesting part is the impact, so every iteration replays the same window: the world is put back
/// to the moment just before impact and stepped <see cref="Window"/> times (0.53 s). The time reported is per step,
/// averaged over the window.
/// </summary>
[InvocationCount(Window, 1)]
[MemoryDiagnoser]
public class Smash
{
    /// <summary>Steps per iteration: from just before the impact to well into the shock wave.</summary>
    public const int Window = 32;

    /// <summary>The striker starts 2.9 m from the grid at 20 m/s: 8 steps bring it to just short of contact.</summary>
    private const int Approach = 8;

    private readonly ReplayedWindow _window = new();
    private World _world = new();

    [ParamsSource(nameof(Counts))]
    public int N { get; set; }

    public static IEnumerable<int> Counts => Sizes.Scenes;

    [GlobalSetup]
    public void Setup()
    {
        _world = Scenes.Smash(N);
        for (int i = 0; i < Approach; i++)
        {
            _world.Step(Warm.Dt);
        }

        // Speculative contacts (the grid is closer than World.ContactMargin) exist before the impact; none may have pushed yet.
        if (_world.Collisions.Contacts.ToArray().Any(c => c.NormalImpulse > 0))
        {
            throw new InvalidOperationException("The smash snapshot must be taken before the impact.");
        }

        _window.TakeSnapshot(_world);

        // One reference run of the window: the peak contact count and penetration it reaches. Also makes every
        // array in the world grow to its size for this window, so the timed runs measure reuse, not growth.
        int peakContacts = 0;
        float peakPenetration = 0;
        for (int i = 0; i < Window; i++)
        {
            _world.Step(Warm.Dt);
            WorldDiagnostics d = _world.Diagnostics;
            peakContacts = Math.Max(peakContacts, d.ContactCount);
            peakPenetration = MathF.Max(peakPenetration, d.MaxPenetration);
        }

        // A second run from the snapshot: the jump back ends every contact of the window's last step at once, which
        // grows the buffer of ended contacts (World.ContactEvents) once; every timed iteration jumps back the same way.
        Rewind();
        for (int i = 0; i < Window; i++)
        {
            _world.Step(Warm.Dt);
        }

        string key = SceneRecord.Key(nameof(Smash), new[] { new KeyValuePair<string, object>("N", N) });
        SceneRecord.Write(key, "peak " + SceneRecord.Count(peakContacts), "peak " + SceneRecord.Metres(peakPenetration));
    }

    /// <summary>Puts every body back to just before the impact; the solver forgets its warm-start impulses (there were none then).</summary>
    [IterationSetup]
    public void Rewind() => _window.Rewind(_world);

    [Benchmark]
    public void Step() => _world.Step(Warm.Dt);
}
