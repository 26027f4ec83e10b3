using System;
using System.Collections.Generic;
using System.Linq;
using BenchmarkDotNet.Attributes;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// Broadphase choice (issue 4): one <see cref="ICollisionDetector.FindContacts"/> call on a settled 2-D ball pit,
/// for brute force (the baseline, so the table shows ratios), the library's spatial hash and a sort-and-sweep,
/// on equal radii (spread 1) and on radii mixed uniformly over a factor of ten (spread 10). The spatial hash is timed
/// twice: building its grid (its kept pairs forgotten before each call), and testing the pairs kept by the call
/// before, as a resting pile's steps do (SpatialHashDetector.KeptPairs.cs).
/// </summary>
[MemoryDiagnoser]
public class Broadphase
{
    private RigidBody[] _bodies = Array.Empty<RigidBody>();
    private readonly CollisionData _collisions = new();
    private readonly BruteForceDetector _bruteForce = new();
    private readonly SpatialHashDetector _spatialHash = new();
    private readonly SpatialHashDetector _keptPairs = new();
    private readonly SortAndSweepDetector _sortAndSweep = new();

    [ParamsSource(nameof(Counts))]
    public int N { get; set; }

    /// <summary>Radii uniform in [r, r × spread].</summary>
    [Params(1, 10)]
    public int RadiusSpread { get; set; }

    public static IEnumerable<int> Counts => Sizes.Broadphase;

    [GlobalSetup]
    public void Setup()
    {
        World world = Scenes.BallPit(N, planar: true, radiusSpread: RadiusSpread);
        world.SleepingEnabled = false; // the same settled pit as before sleeping existed
        Warm.Pour(world);
        _bodies = world.Bodies.ToArray();

        // The three must agree on the pairs before their times mean anything; the kept pairs are those of a first call.
        SpatialHashKeptPairs();
        var counts = new Dictionary<string, int>
        {
            [nameof(BruteForce)] = BruteForce(),
            [nameof(SpatialHash)] = SpatialHash(),
            [nameof(SpatialHashKeptPairs)] = SpatialHashKeptPairs(),
            [nameof(SortAndSweep)] = SortAndSweep(),
        };
        if (!_keptPairs.LastCallKeptPairs)
        {
            throw new InvalidOperationException("The spatial hash built its grid again on an unchanged pit: its kept pairs would not be timed.");
        }

        if (counts.Values.Distinct().Count() != 1)
        {
            throw new InvalidOperationException("Detectors disagree: " + string.Join(", ", counts.Select(c => $"{c.Key} {c.Value}")));
        }

        string key = SceneRecord.Key(nameof(Broadphase), new[]
        {
            new KeyValuePair<string, object>("N", N),
            new KeyValuePair<string, object>(nameof(RadiusSpread), RadiusSpread),
        });
        SceneRecord.Write(key, SceneRecord.Count(counts[nameof(BruteForce)]) + " pairs, all agree", SceneRecord.Metres(world.Diagnostics.MaxPenetration));
    }

    [Benchmark(Baseline = true)]
    public int BruteForce() => Detect(_bruteForce);

    [Benchmark]
    public int SpatialHash()
    {
        _spatialHash.ForgetKeptPairs();
        return Detect(_spatialHash);
    }

    [Benchmark]
    public int SpatialHashKeptPairs() => Detect(_keptPairs);

    [Benchmark]
    public int SortAndSweep() => Detect(_sortAndSweep);

    private int Detect(ICollisionDetector detector)
    {
        _collisions.Clear();
        detector.FindContacts(_bodies, _collisions);
        return _collisions.Count;
    }
}
