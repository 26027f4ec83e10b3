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
    public void Every_scene_runs_with_every_responder_and_every_expectation_printed_holds(string scene, string responder)
    {
        var (code, stdout, stderr) = Run("--scene", scene, "--responder", responder);

        Assert.Equal(0, code);
        Assert.Contains(Lines(stdout), IsHeader);
        Assert.Contains("# summary: every state finite (no NaN)", stdout, StringComparison.Ordinal);
        Assert.All(Lines(stderr), line => Assert.StartsWith("warning: ", line, StringComparison.Ordinal));
        // An expect: line is printed only where the responder does what it says.
        Assert.DoesNotContain(": expected ", stderr, StringComparison.Ordinal);
        Assert.DoesNotContain("# warning: expected ", stdout, StringComparison.Ordinal);
        if (responder != "projection")
        {
            Assert.Equal(string.Empty, stderr); // only projection adds energy
        }
    }

    /// <summary>
    /// Projection changes no velocity, so on its own it lets bodies keep approaching; the world now stops every
    /// approach at the time of impact, so the ball no longer gains energy (it used to go from 29 J to 775 J).
    /// </summary>
    [Fact]
    public void Projection_no_longer_gains_energy_and_promises_nothing()
    {
        var (code, stdout, stderr) = Run("--scene", "bounce", "--responder", "projection");

        Assert.Equal(0, code);
        Assert.DoesNotContain("# expect:", stdout, StringComparison.Ordinal);
        Assert.Equal(string.Empty, stderr);
        Assert.Contains("# summary: E 29.430 -> ", stdout, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("offcentre", "inelastic")]
    [InlineData("offcentre", "projection")]
    [InlineData("row", "impulse")]
    [InlineData("slide", "inelastic")]
    [InlineData("pile", "impulse")]
    public void No_expectation_is_printed_where_the_responder_does_not_meet_it(string scene, string responder)
    {
        var (_, stdout, _) = Run("--scene", scene, "--responder", responder);

        Assert.DoesNotContain("# expect:", stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void A_run_too_short_for_the_expectation_does_not_state_it()
    {
        var (code, stdout, stderr) = Run("--scene", "pile", "--steps", "5");

        Assert.Equal(0, code);
        Assert.DoesNotContain("# expect:", stdout, StringComparison.Ordinal);
        Assert.Equal(string.Empty, stderr);
    }

    [Fact]
    public void The_contacts_column_counts_touching_contacts_only()
    {
        // The bouncing ball: detection reports the ground as a speculative pair just before each impact, while
        // the ball is still above it; those rows must say 0.
        var (code, bounce, _) = Run("--scene", "bounce", "--format", "csv", "--every", "1");
        Assert.Equal(0, code);
        int contacts = CsvColumn("contacts"), y = CsvColumn("y");
        foreach (string[] row in Lines(bounce).Skip(1).Select(line => line.Split(',')))
        {
            if (Number(row[y]) > 0.5 + 1e-3)
            {
                Assert.True(row[contacts] == "0", $"the ball is in the air (y = {row[y]}) but {row[contacts]} contacts are counted");
            }
        }

        // The sliding ball lies on the ground: one touching contact once detection has run.
        var (_, slide, _) = Run("--scene", "slide", "--format", "csv");
        Assert.All(Lines(slide).Skip(2).Select(line => line.Split(',')), row => Assert.Equal("1", row[contacts]));
    }

    [Fact]
    public void Wide_numbers_never_run_into_their_neighbours()
    {
        // A frictionless ball sliding at 5 m/s for 3,000 s ends 15 km away: "15000.000" fills its column.
        var (code, stdout, _) = Run("--scene", "slide", "--friction", "0", "--dt", "0.1", "--steps", "30000", "--every", "10000");

        Assert.Equal(0, code);
        List<string[]> rows = TableRows(stdout, "slide");
        Assert.Equal(4, rows.Count);
        Assert.Equal("15000.000", rows[^1][2]);
        Assert.All(rows, row => Assert.Equal(15, row.Length)); // time body x y vx vy wz | KE PE E px py contacts max-pen
    }

    [Fact]
    public void Csv_numbers_have_one_format_seven_significant_digits_at_most()
    {
        var (_, stdout, _) = Run("--scene", "offcentre", "--format", "csv", "--every", "1", "--steps", "30");

        string[] lines = Lines(stdout);
        Assert.StartsWith("offcentre,3,0.03,", lines[1 + 3 * 2], StringComparison.Ordinal); // float time sums read 0.03
        foreach (string field in lines.Skip(1).SelectMany(line => line.Split(',').Skip(2)).Where(f => f is not ("left" or "right")))
        {
            string digits = field.TrimStart('-').Split('E')[0].Replace(".", string.Empty, StringComparison.Ordinal).TrimStart('0');
            Assert.True(digits.Length <= 7, $"'{field}' has more than seven significant digits");
            Assert.NotEqual("-0", field);
        }
    }

    [Fact]
    public void Long_runs_report_progress_on_stderr_only()
    {
        long saved = Program.ProgressThreshold;
        try
        {
            Program.ProgressThreshold = 100;
            var (code, stdout, stderr) = Run("--scene", "bounce", "--steps", "200");

            Assert.Equal(0, code);
            string[] progress = Lines(stderr);
            Assert.Equal(10, progress.Length);
            Assert.Equal("progress: bounce 10% (step 20 of 200)", progress[0]);
            Assert.Equal("progress: bounce 100% (step 200 of 200)", progress[^1]);
            Assert.DoesNotContain("progress", stdout, StringComparison.Ordinal);
        }
        finally
        {
            Program.ProgressThreshold = saved;
        }
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
    [InlineData("--steps", "99999999999")]
    [InlineData("--dt", "1e9")]
    [InlineData("--format", "pdf")]
    public void Bad_options_print_one_error_line_and_exit_2(params string[] args)
    {
        var (code, stdout, stderr) = Run(args);

        Assert.Equal(2, code);
        Assert.Equal(string.Empty, stdout);
        string[] lines = Lines(stderr);
        Assert.Single(lines);
        Assert.StartsWith("error:", lines[0], StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("--steps 99999999999", "error: --steps must be at most 10000000, got 99999999999 (too large)")]
    [InlineData("--steps 0", "error: --steps must be at least 1, got 0 (too small)")]
    [InlineData("--steps 1.5", "error: --steps needs a whole number, got '1.5'")]
    [InlineData("--dt 1e9", "error: --dt must be more than 0 and at most 0.1, got 1e9 (too large)")]
    [InlineData("--dt 0", "error: --dt must be more than 0 and at most 0.1, got 0 (too small)")]
    [InlineData("--dt 0,01", "error: --dt needs a number such as 0.25 ('.' as decimal separator), got '0,01'")]
    [InlineData("--friction Infinity", "error: --friction needs a number such as 0.25")]
    [InlineData("--restitution 1.1", "error: --restitution must be between 0 and 1, got 1.1 (too large)")]
    [InlineData("--steps --dt 0.1", "error: --steps needs a value, but the next argument is the option --dt")]
    [InlineData("--scene moon", "error: unknown value 'moon' for --scene; expected one of: default, bounce, offcentre, pile, row, slide")]
    public void Bad_values_are_reported_with_the_true_reason(string args, string error)
    {
        var (code, _, stderr) = Run(args.Split(' '));

        Assert.Equal(2, code);
        Assert.StartsWith(error, stderr, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("--help")]
    [InlineData("-h")]
    [InlineData("-?")]
    public void Help_is_generated_and_exits_0(string flag)
    {
        var (code, stdout, stderr) = Run(flag);

        Assert.Equal(0, code);
        Assert.Equal(string.Empty, stderr);
        Assert.Contains("Usage:", stdout, StringComparison.Ordinal);
        Assert.Contains("Exit codes: 0 success, 1 the output file could not be written, 2 invalid options.", stdout, StringComparison.Ordinal);
        foreach (string option in new[] { "--scene", "--responder", "--restitution", "--friction", "--steps", "--dt", "--every", "--format", "--output", "svg", "html" })
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

    [Fact]
    public void The_game_scene_prints_the_events_of_each_row_and_the_balls_falling_asleep()
    {
        var (code, stdout, stderr) = Run("--scene", "game");

        Assert.Equal(0, code);
        Assert.Equal(string.Empty, stderr); // no warning: the expectation "every ball falls asleep" holds
        Assert.Contains("# expect: every ball comes to rest and falls asleep", stdout, StringComparison.Ordinal);
        List<string[]> rows = TableRows(stdout, "game");
        Assert.Equal(13, rows.Count); // t = 0 and a row every 0.5 s for 6 s
        Assert.Equal("0", rows[0][^1]); // the asleep column: nobody at the start ...
        Assert.Equal("12", rows[^1][^1]); // ... every ball at the end
        string[] events = Lines(stdout).Where(l => l.StartsWith("#          ", StringComparison.Ordinal)).Select(l => l.Trim('#', ' ')).ToArray();
        Assert.Equal(12, events.Count(e => e.Contains(" begin, ", StringComparison.Ordinal))); // one summary under each row after t = 0
        Assert.Contains(events, e => e.Contains("hits, fastest", StringComparison.Ordinal) && e.Contains("on the ground", StringComparison.Ordinal));
        Assert.Contains(events, e => e.Contains("enters the drain at t = ", StringComparison.Ordinal));
        Assert.EndsWith("0 begin, 0 end, 0 hits", events[^1], StringComparison.Ordinal); // asleep: no events at all

        var (csvCode, csv, _) = Run("--scene", "game", "--format", "csv");
        Assert.Equal(0, csvCode);
        string[][] csvRows = Lines(csv).Skip(1).Select(line => line.Split(',')).ToArray();
        Assert.Equal("12", csvRows[^1][CsvColumn("asleep")]);
        Assert.True(csvRows.Sum(row => int.Parse(row[CsvColumn("hits")], CultureInfo.InvariantCulture)) >= 10, "the pour makes hits");
        Assert.Equal(
            csvRows.Sum(row => int.Parse(row[CsvColumn("begin_touch")], CultureInfo.InvariantCulture)) - csvRows.Sum(row => int.Parse(row[CsvColumn("end_touch")], CultureInfo.InvariantCulture)),
            TouchingPairsOfGameScene());
    }

    /// <summary>The pairs touching at the end of the game scene, stepped here as the sample steps it.</summary>
    private static int TouchingPairsOfGameScene()
    {
        Scene scene = SceneFactory.Build(new Options { Scene = SceneKind.Game })[0];
        for (int i = 0; i < scene.Steps; i++)
        {
            scene.World.Step(scene.Dt);
        }

        return scene.World.ContactEvents.Touching.Length;
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

    private static int CsvColumn(string name) => CsvTrajectoryWriter.Columns.ToList().IndexOf(name);

    private static double Number(string text) => double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture);
}
