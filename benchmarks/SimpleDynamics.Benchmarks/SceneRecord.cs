using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// Carries each row's physics check (contacts, largest penetration) from the benchmark process, where the world
/// lives, to the host process, where the table is drawn: one small file per benchmark case in a folder whose
/// path the host passes down in an environment variable. A fast but wrong engine must not win unnoticed.
/// </summary>
internal static class SceneRecord
{
    public const string FolderVariable = "SIMPLEDYNAMICS_BENCH_RECORDS";

    /// <summary>The key of a case: its class name and its parameters sorted by name, e.g. <c>BallPit2D_N=1000</c>.</summary>
    public static string Key(string type, IEnumerable<KeyValuePair<string, object>> parameters) =>
        type + string.Concat(parameters
            .OrderBy(p => p.Key, StringComparer.Ordinal)
            .Select(p => "_" + p.Key + "=" + Convert.ToString(p.Value, CultureInfo.InvariantCulture)));

    public static void Write(string key, string contacts, string maxPenetration)
    {
        string? folder = Environment.GetEnvironmentVariable(FolderVariable);
        string line = $"{key}: contacts {contacts}, max penetration {maxPenetration} m";
        Console.WriteLine("// scene " + line); // also in the BenchmarkDotNet log
        if (string.IsNullOrEmpty(folder))
        {
            return;
        }

        Directory.CreateDirectory(folder);
        File.WriteAllLines(Path.Combine(folder, key + ".txt"), new[] { contacts, maxPenetration });
    }

    public static bool TryRead(string key, out string contacts, out string maxPenetration)
    {
        contacts = maxPenetration = "?";
        string? folder = Environment.GetEnvironmentVariable(FolderVariable);
        string path = string.IsNullOrEmpty(folder) ? "" : Path.Combine(folder, key + ".txt");
        if (path.Length == 0 || !File.Exists(path))
        {
            return false;
        }

        string[] lines = File.ReadAllLines(path);
        if (lines.Length < 2)
        {
            return false;
        }

        (contacts, maxPenetration) = (lines[0], lines[1]);
        return true;
    }

    public static string Metres(float value) => value.ToString("0.0000", CultureInfo.InvariantCulture);

    public static string Count(int value) => value.ToString(CultureInfo.InvariantCulture);
}
