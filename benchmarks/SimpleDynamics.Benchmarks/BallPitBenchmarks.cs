using System.Collections.Generic;
using BenchmarkDotNet.Attributes;
using SimpleDynamics.Response;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// Ball pit, 2-D (discs at z = 0): one <see cref="World.Step"/> of dt = 1/60 s on a pit of N balls that has been
/// poured and has settled (<see cref="Warm.Pour"/>). Single thread, the library's defaults (spatial hash,
/// sequential impulses). The world goes on stepping between invocations, as in a game.
/// </summary>
[MemoryDiagnoser]
public class BallPit2D
{
    private readonly BallPit _pit = new(planar: true);

    [ParamsSource(nameof(Counts))]
    public int N { get; set; }

    public static IEnumerable<int> Counts => Sizes.Scenes;

    /// <summary>
    /// The solver's further sweeps per substep while unconverged: 8 is the default; 0 does the same fixed work
    /// per contact whatever the pile, as a peer engine with a fixed iteration count would.
    /// </summary>
    [Params(8, 0)]
    public int Extra { get; set; }

    [GlobalSetup]
    public void Setup() => _pit.Setup(N, Extra, nameof(BallPit2D));

    [Benchmark]
    public void Step() => _pit.World.Step(Warm.Dt);

    [GlobalCleanup]
    public void Cleanup() => _pit.Cleanup();
}

/// <summary>The ball pit in 3-D with spheres, otherwise as <see cref="BallPit2D"/>.</summary>
[MemoryDiagnoser]
public class BallPit3D
{
    private readonly BallPit _pit = new(planar: false);

    [ParamsSource(nameof(Counts))]
    public int N { get; set; }

    public static IEnumerable<int> Counts => Sizes.Scenes;

    /// <summary>
    /// The solver's further sweeps per substep while unconverged: 8 is the default; 0 does the same fixed work
    /// per contact whatever the pile, as a peer engine with a fixed iteration count would.
    /// </summary>
    [Params(8, 0)]
    public int Extra { get; set; }

    [GlobalSetup]
    public void Setup() => _pit.Setup(N, Extra, nameof(BallPit3D));

    [Benchmark]
    public void Step() => _pit.World.Step(Warm.Dt);

    [GlobalCleanup]
    public void Cleanup() => _pit.Cleanup();
}

/// <summary>What the 2-D and 3-D pit benchmarks share: the scene, its warm-up and its record.</summary>
internal sealed class BallPit
{
    private readonly bool _planar;
    private string _key = "";
    private string _startContacts = "", _startPenetration = "";

    public BallPit(bool planar) => _planar = planar;

    public World World { get; private set; } = new();

    public void Setup(int n, int extraIterations, string type)
    {
        var solver = new SequentialImpulseSolver { ExtraIterations = extraIterations };
        World = Scenes.BallPit(n, _planar, responder: solver);
        World.SleepingEnabled = false; // these time the awake pit; the Sleeping benchmark times it asleep
        int steps = Warm.Pour(World);
        WorldDiagnostics d = World.Diagnostics;
        _key = SceneRecord.Key(type, new[] { new KeyValuePair<string, object>("N", n), new KeyValuePair<string, object>("Extra", extraIterations) });
        _startContacts = SceneRecord.Count(d.ContactCount);
        _startPenetration = SceneRecord.Metres(d.MaxPenetration);
        System.Console.WriteLine($"// scene {_key}: warmed for {steps} steps, rms speed {Warm.RmsSpeed(World):E2} m/s");
        SceneRecord.Write(_key, _startContacts, _startPenetration);
    }

    /// <summary>Records the state after warm-up and after the timed steps, so that drift shows in the table.</summary>
    public void Cleanup()
    {
        WorldDiagnostics d = World.Diagnostics;
        SceneRecord.Write(
            _key,
            _startContacts + " → " + SceneRecord.Count(d.ContactCount),
            _startPenetration + " → " + SceneRecord.Metres(d.MaxPenetration));
    }
}
