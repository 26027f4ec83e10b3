using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Text.RegularExpressions;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;

namespace SimpleDynamics.Tests.Game;

/// <summary>
/// The examples of docs/game-features.md run, and the document shows exactly this code: each example lies
/// between "// docs: NAME begin" and "// docs: NAME end" here and is the csharp block after "&lt;!-- NAME --&gt;" there.
/// </summary>
public class GameFeaturesDocTests
{
    private static readonly Vector3 Gravity = new(0, -9.81f, 0);

    [Fact]
    public void User_data_and_ids()
    {
        // docs: user-data begin
        var world = new World(gravity: new Vector3(0, -9.81f, 0));
        world.AddPlane(StaticPlane.Ground() with { UserData = "floor" });
        RigidBody ball = world.Add(new RigidBody(mass: 1f, radius: 0.5f, position: new Vector3(0, 3, 0)) { UserData = "ball" });
        int handle = ball.Id; // unique in the process; keeps naming this ball whatever else is removed
        // docs: user-data end

        world.Add(new RigidBody(1f, 0.5f, new Vector3(3, 3, 0)));
        world.Remove(world.Bodies[0]);
        Assert.Equal("ball", ball.UserData);
        Assert.Equal(handle, ball.Id);
        Assert.Equal("floor", world.Planes[0].UserData);
    }

