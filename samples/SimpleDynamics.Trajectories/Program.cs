using System;
using System.Collections.Generic;
using System.IO;

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

    /// <summary>The process entry point.</summary>
    public static int Main(string[] args) => Run(args, Console.Out, Console.Error);

    /// <summary>Runs the sample with <paramref name="args"/>, writing to the given streams; returns the exit code.</summary>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        if (!Options.TryParse(args, out Options options, out string error))
        {
            stderr.WriteLine("error: " + OneLine(error));
            return InvalidOptions;
        }

        if (options.Help)
        {
            stdout.Write(Options.Usage);
            stdout.WriteLine();
            return Success;
        }

        IReadOnlyList<Scene> scenes = SceneFactory.Build(options);
        if (options.OutputPath is null)
        {
            Simulate(scenes, TrajectoryWriter.Create(options.Format, stdout));
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
                Simulate(scenes, TrajectoryWriter.Create(options.Format, file));
            }
            catch (IOException e)
            {
                return CannotWrite(stderr, options.OutputPath, e);
            }
        }

        return Success;
    }

    /// <summary>Steps each scene, printing step 0, every K-th step and the last one.</summary>
    private static void Simulate(IReadOnlyList<Scene> scenes, TrajectoryWriter writer)
    {
        foreach (Scene scene in scenes)
        {
            writer.BeginScene(scene);
            writer.WriteStep(scene, 0);
            var summary = new RunSummary(scene.World);
            for (int step = 1; step <= scene.Steps; step++)
            {
                scene.World.Step(scene.Dt);
                summary.Observe(scene.World, step);
                if (step % scene.Every == 0 || step == scene.Steps)
                {
                    writer.WriteStep(scene, step);
                }
            }

            writer.EndScene(scene, summary);
        }
    }

    private static int CannotWrite(TextWriter stderr, string path, Exception e)
    {
        stderr.WriteLine("error: cannot write '" + OneLine(path) + "': " + OneLine(e.Message));
        return OutputFailed;
    }

    private static string OneLine(string text) => text.ReplaceLineEndings(" ");
}
