using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;

namespace SimpleDynamics.Tests.Game;

/// <summary>
/// Sleeping: islands at rest fall asleep, stay exactly where they are, cost nothing per step, and wake, whole, when
/// something reaches them; elsewhere nothing changes.
/// </summary>
public class SleepingTests
{
    private const float Dt = 1f / 60f;
    private const float Radius = 0.5f;

    /// <summary>
    /// A 2-D pyramid of discs (4, 3, 2, 1) resting on the ground with its left end at <paramref name="left"/>, its
    /// bottom row held between two static chocks (a pyramid of discs on a flat floor would roll apart).
    /// </summary>
    private static RigidBody[] Heap(World world, float left)
    {
        var heap = new List<RigidBody>();
        float rise = MathF.Sqrt(3) * Radius;
        world.Add(RigidBody.CreateStatic(Radius, new Vector3(left - Radius, Radius, 0)));
        world.Add(RigidBody.CreateStatic(Radius, new Vector3(left + 9 * Radius, Radius, 0)));
        for (int row = 0; row < 4; row++)
        for (int i = 0; i < 4 - row; i++)
        {
            var position = new Vector3(left + Radius + (2 * i + row) * Radius, Radius + row * rise, 0);
            heap.Add(world.Add(new RigidBody(1f, Radius, position, Inertia.Disc(1f, Radius))));
        }

        return heap.ToArray();
    }

    /// <summary>Two heaps 20 m apart on the ground, with friction enough to hold them.</summary>
    private static World TwoHeaps(out RigidBody[] left, out RigidBody[] right)
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        world.AddPlane(new StaticPlane(Vector3.UnitY, Vector3.Zero, restitution: 0f, friction: 1f));
        left = Heap(world, 0f);
        right = Heap(world, 20f);
        foreach (RigidBody body in world.Bodies)
        {
            body.Friction = 1f;
        }

