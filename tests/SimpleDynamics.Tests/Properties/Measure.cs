using System;
using System.Globalization;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Tests.Properties;

/// <summary>A 3-vector in double precision: the tests measure the library's float results in double.</summary>
public readonly record struct D3(double X, double Y, double Z)
{
    public static readonly D3 Zero = new(0, 0, 0);

    public static D3 From(Vector3 v) => new(v.X, v.Y, v.Z);

    public double Length => Math.Sqrt(Dot(this, this));

    public static D3 operator +(D3 a, D3 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    public static D3 operator -(D3 a, D3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    public static D3 operator -(D3 a) => new(-a.X, -a.Y, -a.Z);

    public static D3 operator *(double s, D3 a) => new(s * a.X, s * a.Y, s * a.Z);

    public static D3 operator /(D3 a, double s) => new(a.X / s, a.Y / s, a.Z / s);

    public static double Dot(D3 a, D3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

    public static D3 Cross(D3 a, D3 b) => new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

    public override string ToString() => string.Create(CultureInfo.InvariantCulture, $"({X:G9}, {Y:G9}, {Z:G9})");
}

/// <summary>A 3×3 matrix in double precision, row-major.</summary>
public readonly struct DMat3
{
    private readonly double[,] _m;

    public DMat3(double[,] m) => _m = m;

    public double this[int i, int j] => _m[i, j];

    public static DMat3 From(Matrix3 m) => new(new double[,]
    {
        { m.M11, m.M12, m.M13 }, { m.M21, m.M22, m.M23 }, { m.M31, m.M32, m.M33 },
    });

    public static DMat3 Rotation(Quaternion q)
    {
        // Normalise in double: the library normalises its orientation when it is set.
        double w = q.W, x = q.X, y = q.Y, z = q.Z;
        double n = Math.Sqrt(w * w + x * x + y * y + z * z);
        w /= n; x /= n; y /= n; z /= n;
        return new DMat3(new double[,]
        {
            { 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y) },
            { 2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x) },
            { 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y) },
        });
    }

    public static DMat3 operator *(DMat3 a, DMat3 b)
    {
        var r = new double[3, 3];
        for (int i = 0; i < 3; i++)
        {
            for (int j = 0; j < 3; j++)
            {
                r[i, j] = a[i, 0] * b[0, j] + a[i, 1] * b[1, j] + a[i, 2] * b[2, j];
            }
        }

        return new DMat3(r);
    }

    public static D3 operator *(DMat3 a, D3 v) => new(
        a[0, 0] * v.X + a[0, 1] * v.Y + a[0, 2] * v.Z,
        a[1, 0] * v.X + a[1, 1] * v.Y + a[1, 2] * v.Z,
        a[2, 0] * v.X + a[2, 1] * v.Y + a[2, 2] * v.Z);

    public DMat3 Transpose()
    {
        var r = new double[3, 3];
        for (int i = 0; i < 3; i++)
        {
            for (int j = 0; j < 3; j++)
            {
                r[i, j] = _m[j, i];
            }
        }

        return new DMat3(r);
    }

    /// <summary>Inverse by MathNet's LU in double, independent of the library's float adjugate.</summary>
    public DMat3 Inverse()
    {
        var inverse = MathNet.Numerics.LinearAlgebra.Matrix<double>.Build.DenseOfArray(_m).Inverse();
        return new DMat3(inverse.ToArray());
    }

    /// <summary>Largest absolute row sum (the ∞-norm).</summary>
    public double Norm()
    {
        double best = 0;
        for (int i = 0; i < 3; i++)
        {
            best = Math.Max(best, Math.Abs(_m[i, 0]) + Math.Abs(_m[i, 1]) + Math.Abs(_m[i, 2]));
        }

        return best;
    }
}

/// <summary>Physical quantities of bodies, measured in double precision from their float state.</summary>
public static class Measure
{
    public static bool Finite(RigidBody b) => b.IsDynamic;

    /// <summary>World-frame inertia tensor R I Rᵀ in double.</summary>
    public static DMat3 InertiaWorld(RigidBody b)
    {
        DMat3 r = DMat3.Rotation(b.Orientation);
        return r * DMat3.From(b.Inertia) * r.Transpose();
    }

    /// <summary>World-frame inverse inertia in double; zero for an infinite-mass body.</summary>
    public static DMat3 InverseInertiaWorld(RigidBody b) =>
        b.IsDynamic ? InertiaWorld(b).Inverse() : new DMat3(new double[3, 3]);

    public static double InverseMass(RigidBody b) => b.IsDynamic ? 1.0 / b.Mass : 0.0;

