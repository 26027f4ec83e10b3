using System;
using System.Collections.Generic;
using System.Globalization;

namespace SimpleDynamics.Trajectories;

/// <summary>The scenes the sample can run.</summary>
public enum SceneKind
{
    /// <summary>The tutorial's point: <see cref="Bounce"/> followed by <see cref="OffCentre"/>.</summary>
    Default,

    /// <summary>A ball dropped on the ground, bouncing (ε = 0.8 unless set).</summary>
    Bounce,

    /// <summary>Two discs meeting off-centre, so friction sets them spinning.</summary>
    OffCentre,

    /// <summary>A pile of balls settling in a closed box.</summary>
    Pile,

    /// <summary>A row of touching balls struck at one end.</summary>
    Row,

    /// <summary>A ball sliding on rough ground until it rolls.</summary>
    Slide,
}

/// <summary>The responders the sample can switch between.</summary>
public enum ResponderKind
{
    /// <summary><c>SequentialImpulseSolver</c>: all contacts at once, warm started.</summary>
    Solver,

    /// <summary><c>ImpulseCollisionResponder</c>: the tutorial's eq. 5–16, one pair at a time.</summary>
    Impulse,

    /// <summary><c>PerfectlyInelasticResponder</c>: the tutorial's eq. 2.</summary>
    Inelastic,

    /// <summary><c>ProjectionResponder</c>: the tutorial's listing 2.</summary>
    Projection,
}

/// <summary>How the trajectory is written.</summary>
public enum OutputFormat
{
    /// <summary>Aligned columns for a person to read.</summary>
    Table,

    /// <summary>Comma-separated values, one row per body per printed step.</summary>
    Csv,
}

/// <summary>
/// The command line, parsed by hand. Settings left unset (null) take the scene's own default.
/// </summary>
public sealed class Options
{
    /// <summary>The usage text printed by <c>--help</c>.</summary>
    public const string Usage =
        """
        Usage: SimpleDynamics.Trajectories [options]

        Runs a scene of the SimpleDynamics library and prints its trajectory: time, and per body
        position (m), velocity (m/s) and angular velocity (rad/s), with the world's diagnostics
        (kinetic, potential and mechanical energy in J, linear momentum in kg m/s, contact count,
        largest penetration in m). Many-body scenes print a summary of all bodies instead.

        Options:
          --scene NAME        default | bounce | offcentre | pile | row | slide   (default: default)
                                default    bounce, then offcentre
                                bounce     a ball dropped on the ground, eps = 0.8
                                offcentre  two discs meeting off-centre; friction makes them spin
                                pile       a pile of balls settling in a closed box (summary only)
                                row        a row of touching balls struck at one end
                                slide      a ball sliding on rough ground that starts to roll
          --responder NAME    solver | impulse | inelastic | projection           (default: solver)
                                solver      SequentialImpulseSolver (all contacts together)
                                impulse     ImpulseCollisionResponder (tutorial eq. 5-16)
                                inelastic   PerfectlyInelasticResponder (tutorial eq. 2)
                                projection  ProjectionResponder (tutorial listing 2)
          --restitution EPS   coefficient of restitution, 0..1 (default: per scene)
          --friction MU       Coulomb friction coefficient, >= 0 (default: per scene)
          --steps N           number of steps, >= 1 (default: per scene)
          --dt SECONDS        time step, > 0 (default: 0.01)
          --every K           print every K-th step, >= 1 (default: about 50 rows per scene)
          --format FORMAT     table | csv (default: table)
          --output FILE       write to FILE instead of standard output
          --help              print this text and exit

        Options take their value as the next argument or after '=' (--steps=200). Numbers use '.'
        as the decimal separator. In CSV, each row is one body at one printed step; the pile scene
        writes one row per step for its centre of mass ("com": mean position, velocity of the centre
        of mass, mean angular velocity).

        Exit codes: 0 success, 1 the output file could not be written, 2 invalid options.
        """;

    private static readonly Dictionary<string, SceneKind> s_scenes = new(StringComparer.Ordinal)
    {
        ["default"] = SceneKind.Default,
        ["bounce"] = SceneKind.Bounce,
        ["offcentre"] = SceneKind.OffCentre,
        ["pile"] = SceneKind.Pile,
        ["row"] = SceneKind.Row,
        ["slide"] = SceneKind.Slide,
    };

    private static readonly Dictionary<string, ResponderKind> s_responders = new(StringComparer.Ordinal)
    {
        ["solver"] = ResponderKind.Solver,
        ["impulse"] = ResponderKind.Impulse,
        ["inelastic"] = ResponderKind.Inelastic,
        ["projection"] = ResponderKind.Projection,
    };

    private static readonly Dictionary<string, OutputFormat> s_formats = new(StringComparer.Ordinal)
    {
        ["table"] = OutputFormat.Table,
        ["csv"] = OutputFormat.Csv,
    };

    /// <summary>Which scene to run.</summary>
    public SceneKind Scene { get; private set; } = SceneKind.Default;

    /// <summary>Which responder answers the contacts.</summary>
    public ResponderKind Responder { get; private set; } = ResponderKind.Solver;

    /// <summary>ε ∈ [0, 1], or null for the scene's default.</summary>
    public float? Restitution { get; private set; }

    /// <summary>μ ≥ 0, or null for the scene's default.</summary>
    public float? Friction { get; private set; }

    /// <summary>Steps to run (≥ 1), or null for the scene's default.</summary>
    public int? Steps { get; private set; }

