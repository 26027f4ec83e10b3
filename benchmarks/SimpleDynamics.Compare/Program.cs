using System;
using System.Diagnostics;
using System.Globalization;
using System.CommandLine;
using System.IO;
using System.Linq;
using System.Runtime.ExceptionServices;
using System.Threading;

namespace SimpleDynamics.Compare;

/// <summary>
/// Steps the same ball pit with two builds of the library in one process, in turn, and prints how long build B takes
/// over build A (the median of the rounds' ratios), and whether both left every body in the same state, bit for bit.
/// Timings on a shared or two-core machine drift by several per cent over a minute; stepping the two in turn, round
/// after round, exposes both to the same drift, which separate runs would not. Which build is made first still moves
/// the ratio by a few per cent, so run it both ways round (A B, then B A) and read the two together.
/// Given one folder twice and another thread count for B (<c>--threads-b 2 --strips 2</c>), it measures what a second
/// thread gains on the very same pile: the same build on one thread and on two must end in the same state, bit for bit.
/// With <c>--side-by-side</c> each build steps two copies of its world, A one after the other on this thread, B at the
/// same time on two threads: given one folder twice, that is what the machine gives two threads at most, the gain no
/// split of one world across them can beat.
/// </summary>
internal static class Program
{
    private const float Dt = 1f / 60f;

    private static readonly Argument<DirectoryInfo[]> s_folders = new("folders")
    {
        Description = "Two folders, A and B, each holding a Release build of the library, e.g. from\n" +
            "git worktree add ../old <commit> && dotnet build ../old/src/SimpleDynamics -c Release -f net8.0 -o /tmp/libA",
        Arity = new ArgumentArity(2, 2),
    };

    private static readonly Option<int> s_bodies = Whole("--bodies", "Balls in Scenes.BallPit", 1000, least: 1);
    private static readonly Option<bool> s_3d = new("--3d") { Description = "Spheres instead of discs in the plane" };
    private static readonly Option<int> s_seed = Whole("--seed", "The scene's seed", 1, least: 0);
    private static readonly Option<int> s_pour = Whole("--pour", "Steps before timing, to let the pile settle", 600, least: 0);
    private static readonly Option<int> s_rounds = Whole("--rounds", "Rounds, each timing both builds", 16, least: 1);
    private static readonly Option<int> s_steps = Whole("--steps", "Steps per build per round", 60, least: 1);
    private static readonly Option<int> s_threadsA = Whole("--threads-a", "World.ThreadCount of A's world", 1, least: 1, most: 64);
    private static readonly Option<int> s_threadsB = Whole("--threads-b", "World.ThreadCount of B's world", 1, least: 1, most: 64);
    private static readonly Option<int> s_strips = Whole("--strips", "SequentialImpulseSolver.Strips of both worlds (1, 2, 4 or 8): what threads share", 1, least: 1);
    private static readonly Option<int> s_extra = Whole("--extra", "SequentialImpulseSolver.ExtraIterations of both worlds (-1: the default)", -1, least: -1);
    private static readonly Option<bool> s_sideBySide = new("--side-by-side")
    {
        Description = "Two copies of each world: A's stepped one after the other, B's at the same time on two threads (one thread each)",
    };

    private static int Main(string[] args)
    {
        var command = new RootCommand("Steps the same ball pit with two builds of the library in turn and prints B's time over A's.")
        {
            s_folders, s_bodies, s_3d, s_seed, s_pour, s_rounds, s_steps, s_threadsA, s_threadsB, s_strips, s_extra, s_sideBySide,
        };
        command.Validators.Add(result =>
        {
            if (result.GetValue(s_sideBySide) && (result.GetValue(s_threadsA) > 1 || result.GetValue(s_threadsB) > 1))
            {
                result.AddError("--side-by-side steps each world on one thread: leave --threads-a and --threads-b at 1.");
            }
        });
        s_strips.Validators.Add(result =>
        {
            if (result.GetValueOrDefault<int>() is not (1 or 2 or 4 or 8))
            {
                result.AddError("--strips needs 1, 2, 4 or 8.");
            }
        });
        s_folders.Validators.Add(result =>
        {
            foreach (DirectoryInfo folder in result.GetValueOrDefault<DirectoryInfo[]>() ?? [])
            {
                if (!folder.Exists)
                {
                    result.AddError($"No folder {folder.FullName}.");
                }
            }
        });
        command.SetAction(parse => Run(
            parse.GetValue(s_folders)!, parse.GetValue(s_bodies), !parse.GetValue(s_3d), parse.GetValue(s_seed),
            parse.GetValue(s_pour), parse.GetValue(s_rounds), parse.GetValue(s_steps),
            (parse.GetValue(s_threadsA), parse.GetValue(s_threadsB)), parse.GetValue(s_strips), parse.GetValue(s_extra),
            parse.GetValue(s_sideBySide)));
        return command.Parse(args).Invoke();
    }

