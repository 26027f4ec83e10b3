using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Xml.Linq;
using SimpleDynamics.Bodies;
using SimpleDynamics.Trajectories;
using Xunit;

namespace SimpleDynamics.Tests.Sample;

/// <summary>The sample's pictures: the SVG is well-formed with one path per body; the HTML page draws the balls.</summary>
public class PictureTests
{
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    [Theory]
    [InlineData("default", "bounce", 1)]
    [InlineData("default", "offcentre", 2)]
    [InlineData("row", "row", 4)]
    [InlineData("pile", "pile", 100)]
    public void Svg_is_well_formed_with_one_path_per_body(string scene, string part, int bodies)
    {
        var (code, svg, stderr) = Run("--scene", scene, "--format", "svg");

        Assert.Equal(0, code);
        Assert.Equal(string.Empty, stderr);
        XDocument document = XDocument.Parse(svg); // throws unless well-formed XML
        Assert.Equal(Svg + "svg", document.Root!.Name);
        XElement paths = document.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == "paths-" + part);
        Assert.Equal(bodies, paths.Elements(Svg + "path").Count(p => (string?)p.Attribute("class") == "body-path"));
        Assert.All(paths.Elements(Svg + "path"), p => Assert.StartsWith("M", (string?)p.Attribute("d"), StringComparison.Ordinal));
        Assert.Single(document.Descendants(Svg + "g"), g => (string?)g.Attribute("id") == "energy-" + part);
        Assert.Single(document.Descendants(Svg + "g"), g => (string?)g.Attribute("id") == "positions-" + part);
    }

    /// <summary>
    /// A run whose mechanical energy rises shows the warning in its SVG, as it does on standard error. No scene of the
    /// sample gains energy with the library's responders (collisions are answered at impact), so the test makes one:
    /// a kinematic paddle, driven at a set speed, pushes a ball at rest, and the ball's energy comes from outside.
    /// </summary>
    [Fact]
    public void Svg_shows_the_warning_of_a_run_whose_mechanical_energy_rises()
    {
        var world = new World(Vector3.Zero);
        world.Add(RigidBody.CreateKinematic(0.2f, Vector3.Zero, new Vector3(2f, 0, 0)));
        world.Add(new RigidBody(1f, 0.1f, new Vector3(0.5f, 0, 0), Inertia.Disc(1f, 0.1f)));
        var scene = new Scene("push", "a kinematic paddle pushes a ball", world, new[] { "paddle", "ball" },
            Steps: 60, Dt: 0.01f, Every: 1, SummaryOnly: false, Planar: true, ResponderKind.Solver, Expectation: null);
        var svg = new StringWriter(CultureInfo.InvariantCulture);
        var stderr = new StringWriter(CultureInfo.InvariantCulture);

        Program.Simulate(new[] { scene }, new SvgTrajectoryWriter(svg), stderr);

        XDocument document = XDocument.Parse(svg.ToString());
        Assert.Contains(document.Descendants(Svg + "text"), t => t.Value.StartsWith("warning: mechanical energy rose", StringComparison.Ordinal));
        Assert.StartsWith("warning: push: mechanical energy rose", stderr.ToString(), StringComparison.Ordinal);
    }

    [Fact]
    public void Html_is_self_contained_with_a_canvas_per_scene_and_the_controls()
    {
        var (code, html, _) = Run("--format", "html");

        Assert.Equal(0, code);
        Assert.StartsWith("<!DOCTYPE html>", html, StringComparison.Ordinal);
        Assert.DoesNotContain("<script src", html, StringComparison.OrdinalIgnoreCase);
        Assert.DoesNotContain("<link", html, StringComparison.OrdinalIgnoreCase);
        Assert.DoesNotContain("http://", html, StringComparison.Ordinal);
        Assert.DoesNotContain("https://", html, StringComparison.Ordinal);
        foreach (int scene in new[] { 0, 1 })
        {
            Assert.Contains($"<canvas id=\"world-{scene}\"", html, StringComparison.Ordinal);
            Assert.Contains($"<canvas id=\"energy-{scene}\"", html, StringComparison.Ordinal);
            Assert.Contains($"<button id=\"play-{scene}\">", html, StringComparison.Ordinal);
            Assert.Contains($"<input id=\"slider-{scene}\" type=\"range\"", html, StringComparison.Ordinal);
        }
    }

    [ChromiumFact]
    public void Html_page_draws_the_balls_in_headless_chromium()
    {
        string directory = Path.Combine(Path.GetTempPath(), "sd-html-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(directory);
        try
        {
            string page = Path.Combine(directory, "offcentre.html"), png = Path.Combine(directory, "shot.png");
            var (code, _, _) = Run("--scene", "offcentre", "--format", "html", "--output", page);
            Assert.Equal(0, code);

            string log = Chromium.Screenshot(page, png, width: 800, height: 800);

            Assert.True(File.Exists(png), "chromium wrote no screenshot: " + log);
            Png.Image image = Png.Decode(File.ReadAllBytes(png));
            Assert.Equal(800, image.Width);
            // Two discs of radius 0.5 m, drawn in the first two body colours; a disc covers thousands of pixels.
            foreach (int body in new[] { 0, 1 })
            {
                (byte r, byte g, byte b) = Rgb(PictureWriter.BodyColours[body]);
                int pixels = image.Count((pr, pg, pb) => Math.Abs(pr - r) <= 2 && Math.Abs(pg - g) <= 2 && Math.Abs(pb - b) <= 2);
                Assert.True(pixels > 1000, $"body {body} ({PictureWriter.BodyColours[body]}) covers {pixels} pixels of the screenshot");
            }
        }
        finally
        {
            Directory.Delete(directory, recursive: true);
        }
    }

    private static (byte R, byte G, byte B) Rgb(string hex) => (
        byte.Parse(hex.AsSpan(1, 2), NumberStyles.HexNumber, CultureInfo.InvariantCulture),
        byte.Parse(hex.AsSpan(3, 2), NumberStyles.HexNumber, CultureInfo.InvariantCulture),
        byte.Parse(hex.AsSpan(5, 2), NumberStyles.HexNumber, CultureInfo.InvariantCulture));

    private static (int Code, string Stdout, string Stderr) Run(params string[] args)
    {
        var stdout = new StringWriter(CultureInfo.InvariantCulture);
        var stderr = new StringWriter(CultureInfo.InvariantCulture);
        int code = Program.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }
}