    /// <summary>Time step in seconds (&gt; 0), or null for the default.</summary>
    public float? Dt { get; private set; }

    /// <summary>Print every K-th step (≥ 1), or null for about 50 rows.</summary>
    public int? Every { get; private set; }

    /// <summary>Table or CSV.</summary>
    public OutputFormat Format { get; private set; } = OutputFormat.Table;

    /// <summary>The file to write to, or null for standard output.</summary>
    public string? OutputPath { get; private set; }

    /// <summary>True when <c>--help</c> (or <c>-h</c>) was given; the other options are then ignored.</summary>
    public bool Help { get; private set; }

    /// <summary>
    /// Parses the command line. On failure returns false and a one-line <paramref name="error"/> (without the
    /// "error:" prefix).
    /// </summary>
    public static bool TryParse(IReadOnlyList<string> args, out Options options, out string error)
    {
        options = new Options();
        error = string.Empty;
        foreach (string arg in args)
        {
            if (arg is "--help" or "-h")
            {
                options.Help = true;
                return true;
            }
        }

        for (int i = 0; i < args.Count; i++)
        {
            string arg = args[i];
            if (!arg.StartsWith("--", StringComparison.Ordinal))
            {
                error = $"unexpected argument '{arg}' (see --help)";
                return false;
            }

            string name = arg;
            string? value = null;
            int equals = arg.IndexOf('=', StringComparison.Ordinal);
            if (equals >= 0)
            {
                name = arg[..equals];
                value = arg[(equals + 1)..];
            }

            if (!IsKnown(name))
            {
                error = $"unknown option '{name}' (see --help)";
                return false;
            }

            if (value is null)
            {
                if (i + 1 >= args.Count || args[i + 1].StartsWith("--", StringComparison.Ordinal))
                {
                    error = $"option '{name}' needs a value";
                    return false;
                }

                value = args[++i];
            }

            if (!options.TryApply(name, value, out error))
            {
                return false;
            }
        }

        return true;
    }

    private static bool IsKnown(string name) => name is "--scene" or "--responder" or "--restitution" or "--friction"
        or "--steps" or "--dt" or "--every" or "--format" or "--output";

    private bool TryApply(string name, string value, out string error)
    {
        error = string.Empty;
        switch (name)
        {
            case "--scene":
                if (!TryLookUp(s_scenes, name, value, out SceneKind scene, out error))
                {
                    return false;
                }

                Scene = scene;
                return true;
            case "--responder":
                if (!TryLookUp(s_responders, name, value, out ResponderKind responder, out error))
                {
                    return false;
                }

                Responder = responder;
                return true;
            case "--format":
                if (!TryLookUp(s_formats, name, value, out OutputFormat format, out error))
                {
                    return false;
                }

                Format = format;
                return true;
            case "--output":
                if (string.IsNullOrWhiteSpace(value))
                {
                    error = "option '--output' needs a file name";
                    return false;
                }

                OutputPath = value;
                return true;
            case "--restitution":
                if (!TryFloat(name, value, out float restitution, out error))
                {
                    return false;
                }

                if (!(restitution >= 0f && restitution <= 1f))
                {
                    error = $"--restitution must be between 0 and 1, got {value}";
                    return false;
                }

                Restitution = restitution;
                return true;
            case "--friction":
                if (!TryFloat(name, value, out float friction, out error))
                {
                    return false;
                }

                if (!(friction >= 0f))
                {
                    error = $"--friction must be 0 or more, got {value}";
                    return false;
                }

                Friction = friction;
                return true;
            case "--dt":
                if (!TryFloat(name, value, out float dt, out error))
                {
                    return false;
                }

                if (!(dt > 0f))
                {
                    error = $"--dt must be greater than 0, got {value}";
                    return false;
                }

                Dt = dt;
                return true;
            case "--steps":
                if (!TryInt(name, value, out int steps, out error))
                {
                    return false;
                }

                if (steps < 1)
                {
                    error = $"--steps must be at least 1, got {value}";
                    return false;
                }

                Steps = steps;
                return true;
            default: // "--every", the last known option
                if (!TryInt(name, value, out int every, out error))
                {
                    return false;
                }

                if (every < 1)
                {
                    error = $"--every must be at least 1, got {value}";
                    return false;
                }

                Every = every;
                return true;
        }
    }

    private static bool TryLookUp<T>(Dictionary<string, T> table, string name, string value, out T result, out string error)
    {
        if (table.TryGetValue(value, out T? found))
        {
            result = found;
            error = string.Empty;
            return true;
        }

        result = default!;
        error = $"unknown value '{value}' for {name}; expected one of: {string.Join(", ", table.Keys)}";
        return false;
    }

    private static bool TryFloat(string name, string value, out float result, out string error)
    {
        // float.TryParse accepts "NaN" and "Infinity"; a finite number is required.
        if (float.TryParse(value, NumberStyles.Float, CultureInfo.InvariantCulture, out result) && float.IsFinite(result))
        {
            error = string.Empty;
            return true;
        }

        error = $"{name} needs a finite number, got '{value}'";
        return false;
    }

    private static bool TryInt(string name, string value, out int result, out string error)
    {
        if (int.TryParse(value, NumberStyles.Integer, CultureInfo.InvariantCulture, out result))
        {
            error = string.Empty;
            return true;
        }

        error = $"{name} needs a whole number, got '{value}'";
        return false;
    }
}
