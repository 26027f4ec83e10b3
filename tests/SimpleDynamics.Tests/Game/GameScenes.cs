using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Numerics;
using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Tests.Properties;

namespace SimpleDynamics.Tests.Game;

/// <summary>A generated game body: where, how big, how it moves, and its game settings.</summary>
public sealed record GameBodySpec(BodyType Type, float Radius, Vector3 Position, Vector3 Velocity, CollisionFilter Filter, bool IsSensor)
{
    public RigidBody Build()
    {
        RigidBody body = Type switch
        {
            BodyType.Dynamic => new RigidBody(Radius * Radius, Radius, Position) { LinearVelocity = Velocity },
            BodyType.Static => RigidBody.CreateStatic(Radius, Position),
            _ => RigidBody.CreateKinematic(Radius, Position, Velocity),
        };
        body.Filter = Filter;
        body.IsSensor = IsSensor;
        return body;
    }

    public override string ToString() => string.Create(CultureInfo.InvariantCulture,
        $"{Type} r={Radius:R} c={Position} v={Velocity} [{Filter}]{(IsSensor ? " sensor" : "")}");
}

/// <summary>A generated scene: bodies crowded in a box with a floor and walls, each with its own filter.</summary>
public sealed record GameScene(GameBodySpec[] Bodies, CollisionFilter[] PlaneFilters, bool Planar)
{
    public const float Half = 2f;

    public World Build(out RigidBody[] bodies)
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        StaticPlane[] walls = StaticPlane.Box(new Vector3(-Half, 0, -Half), new Vector3(Half, 3 * Half, Half), Planar);
        for (int p = 0; p < walls.Length; p++)
        {
            world.AddPlane(walls[p] with { Filter = PlaneFilters[p % PlaneFilters.Length] });
        }

        bodies = Bodies.Select(b => world.Add(b.Build())).ToArray();
        return world;
    }

    public override string ToString() =>
        $"{(Planar ? "2-D" : "3-D")}, planes [{string.Join("; ", PlaneFilters)}]{Environment.NewLine}  " +
        string.Join(Environment.NewLine + "  ", Bodies.Select(b => b.ToString()));
}

/// <summary>Generators for the game-feature properties.</summary>
public static class GameGenerators
{
    /// <summary>Three categories, masks over them, and groups that are often shared (±1, ±2) or none.</summary>
    public static Gen<CollisionFilter> Filter { get; } =
        from category in Gen.Elements(1u, 2u, 4u)
        from mask in Gen.Choose(0, 7)
        from groupIndex in Gen.Elements(0, 0, 0, 0, 1, -1, 2, -2)
        from plain in Gen.Choose(0, 3)
        select plain == 0 ? CollisionFilter.Default : new CollisionFilter(category, (uint)mask, groupIndex);

    public static Gen<GameBodySpec> Body(bool planar, bool sensors) =>
        from type in Gen.Elements(BodyType.Dynamic, BodyType.Dynamic, BodyType.Dynamic, BodyType.Dynamic, BodyType.Static, BodyType.Kinematic)
        from radius in Generators.UniformF(0.1, 0.6)
        from position in Generators.Vector(GameScene.Half - 0.2)
        from velocity in Generators.Vector(3)
        from filter in Filter
        from sensor in Gen.Choose(0, 7)
        let flat = new Vector3(1, 1, planar ? 0 : 1)
        select new GameBodySpec(type, radius, (position + new Vector3(0, GameScene.Half, 0)) * flat,
            type == BodyType.Static ? Vector3.Zero : velocity * flat, filter, sensors && sensor == 0);

    public static Gen<GameScene> Scene(bool sensors = true) =>
        from planar in Gen.Elements(true, false)
        from count in Gen.Choose(2, 24)
        from bodies in Body(planar, sensors).ArrayOf(count)
        from planeFilters in Filter.ArrayOf(6)
        select new GameScene(bodies, planeFilters, planar);
}
