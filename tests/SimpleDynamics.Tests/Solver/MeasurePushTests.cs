using System;
using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using SimpleDynamics.Tests.Behavior;
using SimpleDynamics.Tests.Properties;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The solver's measure solves a contact that is apart by less than the slop if it was pushed: in the last substep, or
/// by an impact of this step. It reads the contacts' impulses for that only once something may have pushed one (an
/// impact, a jam, or a detector that hands over contacts with an impulse): a world must step exactly as when it reads
/// them every time, every body, every step, every bit.
/// </summary>
public class MeasurePushTests
{
    private const float Dt = 1f / 60f;
    private readonly ITestOutputHelper _output;

    public MeasurePushTests(ITestOutputHelper output) => _output = output;

    /// <summary>A pour of mixed sizes and materials, with a heavy ball dropped into it, on one thread or in strips on two.</summary>
    private sealed record Pour(int Count, bool Planar, int Seed, float RadiusSpread, float Friction, float Restitution, bool Obstacles, int Threads, int DropAt)
    {
        public override string ToString() =>
            $"{Count} {(Planar ? "discs" : "spheres")}, seed {Seed}, radius spread {RadiusSpread:R}, μ {Friction:R}, ε {Restitution:R}, obstacles {Obstacles}, {Threads} thread(s), ball dropped at step {DropAt}";
    }

    private static Gen<Pour> Pours { get; } =
        from planar in Gen.Elements(true, false)
        from count in Gen.Choose(60, planar ? 300 : 200)
        from seed in Gen.Choose(0, 1_000_000)
        from spread in Gen.Elements(1f, 1.5f, 3f)
        from friction in Gen.OneOf(Gen.Elements(0f, 0.3f, 1f), Generators.UniformF(0, 1))
        from restitution in Gen.OneOf(Gen.Elements(0f, 0.5f, 1f), Generators.UniformF(0, 1))
        from obstacles in Gen.Elements(true, false)
        from threads in Gen.Elements(1, 2)
        from dropAt in Gen.Choose(60, 150)
        select new Pour(count, planar, seed, spread, friction, restitution, obstacles, threads, dropAt);

    [Fact]
    public void Reading_the_impulses_only_once_something_pushed_steps_every_world_bit_for_bit_alike()
    {
        int unpushedSteps = 0, pushedSteps = 0;
        PropertyCheck.Run(Pours, pour =>
        {
            World world = Build(pour, readsEveryPush: false), reference = Build(pour, readsEveryPush: true);
            try
            {
                for (int step = 1; step <= pour.DropAt + 45; step++)
                {
                    if (step == pour.DropAt)
                    {
                        world.Add(QuietPredictionTests.DroppedBall(world, pour.Planar));
                        reference.Add(QuietPredictionTests.DroppedBall(reference, pour.Planar));
                    }

                    world.Step(Dt);
                    reference.Step(Dt);
                    if (world.ImpactCount > 0)
                    {
                        pushedSteps++;
                    }
                    else
                    {
                        unpushedSteps++;
                    }

                    string? difference = WorldMeasure.FirstDifference(reference, world);
                    Law.Holds(difference is null, $"{pour}: step {step}: {difference}");
                }
            }
            finally
            {
                world.ThreadCount = reference.ThreadCount = 1;
            }
        }, seed: 3007, maxTest: 8);

        _output.WriteLine($"{pushedSteps} steps with impacts, {unpushedSteps} without");
        Assert.True(pushedSteps > 100 && unpushedSteps > 100, $"{pushedSteps} steps with impacts, {unpushedSteps} without: the pours test too little");
    }

    /// <summary>A detector of the user's may hand over contacts that already carry a normal impulse: those are read too.</summary>
    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Contacts_a_detector_hands_over_with_an_impulse_are_read_as_pushed(bool planar)
    {
        World world = Pit(planar, readsEveryPush: false), reference = Pit(planar, readsEveryPush: true);
        for (int step = 1; step <= 240; step++)
        {
            world.Step(Dt);
            reference.Step(Dt);
            if (WorldMeasure.FirstDifference(reference, world) is string difference)
            {
                Assert.Fail($"step {step}: {difference}");
            }
        }
    }

    private static World Build(Pour pour, bool readsEveryPush)
    {
        var solver = new SequentialImpulseSolver(pour.Restitution, pour.Friction) { Strips = pour.Threads, ReadsEveryPush = readsEveryPush };
        solver.Cut.ContactsPerStrip = 64; // so that a small pit is cut
        World world = Scenes.BallPit(pour.Count, pour.Planar, seed: pour.Seed, radiusSpread: pour.RadiusSpread, responder: solver);
        world.SleepingEnabled = false;
        if (pour.Obstacles && pour.Planar)
        {
            PitObstacles.AddPostAndPaddle(world);
        }

        world.ThreadCount = pour.Threads;
        return world;
    }

    private static World Pit(bool planar, bool readsEveryPush)
    {
        var solver = new SequentialImpulseSolver { ReadsEveryPush = readsEveryPush };
        World world = Scenes.BallPit(planar ? 200 : 125, planar, seed: 9, radiusSpread: 1.5f, responder: solver);
        world.Detector = new PushingDetector();
        world.SleepingEnabled = false;
        return world;
    }

    /// <summary>The spatial hash's contacts, every third one handed over with a small normal impulse.</summary>
    private sealed class PushingDetector : ICollisionDetector
    {
        private readonly SpatialHashDetector _inner = new();

        public void FindContacts(ReadOnlySpan<RigidBody> bodies, CollisionData collisions, float margin = 0f, float lookahead = 0f)
        {
            int first = collisions.Count;
            _inner.FindContacts(bodies, collisions, margin, lookahead);
            Span<Contact> found = collisions.Contacts;
            for (int k = first; k < found.Length; k += 3)
            {
                found[k].NormalImpulse = 1e-6f;
            }
        }
    }
}
