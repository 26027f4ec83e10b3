using System;
using System.Numerics;

namespace SimpleDynamics.Mathematics;

/// <summary>Small vector helpers the equations need and <see cref="Vector3"/> lacks.</summary>
public static class Vectors
{
    /// <summary>True when all three components are finite (neither NaN nor infinite).</summary>
    public static bool IsFinite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    /// <summary>True when all four components are finite.</summary>
    public static bool IsFinite(Quaternion q) =>
        float.IsFinite(q.X) && float.IsFinite(q.Y) && float.IsFinite(q.Z) && float.IsFinite(q.W);

    /// <summary>
    /// Two unit tangents <paramref name="t1"/>, <paramref name="t2"/> that make (n, t1, t2) a right-handed
    /// orthonormal basis. When n lies in the xy-plane, t1 lies in it too and t2 is ±z exactly, so a planar
    /// (z = 0) simulation never leaves its plane through friction.
    /// </summary>
    public static void Tangents(Vector3 n, out Vector3 t1, out Vector3 t2)
    {
        // Cross with whichever axis is least parallel to n; z first so that planar normals keep t1 planar.
        Vector3 axis = MathF.Abs(n.Z) < 0.9f ? Vector3.UnitZ : Vector3.UnitX;
        t1 = Vector3.Normalize(Vector3.Cross(n, axis));
        t2 = Vector3.Cross(n, t1);
    }
}
