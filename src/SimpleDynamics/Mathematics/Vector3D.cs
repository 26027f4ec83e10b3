using System;
using System.Numerics;

namespace SimpleDynamics.Mathematics;

/// <summary>
/// A point or vector in double precision: where a body is between impacts in a world without gravity
/// (see <see cref="Bodies.RigidBody.PreciseCentre"/>). Float32 positions a kilometre from the origin are 61 µm apart:
/// too coarse to tell a near-miss from a grazing hit.
/// </summary>
internal readonly struct Vector3D
{
    public readonly double X, Y, Z;

    public Vector3D(double x, double y, double z)
    {
        X = x;
        Y = y;
        Z = z;
    }

    /// <summary>The float vector, exactly (every float is a double).</summary>
    public Vector3D(Vector3 v)
        : this(v.X, v.Y, v.Z)
    {
    }

    /// <summary>Each component rounded to the nearest float.</summary>
    public Vector3 Rounded => new((float)X, (float)Y, (float)Z);

    public double LengthSquared => X * X + Y * Y + Z * Z;

    public double Length => Math.Sqrt(LengthSquared);

    public static Vector3D operator +(Vector3D a, Vector3D b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    public static Vector3D operator -(Vector3D a, Vector3D b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    public static Vector3D operator *(double s, Vector3D v) => new(s * v.X, s * v.Y, s * v.Z);

    public static Vector3D operator /(Vector3D v, double s) => new(v.X / s, v.Y / s, v.Z / s);

    public static double Dot(Vector3D a, Vector3D b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

    public static Vector3D Cross(Vector3D a, Vector3D b) =>
        new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

    public override string ToString() => $"<{X:R}, {Y:R}, {Z:R}>";
}
