using System;
using System.Globalization;
using System.Numerics;

namespace SimpleDynamics.Laws;

/// <summary>A 3-vector in double precision, for measuring float bodies without adding rounding of our own.</summary>
internal readonly struct Vec
{
    public readonly double X, Y, Z;

    public Vec(double x, double y, double z)
    {
        X = x;
        Y = y;
        Z = z;
    }

    public static Vec Zero => default;

    public double Length => Math.Sqrt(X * X + Y * Y + Z * Z);

    public static Vec From(Vector3 v) => new(v.X, v.Y, v.Z);

    public Vector3 ToVector3() => new((float)X, (float)Y, (float)Z);

    public static Vec operator +(Vec a, Vec b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    public static Vec operator -(Vec a, Vec b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    public static Vec operator -(Vec a) => new(-a.X, -a.Y, -a.Z);

    public static Vec operator *(double s, Vec a) => new(s * a.X, s * a.Y, s * a.Z);

    public static Vec operator /(Vec a, double s) => new(a.X / s, a.Y / s, a.Z / s);

    public static double Dot(Vec a, Vec b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

    public static Vec Cross(Vec a, Vec b) => new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

    /// <summary>Short, invariant: (1, 0, -0.25).</summary>
    public override string ToString() => "(" + Text.Number(X) + ", " + Text.Number(Y) + ", " + Text.Number(Z) + ")";
}

/// <summary>Invariant number text for messages.</summary>
internal static class Text
{
    /// <summary>At most 6 significant digits, invariant, no "-0".</summary>
    public static string Number(double value)
    {
        if (value == 0)
        {
            return "0";
        }

        return value.ToString("G6", CultureInfo.InvariantCulture);
    }
}
