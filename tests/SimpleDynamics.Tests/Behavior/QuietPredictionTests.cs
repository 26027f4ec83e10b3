using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Tests.Solver;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Behavior;

/// <summary>
/// A quiet pile's later substeps predict only the contacts that can come near their depth limits
/// (ImpactStepper.Quiet.cs): every body must move exactly as when every contact is predicted in every substep, while
/// the pile lands, while it rests, and when a ball dropped onto it sets off impacts.
/// </summary>
public class QuietPredictionTests
{
    private const float Dt = 1f / 60f;
    private readonly ITestOutputHelper _output;

    public QuietPredictionTests(ITestOutputHelper output) => _output = output;

    [Theory]
    [InlineData(true, 400)]
    [InlineData(false, 343)]
    public void Quiet_substeps_move_every_body_as_predicting_every_contact_does(bool planar, int count)
    {
        World world = Scenes.BallPit(count, planar, seed: 5, radiusSpread: 1.5f);
        World reference = Scenes.BallPit(count, planar, seed: 5, radiusSpread: 1.5f);
        reference.PredictQuietly = false;
        world.SleepingEnabled = reference.SleepingEnabled = false;
        long quiet = 0, impactsAfterDrop = 0;
        for (int step = 1; step <= 480; step++)
        {
            if (step == 420)
            {
                // A heavy ball dropped onto the resting pile from 1 m above its top: impacts among calm neighbours.
                world.Add(DroppedBall(world, planar));
                reference.Add(DroppedBall(reference, planar));
            }

            world.Step(Dt);
            reference.Step(Dt);
            quiet += world.QuietSubsteps;
            Assert.Equal(0, reference.QuietSubsteps);
            if (step > 420)
            {
                impactsAfterDrop += world.ImpactCount;
            }

            if (WorldMeasure.FirstDifference(reference, world) is string difference)
            {
                Assert.Fail($"step {step}: {difference}");
            }
        }

        _output.WriteLine($"{quiet} quiet substeps in 480 steps; {impactsAfterDrop} impacts after the drop");
        Assert.True(quiet > 300, $"only {quiet} quiet substeps: the pile never counted as quiet");
        Assert.True(impactsAfterDrop > 0, "the dropped ball set off no impacts");
    }

    private static RigidBody DroppedBall(World world, bool planar)
    {
        float top = 0;
        foreach (RigidBody body in world.Bodies)
        {
            top = MathF.Max(top, body.Position.Y);
        }

        const float radius = 0.15f, mass = 5f;
        return new RigidBody(mass, radius, new Vector3(0.05f, top + 1f, 0), planar ? Inertia.Disc(mass, radius) : Inertia.SolidSphere(mass, radius));
    }
}
