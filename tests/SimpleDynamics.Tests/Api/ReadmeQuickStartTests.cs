using System;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Text.RegularExpressions;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;

namespace SimpleDynamics.Tests.Api;

/// <summary>The README's quick start runs, and the README shows exactly this code.</summary>
public class ReadmeQuickStartTests
{
    [Fact]
    public void Quick_start_runs_and_the_ball_bounces()
    {
        var console = new StringWriter();
        TextWriter original = Console.Out;
        Console.SetOut(console);
        RigidBody ball;
        try
        {
            // README quick start: begin
            var world = new World(gravity: new Vector3(0, -9.81f, 0));
            world.AddPlane(StaticPlane.Ground());
            ball = world.Add(new RigidBody(mass: 1f, radius: 0.5f, position: new Vector3(0, 3, 0)) { Restitution = 0.8f });
            for (int i = 0; i < 120; i++)
            {
                world.Step(1f / 60f);
            }

            Console.WriteLine($"after 2 s the ball is at y = {ball.Position.Y:F2} m, moving at {ball.LinearVelocity.Y:F2} m/s");
            // README quick start: end
        }
        finally
        {
            Console.SetOut(original);
        }

        // It fell 2.5 m in 0.71 s, bounced at 7 m/s with ε = 0.8 and is in the air again, above the ground.
        Assert.StartsWith("after 2 s the ball is at y = ", console.ToString());
        Assert.InRange(ball.Position.Y, 0.5f, 3f);
    }

    [Fact]
    public void Readme_shows_the_quick_start_code_of_this_test()
    {
        string readme = File.ReadAllText(Path.Combine(RepositoryRoot(), "README.md"));
        Match block = Regex.Match(readme, "## Quick start.*?```csharp\n(.*?)```", RegexOptions.Singleline);
        Assert.True(block.Success, "README.md has no csharp block under '## Quick start'");

        string source = File.ReadAllText(Path.Combine(RepositoryRoot(), "tests", "SimpleDynamics.Tests", "Api", "ReadmeQuickStartTests.cs"));
        Match region = Regex.Match(source, "// README quick start: begin\n(.*?)// README quick start: end", RegexOptions.Singleline);
        Assert.True(region.Success);

        // The test assigns ball, declared outside its try block; the README declares it with var.
        string code = Normalize(region.Groups[1].Value).Replace("ball = world.Add(", "var ball = world.Add(");
        Assert.Equal(code, Normalize(block.Groups[1].Value));
    }

    private static string Normalize(string code) =>
        string.Join("\n", code.Split('\n').Select(line => line.Trim()).Where(line => line.Length > 0));

    /// <summary>Found from the test's output folder (source paths are mapped away in CI builds).</summary>
    private static string RepositoryRoot()
    {
        string? directory = AppContext.BaseDirectory;
        while (directory is not null && !File.Exists(Path.Combine(directory, "SimpleDynamics.sln")))
        {
            directory = Path.GetDirectoryName(directory);
        }

        return directory ?? throw new InvalidOperationException("SimpleDynamics.sln not found above this test");
    }
}
