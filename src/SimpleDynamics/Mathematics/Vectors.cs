using System;
using System.Numerics;
using System.Runtime.CompilerServices;

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
    /// The unit quaternion along <paramref name="q"/>, or false when q is zero or not finite. The largest
    /// component is divided out first, so that the squared length can neither overflow (a component of 2·10¹⁹
    /// squares past float's 3.4·10³⁸) nor underflow to zero.
    /// </summary>
    internal static bool TryNormalize(Quaternion q, out Quaternion unit)
    {
        unit = default;
        if (!IsFinite(q))
        {
            return false;
        }

        float lengthSquared = q.LengthSquared();
        if (lengthSquared > 1e-30f && lengthSquared < 1e30f)
        {
            unit = Quaternion.Normalize(q); // the usual case: no scaling needed, same bits as System.Numerics
            return true;
        }

        float largest = MathF.Max(MathF.Max(MathF.Abs(q.X), MathF.Abs(q.Y)), MathF.Max(MathF.Abs(q.Z), MathF.Abs(q.W)));
        if (largest == 0)
        {
            return false;
        }

        unit = Quaternion.Normalize(new Quaternion(q.X / largest, q.Y / largest, q.Z / largest, q.W / largest));
        return true;
    }

    /// <summary>
    /// Two unit tangents <paramref name="t1"/>, <paramref name="t2"/> that make (n, t1, t2) a right-handed
    /// orthonormal basis. When n lies in the xy-plane, t1 lies in it too and t2 is ±z exactly, so a planar
    /// (z = 0) simulation never leaves its plane through friction.
    /// </summary>
    /// <param name="n">A unit normal.</param>
    /// <param name="t1">The first tangent.</param>
    /// <param name="t2">The second tangent, n × t1.</param>
    /// <exception cref="ArgumentException"><paramref name="n"/> is zero or not finite; it has no tangents.</exception>
    public static void Tangents(Vector3 n, out Vector3 t1, out Vector3 t2)
    {
        if (!IsFinite(n) || n == Vector3.Zero)
        {
            throw new ArgumentException($"n must be a finite, non-zero (unit) vector, but was {n}.", nameof(n));
        }

        UncheckedTangents(n, out t1, out t2);
    }

    /// <summary>
    /// <see cref="Tangents"/> without its checks, inlined where the solver measures every contact each substep:
    /// <paramref name="n"/> must be a finite unit vector.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static void UncheckedTangents(Vector3 n, out Vector3 t1, out Vector3 t2)
    {
        // Cross with whichever axis is least parallel to n; z first so that planar normals keep t1 planar.
        Vector3 axis = MathF.Abs(n.Z) < 0.9f ? Vector3.UnitZ : Vector3.UnitX;
        Vector3 across = Vector3.Cross(n, axis);
        t1 = across / Length(across); // Vector3.Normalize's floats, without DPPS (see Dot)
        t2 = Vector3.Cross(n, t1);
    }

    /// <summary>
    /// a · b in scalar arithmetic, for the solver's passes over every contact: the same value as
    /// <see cref="Vector3.Dot(Vector3, Vector3)"/> but for the sign of a zero ((a_x b_x + a_y b_y) + a_z b_z, where the
    /// JIT's DPPS instruction adds a fourth, zero lane to a_z b_z). DPPS takes about 15 cycles on AMD Zen 2 and 3
    /// (A. Fog, "Instruction tables", https://www.agner.org/optimize/instruction_tables.pdf), and the sweeps wait on it.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static float Dot(Vector3 a, Vector3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

    /// <summary>|a − b|² in scalar arithmetic: exactly <see cref="Vector3.DistanceSquared(Vector3, Vector3)"/>, without DPPS (see <see cref="Dot"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static float DistanceSquared(Vector3 a, Vector3 b)
    {
        float x = a.X - b.X, y = a.Y - b.Y, z = a.Z - b.Z;
        return x * x + y * y + z * z;
    }

    /// <summary>max(|v_x|, |v_y|, |v_z|): how far from the origin a point lies along its farthest axis, which sets how finely a float places it.</summary>
    internal static float LargestCoordinate(Vector3 v) => MathF.Max(MathF.Max(MathF.Abs(v.X), MathF.Abs(v.Y)), MathF.Abs(v.Z));

    /// <summary>|v|² in scalar arithmetic: exactly <see cref="Vector3.LengthSquared"/>, without DPPS (see <see cref="Dot"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static float LengthSquared(Vector3 v) => v.X * v.X + v.Y * v.Y + v.Z * v.Z;

    /// <summary>|v| in scalar arithmetic: exactly <see cref="Vector3.Length"/>, without DPPS (see <see cref="Dot"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static float Length(Vector3 v) => MathF.Sqrt(LengthSquared(v));

    /// <summary>|a − b| in scalar arithmetic: exactly <see cref="Vector3.Distance(Vector3, Vector3)"/>, without DPPS (see <see cref="Dot"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static float Distance(Vector3 a, Vector3 b) => MathF.Sqrt(DistanceSquared(a, b));
}
