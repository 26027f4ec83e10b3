using System.Collections.Generic;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// The body counts each benchmark runs. Quick mode (<c>--quick</c>) shrinks them so that a newcomer's run ends
/// in under two minutes. BenchmarkDotNet reads these in the host process, which writes the chosen values into
/// the generated benchmark program, so a static switch set before the run is enough.
/// </summary>
internal static class Sizes
{
    public static bool Quick { get; set; }

    /// <summary>Ball pits and the smash: the N ∈ {1,000, 4,000, 16,000}.</summary>
    public static IEnumerable<int> Scenes => Quick ? new[] { 1000 } : new[] { 1000, 4000, 16000 };

    /// <summary>Pours (one per iteration, seconds each): 4,000 discs, the smallest pit cut into strips for threads.</summary>
    public static IEnumerable<int> Pours => Quick ? new[] { 1000 } : new[] { 4000 };

    /// <summary>Broadphase against brute force: O(n²) brute force at 16,000 would take seconds per call.</summary>
    public static IEnumerable<int> Broadphase => Quick ? new[] { 1000 } : new[] { 1000, 4000 };
}
