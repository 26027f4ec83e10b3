using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The queue of contacts the last position sweep leaves deeper than the slop (SequentialImpulseSolver.Residual.cs),
/// far enough from the origin that float rounding of where a body is matters at the scale of the slop.
/// </summary>
public class ResidualQueueTests
{
    private const int Steps = 60;

    private readonly ITestOutputHelper _output;

    public ResidualQueueTests(ITestOutputHelper output) => _output = output;

    /// <summary>
    /// In the settled 16,000-disc pit, whose top is 8–16 m up, about 1,000 contacts ended each step's last position
    /// sweep beyond 1.001 × the slop by less than one unit in the last place of their centres' coordinates (0.95 µm
    /// there), a depth no float correction can remove: the queue corrected them again and again until its budget ran
    /// out (27,600 corrections a step, about a tenth of the step's time), and moved nothing. Here a disc rests on
    /// another 1 km up, where a coordinate is a multiple of 2⁻¹⁴ m (61 µm), placed 13 µm beyond the slop: a
    /// correction of 13 µm rounds back to where the disc was. The queue takes up no such contact (it took up 128 a
    /// step before), and the stack stays where it is.
    /// </summary>
    [Fact]
    public void A_contact_only_float_rounding_keeps_beyond_the_slop_is_not_queued_again_and_again()
    {
        const float floor = 1000f, radius = 0.05f;
        var solver = new SequentialImpulseSolver();
        var world = new World(Scenes.EarthGravity, solver) { SleepingEnabled = false };
        world.AddPlane(StaticPlane.Ground(floor));
        float lowerY = floor + radius - 0.4f * solver.Slop; // resting on the ground within the slop
        float ulp = MathF.BitIncrement(lowerY) - lowerY;
        float upperY = lowerY + 2 * radius - 2 * solver.Slop;
        while (2 * radius - (upperY - lowerY) > solver.Slop + 0.5f * ulp)
        {
            upperY = MathF.BitIncrement(upperY); // one unit in the last place shallower
        }

        float depth = 2 * radius - (upperY - lowerY);
        Assert.True(depth > 1.001f * solver.Slop, $"the pair is placed {depth} m deep, within 1.001 × the slop");
        float mass = MathF.PI * radius * radius * 1000f;
        RigidBody lower = world.Add(new RigidBody(mass, radius, new Vector3(0, lowerY, 0), Inertia.Disc(mass, radius)));
        RigidBody upper = world.Add(new RigidBody(mass, radius, new Vector3(0, upperY, 0), Inertia.Disc(mass, radius)));

        long visits = 0;
        for (int step = 0; step < Steps; step++)
        {
            world.Step(1f / 60f);
            visits += solver.ResidualVisitsThisStep;
        }

        float endDepth = 2 * radius - Vector3.Distance(lower.Position, upper.Position);
        _output.WriteLine($"placed {depth * 1e3:F4} mm deep (slop {solver.Slop * 1e3:F1} mm, unit in the last place {ulp * 1e6:F1} µm)");
        _output.WriteLine($"after {Steps} steps: {endDepth * 1e3:F4} mm deep, {visits} contacts queued");
        Assert.Equal(0, visits);
        Assert.Equal(new Vector3(0, upperY, 0), upper.Position);
        Assert.Equal(new Vector3(0, lowerY, 0), lower.Position);
    }
}
