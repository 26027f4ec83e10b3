using System;
using System.Globalization;
using System.Runtime.CompilerServices;
using FsCheck;
using FsCheck.Fluent;
using Microsoft.FSharp.Core;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// Runs an FsCheck property inside an xunit [Fact] (FsCheck.Xunit is not available here) with an explicit,
/// reproducible random seed. Every test passes its own fixed seed, so a run is deterministic; setting the
/// environment variable FSCHECK_REPLAY="seed,gamma" (the pair printed on failure) replays that run instead.
/// On failure the exception message names the property, the replay pair and how to replay it, followed by
/// FsCheck's report (the failing case and the law's message). Setting FSCHECK_MAXTEST=n runs every property over n
/// cases instead of its own count, to search deeper than CI does.
/// </summary>
internal static class PropertyCheck
{
    public const string ReplayVariable = "FSCHECK_REPLAY";
    public const string MaxTestVariable = "FSCHECK_MAXTEST";

    /// <summary>An odd gamma for FsCheck's split-mix generator; any odd number works.</summary>
    private const ulong DefaultGamma = 0x9E3779B97F4A7C15UL;

    public static void Run<T>(Gen<T> generator, Action<T> law, ulong seed, int maxTest = 500, [CallerMemberName] string name = "")
    {
        Rnd rnd = ReplayFromEnvironment() ?? new Rnd(seed, DefaultGamma);
        if (int.TryParse(Environment.GetEnvironmentVariable(MaxTestVariable), NumberStyles.None, CultureInfo.InvariantCulture, out int deeper) && deeper > 0)
        {
            maxTest = deeper;
        }

        Config config = Config.QuickThrowOnFailure
            .WithMaxTest(maxTest)
            .WithQuietOnSuccess(true)
            .WithName(name)
            .WithReplay(FSharpOption<Replay>.Some(new Replay(rnd, FSharpOption<int>.None)));
        Property property = Prop.ForAll(generator.ToArbitrary(), law);
        try
        {
            Check.One(config, property);
        }
        catch (Exception failure)
        {
            string replay = string.Create(CultureInfo.InvariantCulture, $"{rnd.Seed},{rnd.Gamma}");
            throw new PropertyFailedException(
                $"Property '{name}' failed (maxTest {maxTest}). Replay seed: {replay}. " +
                $"To replay: {ReplayVariable}={replay} dotnet test --filter \"FullyQualifiedName~{name}\"{Environment.NewLine}{failure.Message}",
                failure);
        }
    }

    private static Rnd? ReplayFromEnvironment()
    {
        string? text = Environment.GetEnvironmentVariable(ReplayVariable);
        if (string.IsNullOrWhiteSpace(text))
        {
            return null;
        }

        string[] parts = text.Trim().Trim('(', ')').Split(',', StringSplitOptions.TrimEntries);
        ulong seed = ulong.Parse(parts[0], CultureInfo.InvariantCulture);
        ulong gamma = parts.Length > 1 ? ulong.Parse(parts[1], CultureInfo.InvariantCulture) : DefaultGamma;
        return new Rnd(seed, gamma);
    }
}

/// <summary>A property found a counter-example; the message carries the replay seed.</summary>
public sealed class PropertyFailedException : Exception
{
    public PropertyFailedException(string message, Exception inner)
        : base(message, inner)
    {
    }
}

/// <summary>Assertions for laws: they throw with the quantities involved, so FsCheck's report shows them.</summary>
internal static class Law
{
    public static void Holds(bool condition, string message)
    {
        if (!condition)
        {
            throw new LawViolatedException(message);
        }
    }

    /// <summary>|actual − expected| ≤ tolerance.</summary>
    public static void Near(double expected, double actual, double tolerance, string what)
    {
        if (!(Math.Abs(actual - expected) <= tolerance))
        {
            throw new LawViolatedException(
                string.Create(CultureInfo.InvariantCulture, $"{what}: expected {expected:R}, got {actual:R}, |diff| {Math.Abs(actual - expected):R} > tolerance {tolerance:R}"));
        }
    }

    public static void Near(D3 expected, D3 actual, double tolerance, string what)
    {
        double diff = (actual - expected).Length;
        if (!(diff <= tolerance))
        {
            throw new LawViolatedException(
                string.Create(CultureInfo.InvariantCulture, $"{what}: expected {expected}, got {actual}, |diff| {diff:R} > tolerance {tolerance:R}"));
        }
    }
}

public sealed class LawViolatedException : Exception
{
    public LawViolatedException(string message)
        : base(message)
    {
    }
}
