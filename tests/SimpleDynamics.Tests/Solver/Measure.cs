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
    /// The first body of <paramref name="actual"/> whose position, velocity, spin or orientation differs in any bit
    /// (−0 from +0 too) from the same body of <paramref name="expected"/>, described; null when every body is the same.
    /// </summary>
    public static string? FirstDifference(World expected, World actual)
    {
        for (int i = 0; i < expected.Bodies.Count; i++)
        {
            RigidBody e = expected.Bodies[i], a = actual.Bodies[i];
            if (!SameBits(a.Position, e.Position) || !SameBits(a.LinearVelocity, e.LinearVelocity) ||
                !SameBits(a.AngularVelocity, e.AngularVelocity) || !SameBits(a.Orientation, e.Orientation))
            {
                return $"body {i} at {a.Position:R} moving {a.LinearVelocity:R}, not {e.Position:R} moving {e.LinearVelocity:R}";
            }
        }

        return null;
    }

    private static bool SameBits(Vector3 a, Vector3 b) => SameBits(new Vector4(a, 0), new Vector4(b, 0));

    private static bool SameBits(Quaternion a, Quaternion b) => SameBits(new Vector4(a.X, a.Y, a.Z, a.W), new Vector4(b.X, b.Y, b.Z, b.W));

    private static bool SameBits(Vector4 a, Vector4 b) =>
        BitConverter.SingleToInt32Bits(a.X) == BitConverter.SingleToInt32Bits(b.X) &&
        BitConverter.SingleToInt32Bits(a.Y) == BitConverter.SingleToInt32Bits(b.Y) &&
        BitConverter.SingleToInt32Bits(a.Z) == BitConverter.SingleToInt32Bits(b.Z) &&
        BitConverter.SingleToInt32Bits(a.W) == BitConverter.SingleToInt32Bits(b.W);
}
