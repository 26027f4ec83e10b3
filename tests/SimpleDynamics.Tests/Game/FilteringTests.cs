using System;
using System.Linq;
using System.Numerics;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Tests.Properties;
using Xunit;

namespace SimpleDynamics.Tests.Game;

/// <summary>Category, mask and group filters (Box2D's rule) and the world's pair callbacks.</summary>
public class FilteringTests
{
    [Theory]
    [InlineData(1u, 0xFFFFFFFFu, 0, 1u, 0xFFFFFFFFu, 0, true)] // defaults collide
    [InlineData(1u, 2u, 0, 2u, 1u, 0, true)] // each in the other's mask
    [InlineData(1u, 2u, 0, 2u, 4u, 0, false)] // B does not want A
    [InlineData(1u, 0u, 3, 1u, 0u, 3, true)] // same positive group beats the bits
    [InlineData(1u, 0xFFFFFFFFu, -3, 1u, 0xFFFFFFFFu, -3, false)] // same negative group never
    [InlineData(1u, 0xFFFFFFFFu, -3, 1u, 0xFFFFFFFFu, -4, true)] // different groups: the bits decide
    [InlineData(1u, 0u, 3, 1u, 0xFFFFFFFFu, 0, false)] // one group only: the bits decide
    public void The_rule_is_Box2Ds(uint catA, uint maskA, int groupA, uint catB, uint maskB, int groupB, bool collide)
    {
        var a = new CollisionFilter(catA, maskA, groupA);
        var b = new CollisionFilter(catB, maskB, groupB);
        Assert.Equal(collide, CollisionFilter.ShouldCollide(a, b));
        Assert.Equal(collide, CollisionFilter.ShouldCollide(b, a));
    }

    [Fact]
    public void Bodies_and_planes_start_with_the_default_filter()
    {
        Assert.Equal(new CollisionFilter(1, uint.MaxValue, 0), CollisionFilter.Default);
        Assert.Equal(CollisionFilter.Default, new RigidBody(1, 1, Vector3.Zero).Filter);
        Assert.Equal(CollisionFilter.Default, StaticPlane.Ground().Filter);
        Assert.Equal(CollisionFilter.Default, default(StaticPlane).Filter);
    }

    [Fact]
    public void Balls_whose_masks_exclude_each_other_pass_through_each_other()
    {
        var world = new World(Vector3.Zero);
        var left = world.Add(new RigidBody(1, 0.5f, new Vector3(-2, 0, 0)) { LinearVelocity = new Vector3(2, 0, 0) });
        var right = world.Add(new RigidBody(1, 0.5f, new Vector3(2, 0, 0)) { LinearVelocity = new Vector3(-2, 0, 0) });
        left.Filter = new CollisionFilter(category: 0b01, mask: 0b01);
        right.Filter = new CollisionFilter(category: 0b10, mask: 0b11);
        for (int i = 0; i < 120; i++)
        {
            world.Step(1f / 60f);
            Assert.Equal(0, world.Collisions.Count);
        }

        Assert.Equal(new Vector3(2, 0, 0), left.LinearVelocity);
        Assert.True(left.Position.X > 1.9f && right.Position.X < -1.9f, $"they should have swapped sides: {left.Position}, {right.Position}");
    }

    /// <summary>Two balls sent at each other pass through exactly when their generated filters reject the pair.</summary>
    [Fact]
    public void Balls_pass_through_each_other_exactly_when_the_filters_say_so()
    {
        int passed = 0, bounced = 0;
        PropertyCheck.Run(
            from a in GameGenerators.Filter
            from b in GameGenerators.Filter
            from speed in Generators.UniformF(0.5, 20)
            from offset in Generators.UniformF(-0.9, 0.9)
            select (a, b, speed, offset),
            x =>
            {
                var world = new World(Vector3.Zero);
                var left = world.Add(new RigidBody(1, 0.5f, new Vector3(-3, 0, 0)) { LinearVelocity = new Vector3(x.speed, 0, 0), Filter = x.a });
                var right = world.Add(new RigidBody(1, 0.5f, new Vector3(3, x.offset, 0)) { LinearVelocity = new Vector3(-x.speed, 0, 0), Filter = x.b });
                int steps = (int)(6 / x.speed * 60) + 30;
                for (int i = 0; i < steps; i++)
                {
                    world.Step(1f / 60f);
                }

                bool collide = CollisionFilter.ShouldCollide(x.a, x.b);
                bool pushed = left.LinearVelocity != new Vector3(x.speed, 0, 0) || right.LinearVelocity != new Vector3(-x.speed, 0, 0);
                Law.Holds(pushed == collide, $"filters [{x.a}] and [{x.b}] {(collide ? "should" : "should not")} collide; velocities {left.LinearVelocity}, {right.LinearVelocity}");
                Law.Holds(collide || (left.Position.X > 2.9f && right.Position.X < -2.9f), $"filtered balls should pass through: {left.Position}, {right.Position}");
                if (!pushed)
                {
                    passed++;
                }
                else
                {
                    bounced++;
                }
            }, seed: 1107, maxTest: 200);
        Assert.True(passed > 20 && bounced > 20, $"{passed} passed through, {bounced} bounced: the generator should give both");
    }

