using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Tests.Solver;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Behavior;

/// <summary>
/// A quiet pile's substeps predict only the contacts that can come near their depth limits, sorted once and kept from
/// step to step (ImpactStepper.Quiet.cs): every body must move exactly as when every contact is predicted in every
/// substep, while the pile lands, while it rests, when a ball dropped onto it sets off impacts, and when the user moves,
/// resizes, replaces and walls in bodies between steps.
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
        world.CheckQuietSubsteps = true;
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
        Assert.Equal(0, world.UnpredictedNearLimits);
        Assert.True(quiet > 300, $"only {quiet} quiet substeps: the pile never counted as quiet");
        Assert.True(impactsAfterDrop > 0, "the dropped ball set off no impacts");
    }

    [Theory]
    [InlineData(true, 400)]
    [InlineData(false, 216)]
    public void Changes_the_user_makes_between_quiet_steps_are_seen(bool planar, int count)
    {
        World world = Pit(planar, count), reference = Pit(planar, count);
        reference.PredictQuietly = false;
        world.CheckQuietSubsteps = true;
        int fullyQuiet = 0;
        bool grewIntoNeighbour = false;
        var random = new Random(11);
        for (int step = 1; step <= 480; step++)
        {
            if (step > 240 && step % 3 == 0)
            {
                int kind = random.Next(5), pick = random.Next(1 << 20);
                Vector3 nudge = 1e-4f * new Vector3(Signed(random), Signed(random), planar ? 0f : Signed(random)); // up to 0.1 mm
                float grow = 1f + 2e-3f * Signed(random); // up to 0.2 %
                Change(world, kind, pick, nudge, grow, planar);
                Change(reference, kind, pick, nudge, grow, planar);
            }

            if (step == 400)
            {
                // A wall that the body nearest the left one just touches: new contacts, none of them sorted.
                float touching = LeftmostSurface(world);
                world.AddPlane(new StaticPlane(Vector3.UnitX, new Vector3(touching, 0, 0)));
                reference.AddPlane(new StaticPlane(Vector3.UnitX, new Vector3(touching, 0, 0)));
            }

            if (step == 450 && PairApart(world) is (int grown, float gap))
            {
                // A body grown until it just touches a neighbour it was apart from, in place.
                world.Bodies[grown].Radius += gap - 2e-6f;
                reference.Bodies[grown].Radius += gap - 2e-6f;
                grewIntoNeighbour = true;
            }

            world.Step(Dt);
            reference.Step(Dt);
            fullyQuiet += world.QuietSubsteps == world.Substeps ? 1 : 0;
            if (WorldMeasure.FirstDifference(reference, world) is string difference)
            {
                Assert.Fail($"step {step}: {difference}");
            }
        }

        _output.WriteLine($"{fullyQuiet} of 480 steps quiet in every substep");
        Assert.True(grewIntoNeighbour, "no body was 0.2–1 mm from a neighbour at step 450 to grow into it");
        Assert.Equal(0, world.UnpredictedNearLimits);
        Assert.True(fullyQuiet > 100, $"only {fullyQuiet} steps were quiet from their first substep: the sorting was not kept");
    }

    /// <summary>A settled-to-be pit with three static balls on its floor.</summary>
    private static World Pit(bool planar, int count)
    {
        World world = Scenes.BallPit(count, planar, seed: 3, radiusSpread: 1.5f);
        world.SleepingEnabled = false;
        for (int s = 0; s < 3; s++)
        {
            world.Add(RigidBody.CreateStatic(0.08f, new Vector3(0.4f + 0.6f * s, 0.08f, planar ? 0f : 0.5f)));
        }

        return world;
    }

    /// <summary>A moving body and its gap to a neighbour 0.2–1 mm apart, if there is one.</summary>
    private static (int Body, float Gap)? PairApart(World world)
    {
        for (int i = 0; i < world.Bodies.Count; i++)
        {
            for (int j = 0; j < world.Bodies.Count; j++)
            {
                RigidBody a = world.Bodies[i], b = world.Bodies[j];
                float gap = Vector3.Distance(a.Position, b.Position) - a.Radius - b.Radius;
                if (i != j && a.Type != BodyType.Static && gap > 2e-4f && gap < 1e-3f)
                {
                    return (i, gap);
                }
            }
        }

        return null;
    }

    private static float LeftmostSurface(World world)
    {
        float left = float.PositiveInfinity;
        foreach (RigidBody body in world.Bodies)
        {
            left = MathF.Min(left, body.Position.X - body.Radius);
        }

        return left;
    }

    private static float Signed(Random random) => 2f * (float)random.NextDouble() - 1f;

    /// <summary>
    /// One change between steps, the same in both worlds: 0 moves a moving body a little, 1 resizes one, 2 moves a
    /// static ball, 3 removes a body and adds one like it a little aside (as many bodies, another order), 4 nothing.
    /// </summary>
    private static void Change(World world, int kind, int pick, Vector3 nudge, float grow, bool planar)
    {
        RigidBody body = world.Bodies[pick % world.Bodies.Count];
        switch (kind)
        {
            case 0 when body.Type != BodyType.Static:
                body.Position += nudge;
                break;
            case 1 when body.Type != BodyType.Static:
                body.Radius *= grow;
                break;
            case 2:
                foreach (RigidBody ball in world.Bodies)
                {
                    if (ball.Type == BodyType.Static)
                    {
                        ball.Position += nudge;
                        break;
                    }
                }

                break;
            case 3 when body.Type != BodyType.Static:
                world.Remove(body);
                float mass = body.Mass, radius = body.Radius;
                world.Add(new RigidBody(mass, radius, body.Position + nudge, planar ? Inertia.Disc(mass, radius) : Inertia.SolidSphere(mass, radius))
                {
                    LinearVelocity = body.LinearVelocity,
                });
                break;
        }
    }

    /// <summary>A 5 kg ball 1 m above the highest body's centre.</summary>
    internal static RigidBody DroppedBall(World world, bool planar)
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