    public static D3 Momentum(params RigidBody[] bodies)
    {
        D3 p = D3.Zero;
        foreach (RigidBody b in bodies)
        {
            if (b.IsDynamic)
            {
                p += (double)b.Mass * D3.From(b.LinearVelocity);
            }
        }

        return p;
    }

    /// <summary>Σ I_w ω + (c − o) × m v over the dynamic bodies.</summary>
    public static D3 AngularMomentum(D3 about, params RigidBody[] bodies)
    {
        D3 l = D3.Zero;
        foreach (RigidBody b in bodies)
        {
            if (b.IsDynamic)
            {
                l += InertiaWorld(b) * D3.From(b.AngularVelocity)
                    + D3.Cross(D3.From(b.Position) - about, (double)b.Mass * D3.From(b.LinearVelocity));
            }
        }

        return l;
    }

    /// <summary>Scale of the angular momentum terms, for relative tolerances: Σ |I_w||ω| + |c − o| m |v|.</summary>
    public static double AngularMomentumScale(D3 about, params RigidBody[] bodies)
    {
        double s = 0;
        foreach (RigidBody b in bodies)
        {
            if (b.IsDynamic)
            {
                s += InertiaWorld(b).Norm() * D3.From(b.AngularVelocity).Length
                    + (D3.From(b.Position) - about).Length * b.Mass * D3.From(b.LinearVelocity).Length;
            }
        }

        return s;
    }

    public static double MomentumScale(params RigidBody[] bodies)
    {
        double s = 0;
        foreach (RigidBody b in bodies)
        {
            if (b.IsDynamic)
            {
                s += b.Mass * D3.From(b.LinearVelocity).Length;
            }
        }

        return s;
    }

    /// <summary>Σ ½ m v² + ½ ωᵀ I_w ω over the dynamic bodies.</summary>
    public static double KineticEnergy(params RigidBody[] bodies) => KineticEnergy(D3.Zero, bodies);

    /// <summary>
    /// Σ ½ m |v − V|² + ½ ωᵀ I_w ω: the kinetic energy seen from a frame moving at velocity V. A kinematic body
    /// (infinite mass, moving at V) does work on what it hits, so energy laws hold in its rest frame, not in
    /// the world's (Galilean invariance; the impulses depend only on relative velocities).
    /// </summary>
    public static double KineticEnergy(D3 frame, params RigidBody[] bodies)
    {
        double e = 0;
        foreach (RigidBody b in bodies)
        {
            if (b.IsDynamic)
            {
                D3 v = D3.From(b.LinearVelocity) - frame, w = D3.From(b.AngularVelocity);
                e += 0.5 * b.Mass * D3.Dot(v, v) + 0.5 * D3.Dot(w, InertiaWorld(b) * w);
            }
        }

        return e;
    }

    /// <summary>v + ω × (p − c) in double.</summary>
    public static D3 VelocityAt(RigidBody b, D3 point) =>
        D3.From(b.LinearVelocity) + D3.Cross(D3.From(b.AngularVelocity), point - D3.From(b.Position));

    /// <summary>Speed scale at a point: |v| + |ω||p − c|, for relative tolerances on contact velocities.</summary>
    public static double SpeedScaleAt(RigidBody b, D3 point) =>
        D3.From(b.LinearVelocity).Length + D3.From(b.AngularVelocity).Length * (point - D3.From(b.Position)).Length;

    /// <summary>
    /// Scale of a normal impulse's float error: m_eff (1 + ε) times the speeds at the contact. The approach speed
    /// v_n is a difference of velocities of size |v| + |ω||r|; when it is small it carries their rounding
    /// (cancellation), so J's error is relative to this, not to J itself.
    /// </summary>
    public static double ImpulseScale(RigidBody a, RigidBody b, D3 point, D3 normal, double restitution) =>
        (1 + restitution) * (SpeedScaleAt(a, point) + SpeedScaleAt(b, point)) / Eq16Denominator(a, b, point, normal);

    /// <summary>
    /// Eq. 16's denominator along a unit direction d, in double with the inverse of the double world inertia:
    /// 1/m_A + 1/m_B + ((I_A⁻¹(r_A × d)) × r_A + (I_B⁻¹(r_B × d)) × r_B)·d. Its inverse is m_eff.
    /// </summary>
    public static double Eq16Denominator(RigidBody a, RigidBody b, D3 point, D3 d)
    {
        D3 rA = point - D3.From(a.Position), rB = point - D3.From(b.Position);
        D3 angular = D3.Cross(InverseInertiaWorld(a) * D3.Cross(rA, d), rA)
            + D3.Cross(InverseInertiaWorld(b) * D3.Cross(rB, d), rB);
        return InverseMass(a) + InverseMass(b) + D3.Dot(angular, d);
    }
}
