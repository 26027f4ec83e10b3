using System;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>The position pass without gravity, where a light body is crushed against a wall by a far heavier one.</summary>
public class AnchoringTests
{
    private readonly ITestOutputHelper _output;

    public AnchoringTests(ITestOutputHelper output) => _output = output;

    /// <summary>
    /// Generated world 233 of 2,000 (seed 801): a closed 4 m box without gravity in which a 597 kg disc at 61 m/s
    /// crushes a 0.35 kg one against the wall. Position sweeps split each correction by inverse mass, so the light
    /// disc was pushed into the wall and back and the pair ended step 21 3.9 mm deep; propagating the correction out
    /// from the wall, nearest first, leaves no pair deeper than the slop.
    /// </summary>
    [Fact]
    public void A_light_disc_crushed_against_a_wall_by_a_heavy_one_ends_no_deeper_than_the_slop()
    {
        var solver = new SequentialImpulseSolver(0.91104186f, 0f) { RestitutionThreshold = 0.5f };
        var world = new World(Vector3.Zero, solver) { Substeps = 8 };
        world.AddPlanes(StaticPlane.Box(Vector3.Zero, new Vector3(4, 4, 0), planar: true));
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (0.010311178f, 0.100420624f, new(0.26142025f, 2.191919f, 0), new(0.44977012f, 0.19623159f, 0), -1.2990228f),
            (0.06908223f, 0.23821373f, new(3.5807896f, 2.5253186f, 0), new(-2.0435836f, 3.4348392f, 0), -4.560047f),
            (0.34776273f, 0.30847374f, new(1.2597636f, 3.5178502f, 0), new(0.004648247f, 0.63759327f, 0), 2.4179134f),
            (0.06651836f, 0.33584017f, new(2.3203568f, 0.79267836f, 0), new(3.902747f, -6.2514486f, 0), 2.1437538f),
            (596.64374f, 0.38163942f, new(3.1490219f, 1.0845429f, 0), new(-43.764366f, 42.30773f, 0), 0.27231076f),
            (0.102169864f, 0.15122543f, new(2.5215971f, 3.3907955f, 0), new(-31.851658f, -16.856152f, 0), -3.176812f),
        };
        RigidBody[] bodies = discs.Select(d => world.Add(new RigidBody(d.Mass, d.Radius, d.Position, Inertia.Disc(d.Mass, d.Radius))
        {
            LinearVelocity = d.Velocity,
            AngularVelocity = new Vector3(0, 0, d.Spin),
        })).ToArray();

        float deepest = 0;
        for (int step = 0; step < 40; step++)
        {
            world.Step(1f / 240f);
            for (int i = 0; i < bodies.Length; i++)
            {
                for (int j = i + 1; j < bodies.Length; j++)
                {
                    float depth = bodies[i].Radius + bodies[j].Radius - Vector3.Distance(bodies[i].Position, bodies[j].Position);
                    deepest = MathF.Max(deepest, depth);
                }
            }
        }

        _output.WriteLine($"deepest pair over 40 steps: {deepest} m (slop {solver.Slop} m)");
        Assert.True(deepest <= solver.Slop + 1e-6f, $"a pair ended {deepest} m deep");
    }
}
