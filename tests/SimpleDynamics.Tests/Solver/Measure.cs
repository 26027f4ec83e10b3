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

    /// <summary>
    /// The energy that semi-implicit Euler keeps constant in free flight under gravity, with substep h:
    /// H = KE + PE + ½ h Σ m (g·v). The plain mechanical energy E = KE + PE swings by ½ h m |g·v| around it within
    /// a flight (it falls ½ g² h² per substep on the way down and is given back at a bounce), so "energy never
    /// rises" is a statement about H; E itself stays within that swing of it.
    /// </summary>
    public static double IntegratorEnergy(World world)
    {
        float h = 1f / 60f / world.Substeps;
        double correction = world.Bodies.Where(b => b.IsDynamic).Sum(b => 0.5 * h * b.Mass * (double)Vector3.Dot(world.Gravity, b.LinearVelocity));
        return world.Diagnostics.MechanicalEnergy + correction;
    }

    public static bool InsideBox(World world, Vector3 min, Vector3 max, float tolerance) =>
        world.Bodies.All(b =>
            b.Position.X >= min.X - tolerance && b.Position.X <= max.X + tolerance &&
            b.Position.Y >= min.Y - tolerance && b.Position.Y <= max.Y + tolerance &&
            b.Position.Z >= min.Z - tolerance && b.Position.Z <= max.Z + tolerance);
}
