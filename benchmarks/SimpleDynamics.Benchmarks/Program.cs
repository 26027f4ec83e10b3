using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Jobs;
using BenchmarkDotNet.Reports;
using BenchmarkDotNet.Running;
using BenchmarkDotNet.Toolchains.InProcess.Emit;
using Perfolizer.Horology;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// <c>dotnet run -c Release --project benchmarks/SimpleDynamics.Benchmarks [-- --quick] [BenchmarkDotNet options]</c>.
/// Without <c>--filter</c> every benchmark runs. <c>--quick</c>: N = 1,000 only, few short iterations, in process
/// (no per-benchmark build): under two minutes, numbers good to tens of percent.
/// </summary>
public static class Program
{
    public static int Main(string[] args)
    {
        bool quick = args.Contains("--quick");
        List<string> rest = args.Where(a => a != "--quick").ToList();
        if (!rest.Any(a => a == "--filter" || a.StartsWith("--filter=", StringComparison.Ordinal) || a == "-f"
                           || a == "--list" || a == "--help" || a == "-h" || a == "--version"))
        {
            rest.AddRange(new[] { "--filter", "*" });
        }

        Sizes.Quick = quick;
        string artifacts = Path.Combine(Directory.GetCurrentDirectory(), "BenchmarkDotNet.Artifacts");
        string records = Path.Combine(artifacts, "scenes");
        if (Directory.Exists(records))
        {
            Directory.Delete(records, recursive: true);
        }

        // Inherited by the benchmark processes BenchmarkDotNet starts.
        Environment.SetEnvironmentVariable(SceneRecord.FolderVariable, records);

        IEnumerable<Summary> summaries = BenchmarkSwitcher
            .FromAssembly(typeof(Program).Assembly)
            .Run(rest.ToArray(), CreateConfig(quick, artifacts));
        ReportGrowth(summaries.ToList(), artifacts);
        return 0;
    }

    private static IConfig CreateConfig(bool quick, string artifacts)
    {
        Job job = quick
            ? Job.Default
                .WithId("Quick")
                .WithToolchain(InProcessEmitToolchain.Instance)
                .WithLaunchCount(1)
                .WithWarmupCount(2)
                .WithIterationCount(5)
                .WithIterationTime(TimeInterval.FromMilliseconds(100))
            : Job.Default
                .WithId("Full")
                .WithMinIterationCount(10)
                .WithMaxIterationCount(30); // the pits keep settling while timed; more iterations add drift, not precision

        return DefaultConfig.Instance
            .WithArtifactsPath(artifacts)
            .AddJob(job)
            .AddColumn(SceneColumn.Contacts, SceneColumn.MaxPenetration, GrowthColumn.Instance);
    }

    /// <summary>Prints t(largest N)/t(1,000) per benchmark, and writes it next to BenchmarkDotNet's reports.</summary>
    private static void ReportGrowth(IReadOnlyList<Summary> summaries, string artifacts)
    {
        var lines = new List<string> { "| Benchmark | N | Mean | t/t(1k) |", "|---|---:|---:|---:|" };
        foreach (Summary summary in summaries)
        {
            foreach (BenchmarkReport report in summary.Reports)
            {
                double? ratio = GrowthColumn.Ratio(summary, report.BenchmarkCase);
                if (ratio is null || report.ResultStatistics is null)
                {
                    continue;
                }

                string name = report.BenchmarkCase.Descriptor.DisplayInfo
                    + string.Concat(report.BenchmarkCase.Parameters.Items.Where(p => p.Name != "N").Select(p => $" {p.Name}={p.Value}"));
                lines.Add(string.Format(
                    CultureInfo.InvariantCulture,
                    "| {0} | {1} | {2:N0} ns | {3:0.00} |",
                    name,
                    report.BenchmarkCase.Parameters["N"],
                    report.ResultStatistics.Mean,
                    ratio));
            }
        }

        if (lines.Count == 2)
        {
            return;
        }

        Console.WriteLine();
        Console.WriteLine("// Step time growth with N (issue 10 target for the pits: t(16000)/t(1000) <= 18):");
        lines.ForEach(Console.WriteLine);
        string results = Path.Combine(artifacts, "results");
        Directory.CreateDirectory(results);
        File.WriteAllLines(Path.Combine(results, "growth.md"), lines);
    }
}