        return world;
    }

    /// <summary>
    /// Steps until the <paramref name="dynamic"/> dynamic bodies sleep (static and kinematic bodies never do); fails
    /// after <paramref name="seconds"/>. Allocates nothing.
    /// </summary>
    private static void StepUntilAsleep(World world, int dynamic = 20, float seconds = 5f)
    {
        for (int i = 0; i < seconds / Dt; i++)
        {
            world.Step(Dt);
            if (world.SleepingBodyCount == dynamic)
            {
                return;
            }
        }

        Assert.Fail($"{world.SleepingBodyCount} of {dynamic} dynamic bodies asleep after {seconds} s");
    }

    /// <summary>
    /// Drops a ball onto the sleeping <paramref name="heap"/> and steps 2 s: the whole heap must wake, and the
    /// <paramref name="far"/> one must sleep on throughout. Returns the ball.
    /// </summary>
    private static RigidBody DropBallAndWatch(World world, RigidBody[] heap, RigidBody[] far)
    {
        RigidBody ball = world.Add(new RigidBody(1f, Radius, heap[9].Position + new Vector3(0, 3, 0), Inertia.Disc(1f, Radius)));
        bool heapWoke = false;
        for (int i = 0; i < 120; i++)
        {
            world.Step(Dt);
            heapWoke |= heap.All(b => b.IsAwake);
            Assert.All(far, b => Assert.False(b.IsAwake));
        }

        Assert.True(heapWoke, "the heap the ball fell on woke, all of it");
        return ball;
    }

    [Fact]
    public void Sleeping_is_on_by_default_with_the_thresholds_of_Box2D()
    {
        var world = new World();
        Assert.True(world.SleepingEnabled);
        Assert.Equal(0.05f, world.SleepSpeed);
        Assert.Equal(0.5f, world.TimeToSleep);
        Assert.True(new RigidBody(1f, 1f, Vector3.Zero).IsAwake);
    }

    [Fact]
    public void A_settled_pile_falls_asleep_and_stays_put_bit_for_bit()
    {
        World world = TwoHeaps(out RigidBody[] left, out _);
        StepUntilAsleep(world);
        Assert.All(world.Bodies.Where(b => b.IsDynamic), b => Assert.False(b.IsAwake));
        Vector3[] positions = world.Bodies.Select(b => b.Position).ToArray();
        Quaternion[] orientations = world.Bodies.Select(b => b.Orientation).ToArray();

        for (int i = 0; i < 300; i++)
        {
            world.Step(Dt);
        }

        Assert.Equal(20, world.SleepingBodyCount);
        Assert.Equal(positions, world.Bodies.Select(b => b.Position).ToArray());
        Assert.Equal(orientations, world.Bodies.Select(b => b.Orientation).ToArray());
        Assert.All(world.Bodies, b => Assert.Equal(Vector3.Zero, b.LinearVelocity));
        Assert.Equal(0, world.Collisions.Count); // sleeping bodies are not even detected
        Assert.Equal(4, world.AwakeSpan.Length); // the chocks: static bodies never sleep
        Assert.True(left[0].Position.Y > 0.49f && left[9].Position.Y > 2.9f, "the heap still stands");
    }

    [Fact]
    public void A_ball_dropped_onto_one_heap_wakes_it_and_not_the_heap_far_away()
    {
        World world = TwoHeaps(out RigidBody[] left, out RigidBody[] right);
        StepUntilAsleep(world);
        Vector3[] farPositions = right.Select(b => b.Position).ToArray();
        RigidBody ball = DropBallAndWatch(world, left, right);
        Assert.Equal(farPositions, right.Select(b => b.Position).ToArray());
        Assert.True(ball.Position.Y > left[9].Position.Y, "the ball landed on the heap, not through it");
    }

    [Fact]
    public void TrimExcess_keeps_each_sleeping_island_whole_after_a_crowd_has_come_and_gone()
    {
        World world = TwoHeaps(out RigidBody[] left, out RigidBody[] right);
        StepUntilAsleep(world);
        // A crowd of 300 far away grows the sleeping arrays with the world; removed and trimmed, they shrink back.
        var crowd = new RigidBody[300];
        for (int i = 0; i < crowd.Length; i++)
        {
            crowd[i] = world.Add(new RigidBody(1f, 0.1f, new Vector3(100 + 0.3f * i, 50, 0)));
        }

        world.Step(Dt);
        foreach (RigidBody body in crowd)
        {
            world.Remove(body);
        }

        world.TrimExcess();
        Assert.Equal(20, world.SleepingBodyCount);

        DropBallAndWatch(world, left, right);
        right[0].Wake();
        Assert.All(right, b => Assert.True(b.IsAwake));
    }

    public static TheoryData<string> WakeTriggers => new()
    {
        "ApplyImpulse", "ApplyForce", "ApplyForceAtPoint", "ApplyTorque", "Position", "LinearVelocity",
        "AngularVelocity", "Orientation", "SetMass", "Radius", "Filter", "Wake", "AllowSleep",
    };

    [Theory]
    [MemberData(nameof(WakeTriggers))]
    public void Each_wake_trigger_wakes_the_whole_island_and_nothing_else(string trigger)
    {
        World world = TwoHeaps(out RigidBody[] left, out RigidBody[] right);
        StepUntilAsleep(world);
        RigidBody top = left[9];
        switch (trigger)
        {
            case "ApplyImpulse": top.ApplyImpulse(new Vector3(0.01f, 0, 0), top.Position); break;
            case "ApplyForce": top.ApplyForce(new Vector3(0.01f, 0, 0)); break;
            case "ApplyForceAtPoint": top.ApplyForce(new Vector3(0.01f, 0, 0), top.Position + Vector3.UnitY); break;
            case "ApplyTorque": top.ApplyTorque(new Vector3(0, 0, 0.01f)); break;
            case "Position": top.Position += new Vector3(0, 0.01f, 0); break;
            case "LinearVelocity": top.LinearVelocity = new Vector3(0.01f, 0, 0); break;
            case "AngularVelocity": top.AngularVelocity = new Vector3(0, 0, 0.01f); break;
            case "Orientation": top.Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.1f); break;
            case "SetMass": top.SetMass(2f, Inertia.Disc(2f, Radius)); break;
            case "Radius": top.Radius = 0.49f; break;
            case "Filter": top.Filter = new CollisionFilter(2, 0xFFFF_FFFF); break;
            case "Wake": top.Wake(); break;
            case "AllowSleep": top.AllowSleep = false; break;
        }

        Assert.All(left, b => Assert.True(b.IsAwake, $"{trigger}: body #{b.Id} of the touched heap"));
        Assert.All(right, b => Assert.False(b.IsAwake, $"{trigger}: body #{b.Id} of the heap far away"));
        Assert.Equal(right.Length, world.SleepingBodyCount);
        world.Step(Dt);
        Assert.True(world.Collisions.Count >= 13, $"{trigger}: the woken heap's contacts are detected again ({world.Collisions.Count})");
    }

    [Fact]
    public void A_body_that_may_not_sleep_keeps_its_island_awake()
    {
        World world = TwoHeaps(out RigidBody[] left, out RigidBody[] right);
        left[0].AllowSleep = false;
        for (int i = 0; i < 180; i++)
        {
            world.Step(Dt);
        }

        Assert.All(left, b => Assert.True(b.IsAwake));
        Assert.All(right, b => Assert.False(b.IsAwake));
    }

    [Fact]
    public void A_moving_kinematic_body_that_reaches_a_sleeping_heap_wakes_it_and_pushes_it()
    {
        World world = TwoHeaps(out RigidBody[] left, out RigidBody[] right);
        StepUntilAsleep(world);
        // A paddle sweeping from the left at the height of the heap's top disc.
        world.Add(RigidBody.CreateKinematic(Radius, new Vector3(-1f, left[9].Position.Y, 0), new Vector3(1, 0, 0)));
        float before = left[9].Position.X;
        for (int i = 0; i < 180; i++)
        {
            world.Step(Dt);
        }

        Assert.True(left[0].IsAwake, "the heap the paddle reached woke, all of it");
        Assert.True(left[9].Position.X > before + 0.2f, $"pushed from {before} to {left[9].Position.X}");
        Assert.All(right, b => Assert.False(b.IsAwake));
    }

    /// <summary>
    /// Waking at the start of a step looks only as far as each body's speed then reaches. Here a light ball lies 5 cm
    /// from a sleeping disc, and a heavy ball strikes it at 6 m/s early in a step, sending it at about 9 m/s across
    /// the gap within the same step: the impact pass looks the ball up again along its new path, finds the sleeper,
    /// wakes it and answers the collision (before, the ball ended the step 9 cm inside the sleeping disc, which woke
    /// only a step later).
    /// </summary>
    [Fact]
    public void A_ball_knocked_into_a_sleeping_body_within_a_step_wakes_it_and_does_not_pass_into_it()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        world.AddPlane(new StaticPlane(Vector3.UnitY, Vector3.Zero));
        RigidBody sleeper = world.Add(new RigidBody(10f, Radius, new Vector3(0, Radius, 0), Inertia.Disc(10f, Radius)));
        StepUntilAsleep(world, dynamic: 1);
        RigidBody light = world.Add(new RigidBody(0.1f, 0.1f, new Vector3(Radius + 0.15f, Radius, 0), Inertia.Disc(0.1f, 0.1f)));
        RigidBody heavy = world.Add(new RigidBody(10f, 0.1f, new Vector3(Radius + 0.355f, Radius, 0), Inertia.Disc(10f, 0.1f)));
        heavy.LinearVelocity = new Vector3(-6f, 0, 0);
        RigidBody[] bodies = [sleeper, light, heavy];
        float slop = ((Response.SequentialImpulseSolver)world.Responder).Slop;

        for (int step = 0; step < 60; step++)
        {
            world.Step(Dt);
            for (int i = 0; i < bodies.Length; i++)
            {
                for (int j = i + 1; j < bodies.Length; j++)
                {
                    float overlap = bodies[i].Radius + bodies[j].Radius - Vector3.Distance(bodies[i].Position, bodies[j].Position);
                    Assert.True(overlap <= slop + 1e-5f, $"step {step}: bodies {i} and {j} overlap by {overlap} m");
                }
            }

            if (step == 0)
            {
                Assert.True(light.LinearVelocity.X < -1f, $"the light ball was struck: {light.LinearVelocity}");
                Assert.True(sleeper.IsAwake, "the sleeper in the light ball's new path woke within the step");
            }
        }

        Assert.True(sleeper.Position.X < -0.05f, $"the balls pushed the woken disc along: it is at {sleeper.Position}");
    }

    [Fact]
    public void A_kinematic_body_at_rest_holds_an_island_and_one_that_moves_keeps_it_awake()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        RigidBody platform = world.Add(RigidBody.CreateKinematic(1f, Vector3.Zero, Vector3.Zero));
        RigidBody ball = world.Add(new RigidBody(1f, Radius, new Vector3(0, 1 + Radius, 0)));
        StepUntilAsleep(world, dynamic: 1);

        platform.LinearVelocity = new Vector3(0, 0.5f, 0); // a lift starts: it wakes what rests on it at the next step
        world.Step(Dt);
        Assert.True(ball.IsAwake);
        for (int i = 0; i < 120; i++)
        {
            world.Step(Dt);
            Assert.True(ball.IsAwake, $"step {i}: a ball riding a moving lift must not sleep");
        }

        Assert.True(ball.Position.Y > 1 + Radius + 0.9f, $"the ball rode the lift up to {ball.Position.Y}");
    }

    [Fact]
    public void Removing_the_static_body_a_heap_rests_on_wakes_the_heap()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        RigidBody post = world.Add(RigidBody.CreateStatic(1f, Vector3.Zero));
        RigidBody ball = world.Add(new RigidBody(1f, Radius, new Vector3(0, 1 + Radius, 0)));
        StepUntilAsleep(world, dynamic: 1);
        Assert.False(ball.IsAwake);

        world.Remove(post);
        Assert.True(ball.IsAwake);
        world.Step(Dt);
        Assert.True(ball.LinearVelocity.Y < 0, "with its support gone the ball falls");
    }

    [Fact]
    public void With_sleeping_off_nothing_ever_sleeps_and_turning_it_off_wakes_everything()
    {
        World world = TwoHeaps(out _, out _);
        world.SleepingEnabled = false;
        for (int i = 0; i < 300; i++)
        {
            world.Step(Dt);
            Assert.Equal(0, world.SleepingBodyCount);
        }

        Assert.All(world.Bodies, b => Assert.True(b.IsAwake));

        world.SleepingEnabled = true;
        StepUntilAsleep(world);
        world.SleepingEnabled = false;
        Assert.Equal(0, world.SleepingBodyCount);
        Assert.All(world.Bodies, b => Assert.True(b.IsAwake));
    }

    [Fact]
    public void Bodies_drifting_slowly_in_free_space_never_sleep_and_keep_their_momentum()
    {
        // Only an island resting on something fixed sleeps: the laws of free space hold with sleeping on.
        var world = new World(Vector3.Zero);
        RigidBody a = world.Add(new RigidBody(1f, Radius, Vector3.Zero) { LinearVelocity = new Vector3(0.01f, 0, 0) });
        RigidBody b = world.Add(new RigidBody(2f, Radius, new Vector3(1, 0, 0)) { LinearVelocity = new Vector3(0.01f, 0, 0) });
        Vector3 momentum = world.Diagnostics.LinearMomentum;
        for (int i = 0; i < 300; i++)
        {
            world.Step(Dt);
        }

        Assert.True(a.IsAwake && b.IsAwake);
        Assert.Equal(momentum, world.Diagnostics.LinearMomentum);
    }

    [Fact]
    public void Touching_pairs_neither_end_when_a_heap_falls_asleep_nor_begin_when_it_wakes()
    {
        World world = TwoHeaps(out RigidBody[] left, out _);
        var touching = new HashSet<(int, int)>();
        int sleepStep = -1;
        int touchingBeforeSleep = 0;
        void StepAndCount(int i)
        {
            int asleepBefore = world.SleepingBodyCount;
            int touchingBefore = world.ContactEvents.Touching.Length;
            world.Step(Dt);
            foreach (ContactEvent e in world.ContactEvents.EndTouch)
            {
                Assert.True(touching.Remove(Pairs.Key(e)), $"step {i}: an end without a begin");
            }

            foreach (ContactEvent e in world.ContactEvents.BeginTouch)
            {
                Assert.True(touching.Add(Pairs.Key(e)), $"step {i}: a begin of a pair already touching");
            }

            Assert.Equal(touching.Count, world.ContactEvents.Touching.Length);
            Assert.Equal(touching, world.ContactEvents.Touching.ToArray().Select(Pairs.Key).ToHashSet());
            if (asleepBefore == 0 && world.SleepingBodyCount > 0)
            {
                sleepStep = i;
                touchingBeforeSleep = touchingBefore;
                Assert.Equal(0, world.ContactEvents.EndTouch.Length);
            }
        }

        int step = 0;
        for (; step < 300 && world.SleepingBodyCount < 20; step++)
        {
            StepAndCount(step);
        }

        Assert.True(sleepStep > 0, "the heaps fell asleep");
        Assert.True(touchingBeforeSleep >= 2 * 13, $"{touchingBeforeSleep} pairs touched as the heaps fell asleep");
        Assert.Equal(touchingBeforeSleep, world.ContactEvents.Touching.Length);

        // Asleep: the pairs stay touching, and each body still lists its contacts.
        var contacts = new Contact[8];
        Assert.Equal(4, world.ContactsOf(left[4], contacts)); // the second row's first disc: two below, one beside, one above
        Assert.All(contacts.Take(4), c => Assert.True(c.BodyA == left[4] || c.BodyB == left[4]));
        for (int i = 0; i < 30; i++, step++)
        {
            StepAndCount(step);
            Assert.Equal(0, world.ContactEvents.BeginTouch.Length + world.ContactEvents.EndTouch.Length);
        }

        // Woken by a nudge too small to part anything: no pair begins again.
        left[9].ApplyImpulse(new Vector3(0.001f, 0, 0), left[9].Position);
        Assert.Equal(4, world.ContactsOf(left[4], contacts));
        StepAndCount(step++);
        Assert.Equal(0, world.ContactEvents.BeginTouch.Length);
        Assert.Equal(4, world.ContactsOf(left[4], contacts));
        for (int i = 0; i < 120; i++, step++)
        {
            StepAndCount(step);
        }
    }

    [Fact]
    public void Removing_a_sleeping_body_ends_its_touches_and_wakes_its_island()
    {
        World world = TwoHeaps(out RigidBody[] left, out RigidBody[] right);
        StepUntilAsleep(world);
        int touching = world.ContactEvents.Touching.Length;
        world.Remove(left[9]); // the top of the left heap: it touches the two discs below it
        Assert.All(left.Take(9), b => Assert.True(b.IsAwake));
        Assert.All(right, b => Assert.False(b.IsAwake));
        world.Step(Dt);
        Assert.Equal(2, world.ContactEvents.EndTouch.Length);
        Assert.All(world.ContactEvents.EndTouch.ToArray(), e => Assert.True(e.Involves(left[9])));
        Assert.Equal(touching - 2, world.ContactEvents.Touching.Length);
    }

    [Fact]
    public void A_sleeping_world_steps_without_allocating()
    {
        World world = TwoHeaps(out RigidBody[] left, out _);
        StepUntilAsleep(world);

        // Wake and sleep again twice, with a step asleep in between, so that every buffer of the cycle has grown
        // to its largest once (a warm world); after that sleeping, waking and sleeping steps allocate nothing.
        for (int cycle = 0; cycle < 2; cycle++)
        {
            world.Step(Dt);
            left[9].Wake();
            StepUntilAsleep(world);
        }

        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            world.Step(Dt);
        }

        left[9].Wake();
        StepUntilAsleep(world);
        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    [Fact]
    public void Settings_are_validated_and_name_their_property()
    {
        var world = new World();
        foreach (float bad in new[] { -1f, float.NaN, float.PositiveInfinity })
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => world.SleepSpeed = bad);
            Assert.Equal(nameof(World.SleepSpeed), e.ParamName);
        }

        foreach (float bad in new[] { 0f, -1f, float.NaN, float.PositiveInfinity })
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => world.TimeToSleep = bad);
            Assert.Equal(nameof(World.TimeToSleep), e.ParamName);
        }

        Assert.Equal(0.05f, world.SleepSpeed);
        Assert.Equal(0.5f, world.TimeToSleep);
        world.SleepSpeed = 0f;
        world.TimeToSleep = 2f;
        Assert.Equal(0f, world.SleepSpeed);
        Assert.Equal(2f, world.TimeToSleep);
    }

    [Fact]
    public void A_longer_time_to_sleep_delays_sleep_and_a_zero_speed_threshold_prevents_it()
    {
        World quick = TwoHeaps(out _, out _);
        World slow = TwoHeaps(out _, out _);
        slow.TimeToSleep = 2f;
        int quickSteps = 0, slowSteps = 0;
        for (; quick.SleepingBodyCount < 20 && quickSteps < 600; quickSteps++)
        {
            quick.Step(Dt);
        }

        for (; slow.SleepingBodyCount < 20 && slowSteps < 600; slowSteps++)
        {
            slow.Step(Dt);
        }

        Assert.True(slowSteps >= quickSteps + 1.5f / Dt - 1, $"asleep after {quickSteps} steps (0.5 s) and {slowSteps} steps (2 s)");

        World never = TwoHeaps(out _, out _);
        never.SleepSpeed = 0f;
        for (int i = 0; i < 300; i++)
        {
            never.Step(Dt);
        }

        Assert.True(never.SleepingBodyCount < 20, "with a zero threshold only bodies exactly at rest may sleep");
    }
}
