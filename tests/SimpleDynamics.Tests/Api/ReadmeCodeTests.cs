using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Reflection;
using System.Runtime.Loader;
using System.Text.RegularExpressions;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Laws;
using Xunit;

namespace SimpleDynamics.Tests.Api;

/// <summary>
/// Every ```csharp block of README.md compiles as shown (Roslyn, against the library, the laws kit, xunit and
/// the .NET runtime); a block with top-level statements also runs, and what it prints must be the
/// "// prints:" comment at its end. The Unity block compiles against stand-ins for the few UnityEngine types it
/// uses. (All in one class: the runs redirect Console.Out, which xunit must not share between parallel tests.)
/// </summary>
public class ReadmeCodeTests
{
    private const string PrintsMarker = "// prints:";

    public static TheoryData<int, string> Blocks()
    {
        var data = new TheoryData<int, string>();
        foreach (var (index, heading, _) in ReadmeBlocks())
        {
            data.Add(index, heading);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Blocks))]
    public void Readme_csharp_block_compiles_and_prints_what_it_shows(int index, string heading)
    {
        string code = ReadmeBlocks().Single(b => b.Index == index).Code;

        Assembly assembly = Compile(code, heading);

        MethodInfo? entry = assembly.EntryPoint;
        if (entry is null)
        {
            Assert.DoesNotContain(PrintsMarker, code, StringComparison.Ordinal); // declarations only: nothing runs
            return;
        }

        Assert.True(code.Contains(PrintsMarker, StringComparison.Ordinal), $"the block under '{heading}' runs but does not show its output ({PrintsMarker} ...)");
        string printed = RunCapturingConsole(entry);
        Assert.Equal(ShownOutput(code), Normalize(printed));
    }

    [Fact]
    public void Readme_has_the_blocks_this_test_expects()
    {
        string[] headings = ReadmeBlocks().Select(b => b.Heading).ToArray();

        Assert.Contains("Quick start", headings);
        Assert.Contains("MonoGame and Godot", headings);
        Assert.Contains("Unity", headings);
        Assert.Contains("Check your own responder", headings);
    }

    [Fact]
    public void Quick_start_block_has_its_usings_inside()
    {
        string code = ReadmeBlocks().First(b => b.Heading == "Quick start").Code;

        Assert.StartsWith("using System;", code, StringComparison.Ordinal);
        Assert.Contains("using SimpleDynamics.Collision;", code, StringComparison.Ordinal);
    }

    [Fact]
    public void Readme_names_the_version_that_Directory_Build_props_sets()
    {
        string props = File.ReadAllText(Path.Combine(RepositoryRoot(), "Directory.Build.props"));
        string version = Regex.Match(props, "<Version>(.*?)</Version>").Groups[1].Value;

        Assert.Matches(@"^0\.\d+\.\d+$", version);
        Assert.Contains($"dotnet add package SimpleDynamics --version {version}", Readme(), StringComparison.Ordinal);
    }

    [Fact]
    public void Readme_states_the_laws_kit_defaults_the_kit_has()
    {
        var options = new LawOptions();

        Assert.Equal(200, options.MaxTest);
        Assert.Equal(1e-4, options.Tolerance);
        Assert.Contains("up to 200 generated collisions per law", Readme(), StringComparison.Ordinal);
        Assert.Contains("relative tolerance 1e-4", Readme(), StringComparison.Ordinal);
    }

    /// <summary>The quick start's physics, checked directly: the ball fell, bounced and is in the air again.</summary>
    [Fact]
    public void Quick_start_ball_bounces()
    {
        var world = new World(gravity: new Vector3(0, -9.81f, 0));
        world.AddPlane(StaticPlane.Ground());
        var ball = world.Add(new RigidBody(mass: 1f, radius: 0.5f, position: new Vector3(0, 3, 0)) { Restitution = 0.8f });
        for (int i = 0; i < 120; i++)
        {
            world.Step(1f / 60f);
        }

        // It fell 2.5 m in 0.71 s, bounced at 7 m/s with ε = 0.8 and is in the air again, above the ground.
        Assert.InRange(ball.Position.Y, 0.5f, 3f);
    }

    private static IEnumerable<(int Index, string Heading, string Code)> ReadmeBlocks()
    {
        string readme = Readme();
        int index = 0;
        foreach (Match block in Regex.Matches(readme, "```csharp\n(.*?)```", RegexOptions.Singleline))
        {
            string before = readme[..block.Index];
            MatchCollection headings = Regex.Matches(before, @"^#{2,3} (.+)$", RegexOptions.Multiline);
            string heading = headings.Count > 0 ? headings[^1].Groups[1].Value.Trim() : "(top)";
            yield return (index++, heading, block.Groups[1].Value);
        }
    }

    private static Assembly Compile(string code, string heading)
    {
        var trees = new List<SyntaxTree> { CSharpSyntaxTree.ParseText(code, new CSharpParseOptions(LanguageVersion.Latest), path: "README.md") };
        if (code.Contains("using UnityEngine;", StringComparison.Ordinal))
        {
            trees.Add(CSharpSyntaxTree.ParseText(UnityStandIns, new CSharpParseOptions(LanguageVersion.Latest)));
        }

        bool runs = trees[0].GetCompilationUnitRoot().Members.OfType<Microsoft.CodeAnalysis.CSharp.Syntax.GlobalStatementSyntax>().Any();
        var compilation = CSharpCompilation.Create(
            "ReadmeBlock" + Guid.NewGuid().ToString("N"),
            trees,
            References(),
            new CSharpCompilationOptions(runs ? OutputKind.ConsoleApplication : OutputKind.DynamicallyLinkedLibrary, nullableContextOptions: NullableContextOptions.Enable));
        using var image = new MemoryStream();
        var result = compilation.Emit(image);
        string[] errors = result.Diagnostics.Where(d => d.Severity == DiagnosticSeverity.Error).Select(d => d.ToString()).ToArray();
        Assert.True(result.Success, $"the block under '{heading}' does not compile:\n{string.Join("\n", errors)}");
        image.Position = 0;
        return new AssemblyLoadContext("readme", isCollectible: true).LoadFromStream(image);
    }

    private static IEnumerable<MetadataReference> References()
    {
        var paths = ((string)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES")!).Split(Path.PathSeparator).ToList();
        paths.Add(typeof(World).Assembly.Location);
        paths.Add(typeof(ResponderLaws).Assembly.Location);
        paths.Add(typeof(FactAttribute).Assembly.Location);
        return paths.Where(p => p.Length > 0).Distinct().Select(p => MetadataReference.CreateFromFile(p));
    }

    private static string RunCapturingConsole(MethodInfo entry)
    {
        var output = new StringWriter();
        TextWriter original = Console.Out;
        Console.SetOut(output);
        try
        {
            entry.Invoke(null, entry.GetParameters().Length == 0 ? null : new object[] { Array.Empty<string>() });
        }
        finally
        {
            Console.SetOut(original);
        }

        return output.ToString();
    }

    /// <summary>The comment lines after "// prints:", without their "// ".</summary>
    private static string ShownOutput(string code)
    {
        string[] lines = code.Split('\n');
        int start = Array.FindIndex(lines, l => l.TrimStart().StartsWith(PrintsMarker, StringComparison.Ordinal));
        var shown = new List<string> { lines[start].Trim()[PrintsMarker.Length..].Trim() };
        for (int i = start + 1; i < lines.Length && lines[i].TrimStart().StartsWith("//", StringComparison.Ordinal); i++)
        {
            string comment = lines[i].TrimStart()[2..];
            shown.Add(comment.StartsWith(' ') ? comment[1..] : comment);
        }

        return Normalize(string.Join("\n", shown));
    }

    private static string Normalize(string text) => string.Join("\n", text.Replace("\r", string.Empty, StringComparison.Ordinal).Split('\n').Select(l => l.TrimEnd())).Trim('\n');

    private static string Readme() => File.ReadAllText(Path.Combine(RepositoryRoot(), "README.md")).Replace("\r\n", "\n", StringComparison.Ordinal);

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

    /// <summary>Stand-ins with the shape of the UnityEngine members the README's Unity block uses.</summary>
    private const string UnityStandIns = """
        namespace UnityEngine
        {
            public struct Vector3
            {
                public float x, y, z;
                public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
            }

            public struct Quaternion
            {
                public float x, y, z, w;
                public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
            }

            public class Transform
            {
                public Vector3 position { get; set; }
                public Quaternion rotation { get; set; }
            }

            public class Object { }

            public class Component : Object
            {
                public Transform transform { get; } = new Transform();
            }

            public class Behaviour : Component { }

            public class MonoBehaviour : Behaviour { }

            public static class Time
            {
                public static float fixedDeltaTime { get; set; } = 0.02f;
            }
        }
        """;
}