/// <summary>A [Fact] that is skipped, saying why, when no <c>chromium</c> is on PATH.</summary>
public sealed class ChromiumFactAttribute : FactAttribute
{
    public ChromiumFactAttribute()
    {
        if (Chromium.Path is null)
        {
            Skip = "chromium is not on PATH: install it (Debian: apt-get install -y chromium; .ci/run does this when it can) to check the HTML page in a browser";
        }
    }
}

/// <summary>Headless Chromium, found on PATH.</summary>
public static class Chromium
{
    public static string? Path { get; } = Find();

    /// <summary>Opens <paramref name="page"/> and saves a PNG screenshot after ~1.5 s of page time; returns chromium's output.</summary>
    public static string Screenshot(string page, string png, int width, int height)
    {
        var start = new ProcessStartInfo(Path ?? throw new InvalidOperationException("chromium is not on PATH"))
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        foreach (string argument in new[]
        {
            "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--force-color-profile=srgb",
            "--virtual-time-budget=1500", $"--window-size={width},{height}", $"--screenshot={png}",
            new Uri(page).AbsoluteUri,
        })
        {
            start.ArgumentList.Add(argument);
        }

        using Process process = Process.Start(start)!;
        var error = process.StandardError.ReadToEndAsync();
        var output = process.StandardOutput.ReadToEndAsync();
        if (!process.WaitForExit(TimeSpan.FromSeconds(90)))
        {
            process.Kill(entireProcessTree: true);
            throw new TimeoutException("chromium did not finish within 90 s");
        }

        return output.Result + error.Result;
    }

    private static string? Find()
    {
        foreach (string directory in (Environment.GetEnvironmentVariable("PATH") ?? string.Empty).Split(System.IO.Path.PathSeparator))
        {
            foreach (string name in new[] { "chromium", "chromium-browser" })
            {
                string candidate = System.IO.Path.Combine(directory, name);
                if (directory.Length > 0 && File.Exists(candidate))
                {
                    return candidate;
                }
            }
        }

        return null;
    }
}
