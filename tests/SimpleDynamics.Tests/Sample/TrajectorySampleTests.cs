using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using SimpleDynamics.Trajectories;
using Xunit;

namespace SimpleDynamics.Tests.Sample;

/// <summary>Runs the console sample's entry point, <see cref="Program.Run"/>, as a user would.</summary>
public class TrajectorySampleTests
{
    [Fact]
    public void No_arguments_prints_a_header_and_many_rows()
    {
        var (code, stdout, stderr) = Run();

        Assert.Equal(0, code);
        Assert.Equal(string.Empty, stderr);
        string[] lines = Lines(stdout);
        Assert.Contains(lines, l => l.StartsWith("# scene: bounce", StringComparison.Ordinal));
        Assert.Contains(lines, l => l.StartsWith("# scene: offcentre", StringComparison.Ordinal));
        Assert.Equal(2, lines.Count(IsHeader));
        Assert.True(TableRows(stdout, "bounce").Count >= 40, "the bounce table should have about 50 rows");
        Assert.True(TableRows(stdout, "offcentre").Count >= 40, "the offcentre table should have about 40 steps of 2 bodies");
    }

    [Fact]
    public void No_arguments_the_dropped_ball_falls_then_bounces_back_up()
    {
        var (_, stdout, _) = Run();

        List<double> heights = TableRows(stdout, "bounce").Select(row => Number(row[3])).ToList(); // time body x y ...
        int lowest = heights.IndexOf(heights.Take(heights.Count / 2).Min());
        Assert.InRange(lowest, 1, heights.Count - 2);
        Assert.True(heights[0] - heights[lowest] > 2, "the ball should fall most of its 3 m");
        Assert.True(heights.Skip(lowest).Max() - heights[lowest] > 1, "with eps = 0.8 the ball should bounce well back up");
        Assert.True(heights.Skip(lowest).Max() < heights[0], "a bounce with eps < 1 should not reach the drop height");
    }

    [Fact]
    public void No_arguments_the_off_centre_collision_sets_both_discs_spinning()
    {
        var (_, stdout, _) = Run();

        List<string[]> rows = TableRows(stdout, "offcentre");
        Assert.Equal(0, Number(rows[0][6])); // time body x y vx vy wz
        string[] lastLeft = rows[^2], lastRight = rows[^1];
        Assert.Equal("left", lastLeft[1]);
        Assert.Equal("right", lastRight[1]);
        Assert.True(Math.Abs(Number(lastLeft[6])) > 0.5, "friction should spin the left disc");
        Assert.True(Math.Abs(Number(lastRight[6])) > 0.5, "friction should spin the right disc");
    }

    [Fact]
    public void Csv_rows_parse_and_have_the_header_s_column_count()
    {
        var (code, stdout, stderr) = Run("--format", "csv");

        Assert.Equal(0, code);
        Assert.Equal(string.Empty, stderr);
        string[] lines = Lines(stdout);
        Assert.Equal(string.Join(",", CsvTrajectoryWriter.Columns), lines[0]);
        Assert.True(lines.Length > 100, "both default scenes, one row per body per printed step");
        foreach (string line in lines.Skip(1))
        {
            string[] fields = line.Split(',');
            Assert.Equal(CsvTrajectoryWriter.Columns.Count, fields.Length);
            Assert.Contains(fields[0], new[] { "bounce", "offcentre" });
            Assert.True(int.TryParse(fields[1], NumberStyles.Integer, CultureInfo.InvariantCulture, out _), line);
            foreach (string field in fields.Skip(4))
            {
                Assert.True(double.TryParse(field, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) && double.IsFinite(value), line);
            }
        }
    }

    [Fact]
    public void Csv_slide_ends_rolling_at_five_sevenths_of_the_start_speed()
    {
        var (code, stdout, _) = Run("--scene", "slide", "--format", "csv");

        Assert.Equal(0, code);
        string[] last = Lines(stdout)[^1].Split(',');
        double vx = Number(last[7]), wz = Number(last[12]);
        Assert.Equal(5.0 * 5 / 7, vx, 0.02); // solid sphere, v0 = 5 m/s
        Assert.Equal(vx, -wz * 0.5, 0.02);    // rolling: v = −ω_z r
    }

