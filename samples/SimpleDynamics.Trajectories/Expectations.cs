using System;
using System.Collections.Generic;
using System.Globalization;

namespace SimpleDynamics.Trajectories;

/// <summary>
/// What classical mechanics predicts for a scene, in words and as a check of the finished run. A scene states it
/// (an <c>expect:</c> line) only for the responders it holds for; a run that breaks it gets a <c>warning:</c>.
/// </summary>
/// <param name="Text">The prediction, one line.</param>
/// <param name="Broken">Null when the run met the prediction, else what the run did instead.</param>
public sealed record Expectation(string Text, Func<Scene, RunSummary, string?> Broken);

/// <summary>The checks made after every run.</summary>
public static class Expectations
{
    /// <summary>
    /// The warnings for a finished run: its expectation broken, mechanical energy risen above the start (no
    /// responder should add energy; gravity and contacts only trade it), or a state that stopped being finite.
    /// </summary>
    public static IReadOnlyList<string> Check(Scene scene, RunSummary summary)
    {
        var warnings = new List<string>();
        if (summary.FirstNonFiniteStep is int bad)
        {
            warnings.Add(Format.Invariant($"a body's state became NaN or infinite at step {bad}"));
            return warnings;
        }

        if (scene.Expectation is { } expectation && expectation.Broken(scene, summary) is string broken)
        {
            warnings.Add($"expected {expectation.Text}; but {broken}");
        }

        double rise = summary.MaxMechanicalEnergy - summary.StartMechanicalEnergy;
        if (rise > EnergyTolerance(summary))
        {
            warnings.Add(Format.Invariant(
                $"mechanical energy rose from {Format.Number(summary.StartMechanicalEnergy)} J to {Format.Number(summary.MaxMechanicalEnergy)} J (responder = {SceneFactory.NameOf(scene.Responder)}); collisions should never add energy"));
        }

        return warnings;
    }

    /// <summary>1 % of the energy in play at the start, and at least 1 mJ: what float steps may drift.</summary>
    public static double EnergyTolerance(RunSummary summary) =>
        Math.Max(1e-3, 0.01 * (Math.Abs(summary.StartMechanicalEnergy) + summary.StartKineticEnergy));
}

/// <summary>Invariant number text shared by the writers and messages.</summary>
public static class Format
{
    /// <summary>Seven significant digits (what a float holds), invariant, "0" instead of "-0": the one number format of CSV and messages.</summary>
    public static string Number(double value)
    {
        if (value == 0)
        {
            return "0";
        }

        return value.ToString("G7", CultureInfo.InvariantCulture);
    }

    /// <summary>An interpolated string formatted with the invariant culture.</summary>
    public static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