    [Fact]
    public void Contact_events()
    {
        var world = new World(Gravity);
        world.AddPlane(StaticPlane.Ground() with { UserData = "floor" });
        world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 3, 0)) { UserData = "ball", Restitution = 0.5f });
        var log = new List<string>();
        void PlaySound(float volume) => log.Add($"sound {volume:F1}");
        void Score(object? what) => log.Add($"score {what}");
        for (int i = 0; i < 120; i++)
        {
            // docs: events begin
            world.HitSpeedThreshold = 1f; // m/s: a ball resting on the floor makes no hits
            world.Step(1f / 60f);
            foreach (HitEvent hit in world.ContactEvents.Hits)
            {
                PlaySound(volume: hit.Speed); // approach speed, m/s; hit.NormalImpulse is in N·s
            }

            foreach (ContactEvent begin in world.ContactEvents.BeginTouch)
            {
                if (begin.IsPlaneContact && world.Planes[begin.PlaneIndex].UserData is "floor")
                {
                    Score(begin.BodyA.UserData);
                }
            }
            // docs: events end
        }

        Assert.StartsWith("sound ", log[0]);
        Assert.InRange(float.Parse(log[0]["sound ".Length..], System.Globalization.CultureInfo.CurrentCulture), 6.8f, 7.2f); // √(2 g 2.5 m)
        Assert.Equal("score ball", log[1]);
        Assert.Contains("sound", log[2]); // the bounce comes down again
    }

    [Fact]
    public void Contacts_of_a_body()
    {
        var world = new World(Gravity);
        world.AddPlane(StaticPlane.Ground());
        RigidBody ball = world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 0.5f, 0)));
        world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 1.5f, 0)));
        world.Step(1f / 60f);
        bool onTheGround = false;
        // docs: contacts-of begin
        var contacts = new Contact[8]; // allocate once, reuse every frame
        int count = world.ContactsOf(ball, contacts);
        for (int i = 0; i < Math.Min(count, contacts.Length); i++)
        {
            Vector3 normal = contacts[i].BodyA == ball ? contacts[i].Normal : -contacts[i].Normal; // towards the ball
            onTheGround |= contacts[i].IsPlaneContact && normal.Y > 0.7f;
        }
        // docs: contacts-of end

        Assert.Equal(2, count);
        Assert.True(onTheGround);
    }

    [Fact]
    public void Filtering()
    {
        var world = new World(Vector3.Zero);
        // docs: filtering begin
        const uint Scenery = 1 << 0, Player = 1 << 1, Enemy = 1 << 2, Bullet = 1 << 3; // planes are Scenery (category 1) by default
        var player = world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 0.5f, 0)) { Filter = new CollisionFilter(Player, Scenery | Enemy) });
        var bullet = world.Add(new RigidBody(0.01f, 0.05f, new Vector3(-2, 0.5f, 0))
        {
            Filter = new CollisionFilter(category: Bullet, mask: Scenery | Enemy), // bullets pass through the player
            LinearVelocity = new Vector3(20, 0, 0),
        });
        world.ShouldCollide = (a, b) => !(a.UserData is "ghost" || b.UserData is "ghost"); // any rule of the game's
        // docs: filtering end

        for (int i = 0; i < 30; i++)
        {
            world.Step(1f / 60f);
        }

        Assert.True(bullet.Position.X > 2f, "the bullet passes through the player");
        Assert.InRange(player.Position.X, -0.01f, 0.01f);
    }

    [Fact]
    public void Sensors()
    {
        var world = new World(Gravity);
        var entered = new List<object?>();
        // docs: sensors begin
        RigidBody goal = world.Add(RigidBody.CreateStatic(radius: 1f, position: new Vector3(0, -2, 0)));
        goal.IsSensor = true; // takes and gives no impulses; reports what overlaps it
        world.Add(new RigidBody(1f, 0.25f, new Vector3(0, 2, 0)) { UserData = "ball" });
        for (int i = 0; i < 60; i++)
        {
            world.Step(1f / 60f);
            foreach (SensorEvent e in world.ContactEvents.SensorBegin)
            {
                entered.Add(e.Visitor.UserData); // e.Sensor == goal
            }
        }
        // docs: sensors end

        Assert.Equal(new object?[] { "ball" }, entered);
    }

    [Fact]
    public void Queries()
    {
        var world = new World(Gravity);
        world.AddPlane(StaticPlane.Ground() with { UserData = "floor" });
        world.Add(new RigidBody(1f, 0.5f, new Vector3(3, 0.5f, 0)) { UserData = "crate" });
        world.Step(1f / 60f);
        Vector3 mouse = new(3.2f, 0.6f, 0);
        var picked = new List<object?>();
        // docs: queries begin
        var found = new Overlap[16]; // caller's buffers: the queries allocate nothing
        var hits = new RayHit[16];

        // What is under the mouse?
        int n = world.QueryPoint(mouse, found);
        for (int i = 0; i < Math.Min(n, found.Length); i++)
        {
            picked.Add(found[i].IsPlane ? world.Planes[found[i].PlaneIndex].UserData : found[i].Body!.UserData);
        }

        // Line of sight: the nearest thing along a 10 m ray.
        if (world.RayCastClosest(origin: new Vector3(0, 0.5f, 0), translation: new Vector3(10, 0, 0), out RayHit hit))
        {
            Console.WriteLine($"{hit.Body?.UserData} at {hit.Point}, {hit.Fraction * 10:F1} m away");
        }

        // Everything a falling ray crosses, nearest first; and what lies in a blast radius or a box.
        int crossed = world.RayCastAll(new Vector3(3, 5, 0), new Vector3(0, -10, 0), hits);
        int inBlast = world.OverlapCircle(centre: new Vector3(2, 2, 0), radius: 1.6f, found);
        int inBox = world.OverlapBox(min: new Vector3(2, 0.1f, -1), max: new Vector3(4, 2, 1), found, new QueryFilter(mask: ~0u, includeSensors: true));
        // docs: queries end

        Assert.Equal(new object?[] { "crate" }, picked);
        Assert.Equal("crate", hit.Body?.UserData);
        Assert.Equal(2, crossed); // the crate, then the floor
        Assert.Equal("crate", hits[0].Body?.UserData);
        Assert.True(hits[1].IsPlane);
        Assert.Equal(1, inBlast);
        Assert.Equal(1, inBox);
    }

    [Fact]
    public void The_document_shows_exactly_the_code_of_these_tests()
    {
        string document = File.ReadAllText(Path.Combine(RepositoryRoot(), "docs", "game-features.md"));
        string source = File.ReadAllText(Path.Combine(RepositoryRoot(), "tests", "SimpleDynamics.Tests", "Game", "GameFeaturesDocTests.cs"));
        MatchCollection regions = Regex.Matches(source, "// docs: ([a-z-]+) begin\n(.*?)// docs: \\1 end", RegexOptions.Singleline);
        Assert.Equal(6, regions.Count);
        foreach (Match region in regions)
        {
            string name = region.Groups[1].Value;
            Match block = Regex.Match(document, $"<!-- {name} -->\\s*```csharp\n(.*?)```", RegexOptions.Singleline);
            Assert.True(block.Success, $"docs/game-features.md has no csharp block after <!-- {name} -->");
            Assert.Equal(Normalize(region.Groups[2].Value), Normalize(block.Groups[1].Value));
        }
    }

    private static string Normalize(string code) =>
        string.Join("\n", code.Split('\n').Select(line => line.Trim()).Where(line => line.Length > 0));

    private static string RepositoryRoot()
    {
        string? directory = AppContext.BaseDirectory;
        while (directory is not null && !File.Exists(Path.Combine(directory, "SimpleDynamics.sln")))
        {
            directory = Path.GetDirectoryName(directory);
        }

        return directory ?? throw new InvalidOperationException("SimpleDynamics.sln not found above this test");
    }
}
