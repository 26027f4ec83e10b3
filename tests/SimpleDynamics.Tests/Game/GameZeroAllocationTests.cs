using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Game;

/// <summary>
/// Events, sensors, filters and queries keep a warm world allocation-free (the pattern of
/// Api/ZeroAllocationTests: bytes allocated on this thread, where the whole step runs).
/// </summary>
public class GameZeroAllocationTests
{
    private readonly ITestOutputHelper _output;

    public GameZeroAllocationTests(ITestOutputHelper output) => _output = output;

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void A_warm_pile_with_events_sensors_filters_and_queries_allocates_nothing(bool planar)
    {
        World world = Scenes.BallPit(1000, planar, seed: 4);
        world.SleepingEnabled = false; // the pile must stay awake to make events; sleeping's own allocations: SleepingTests
        world.HitSpeedThreshold = 0.1f;
        RigidBody sensor = world.Add(RigidBody.CreateStatic(0.5f, world.Bodies[0].Position));
        sensor.IsSensor = true;
        for (int i = 0; i < world.Bodies.Count; i += 7)
        {
            world.Bodies[i].Filter = new CollisionFilter(2, 0xFFFF_FFFD); // some balls pass through each other
        }

        world.ShouldCollide = (a, b) => true;
        var hits = new RayHit[16];
        var found = new Overlap[64];
        var contacts = new Contact[8];
        int events = 0;
        void StepAndAsk()
        {
            world.Step(1f / 60f);
            events += world.ContactEvents.BeginTouch.Length + world.ContactEvents.EndTouch.Length + world.ContactEvents.Hits.Length
                + world.ContactEvents.SensorBegin.Length + world.ContactEvents.SensorEnd.Length;
            world.RayCastClosest(new Vector3(0, 1, 0.5f), new Vector3(10, 0, 0), out _);
            world.RayCastAll(new Vector3(0, 0.5f, 0.5f), new Vector3(10, 0, 0), hits);
            world.QueryPoint(new Vector3(1, 0.1f, 0.5f), found);
            world.OverlapCircle(new Vector3(1, 0.5f, 0.5f), 0.5f, found);
            world.OverlapBox(new Vector3(0, 0, 0), new Vector3(1, 1, 1), found);
            world.ContactsOf(world.Bodies[5], contacts);
        }

        for (int i = 0; i < 300; i++)
        {
            StepAndAsk();
        }

        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            StepAndAsk();
        }

        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        _output.WriteLine($"{allocated} bytes over 100 steps, {world.Collisions.Count} contacts, {world.ContactEvents.Touching.Length} touching, {events} events");
        Assert.True(world.ContactEvents.Touching.Length > 1000, "the pile should be touching");
        Assert.Equal(0, allocated);
    }
}