    public static TheoryData<string, string> ScenesAndResponders()
    {
        var data = new TheoryData<string, string>();
        foreach (string scene in new[] { "default", "bounce", "offcentre", "pile", "row", "slide" })
        {
            foreach (string responder in new[] { "solver", "impulse", "inelastic", "projection" })
            {
                data.Add(scene, responder);
            }
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(ScenesAndResponders))]
    public void Every_scene_runs_with_every_responder(string scene, string responder)
    {
        var (code, stdout, stderr) = Run("--scene", scene, "--responder", responder);

        Assert.Equal(0, code);
        Assert.Equal(string.Empty, stderr);
        Assert.Contains(Lines(stdout), IsHeader);
        Assert.Contains("# summary: every state finite (no NaN)", stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void The_pile_prints_a_summary_row_per_step_not_every_body()
    {
        var (code, stdout, _) = Run("--scene", "pile", "--steps", "50", "--every", "10");

        Assert.Equal(0, code);
        List<string[]> rows = TableRows(stdout, "pile");
        Assert.Equal(6, rows.Count); // steps 0, 10, 20, 30, 40, 50
        Assert.All(rows, row => Assert.Equal("100", row[1]));
    }

    [Fact]
    public void Settings_are_applied_and_the_last_step_is_always_printed()
    {
        var (code, stdout, _) = Run("--scene", "bounce", "--restitution", "0.5", "--friction=0", "--dt", "0.005", "--steps", "7", "--every", "3");

        Assert.Equal(0, code);
        Assert.Contains("eps = 0.5, mu = 0", stdout, StringComparison.Ordinal);
        List<string[]> rows = TableRows(stdout, "bounce");
        Assert.Equal(new[] { 0, 0.015, 0.03, 0.035 }, rows.Select(row => Number(row[0])));
    }

    [Theory]
    [InlineData("--bogus")]
    [InlineData("--steps")]
    [InlineData("--steps", "many")]
    [InlineData("--steps", "0")]
    [InlineData("--steps", "1.5")]
    [InlineData("--dt", "0")]
    [InlineData("--dt", "-0.01")]
    [InlineData("--dt", "NaN")]
    [InlineData("--dt", "0,01")]
    [InlineData("--restitution", "1.1")]
    [InlineData("--restitution", "-0.1")]
    [InlineData("--friction", "-1")]
    [InlineData("--friction", "Infinity")]
    [InlineData("--every", "0")]
    [InlineData("--scene", "moon")]
    [InlineData("--responder", "magic")]
    [InlineData("--format", "xml")]
    [InlineData("--output")]
    [InlineData("--steps", "--dt", "0.1")]
    [InlineData("stray")]
    public void Bad_options_print_one_error_line_and_exit_2(params string[] args)
    {
        var (code, stdout, stderr) = Run(args);

        Assert.Equal(2, code);
        Assert.Equal(string.Empty, stdout);
        string[] lines = Lines(stderr);
        Assert.Single(lines);
        Assert.StartsWith("error:", lines[0], StringComparison.Ordinal);
    }

    [Fact]
    public void Help_prints_the_usage_and_exits_0()
    {
        var (code, stdout, stderr) = Run("--help");

        Assert.Equal(0, code);
        Assert.Equal(string.Empty, stderr);
        Assert.StartsWith("Usage:", stdout, StringComparison.Ordinal);
        foreach (string option in new[] { "--scene", "--responder", "--restitution", "--friction", "--steps", "--dt", "--every", "--format", "--output" })
        {
            Assert.Contains(option, stdout, StringComparison.Ordinal);
        }
    }

    [Theory]
    [InlineData("csv")]
    [InlineData("table")]
    public void Output_goes_to_the_file_instead_of_stdout(string format)
    {
        string path = Path.Combine(Path.GetTempPath(), $"trajectory-{Guid.NewGuid():N}.{format}");
        try
        {
            var (code, stdout, stderr) = Run("--scene", "offcentre", "--format", format, "--output", path);

            Assert.Equal(0, code);
            Assert.Equal(string.Empty, stdout);
            Assert.Equal(string.Empty, stderr);
            string[] lines = File.ReadAllLines(path);
            Assert.True(lines.Length > 40);
            if (format == "csv")
            {
                Assert.Equal(string.Join(",", CsvTrajectoryWriter.Columns), lines[0]);
            }
            else
            {
                Assert.Contains(lines, IsHeader);
            }
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Fact]
    public void An_unwritable_output_file_is_one_error_line_and_exit_1()
    {
        string path = Path.Combine(Path.GetTempPath(), $"no-such-dir-{Guid.NewGuid():N}", "out.csv");

        var (code, stdout, stderr) = Run("--output", path);

        Assert.Equal(1, code);
        Assert.Equal(string.Empty, stdout);
        Assert.StartsWith("error:", Assert.Single(Lines(stderr)), StringComparison.Ordinal);
    }

    [Fact]
    public void Numbers_are_invariant_whatever_the_current_culture()
    {
        CultureInfo saved = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = CultureInfo.GetCultureInfo("de-DE");

            var (code, stdout, _) = Run("--scene", "bounce", "--dt", "0.02", "--steps", "2");

            Assert.Equal(0, code);
            Assert.Contains("3.000", stdout, StringComparison.Ordinal);
            Assert.DoesNotContain("3,000", stdout, StringComparison.Ordinal);
        }
        finally
        {
            CultureInfo.CurrentCulture = saved;
        }
    }

    private static (int Code, string Stdout, string Stderr) Run(params string[] args)
    {
        var stdout = new StringWriter(CultureInfo.InvariantCulture);
        var stderr = new StringWriter(CultureInfo.InvariantCulture);
        int code = Program.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    private static string[] Lines(string text) =>
        text.Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(l => l.TrimEnd('\r')).Where(l => l.Length > 0).ToArray();

    private static bool IsHeader(string line) => line.TrimStart().StartsWith("time ", StringComparison.Ordinal);

    /// <summary>The whitespace-separated data rows of one scene's table (its lines that are not '#', blank or the header).</summary>
    private static List<string[]> TableRows(string table, string scene)
    {
        var rows = new List<string[]>();
        bool inScene = false;
        foreach (string raw in table.Split('\n'))
        {
            string line = raw.TrimEnd('\r');
            if (line.StartsWith("# scene: ", StringComparison.Ordinal))
            {
                inScene = line.StartsWith("# scene: " + scene + " ", StringComparison.Ordinal);
                continue;
            }

            if (!inScene || line.Length == 0 || line.StartsWith('#') || IsHeader(line))
            {
                continue;
            }

            rows.Add(line.Split(' ', StringSplitOptions.RemoveEmptyEntries));
        }

        return rows;
    }

    private static double Number(string text) => double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture);
}
