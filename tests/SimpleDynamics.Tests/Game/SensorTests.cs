using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Tests.Properties;
using Xunit;

namespace SimpleDynamics.Tests.Game;

/// <summary>Sensors: no impulses either way, overlap begin/end events instead.</summary>
public class SensorTests
{
    [Fact]
    public void A_ball_falls_through_a_static_sensor_untouched_and_enters_and_leaves_it_once()
    {
        const float dt = 1f / 60f;
        var world = new World(new Vector3(0, -9.81f, 0));
        RigidBody sensor = world.Add(RigidBody.CreateStatic(1f, new Vector3(0, 0, 0)));
        sensor.IsSensor = true;
        RigidBody ball = world.Add(new RigidBody(1f, 0.25f, new Vector3(0.3f, 3, 0)));
        var entered = new List<(int Step, SensorEvent Event)>();
        var left = new List<(int Step, SensorEvent Event)>();
        for (int step = 0; step < 90; step++)
        {
            world.Step(dt);
            Assert.Equal(0, world.Collisions.Count);
            entered.AddRange(world.ContactEvents.SensorBegin.ToArray().Select(e => (step, e)));
            left.AddRange(world.ContactEvents.SensorEnd.ToArray().Select(e => (step, e)));
            bool inside = Vector3.Distance(ball.Position, sensor.Position) < 1.25f;
            Assert.Equal(inside ? 1 : 0, world.ContactEvents.SensorOverlaps.Length);
        }

        (int stepIn, SensorEvent begin) = Assert.Single(entered);
        (int stepOut, SensorEvent end) = Assert.Single(left);
        Assert.Equal(sensor, begin.Sensor);
        Assert.Equal(ball, begin.Visitor);
        Assert.Equal(ball, end.Visitor);
        Assert.True(stepOut > stepIn);
        // Free fall all the way: the sensor pushed nothing.
        float t = 90 * dt;
        Assert.InRange(ball.LinearVelocity.Y, -9.81f * t - 0.01f, -9.81f * t + 0.01f);
        Assert.Equal(0.3f, ball.Position.X);
    }

    [Fact]
    public void A_dynamic_sensor_falls_through_the_ground_and_through_bodies()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        world.AddPlane(StaticPlane.Ground());
        RigidBody block = world.Add(RigidBody.CreateStatic(0.5f, new Vector3(0, 1, 0)));
        RigidBody sensor = world.Add(new RigidBody(1f, 0.25f, new Vector3(0, 3, 0)) { IsSensor = true });
        bool sawBlock = false;
        for (int step = 0; step < 120; step++)
        {
            world.Step(1f / 60f);
            Assert.Equal(0, world.Collisions.Count);
            sawBlock |= world.ContactEvents.SensorBegin.ToArray().Any(e => e.Sensor == sensor && e.Visitor == block);
        }

        Assert.True(sawBlock, "the falling sensor should report the static body it passed through");
        Assert.True(sensor.Position.Y < -1, $"it should have fallen through the ground: {sensor.Position}");
    }

    [Fact]
    public void A_sensor_sees_only_bodies_its_filter_accepts_and_never_other_sensors()
    {
        var world = new World(Vector3.Zero);
        RigidBody sensor = world.Add(RigidBody.CreateStatic(2f, Vector3.Zero));
        sensor.IsSensor = true;
        sensor.Filter = new CollisionFilter(category: 0b100, mask: 0b001);
        RigidBody player = world.Add(new RigidBody(1, 0.5f, new Vector3(1, 0, 0)) { Filter = new CollisionFilter(0b001, uint.MaxValue) });
        world.Add(new RigidBody(1, 0.5f, new Vector3(-1, 0, 0)) { Filter = new CollisionFilter(0b010, uint.MaxValue) });
        world.Add(new RigidBody(1, 0.5f, new Vector3(0, 1, 0)) { IsSensor = true });
        world.Step(1f / 60f);
        SensorEvent seen = Assert.Single(world.ContactEvents.SensorBegin.ToArray());
        Assert.Equal(player, seen.Visitor);
    }

    [Fact]
    public void Removing_a_sensor_or_a_visitor_ends_its_overlaps()
    {
        var world = new World(Vector3.Zero);
        RigidBody sensor = world.Add(RigidBody.CreateStatic(2f, Vector3.Zero));
        sensor.IsSensor = true;
        RigidBody a = world.Add(new RigidBody(1, 0.5f, new Vector3(1, 0, 0)));
        RigidBody b = world.Add(new RigidBody(1, 0.5f, new Vector3(-1, 0, 0)));
        world.Step(1f / 60f);
        Assert.Equal(2, world.ContactEvents.SensorBegin.Length);
        world.Remove(a);
        world.Step(1f / 60f);
        Assert.Equal(a, Assert.Single(world.ContactEvents.SensorEnd.ToArray()).Visitor);
        sensor.IsSensor = false; // now it is a plain static body: its overlap with b ends
        world.Step(1f / 60f);
        Assert.Equal(b, Assert.Single(world.ContactEvents.SensorEnd.ToArray()).Visitor);
    }

    /// <summary>Sensor overlaps are exactly the overlapping (sensor, non-sensor) pairs the filters allow, found by brute force.</summary>
    [Fact]
    public void Sensor_overlaps_match_brute_force_and_balance()
    {
        int begins = 0;
        PropertyCheck.Run(GameGenerators.Scene(), scene =>
        {
            World world = scene.Build(out RigidBody[] bodies);
            var open = new HashSet<(int, int)>();
            for (int step = 0; step < 30; step++)
            {
                world.Step(1f / 60f);
                foreach (SensorEvent e in world.ContactEvents.SensorEnd)
                {
                    Law.Holds(open.Remove(Pairs.Key(e)), $"step {step}: sensor end without begin: {e}");
                }

                begins += world.ContactEvents.SensorBegin.Length;
                foreach (SensorEvent e in world.ContactEvents.SensorBegin)
                {
                    Law.Holds(open.Add(Pairs.Key(e)), $"step {step}: sensor begins twice: {e}");
                }

                var expected = new HashSet<(int, int)>();
                foreach (RigidBody s in bodies.Where(b => b.IsSensor))
                foreach (RigidBody v in bodies.Where(b => !b.IsSensor))
                {
                    if (CollisionFilter.ShouldCollide(s.Filter, v.Filter) && Vector3.Distance(s.Position, v.Position) < s.Radius + v.Radius - 1e-5f)
                    {
                        expected.Add((s.Id, v.Id));
                    }
                }

                var reported = world.ContactEvents.SensorOverlaps.ToArray().Select(Pairs.Key).ToHashSet();
                Law.Holds(open.SetEquals(reported), $"step {step}: begins − ends ≠ overlaps");
                Law.Holds(expected.IsSubsetOf(reported), $"step {step}: brute force finds {expected.Count} overlaps, reported {reported.Count}");
                foreach ((int s, int v) in reported)
                {
                    RigidBody sensor = bodies.First(b => b.Id == s), visitor = bodies.First(b => b.Id == v);
                    Law.Holds(Vector3.Distance(sensor.Position, visitor.Position) < sensor.Radius + visitor.Radius + 1e-5f, $"step {step}: {sensor} and {visitor} do not overlap");
                }
            }
        }, seed: 1103, maxTest: 60);
        Assert.True(begins > 20, $"only {begins} sensor begins in all: the scenes test too little");
    }
}
