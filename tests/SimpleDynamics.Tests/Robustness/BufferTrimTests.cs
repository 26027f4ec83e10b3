using System;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Robustness;

/// <summary>
/// The working arrays grow to the largest scene seen and are kept (a warm step allocates nothing); an explicit
/// <see cref="World.TrimExcess"/> gives the room back once the scene has shrunk.
/// </summary>
public class BufferTrimTests
{
    [Fact]
    public void A_crowd_of_2000_grows_the_contact_buffer_and_TrimExcess_gives_the_room_back()
    {
        World world = Crowd(2000);
        // Detection alone, into the world's own contact buffer, as the first stage of Step does: solving two
        // million contacts would take seconds and is not what this test is about.
        new BruteForceDetector().FindContacts(world.BodySpan, world.Collisions);
        AssertTrimmedAfterRemovingAllButTwo(world, 2000);
    }

    [Fact]
    public void A_crowd_stepped_by_the_world_grows_the_buffers_and_TrimExcess_gives_the_room_back()
    {
        World world = Crowd(300);
        // One substep and one cheap iteration: the buffers are the point, not the solution.
        world.Responder = new SequentialImpulseSolver { VelocityIterations = 1, PositionIterations = 0 };
        world.Substeps = 1;
        world.Step(1f / 60f);
        AssertTrimmedAfterRemovingAllButTwo(world, 300);

        // The trimmed world grows again as needed and steps as before.
        world.Add(new RigidBody(1f, 0.1f, new Vector3(1, 1, 1)));
        world.Step(1f / 60f);
        Assert.Equal(3, world.Bodies.Count);
        Assert.All(world.Bodies, b => Assert.True(float.IsFinite(b.Position.X)));
    }

    /// <summary>Bodies of radius 0.1 m all within 1 mm of each other, so every pair overlaps, in a closed box.</summary>
    private static World Crowd(int count)
    {
        var world = new World(Vector3.Zero);
        world.AddPlanes(StaticPlane.Box(new Vector3(-5, -5, -5), new Vector3(5, 5, 5)));
        var random = new Random(7);
        for (int i = 0; i < count; i++)
        {
            var p = new Vector3((float)random.NextDouble(), (float)random.NextDouble(), (float)random.NextDouble()) * 1e-3f;
            world.Add(new RigidBody(1f, 0.1f, p));
        }

        return world;
    }

    private static void AssertTrimmedAfterRemovingAllButTwo(World world, int count)
    {
        int crowdedCapacity = world.Collisions.Capacity;
        Assert.True(crowdedCapacity >= count * (count - 1) / 2, $"capacity {crowdedCapacity}");
        Assert.True(world.BodyCapacity >= count);

        RigidBody[] keep = world.Bodies.Take(2).ToArray();
        foreach (RigidBody body in world.Bodies.Skip(2).ToArray())
        {
            world.Remove(body);
        }

        Assert.Equal(crowdedCapacity, world.Collisions.Capacity); // kept until asked for
        Assert.True(world.Collisions.Count <= 1);
        world.TrimExcess();

        Assert.True(world.Collisions.Capacity <= 1, $"capacity {world.Collisions.Capacity}");
        Assert.Equal(2, world.BodyCapacity);
        Assert.Equal(6, world.PlaneCapacity);
        Assert.Equal(keep, world.Bodies.ToArray());
        Assert.Equal(6, world.Planes.Length);
    }

    [Fact]
    public void CollisionData_TrimExcess_keeps_its_contacts()
    {
        var a = new RigidBody(1f, 1f, Vector3.Zero);
        var b = new RigidBody(1f, 1f, new Vector3(1, 0, 0));
        var collisions = new CollisionData(1000);
        Assert.True(ContactGeometry.TryCollide(a, b, out Contact contact));
        collisions.Add(contact);
        collisions.Add(contact);
        collisions.TrimExcess();
        Assert.Equal(2, collisions.Capacity);
        Assert.Equal(2, collisions.Count);
        Assert.Same(a, collisions[1].BodyA);
        collisions.Clear();
        collisions.TrimExcess();
        Assert.Equal(1, collisions.Capacity);
        collisions.Add(contact);
        collisions.Add(contact);
        Assert.Equal(2, collisions.Count);
    }
}
