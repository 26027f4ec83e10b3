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

    /// <summary>
    /// The first body of <paramref name="actual"/> whose position, velocity or spin differs in any bit from the same
    /// body of <paramref name="expected"/>, described; null when every body is the same.
    /// </summary>
    public static string? FirstDifference(World expected, World actual)
    {
        for (int i = 0; i < expected.Bodies.Count; i++)
        {
            RigidBody e = expected.Bodies[i], a = actual.Bodies[i];
            if (a.Position != e.Position || a.LinearVelocity != e.LinearVelocity || a.AngularVelocity != e.AngularVelocity)
            {
                return $"body {i} at {a.Position:R} moving {a.LinearVelocity:R}, not {e.Position:R} moving {e.LinearVelocity:R}";
            }
        }

        return null;
    }
}
