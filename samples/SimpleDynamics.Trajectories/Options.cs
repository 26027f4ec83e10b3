using System;
using System.Collections.Generic;
using System.CommandLine;
using System.CommandLine.Parsing;
using System.Globalization;
using System.Linq;
using System.Numerics;

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

    /// <summary>Balls poured onto the ground beside a drain sensor: contact events and sleeping bodies per row.</summary>
    Game,
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

    /// <summary>A standalone SVG picture: position over time, the path in the plane, energy over time.</summary>
    Svg,

    /// <summary>A self-contained HTML page that replays the run on a canvas.</summary>
    Html,
}

/// <summary>The settings of one run. Settings left unset (null) take the scene's own default.</summary>
public sealed class Options
{
    /// <summary>The largest --steps: ten million steps (a day of simulated time at 0.01 s is 8.6 million).</summary>
    public const int MaxSteps = 10_000_000;

    /// <summary>The largest --dt (s): a ball falls 5 cm in one such step; larger steps tunnel through contacts.</summary>
    public const double MaxDt = 0.1;

    /// <summary>The largest --friction: μ of rubber on dry concrete is about 1; 10 is far beyond any surface.</summary>
    public const double MaxFriction = 10;

    /// <summary>Which scene to run.</summary>
    public SceneKind Scene { get; set; } = SceneKind.Default;

    /// <summary>Which responder answers the contacts.</summary>
    public ResponderKind Responder { get; set; } = ResponderKind.Solver;

    /// <summary>ε ∈ [0, 1], or null for the scene's default.</summary>
    public float? Restitution { get; set; }

    /// <summary>μ ∈ [0, <see cref="MaxFriction"/>], or null for the scene's default.</summary>
    public float? Friction { get; set; }

    /// <summary>Steps to run, 1 to <see cref="MaxSteps"/>, or null for the scene's default.</summary>
    public int? Steps { get; set; }

    /// <summary>Time step in seconds, in (0, <see cref="MaxDt"/>], or null for the default.</summary>
    public float? Dt { get; set; }

    /// <summary>Print every K-th step (≥ 1), or null for about 50 rows (1,000 frames for pictures).</summary>
    public int? Every { get; set; }

    /// <summary>Table, CSV, SVG or HTML.</summary>
    public OutputFormat Format { get; set; } = OutputFormat.Table;

    /// <summary>The file to write to, or null for standard output.</summary>
    public string? OutputPath { get; set; }
}

/// <summary>
/// The command line on System.CommandLine: the options with their help text and validation. Every number is
/// parsed invariantly ('.' decimal separator) and checked against its range, and a bad value is reported with
/// the true reason (not a number, not a whole number, too small, too large).
/// </summary>
public sealed class CommandLine
{
    private static readonly (string Name, SceneKind Kind, string Help)[] s_scenes =
    {
        ("default", SceneKind.Default, "bounce, then offcentre"),
        ("bounce", SceneKind.Bounce, "a ball dropped on the ground, eps = 0.8"),
        ("offcentre", SceneKind.OffCentre, "two discs meeting off-centre; friction makes them spin"),
        ("pile", SceneKind.Pile, "100 discs settling in a closed box (table: a summary row per step)"),
        ("row", SceneKind.Row, "a row of touching balls struck at one end"),
        ("slide", SceneKind.Slide, "a ball sliding on rough ground that starts to roll"),
        ("game", SceneKind.Game, "balls poured beside a drain sensor: contact events and sleeping bodies per row"),
    };

    private static readonly (string Name, ResponderKind Kind, string Help)[] s_responders =
    {
        ("solver", ResponderKind.Solver, "SequentialImpulseSolver (all contacts together)"),
        ("impulse", ResponderKind.Impulse, "ImpulseCollisionResponder (tutorial eq. 5-16)"),
        ("inelastic", ResponderKind.Inelastic, "PerfectlyInelasticResponder (tutorial eq. 2)"),
        ("projection", ResponderKind.Projection, "ProjectionResponder (tutorial listing 2)"),
    };

    private static readonly (string Name, OutputFormat Kind, string Help)[] s_formats =
    {
        ("table", OutputFormat.Table, "aligned columns"),
        ("csv", OutputFormat.Csv, "one row per body per printed step"),
        ("svg", OutputFormat.Svg, "a picture: position over time, path in the plane, energy"),
        ("html", OutputFormat.Html, "a page that replays the run on a canvas"),
    };

    private readonly Option<SceneKind> _scene = Choice("--scene", "The scene to run", s_scenes);
    private readonly Option<ResponderKind> _responder = Choice("--responder", "The collision responder", s_responders);
    private readonly Option<float?> _restitution = Real("--restitution", "EPS", "Coefficient of restitution eps, 0 to 1 [default: per scene]", 0, 1, minExclusive: false);
    private readonly Option<float?> _friction = Real("--friction", "MU", $"Coulomb friction coefficient mu, 0 to {Options.MaxFriction} [default: per scene]", 0, Options.MaxFriction, minExclusive: false);
    private readonly Option<int?> _steps = Whole("--steps", "N", $"Number of steps, 1 to {Options.MaxSteps} [default: per scene]", 1, Options.MaxSteps);
    private readonly Option<float?> _dt = Real("--dt", "SECONDS", $"Time step, more than 0 and at most {Options.MaxDt} s [default: {SceneFactory.DefaultDt}]", 0, Options.MaxDt, minExclusive: true);
    private readonly Option<int?> _every = Whole("--every", "K", $"Print every K-th step and the last, 1 to {Options.MaxSteps} [default: about 50 rows; 1,000 frames for svg and html]", 1, Options.MaxSteps);
    private readonly Option<OutputFormat> _format = Choice("--format", "The output format", s_formats);
    private readonly Option<string?> _output = new("--output", "-o")
    {
        Description = "Write to FILE instead of standard output",
        HelpName = "FILE",
        Arity = ArgumentArity.ExactlyOne,
    };

