using System;
using System.Collections.Generic;
using System.CommandLine;
using System.CommandLine.Help;
using System.CommandLine.Parsing;
using System.IO;
using System.Linq;

namespace SimpleDynamics.Trajectories;

/// <summary>
/// The console sample: parse the options, build the scene(s), step them, write the trajectory.
/// Run <c>dotnet run --project samples/SimpleDynamics.Trajectories -- --help</c> for the options.
/// </summary>
public static class Program
{
    /// <summary>Exit code of a successful run.</summary>
    public const int Success = 0;

    /// <summary>Exit code when the output file cannot be written.</summary>
    public const int OutputFailed = 1;

    /// <summary>Exit code for unknown or invalid options.</summary>
    public const int InvalidOptions = 2;

    /// <summary>Runs of at least this many body-steps (1,000,000 unless set) report their progress on standard error.</summary>
    public static long ProgressThreshold { get; set; } = 1_000_000;

    /// <summary>The process entry point.</summary>
    public static int Main(string[] args) => Run(args, Console.Out, Console.Error);

    /// <summary>Runs the sample with <paramref name="args"/>, writing to the given streams; returns the exit code.</summary>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var commandLine = new CommandLine(options => Execute(options, stdout, stderr));
        ParseResult parse = commandLine.Command.Parse(args);
        if (parse.Errors.Count > 0 && parse.Action is not HelpAction)
        {
            // Errors of an option's value first: they name the option and the reason; an unmatched token may only
            // be the consequence (in "--steps --dt 0.1", "0.1" is left over because "--dt" was taken as --steps' value).
            ParseError first = parse.Errors.FirstOrDefault(e => e.SymbolResult is OptionResult or ArgumentResult) ?? parse.Errors[0];
            stderr.WriteLine("error: " + OneLine(first.Message) + " (see --help)");
            return InvalidOptions;
        }

        return parse.Invoke(new InvocationConfiguration { Output = stdout, Error = stderr, EnableDefaultExceptionHandler = false });
    }

    private static int Execute(Options options, TextWriter stdout, TextWriter stderr)
    {
        IReadOnlyList<Scene> scenes = SceneFactory.Build(options);
        if (options.OutputPath is null)
        {
            Simulate(scenes, TrajectoryWriter.Create(options.Format, stdout), stderr);
            return Success;
        }

        StreamWriter file;
        try
        {
            file = new StreamWriter(options.OutputPath);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            return CannotWrite(stderr, options.OutputPath, e);
        }

        using (file)
        {
            try
            {
                Simulate(scenes, TrajectoryWriter.Create(options.Format, file), stderr);
            }
            catch (IOException e)
            {
                return CannotWrite(stderr, options.OutputPath, e);
            }
        }

        return Success;
    }

    /// <summary>
    /// Steps each scene, writing step 0, every K-th step and the last one; then checks the scene's expectation and
    /// the energy, and reports a broken one as a warning (in the output and on standard error). Public so that a
    /// project (or a test) can run scenes of its own through the sample's writers and checks.
    /// </summary>
    public static void Simulate(IReadOnlyList<Scene> scenes, TrajectoryWriter writer, TextWriter stderr)
    {
        foreach (Scene scene in scenes)
        {
            writer.BeginScene(scene);
            writer.WriteStep(scene, 0);
            var summary = new RunSummary(scene.World);
            var progress = new Progress(scene, stderr);
            for (int step = 1; step <= scene.Steps; step++)
            {
                scene.World.Step(scene.Dt);
                summary.Observe(scene.World, step);
                scene.Events.Observe(scene.World);
                if (step % scene.Every == 0 || step == scene.Steps)
                {
                    writer.WriteStep(scene, step);
                }

                progress.Report(step);
            }

            IReadOnlyList<string> warnings = Expectations.Check(scene, summary);
            foreach (string warning in warnings)
            {
                stderr.WriteLine($"warning: {scene.Name}: {warning}");
            }

            writer.EndScene(scene, summary, warnings);
        }

        writer.Complete();
    }

    private static int CannotWrite(TextWriter stderr, string path, Exception e)
    {
        stderr.WriteLine("error: cannot write '" + OneLine(path) + "': " + OneLine(e.Message));
        return OutputFailed;
    }

    private static string OneLine(string text) => string.Join(" ", text.Split(new[] { '\r', '\n', '\t' }, StringSplitOptions.RemoveEmptyEntries)).Trim();

    /// <summary>A "progress:" line on standard error at every tenth of a long run; nothing for short runs.</summary>
    private sealed class Progress
    {
        private readonly Scene _scene;
        private readonly TextWriter _stderr;
        private readonly bool _enabled;
        private int _nextTenth = 1;

        public Progress(Scene scene, TextWriter stderr)
        {
            _scene = scene;
            _stderr = stderr;
            _enabled = (long)scene.Steps * Math.Max(1, scene.World.Bodies.Count) >= ProgressThreshold;
        }

        public void Report(int step)
        {
            if (!_enabled || step * 10L < _nextTenth * (long)_scene.Steps)
            {
                return;
            }

            _stderr.WriteLine(Format.Invariant($"progress: {_scene.Name} {_nextTenth * 10}% (step {step} of {_scene.Steps})"));
            _nextTenth++;
        }
    }
}
