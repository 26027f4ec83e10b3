using System;
using System.Globalization;
using System.Linq;
using BenchmarkDotNet.Columns;
using BenchmarkDotNet.Reports;
using BenchmarkDotNet.Running;

namespace SimpleDynamics.Benchmarks;

/// <summary>A column whose value comes from the <see cref="SceneRecord"/> the benchmark process wrote.</summary>
internal sealed class SceneColumn : IColumn
{
    private readonly bool _penetration;

    private SceneColumn(bool penetration) => _penetration = penetration;

    public static readonly IColumn Contacts = new SceneColumn(false);
    public static readonly IColumn MaxPenetration = new SceneColumn(true);

    public string Id => "Scene." + ColumnName;
    public string ColumnName => _penetration ? "MaxPen [m]" : "Contacts";
    public bool AlwaysShow => true;
    public ColumnCategory Category => ColumnCategory.Custom;
    public int PriorityInCategory => _penetration ? 1 : 0;
    public bool IsNumeric => false;
    public UnitType UnitType => UnitType.Dimensionless;

    public string Legend => _penetration
        ? "Largest penetration between bodies or into a wall (m; ball radius 0.1 m): after warm-up → after the timed steps (pits), peak over the window (smash)"
        : "Contacts (ball–ball and ball–wall): after warm-up → after the timed steps (pits), peak over the window (smash); pairs found (broadphase)";

    public string GetValue(Summary summary, BenchmarkCase benchmarkCase) => GetValue(summary, benchmarkCase, SummaryStyle.Default);

    public string GetValue(Summary summary, BenchmarkCase benchmarkCase, SummaryStyle style)
    {
        string key = SceneRecord.Key(
            benchmarkCase.Descriptor.Type.Name,
            benchmarkCase.Parameters.Items.Select(p => new System.Collections.Generic.KeyValuePair<string, object>(p.Name, p.Value)));
        return SceneRecord.TryRead(key, out string contacts, out string penetration)
            ? (_penetration ? penetration : contacts)
            : "?";
    }

    public bool IsDefault(Summary summary, BenchmarkCase benchmarkCase) => false;

    public bool IsAvailable(Summary summary) => true;

    public override string ToString() => ColumnName;
}

/// <summary>How step time grows with N: this row's mean over the mean of the same benchmark at N = 1,000.</summary>
internal sealed class GrowthColumn : IColumn
{
    public const int ReferenceCount = 1000;

    public static readonly IColumn Instance = new GrowthColumn();

    public string Id => nameof(GrowthColumn);
    public string ColumnName => "t/t(1k)";
    public bool AlwaysShow => true;
    public ColumnCategory Category => ColumnCategory.Custom;
    public int PriorityInCategory => 2;
    public bool IsNumeric => true;
    public UnitType UnitType => UnitType.Dimensionless;
    public string Legend => "Mean time over the mean time of the same benchmark at N = 1,000 (issue 10 target for the pits: t(16k)/t(1k) ≤ 18)";

    public string GetValue(Summary summary, BenchmarkCase benchmarkCase) => GetValue(summary, benchmarkCase, SummaryStyle.Default);

    public string GetValue(Summary summary, BenchmarkCase benchmarkCase, SummaryStyle style)
    {
        double? ratio = Ratio(summary, benchmarkCase);
        return ratio is double r ? r.ToString("0.00", CultureInfo.InvariantCulture) : "-";
    }

    /// <summary>Mean(this case) / mean(same method and other parameters, N = 1,000); null when either is missing.</summary>
    public static double? Ratio(Summary summary, BenchmarkCase benchmarkCase)
    {
        if (!benchmarkCase.Parameters.Items.Any(p => p.Name == "N"))
        {
            return null;
        }

        BenchmarkReport? reference = summary.Reports.FirstOrDefault(r =>
            r.BenchmarkCase.Descriptor.Equals(benchmarkCase.Descriptor) &&
            r.BenchmarkCase.Job == benchmarkCase.Job &&
            r.BenchmarkCase.Parameters.Items.All(p => p.Name == "N"
                ? Equals(p.Value, ReferenceCount)
                : Equals(p.Value, benchmarkCase.Parameters[p.Name])));
        double? mine = summary[benchmarkCase]?.ResultStatistics?.Mean;
        double? theirs = reference?.ResultStatistics?.Mean;
        return mine is double m && theirs is double t && t > 0 ? m / t : null;
    }

    public bool IsDefault(Summary summary, BenchmarkCase benchmarkCase) => false;

    public bool IsAvailable(Summary summary) => true;

    public override string ToString() => ColumnName;
}