    [Fact]
    public void A_shared_negative_group_passes_through_and_a_shared_positive_group_collides()
    {
        foreach (int group in new[] { -1, 1 })
        {
            var world = new World(Vector3.Zero);
            var left = world.Add(new RigidBody(1, 0.5f, new Vector3(-2, 0, 0)) { LinearVelocity = new Vector3(2, 0, 0) });
            var right = world.Add(new RigidBody(1, 0.5f, new Vector3(2, 0, 0)) { LinearVelocity = new Vector3(-2, 0, 0) });
            // Masks that would forbid the pair: only the group can make it collide.
            left.Filter = new CollisionFilter(1, 0, group);
            right.Filter = new CollisionFilter(1, 0, group);
            for (int i = 0; i < 120; i++)
            {
                world.Step(1f / 60f);
            }

            Assert.Equal(group > 0, left.Position.X < right.Position.X);
        }
    }

    [Fact]
    public void A_plane_filter_and_the_plane_callback_let_bodies_fall_through_the_floor()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        world.AddPlane(StaticPlane.Ground() with { Filter = new CollisionFilter(category: 0b10, mask: 0b10) });
        world.AddPlane(StaticPlane.Ground(-5f));
        var ghost = world.Add(new RigidBody(1, 0.5f, new Vector3(0, 1, 0)));
        var solid = world.Add(new RigidBody(1, 0.5f, new Vector3(3, 1, 0)) { Filter = new CollisionFilter(0b10, 0b10) });
        var skipsDeepFloor = world.Add(new RigidBody(1, 0.5f, new Vector3(6, 1, 0)));
        world.ShouldCollideWithPlane = (body, plane) => !(body == skipsDeepFloor && plane == 1);
        for (int i = 0; i < 180; i++)
        {
            world.Step(1f / 60f);
        }

        Assert.InRange(solid.Position.Y, 0.45f, 0.55f); // stands on the upper floor
        Assert.InRange(ghost.Position.Y, -4.55f, -4.45f); // fell through it onto the lower one
        Assert.True(skipsDeepFloor.Position.Y < -6, $"it should fall through both floors: {skipsDeepFloor.Position}");
    }

    [Fact]
    public void The_pair_callback_can_veto_a_pair()
    {
        var world = new World(Vector3.Zero);
        var left = world.Add(new RigidBody(1, 0.5f, new Vector3(-2, 0, 0)) { LinearVelocity = new Vector3(2, 0, 0), UserData = "ghost" });
        var right = world.Add(new RigidBody(1, 0.5f, new Vector3(2, 0, 0)) { LinearVelocity = new Vector3(-2, 0, 0) });
        world.ShouldCollide = (a, b) => (string?)a.UserData != "ghost" && (string?)b.UserData != "ghost";
        for (int i = 0; i < 120; i++)
        {
            world.Step(1f / 60f);
            Assert.Equal(0, world.Collisions.Count);
        }

        Assert.True(left.Position.X > 1.9f);
    }

    [Fact]
    public void No_contact_ever_names_a_filtered_pair_or_a_sensor()
    {
        int contacts = 0;
        PropertyCheck.Run(GameGenerators.Scene(), scene =>
        {
            World world = scene.Build(out _);
            // The callback vetoes some pairs the filters allow: those whose ids sum to a multiple of 5.
            world.ShouldCollide = (a, b) => (a.Id + b.Id) % 5 != 0;
            world.ShouldCollideWithPlane = (body, plane) => (body.Id + plane) % 7 != 0;
            for (int step = 0; step < 40; step++)
            {
                world.Step(1f / 60f);
                contacts += world.Collisions.Count;
                foreach (ref readonly Contact c in world.Collisions.Contacts)
                {
                    Law.Holds(!c.BodyA.IsSensor && !c.BodyB.IsSensor, $"step {step}: a contact names a sensor: {c.BodyA} / {c.BodyB}");
                    if (c.IsPlaneContact)
                    {
                        int p = c.PlaneIndex;
                        Law.Holds(CollisionFilter.ShouldCollide(c.BodyA.Filter, world.Planes[p].Filter) && (c.BodyA.Id + p) % 7 != 0,
                            $"step {step}: {c.BodyA} [{c.BodyA.Filter}] touches plane {p} [{world.Planes[p].Filter}]");
                    }
                    else
                    {
                        Law.Holds(CollisionFilter.ShouldCollide(c.BodyA.Filter, c.BodyB.Filter) && (c.BodyA.Id + c.BodyB.Id) % 5 != 0,
                            $"step {step}: masked pair {c.BodyA} [{c.BodyA.Filter}] / {c.BodyB} [{c.BodyB.Filter}]");
                    }
                }

                foreach (HitEvent hit in world.ContactEvents.Hits)
                {
                    Law.Holds(hit.IsPlaneContact || CollisionFilter.ShouldCollide(hit.BodyA.Filter, hit.BodyB!.Filter), $"a hit names a masked pair: {hit}");
                }
            }
        }, seed: 1101, maxTest: 60);
        Assert.True(contacts > 1000, $"only {contacts} contacts in all: the scenes test too little");
    }
}