    /// <summary>Builds the command; <paramref name="run"/> is what a valid command line does.</summary>
    public CommandLine(Func<Options, int> run)
    {
        _output.Validators.Add(result =>
        {
            if (result.Tokens.Count == 1 && string.IsNullOrWhiteSpace(result.Tokens[0].Value))
            {
                result.AddError("--output needs a file name");
            }
        });
        Command = new RootCommand(
            "Runs a scene of the SimpleDynamics library and writes its trajectory: time, and per body position (m), "
            + "velocity (m/s) and angular velocity (rad/s), with the world's diagnostics (kinetic, potential and mechanical "
            + "energy in J, linear momentum in kg m/s, touching contacts, largest penetration in m). Many-body scenes print "
            + "a summary of all bodies in the table. svg draws the run; html replays it in a browser. Numbers use '.' as the "
            + "decimal separator. Exit codes: 0 success, 1 the output file could not be written, 2 invalid options.")
        {
            _scene, _responder, _restitution, _friction, _steps, _dt, _every, _format, _output,
        };
        Command.SetAction(parse => run(Read(parse)));
    }

    /// <summary>The root command, with generated help (--help, -h, -?) and version (--version).</summary>
    public RootCommand Command { get; }

    private Options Read(ParseResult parse) => new()
    {
        Scene = parse.GetValue(_scene),
        Responder = parse.GetValue(_responder),
        Restitution = parse.GetValue(_restitution),
        Friction = parse.GetValue(_friction),
        Steps = parse.GetValue(_steps),
        Dt = parse.GetValue(_dt),
        Every = parse.GetValue(_every),
        Format = parse.GetValue(_format),
        OutputPath = parse.GetValue(_output),
    };

    /// <summary>An option naming one of <paramref name="choices"/>; the first is the default.</summary>
    private static Option<T> Choice<T>(string name, string description, (string Name, T Kind, string Help)[] choices)
    {
        string names = string.Join("|", choices.Select(c => c.Name));
        string help = description + ": " + string.Join("; ", choices.Select(c => c.Name + " = " + c.Help)) + $" [default: {choices[0].Name}]";
        T defaultValue = choices[0].Kind;
        var option = new Option<T>(name)
        {
            Description = help,
            HelpName = names,
            Arity = ArgumentArity.ExactlyOne, // left out, the option reads default(T): the first choice
        };
        option.CustomParser = result =>
        {
            string text = Single(result);
            if (IsOptionName(text))
            {
                result.AddError($"{name} needs a value, but the next argument is the option {text}");
                return defaultValue;
            }

            foreach (var choice in choices)
            {
                if (string.Equals(choice.Name, text, StringComparison.Ordinal))
                {
                    return choice.Kind;
                }
            }

            result.AddError($"unknown value '{text}' for {name}; expected one of: {string.Join(", ", choices.Select(c => c.Name))}");
            return defaultValue;
        };
        return option;
    }

    private static Option<float?> Real(string name, string helpName, string description, double min, double max, bool minExclusive)
    {
        var option = new Option<float?>(name) { Description = description, HelpName = helpName, Arity = ArgumentArity.ExactlyOne };
        string range = minExclusive
            ? Invariant($"more than {min} and at most {max}")
            : Invariant($"between {min} and {max}");
        option.CustomParser = result =>
        {
            string text = Single(result);
            if (IsOptionName(text))
            {
                result.AddError($"{name} needs a value, but the next argument is the option {text}");
                return null;
            }

            // double.TryParse accepts "NaN" and "Infinity", and "1e999" becomes infinity: a finite number is required.
            if (!double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) || !double.IsFinite(value))
            {
                result.AddError($"{name} needs a number such as 0.25 ('.' as decimal separator), got '{text}'");
                return null;
            }

            bool tooSmall = minExclusive ? !(value > min) : value < min;
            if (tooSmall || value > max)
            {
                result.AddError($"{name} must be {range}, got {text} ({(tooSmall ? "too small" : "too large")})");
                return null;
            }

            return (float)value;
        };
        return option;
    }

    private static Option<int?> Whole(string name, string helpName, string description, int min, int max)
    {
        var option = new Option<int?>(name) { Description = description, HelpName = helpName, Arity = ArgumentArity.ExactlyOne };
        option.CustomParser = result =>
        {
            string text = Single(result);
            if (IsOptionName(text))
            {
                result.AddError($"{name} needs a value, but the next argument is the option {text}");
                return null;
            }

            // BigInteger reads any whole number, so one too large for int is reported as too large, not as "not a number".
            if (!BigInteger.TryParse(text, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out BigInteger value))
            {
                result.AddError($"{name} needs a whole number, got '{text}'");
                return null;
            }

            if (value < min)
            {
                result.AddError(Invariant($"{name} must be at least {min}, got {text} (too small)"));
                return null;
            }

            if (value > max)
            {
                result.AddError(Invariant($"{name} must be at most {max}, got {text} (too large)"));
                return null;
            }

            return (int)value;
        };
        return option;
    }

    /// <summary>"--dt" or "-o": an option name where a value should be (System.CommandLine takes it as the value).</summary>
    private static bool IsOptionName(string text) => text.StartsWith("-", StringComparison.Ordinal) && text.Length > 1 && !char.IsDigit(text[1]) && text[1] != '.';

    private static string Single(ArgumentResult result) => result.Tokens.Count > 0 ? result.Tokens[0].Value : string.Empty;

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
