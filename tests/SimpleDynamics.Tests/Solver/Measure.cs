using System;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Tests.Solver;

/// <summary>Measurements over a whole world that the solver tests assert on.</summary>
internal static class WorldMeasure
{
    public static bool AnyNaN(World world) =>
        world.Bodies.Any(b => !float.IsFinite(b.Position.X + b.Position.Y + b.Position.Z + b.LinearVelocity.X + b.LinearVelocity.Y + b.LinearVelocity.Z));

    public static float MaxSpeed(World world) => world.Bodies.Max(b => b.LinearVelocity.Length());

    public static bool InsideBox(World world, Vector3 min, Vector3 max, float tolerance) =>
        world.Bodies.All(b =>
            b.Position.X >= min.X - tolerance && b.Position.X <= max.X + tolerance &&
            b.Position.Y >= min.Y - tolerance && b.Position.Y <= max.Y + tolerance &&
            b.Position.Z >= min.Z - tolerance && b.Position.Z <= max.Z + tolerance);
}
