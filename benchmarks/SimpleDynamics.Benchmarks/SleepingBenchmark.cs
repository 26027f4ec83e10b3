using System;
using System.Collections.Generic;
using BenchmarkDotNet.Attributes;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// Sleeping: one <see cref="World.Step"/> of dt = 1/60 s on the settled 2-D ball pit of <see cref="BallPit2D"/>,
/// awake (<c>Asleep = false</c>: sleeping off, every ball stepped) and asleep (<c>Asleep = true</c>: the same pit
/// after it has fallen asleep at the default <see cref="World.SleepSpeed"/> and <see cref="World.TimeToSleep"/>). Both
/// start from the same pour (<see cref="Warm.Pour"/>, sleeping off, which is deterministic); the asleep case then
/// turns sleeping on and steps until every ball sleeps.
/// </summary>
[MemoryDiagnoser]
public class Sleeping
{
    private string _key = "";
    private string _startContacts = "", _startPenetration = "";

    public World World { get; private set; } = new();

    [ParamsSource(nameof(Counts))]
    public int N { get; set; }

    public static IEnumerable<int> Counts => Sizes.Scenes;

    [Params(false, true)]
    public bool Asleep { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        World = Scenes.BallPit(N, planar: true);
        World.SleepingEnabled = false;
        int steps = Warm.Pour(World);
        if (Asleep)
        {
            World.SleepingEnabled = true;
            for (int i = 0; i < Warm.MaxSteps && World.SleepingBodyCount < N; i++, steps++)
            {
                World.Step(Warm.Dt);
            }

            if (World.SleepingBodyCount < N)
            {
                throw new InvalidOperationException($"Only {World.SleepingBodyCount} of {N} balls fell asleep in {Warm.MaxSteps} steps.");
            }
        }

        _key = SceneRecord.Key(nameof(Sleeping), new[] { new KeyValuePair<string, object>("N", N), new KeyValuePair<string, object>("Asleep", Asleep) });
        _startContacts = Contacts();
        _startPenetration = SceneRecord.Metres(World.Diagnostics.MaxPenetration);
        Console.WriteLine($"// scene {_key}: warmed for {steps} steps, {World.SleepingBodyCount} asleep");
        SceneRecord.Write(_key, _startContacts, _startPenetration);
    }

    [Benchmark]
    public void Step() => World.Step(Warm.Dt);

    /// <summary>Records the state after the timed steps: a pit that stays asleep keeps every ball asleep.</summary>
    [GlobalCleanup]
    public void Cleanup() => SceneRecord.Write(
        _key,
        _startContacts + " → " + Contacts(),
        _startPenetration + " → " + SceneRecord.Metres(World.Diagnostics.MaxPenetration));

    /// <summary>The contacts stepped (a sleeping pit has none) and the balls asleep.</summary>
    private string Contacts() => $"{SceneRecord.Count(World.Diagnostics.ContactCount)} ({SceneRecord.Count(World.SleepingBodyCount)} asleep)";
}
