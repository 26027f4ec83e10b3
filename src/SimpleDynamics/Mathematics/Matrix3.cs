using System;
using System.Numerics;

namespace SimpleDynamics.Mathematics;

/// <summary>
/// A 3×3 matrix of single-precision floats, row-major (<c>M12</c> is row 1, column 2).
/// <see cref="System.Numerics"/> has no 3×3 matrix; inertia tensors (tutorial eq. 11, 15, 16) need one.
/// </summary>
public readonly struct Matrix3 : IEquatable<Matrix3>
{
    /// <summary>Row 1.</summary>
    public readonly float M11, M12, M13;
    /// <summary>Row 2.</summary>
    public readonly float M21, M22, M23;
    /// <summary>Row 3.</summary>
    public readonly float M31, M32, M33;

    /// <summary>Creates a matrix from its nine entries, row by row.</summary>
    public Matrix3(
        float m11, float m12, float m13,
        float m21, float m22, float m23,
        float m31, float m32, float m33)
    {
        M11 = m11; M12 = m12; M13 = m13;
        M21 = m21; M22 = m22; M23 = m23;
        M31 = m31; M32 = m32; M33 = m33;
    }

    /// <summary>The zero matrix: the inverse inertia of a body that cannot rotate (a static body).</summary>
    public static Matrix3 Zero => default;

    /// <summary>The identity matrix.</summary>
    public static Matrix3 Identity => new(1, 0, 0, 0, 1, 0, 0, 0, 1);

    /// <summary>A diagonal matrix.</summary>
    public static Matrix3 Diagonal(float x, float y, float z) => new(x, 0, 0, 0, y, 0, 0, 0, z);

    /// <summary>The rotation matrix of a unit quaternion.</summary>
    public static Matrix3 FromQuaternion(Quaternion q)
    {
        float xx = q.X * q.X, yy = q.Y * q.Y, zz = q.Z * q.Z;
        float xy = q.X * q.Y, xz = q.X * q.Z, yz = q.Y * q.Z;
        float wx = q.W * q.X, wy = q.W * q.Y, wz = q.W * q.Z;
        return new Matrix3(
            1 - 2 * (yy + zz), 2 * (xy - wz), 2 * (xz + wy),
            2 * (xy + wz), 1 - 2 * (xx + zz), 2 * (yz - wx),
            2 * (xz - wy), 2 * (yz + wx), 1 - 2 * (xx + yy));
    }

    /// <summary>The matrix times a column vector.</summary>
    public Vector3 Transform(Vector3 v) => new(
        M11 * v.X + M12 * v.Y + M13 * v.Z,
        M21 * v.X + M22 * v.Y + M23 * v.Z,
        M31 * v.X + M32 * v.Y + M33 * v.Z);

    /// <summary>The transpose.</summary>
    public Matrix3 Transpose() => new(M11, M21, M31, M12, M22, M32, M13, M23, M33);

    /// <summary>The determinant.</summary>
    public float Determinant() =>
        M11 * (M22 * M33 - M23 * M32) - M12 * (M21 * M33 - M23 * M31) + M13 * (M21 * M32 - M22 * M31);

    /// <summary>The inverse; throws when the matrix has no inverse that is finite in float.</summary>
    /// <remarks>See <see cref="TryInvert"/> for how it avoids underflow and overflow.</remarks>
    /// <exception cref="InvalidOperationException">The matrix is singular, not finite, or its inverse is not finite in float.</exception>
    public Matrix3 Inverse()
    {
        if (!TryInvert(out Matrix3 inverse))
        {
            throw new InvalidOperationException("The matrix is singular or its inverse is not finite in float.");
        }

        return inverse;
    }

    /// <summary>
    /// The inverse, if the matrix has one whose entries are all finite floats; otherwise false and
    /// <see cref="Zero"/>.
    /// </summary>
    /// <remarks>
    /// Inertia tensors span many decades (a 1 µg, 0.1 mm bead has I ≈ 4·10⁻¹⁵ kg·m²; a 1,000 t, 10 km sphere
    /// 4·10¹³), so the determinant, a product of three entries, underflows or overflows float long before the
    /// inverse itself does. A diagonal matrix is therefore inverted entry by entry (exact to rounding); any
    /// other is scaled by its largest entry, inverted by the adjugate in double (whose exponent range holds any
    /// product of three such entries), and scaled back: (sA)⁻¹ = A⁻¹ / s.
    /// </remarks>
    internal bool TryInvert(out Matrix3 inverse)
    {
        inverse = Zero;
        if (!IsFinite())
        {
            return false;
        }

        Matrix3 result;
        if (M12 == 0 && M13 == 0 && M21 == 0 && M23 == 0 && M31 == 0 && M32 == 0)
        {
            result = Diagonal(1f / M11, 1f / M22, 1f / M33);
        }
        else
        {
            double s = MathF.Max(
                MathF.Max(MathF.Max(MathF.Abs(M11), MathF.Abs(M12)), MathF.Max(MathF.Abs(M13), MathF.Abs(M21))),
                MathF.Max(MathF.Max(MathF.Abs(M22), MathF.Abs(M23)), MathF.Max(MathF.Max(MathF.Abs(M31), MathF.Abs(M32)), MathF.Abs(M33))));
            double a11 = M11 / s, a12 = M12 / s, a13 = M13 / s;
            double a21 = M21 / s, a22 = M22 / s, a23 = M23 / s;
            double a31 = M31 / s, a32 = M32 / s, a33 = M33 / s;
            double c11 = a22 * a33 - a23 * a32, c12 = a13 * a32 - a12 * a33, c13 = a12 * a23 - a13 * a22;
            double det = a11 * c11 + a21 * c12 + a31 * c13;
            if (det == 0 || !double.IsFinite(det))
            {
                return false;
            }

            // A⁻¹ = adj(A/s) / (det(A/s) · s).
            double k = 1.0 / (det * s);
            result = new Matrix3(
                (float)(c11 * k), (float)(c12 * k), (float)(c13 * k),
                (float)((a23 * a31 - a21 * a33) * k), (float)((a11 * a33 - a13 * a31) * k), (float)((a13 * a21 - a11 * a23) * k),
                (float)((a21 * a32 - a22 * a31) * k), (float)((a12 * a31 - a11 * a32) * k), (float)((a11 * a22 - a12 * a21) * k));
        }

        if (!result.IsFinite())
        {
            return false;
        }

        inverse = result;
        return true;
    }

    /// <summary>
    /// Rotates a body-frame tensor into the world frame: <c>R · this · Rᵀ</c>, where R is the orientation's
    /// rotation matrix. Used for the world-frame inverse inertia of eq. 15–16.
    /// </summary>
    public Matrix3 RotatedBy(Quaternion orientation)
    {
        Matrix3 r = FromQuaternion(orientation);
        return r * this * r.Transpose();
    }

    /// <summary>True when the matrix is diag(a, a, b): a rotation about z leaves it unchanged (a disc's tensor).</summary>
    internal bool IsSymmetricAboutZ() =>
        M11 == M22 && M12 == 0 && M13 == 0 && M21 == 0 && M23 == 0 && M31 == 0 && M32 == 0;

    /// <summary>True when every entry is a finite number.</summary>
    public bool IsFinite() =>
        float.IsFinite(M11) && float.IsFinite(M12) && float.IsFinite(M13) &&
        float.IsFinite(M21) && float.IsFinite(M22) && float.IsFinite(M23) &&
        float.IsFinite(M31) && float.IsFinite(M32) && float.IsFinite(M33);

    /// <summary>True when the matrix equals its transpose within a relative tolerance.</summary>
    public bool IsSymmetric(float relativeTolerance = 1e-5f)
    {
        float scale = MathF.Max(MathF.Abs(M11), MathF.Max(MathF.Abs(M22), MathF.Abs(M33)));
        float tolerance = relativeTolerance * MathF.Max(scale, float.Epsilon);
        return MathF.Abs(M12 - M21) <= tolerance && MathF.Abs(M13 - M31) <= tolerance && MathF.Abs(M23 - M32) <= tolerance;
    }

    /// <summary>
    /// True when the (symmetric) matrix is positive definite, by Sylvester's criterion: all leading principal
    /// minors are positive.
    /// </summary>
    public bool IsPositiveDefinite()
    {
        double m11 = M11, m12 = M12, m13 = M13, m22 = M22, m23 = M23, m33 = M33;
        double minor2 = m11 * m22 - m12 * m12;
        double det = m11 * (m22 * m33 - m23 * m23) - m12 * (m12 * m33 - m23 * m13) + m13 * (m12 * m23 - m22 * m13);
        return m11 > 0 && minor2 > 0 && det > 0;
    }

    /// <summary>Matrix product.</summary>
    public static Matrix3 operator *(Matrix3 a, Matrix3 b) => new(
        a.M11 * b.M11 + a.M12 * b.M21 + a.M13 * b.M31,
        a.M11 * b.M12 + a.M12 * b.M22 + a.M13 * b.M32,
        a.M11 * b.M13 + a.M12 * b.M23 + a.M13 * b.M33,
        a.M21 * b.M11 + a.M22 * b.M21 + a.M23 * b.M31,
        a.M21 * b.M12 + a.M22 * b.M22 + a.M23 * b.M32,
        a.M21 * b.M13 + a.M22 * b.M23 + a.M23 * b.M33,
        a.M31 * b.M11 + a.M32 * b.M21 + a.M33 * b.M31,
        a.M31 * b.M12 + a.M32 * b.M22 + a.M33 * b.M32,
        a.M31 * b.M13 + a.M32 * b.M23 + a.M33 * b.M33);

    /// <summary>Scales every entry.</summary>
    public static Matrix3 operator *(Matrix3 a, float s) => new(
        a.M11 * s, a.M12 * s, a.M13 * s, a.M21 * s, a.M22 * s, a.M23 * s, a.M31 * s, a.M32 * s, a.M33 * s);

    /// <summary>Matrix times column vector; the same as <see cref="Transform"/>.</summary>
    public static Vector3 operator *(Matrix3 a, Vector3 v) => a.Transform(v);

    /// <inheritdoc />
    public bool Equals(Matrix3 other) =>
        M11 == other.M11 && M12 == other.M12 && M13 == other.M13 &&
        M21 == other.M21 && M22 == other.M22 && M23 == other.M23 &&
        M31 == other.M31 && M32 == other.M32 && M33 == other.M33;

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is Matrix3 other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() =>
        HashCode.Combine(HashCode.Combine(M11, M12, M13, M21, M22), HashCode.Combine(M23, M31, M32, M33));

    /// <inheritdoc />
    public override string ToString() =>
        $"[{M11}, {M12}, {M13}; {M21}, {M22}, {M23}; {M31}, {M32}, {M33}]";
}
