using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Robustness;

/// <summary>
/// The mutation rule of <see cref="World"/>: bodies and planes change between steps, never during one;
/// enumerators of <see cref="World.Bodies"/> notice a change as <see cref="List{T}"/>'s do; no contact names a body
/// that has left the world; a call that throws changes nothing.
/// </summary>
public class SafeMutationTests
{
    [Fact]
    public void Changing_the_world_from_inside_a_step_throws_and_changes_nothing()
    {
        var world = new World(Scenes.EarthGravity);
        world.AddPlane(StaticPlane.Ground());
        var ball = world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 0.5f, 0)) { Restitution = 0.5f });
        var other = world.Add(new RigidBody(1f, 0.5f, new Vector3(3, 0.5f, 0)) { Restitution = 0.5f });
        var attempts = new Dictionary<string, Action>
        {
            ["Add"] = () => world.Add(new RigidBody(1f, 1f, new Vector3(10, 10, 0))),
            ["Remove"] = () => world.Remove(other),
            ["AddPlane"] = () => world.AddPlane(StaticPlane.Ground(-1f)),
            ["AddPlanes"] = () => world.AddPlanes(new[] { StaticPlane.Ground(-1f) }),
            ["TrimExcess"] = () => world.TrimExcess(),
            ["Substeps"] = () => world.Substeps = 1,
            ["Responder"] = () => world.Responder = new SequentialImpulseSolver(),
            ["Detector"] = () => world.Detector = new BruteForceDetector(),
            ["ThreadCount"] = () => world.ThreadCount = 2,
        };
        var caught = new Dictionary<string, Exception?>();

        // The mixing rule is user code that the solver calls in the middle of a step.
        float Restitution(float a, float b)
        {
            foreach (var (name, attempt) in attempts)
            {
                caught.TryAdd(name, Record.Exception(attempt));
            }

            return MathF.Max(a, b);
        }

        var solver = new SequentialImpulseSolver { Mixing = new MaterialMixing(Restitution, MathF.Max) };
        world.Responder = solver;
        world.Step(1f / 60f);

        Assert.Equal(attempts.Keys.OrderBy(k => k), caught.Keys.OrderBy(k => k));
        foreach (var (name, exception) in caught)
        {
            Assert.True(exception is InvalidOperationException, $"{name}: {exception?.GetType().Name ?? "no exception"}");
            Assert.Contains("stepping", exception!.Message);
        }

        Assert.Equal(new[] { ball, other }, world.Bodies.ToArray());
        Assert.Equal(1, world.Planes.Length);
        Assert.Equal(4, world.Substeps);
        Assert.Same(solver, world.Responder);
        Assert.IsType<SpatialHashDetector>(world.Detector);
        Assert.Equal(1, world.ThreadCount);

        // Between steps the same calls succeed.
        foreach (Action attempt in attempts.Values)
        {
            attempt();
        }

        world.ThreadCount = 1;
    }

    [Fact]
    public void Removing_bodies_while_enumerating_them_throws_instead_of_skipping_half()
    {
        World world = Scenes.BallPit(10, planar: true);
        Assert.Throws<InvalidOperationException>(() =>
        {
            foreach (RigidBody body in world.Bodies)
            {
                world.Remove(body);
            }
        });
        Assert.Equal(9, world.Bodies.Count);
    }

    [Fact]
    public void Any_add_or_remove_invalidates_an_enumerator_even_after_its_last_item()
    {
        World world = Scenes.BallPit(3, planar: true);
        using (IEnumerator<RigidBody> e = world.Bodies.GetEnumerator())
        {
            Assert.True(e.MoveNext());
            world.Add(new RigidBody(1f, 0.1f, new Vector3(50, 50, 0)));
            Assert.Throws<InvalidOperationException>(() => e.MoveNext());
        }

        using (IEnumerator<RigidBody> e = world.Bodies.GetEnumerator())
        {
            while (e.MoveNext())
            {
            }

            world.Remove(world.Bodies[0]);
            Assert.Throws<InvalidOperationException>(() => e.MoveNext());
        }

        // Loops that do not change the world, and removal backwards by index, are fine.
        Assert.Equal(3, world.Bodies.Count(b => b.IsDynamic));
        for (int i = world.Bodies.Count - 1; i >= 0; i--)
        {
            world.Remove(world.Bodies[i]);
        }

        Assert.Empty(world.Bodies);
    }

    [Fact]
    public void A_removed_body_is_named_by_no_contact_and_the_others_keep_their_order()
    {
        World world = Scenes.BallPit(60, planar: true, seed: 5);
        world.SleepingEnabled = false; // a settled pile falls asleep, and then has no contacts to step
        for (int i = 0; i < 120; i++)
        {
            world.Step(1f / 60f);
        }

        RigidBody removed = world.Bodies
            .OrderByDescending(b => world.Collisions.Contacts.ToArray().Count(c => c.BodyA == b || c.BodyB == b))
            .First();
        var expected = world.Collisions.Contacts.ToArray()
            .Where(c => c.BodyA != removed && c.BodyB != removed)
            .Select(c => (c.BodyA.Id, c.BodyB.Id, c.Penetration))
            .ToList();
        Assert.True(world.Collisions.Count > expected.Count, "the removed body had contacts");

        Assert.True(world.Remove(removed));

        Assert.Equal(expected.Count, world.Collisions.Count);
        Assert.Equal(expected, world.Collisions.Contacts.ToArray().Select(c => (c.BodyA.Id, c.BodyB.Id, c.Penetration)).ToList());
        foreach (Contact c in world.Collisions.Contacts)
        {
            Assert.True(c.BodyB == world.Ground || c.BodyB.World == world);
            Assert.Same(world, c.BodyA.World);
        }

        // The world steps on as before.
        world.Step(1f / 60f);
        Assert.DoesNotContain(world.Collisions.Contacts.ToArray(), c => c.BodyA == removed || c.BodyB == removed);
    }

    [Fact]
    public void Removing_every_body_leaves_only_contacts_of_bodies_still_in_the_world()
    {
        World world = Scenes.BallPit(40, planar: false, seed: 2);
        for (int i = 0; i < 60; i++)
        {
            world.Step(1f / 60f);
        }

        Assert.True(world.Collisions.Count > 0);
        RigidBody[] bodies = world.Bodies.ToArray();
        foreach (RigidBody body in bodies.Take(20))
        {
            world.Remove(body);
        }

        Assert.All(world.Collisions.Contacts.ToArray(), c => Assert.Same(world, c.BodyA.World));
        foreach (RigidBody body in bodies.Skip(20))
        {
            world.Remove(body);
        }

        Assert.Equal(0, world.Collisions.Count);
    }

    [Fact]
    public void AddPlanes_with_one_bad_plane_adds_none_and_reads_the_sequence_once()
    {
        var world = new World();
        world.AddPlane(StaticPlane.Ground());
        int enumerations = 0;
        IEnumerable<StaticPlane> Planes(bool withBad)
        {
            enumerations++;
            yield return StaticPlane.Ground(1f);
            if (withBad)
            {
                yield return default;
            }

            yield return StaticPlane.Ground(2f);
        }

        ArgumentException e = Assert.ThrowsAny<ArgumentException>(() => world.AddPlanes(Planes(withBad: true)));
        Assert.Equal("planes", e.ParamName);
        Assert.Equal(1, world.Planes.Length);

        enumerations = 0;
        world.AddPlanes(Planes(withBad: false));
        Assert.Equal(1, enumerations);
        Assert.Equal(new[] { 0f, 1f, 2f }, world.Planes.ToArray().Select(p => p.Offset));
    }
}