    private static Option<int> Whole(string name, string description, int fallback, int least, int most = int.MaxValue)
    {
        var option = new Option<int>(name) { Description = description, HelpName = "N", DefaultValueFactory = _ => fallback };
        option.Validators.Add(result =>
        {
            int value = result.GetValueOrDefault<int>();
            if (value < least || value > most)
            {
                result.AddError(most == int.MaxValue
                    ? $"{name} needs a whole number of at least {least}."
                    : $"{name} needs a whole number from {least} to {most}.");
            }
        });
        return option;
    }

    private static int Run(
        DirectoryInfo[] folders, int bodies, bool planar, int seed, int pour, int rounds, int steps, (int A, int B) threads, int strips,
        int extra, bool sideBySide)
    {
        var a = new LoadedBuild(folders[0].FullName, bodies, planar, seed, threads.A, strips, extra);
        var b = new LoadedBuild(folders[1].FullName, bodies, planar, seed, threads.B, strips, extra);
        LoadedBuild? twinA = sideBySide ? new LoadedBuild(folders[0].FullName, bodies, planar, seed, 1, strips, extra) : null;
        LoadedBuild? twinB = sideBySide ? new LoadedBuild(folders[1].FullName, bodies, planar, seed, 1, strips, extra) : null;
        AtOnce(a, twinA, pour); // the pours are not timed: two at a time where there are two
        AtOnce(b, twinB, pour);
        bool samePour = a.State().SequenceEqual(b.State()) && SameAs(twinA, a) && SameAs(twinB, b);
        a.Sweeps = b.Sweeps = 0;

        var ratios = new double[rounds];
        double totalA = 0, totalB = 0;
        for (int round = 0; round < rounds; round++)
        {
            long start = Stopwatch.GetTimestamp();
            a.Step(steps, Dt);
            twinA?.Step(steps, Dt); // after A's own: one after the other
            double timeA = Stopwatch.GetElapsedTime(start).TotalMilliseconds;
            start = Stopwatch.GetTimestamp();
            AtOnce(b, twinB, steps);
            double timeB = Stopwatch.GetElapsedTime(start).TotalMilliseconds;
            ratios[round] = timeB / timeA;
            totalA += timeA;
            totalB += timeB;
        }

        Array.Sort(ratios);
        bool same = a.State().SequenceEqual(b.State()) && SameAs(twinA, a) && SameAs(twinB, b);
        int stepsTimed = rounds * steps;
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{bodies} {(planar ? "discs (2-D)" : "balls (3-D)")}, seed {seed}, {pour} steps poured, {rounds} rounds of {steps} steps, {strips} strip(s) at most"));
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"A {totalA / stepsTimed:F3} ms a step, {a.Sweeps / (double)stepsTimed:F1} sweeps a step, {threads.A} thread(s)"));
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"B {totalB / stepsTimed:F3} ms a step, {b.Sweeps / (double)stepsTimed:F1} sweeps a step, {threads.B} thread(s)"));
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"B / A: median {ratios[rounds / 2]:F3}, rounds {ratios[0]:F3}–{ratios[^1]:F3}"));
        if (sideBySide)
        {
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"side by side: two copies of a world stepped at once {1 / ratios[rounds / 2]:F2}× as fast as one after the other (median; rounds {1 / ratios[^1]:F2}–{1 / ratios[0]:F2}×), the times per step above being of both copies"));
        }

        Console.WriteLine(same && samePour
            ? $"every body's state the same in {(sideBySide ? "A, B and their copies" : "A and B")}, bit for bit, after the pour and at the end"
            : $"the builds' states differ ({(samePour ? "at the end" : "already after the pour")}): they are not the same physics, and the times compare different piles");
        return 0;
    }

    /// <summary>Steps <paramref name="world"/> and, if there is one, <paramref name="twin"/> at the same time on a second thread.</summary>
    private static void AtOnce(LoadedBuild world, LoadedBuild? twin, int steps)
    {
        if (twin is null)
        {
            world.Step(steps, Dt);
            return;
        }

        Exception? failure = null;
        var other = new Thread(() =>
        {
            try
            {
                twin.Step(steps, Dt);
            }
            catch (Exception e)
            {
                failure = e;
            }
        });
        other.Start();
        world.Step(steps, Dt);
        other.Join();
        if (failure is not null)
        {
            ExceptionDispatchInfo.Capture(failure).Throw();
        }
    }

    private static bool SameAs(LoadedBuild? twin, LoadedBuild world) => twin is null || twin.State().SequenceEqual(world.State());
}
