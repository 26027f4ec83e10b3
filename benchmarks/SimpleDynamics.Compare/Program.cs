using System;
using System.Diagnostics;
using System.Globalization;
using System.Linq;

namespace SimpleDynamics.Compare;

/// <summary>
/// Steps the same ball pit with two builds of the library in one process, in turn, and prints how long build B takes
/// over build A (the median of the rounds' ratios), and whether both left every body in the same state, bit for bit.
/// Timings on a shared or two-core machine drift by several per cent over a minute; stepping the two in turn, round
/// after round, exposes both to the same drift, which separate runs would not. Which build is made first still moves
/// the ratio by a few per cent, so run it both ways round (A B, then B A) and read the two together.
/// </summary>
internal static class Program
{
    private const string Usage = """
        Usage: dotnet run -c Release --project benchmarks/SimpleDynamics.Compare -- <folder A> <folder B> [options]

        Each folder holds a Release build of the library, e.g.
          git worktree add ../old <commit> && dotnet build ../old/src/SimpleDynamics -c Release -f net8.0 -o /tmp/libA
          dotnet build src/SimpleDynamics -c Release -f net8.0 -o /tmp/libB

        Options (defaults in brackets):
          --bodies N    balls in Scenes.BallPit [1000]
          --3d          spheres instead of discs in the plane
          --seed S      the scene's seed [1]
          --pour N      steps before timing, to let the pile settle [600]
          --rounds N    rounds, each timing both builds [16]
          --steps N     steps per build per round [60]
        """;

    private const float Dt = 1f / 60f;

    private static int Main(string[] args)
    {
        try
        {
            return Run(args);
        }
        catch (ArgumentException error)
        {
            Console.Error.WriteLine(error.Message);
            Console.Error.WriteLine(Usage);
            return 2;
        }
    }

    private static int Run(string[] args)
    {
        string[] folders = args.Where(a => !a.StartsWith("--", StringComparison.Ordinal) && !IsOptionValue(args, a)).ToArray();
        if (folders.Length != 2)
        {
            throw new ArgumentException("Give two folders, A and B.");
        }

        int bodies = Option(args, "--bodies", 1000, 1), seed = Option(args, "--seed", 1, 0), pour = Option(args, "--pour", 600, 0);
        int rounds = Option(args, "--rounds", 16, 1), steps = Option(args, "--steps", 60, 1);
        bool planar = !args.Contains("--3d");
        var a = new LoadedBuild(folders[0], bodies, planar, seed);
        var b = new LoadedBuild(folders[1], bodies, planar, seed);
        a.Step(pour, Dt);
        b.Step(pour, Dt);
        bool samePour = a.State().SequenceEqual(b.State());
        a.Sweeps = b.Sweeps = 0;

        var ratios = new double[rounds];
        double totalA = 0, totalB = 0;
        for (int round = 0; round < rounds; round++)
        {
            long start = Stopwatch.GetTimestamp();
            a.Step(steps, Dt);
            double timeA = Stopwatch.GetElapsedTime(start).TotalMilliseconds;
            start = Stopwatch.GetTimestamp();
            b.Step(steps, Dt);
            double timeB = Stopwatch.GetElapsedTime(start).TotalMilliseconds;
            ratios[round] = timeB / timeA;
            totalA += timeA;
            totalB += timeB;
        }

        Array.Sort(ratios);
        bool same = a.State().SequenceEqual(b.State());
        int stepsTimed = rounds * steps;
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{bodies} {(planar ? "discs (2-D)" : "balls (3-D)")}, seed {seed}, {pour} steps poured, {rounds} rounds of {steps} steps"));
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"A {totalA / stepsTimed:F3} ms a step, {a.Sweeps / (double)stepsTimed:F1} sweeps a step"));
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"B {totalB / stepsTimed:F3} ms a step, {b.Sweeps / (double)stepsTimed:F1} sweeps a step"));
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"B / A: median {ratios[rounds / 2]:F3}, rounds {ratios[0]:F3}–{ratios[^1]:F3}"));
        Console.WriteLine(same && samePour
            ? "every body's state the same in A and B, bit for bit, after the pour and at the end"
            : $"the builds' states differ ({(samePour ? "at the end" : "already after the pour")}): they are not the same physics, and the times compare different piles");
        return 0;
    }

    private static bool IsOptionValue(string[] args, string value)
    {
        int at = Array.IndexOf(args, value);
        return at > 0 && args[at - 1].StartsWith("--", StringComparison.Ordinal) && args[at - 1] != "--3d";
    }

    private static int Option(string[] args, string name, int fallback, int least)
    {
        int at = Array.IndexOf(args, name);
        if (at < 0)
        {
            return fallback;
        }

        if (at + 1 >= args.Length || !int.TryParse(args[at + 1], NumberStyles.Integer, CultureInfo.InvariantCulture, out int value) || value < least)
        {
            throw new ArgumentException($"{name} needs a whole number of at least {least}.");
        }

        return value;
    }
}
