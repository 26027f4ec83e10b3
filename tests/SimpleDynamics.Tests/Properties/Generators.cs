using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Numerics;
using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Tests.Properties;

/// <summary>Which bodies of a generated contact have infinite mass.</summary>
public enum InfiniteMass
{
    /// <summary>Both bodies dynamic.</summary>
    None,

    /// <summary>Exactly one body, A or B, static or kinematic.</summary>
    One,

    /// <summary>Either of the above.</summary>
    Any,
}

/// <summary>A body as generated: plain data, so FsCheck prints a failing case readably.</summary>
public sealed record BodySpec(
    BodyType Type,
    float Mass,
    float Radius,
    Vector3 Position,
    Quaternion Orientation,
    Matrix3 Inertia,
    Vector3 Velocity,
    Vector3 AngularVelocity)
{
    public RigidBody Build()
    {
        RigidBody body = Type switch
        {
            BodyType.Dynamic => new RigidBody(Mass, Radius, Position, Inertia)
            {
                Orientation = Orientation, LinearVelocity = Velocity, AngularVelocity = AngularVelocity,
            },
            BodyType.Static => RigidBody.CreateStatic(Radius, Position),
            _ => RigidBody.CreateKinematic(Radius, Position, Velocity),
        };
        if (Type != BodyType.Dynamic)
        {
            body.Orientation = Orientation;
        }

        return body;
    }

    public BodySpec Reversed() => Type == BodyType.Static ? this : this with { Velocity = -Velocity, AngularVelocity = -AngularVelocity };

    public override string ToString() => string.Create(CultureInfo.InvariantCulture,
        $"{Type} m={Mass:R} r={Radius:R} c={Position} q={Orientation} I={Inertia} v={Velocity} w={AngularVelocity}");
}

/// <summary>One contact between two generated bodies, with the responder settings to answer it.</summary>
public sealed record ContactCase(BodySpec A, BodySpec B, Vector3 Point, Vector3 Normal, float Penetration, float Restitution, float Friction)
{
    public (RigidBody A, RigidBody B) BuildBodies() => (A.Build(), B.Build());

    public Contact BuildContact(RigidBody a, RigidBody b) => new(a, b, Point, Normal, Penetration);

    /// <summary>The velocity of the infinite-mass body, if one is kinematic; else zero (see Measure.KineticEnergy).</summary>
    public D3 RestFrame => A.Type == BodyType.Kinematic ? D3.From(A.Velocity) : B.Type == BodyType.Kinematic ? D3.From(B.Velocity) : D3.Zero;

    /// <summary>(v_pA − v_pB)·n from the spec, in double.</summary>
    public double NormalVelocity()
    {
        D3 p = D3.From(Point);
        D3 va = D3.From(A.Velocity) + D3.Cross(D3.From(A.AngularVelocity), p - D3.From(A.Position));
        D3 vb = D3.From(B.Velocity) + D3.Cross(D3.From(B.AngularVelocity), p - D3.From(B.Position));
        return D3.Dot(va - vb, D3.From(Normal));
    }

    public override string ToString() => string.Create(CultureInfo.InvariantCulture,
        $"{Environment.NewLine}  A: {A}{Environment.NewLine}  B: {B}{Environment.NewLine}  p={Point} n={Normal} pen={Penetration:R} eps={Restitution:R} mu={Friction:R} vn={NormalVelocity():R}");
}

/// <summary>A scene for the detectors: bodies as generated.</summary>
public sealed record DetectionScene(BodySpec[] Bodies)
{
    public override string ToString() =>
        $"{Bodies.Length} bodies:{Environment.NewLine}" + string.Join(Environment.NewLine, Bodies.Select((b, i) => $"  [{i}] {b}"));
}

/// <summary>
/// FsCheck generators of physically sane inputs: finite numbers in ranges where float arithmetic is well
/// conditioned, so that a failure means a wrong law, not a meaningless input.
/// </summary>
public static class Generators
{
    /// <summary>Passed as ε to mean "uniform in [0, 1]" (an attribute argument must be a constant).</summary>
    public const float RandomRestitution = -1f;

    private const int Resolution = 1 << 30;

    /// <summary>Uniform in [0, 1].</summary>
    public static Gen<double> Unit { get; } = Gen.Choose(0, Resolution).Select(i => i / (double)Resolution);

    public static Gen<double> Uniform(double lo, double hi) => Unit.Select(u => lo + (hi - lo) * u);

    public static Gen<float> UniformF(double lo, double hi) => Uniform(lo, hi).Select(x => (float)x);

    /// <summary>Log-uniform in [lo, hi]: every decade equally likely.</summary>
    public static Gen<float> LogUniform(double lo, double hi) =>
        Unit.Select(u => (float)Math.Exp(Math.Log(lo) + u * (Math.Log(hi) - Math.Log(lo))));

    /// <summary>Masses from 1e-2 to 1e3 kg, log-uniform; two independent draws are an unequal pair.</summary>
    public static Gen<float> Mass { get; } = LogUniform(1e-2, 1e3);

    public static Gen<Vector3> Vector(double range) =>
        from x in UniformF(-range, range)
        from y in UniformF(-range, range)
        from z in UniformF(-range, range)
        select new Vector3(x, y, z);

    /// <summary>Uniform on the unit sphere (z uniform in [−1, 1], azimuth uniform).</summary>
    public static Gen<Vector3> UnitVector { get; } =
        from z in Uniform(-1, 1)
        from phi in Uniform(0, 2 * Math.PI)
        let s = Math.Sqrt(Math.Max(0, 1 - z * z))
        select Vector3.Normalize(new Vector3((float)(s * Math.Cos(phi)), (float)(s * Math.Sin(phi)), (float)z));

    /// <summary>Uniform random rotation (Shoemake's method).</summary>
    public static Gen<Quaternion> Orientation { get; } =
        from u1 in Unit
        from u2 in Unit
        from u3 in Unit
        let a = Math.Sqrt(1 - u1)
        let b = Math.Sqrt(u1)
        select Quaternion.Normalize(new Quaternion(
            (float)(a * Math.Sin(2 * Math.PI * u2)), (float)(a * Math.Cos(2 * Math.PI * u2)),
            (float)(b * Math.Sin(2 * Math.PI * u3)), (float)(b * Math.Cos(2 * Math.PI * u3))));

    /// <summary>
    /// A full, non-diagonal, symmetric positive-definite body-frame inertia tensor R·diag(I1, I2, I3)·Rᵀ with a
    /// random rotation R. The principal moments come from second moments s_i = m r² k_i (k_i in [0.02, 0.5])
    /// as I1 = s2 + s3 and so on, so they obey the triangle inequality of real bodies; their ratio is at most 25.
    /// Symmetric exactly (the upper triangle is mirrored after rounding to float).
    /// </summary>
    public static Gen<Matrix3> InertiaTensor(float mass, float radius) =>
        from k1 in Uniform(0.02, 0.5)
        from k2 in Uniform(0.02, 0.5)
        from k3 in Uniform(0.02, 0.5)
        from q in Orientation
        select FullTensor(mass * (double)radius * radius, k1, k2, k3, q);

    private static Matrix3 FullTensor(double scale, double k1, double k2, double k3, Quaternion q)
    {
        var d = new DMat3(new double[,] { { scale * (k2 + k3), 0, 0 }, { 0, scale * (k1 + k3), 0 }, { 0, 0, scale * (k1 + k2) } });
        DMat3 r = DMat3.Rotation(q);
        DMat3 t = r * d * r.Transpose();
        float m12 = (float)t[0, 1], m13 = (float)t[0, 2], m23 = (float)t[1, 2];
        return new Matrix3((float)t[0, 0], m12, m13, m12, (float)t[1, 1], m23, m13, m23, (float)t[2, 2]);
    }

    /// <summary>ε uniform in [0, 1] or one of the listed values.</summary>
    public static Gen<float> Restitution(float fixedValue) =>
        fixedValue == RandomRestitution ? UniformF(0, 1) : Gen.Constant(fixedValue);

    public static Gen<float> Friction(bool withFriction) => withFriction ? UniformF(0.05, 1.5) : Gen.Constant(0f);

    /// <summary>A body of the given type: dynamic ones get mass, a full tensor, orientation, v and ω.</summary>
    public static Gen<BodySpec> Body(BodyType type, Vector3 position, float radius) =>
        from mass in Mass
        from inertia in InertiaTensor(mass, radius)
        from q in Orientation
        from v in Vector(5)
        from w in Vector(5)
        select type switch
        {
            BodyType.Dynamic => new BodySpec(type, mass, radius, position, q, inertia, v, w),
            BodyType.Static => new BodySpec(type, float.PositiveInfinity, radius, position, q, default, Vector3.Zero, Vector3.Zero),
            _ => new BodySpec(type, float.PositiveInfinity, radius, position, q, default, v, Vector3.Zero),
        };

    private static Gen<(BodyType A, BodyType B)> Types(InfiniteMass infinite)
    {
        Gen<BodyType> infiniteType = Gen.Elements(BodyType.Static, BodyType.Static, BodyType.Kinematic);
        Gen<(BodyType, BodyType)> one =
            from t in infiniteType
            from infiniteIsA in Gen.Elements(true, false)
            select infiniteIsA ? (t, BodyType.Dynamic) : (BodyType.Dynamic, t);
        Gen<(BodyType, BodyType)> none = Gen.Constant((BodyType.Dynamic, BodyType.Dynamic));
        return infinite switch
        {
            InfiniteMass.None => none,
            InfiniteMass.One => one,
            _ => Gen.OneOf(none, none, one),
        };
    }

    /// <summary>
    /// A contact between two bodies (of radius 0.1..2 m, centres within ±5 m) whose line of centres is a
    /// random unit normal n from B to A, overlapping by up to a fifth of the smaller radius, with the contact
    /// point off the line of centres (offset up to half the smaller radius across n), so that r × n ≠ 0 and
    /// the angular terms of eq. 15–16 matter. <paramref name="approaching"/> chooses the sign of
    /// (v_pA − v_pB)·n by reversing all velocities when needed.
    /// </summary>
    public static Gen<ContactCase> Contact(float restitution = RandomRestitution, bool friction = false, InfiniteMass infinite = InfiniteMass.None, bool approaching = true) =>
        (from types in Types(infinite)
         from rA in UniformF(0.1, 2)
         from rB in UniformF(0.1, 2)
         from cB in Vector(5)
         from n in UnitVector
         from overlap in Uniform(0, 0.2)
         from offsetDirection in UnitVector
         from offsetSize in Uniform(0, 0.5)
         let penetration = (float)(overlap * Math.Min(rA, rB))
         let cA = cB + n * (rA + rB - penetration)
         let across = offsetDirection - Vector3.Dot(offsetDirection, n) * n
         let point = cA - n * (rA - 0.5f * penetration) + across * (float)(offsetSize * Math.Min(rA, rB))
         from a in Body(types.A, cA, rA)
         from b in Body(types.B, cB, rB)
         from e in Restitution(restitution)
         from mu in Friction(friction)
         let raw = new ContactCase(a, b, point, n, penetration, e, mu)
         let vn = raw.NormalVelocity()
         select (vn < 0) == approaching ? raw : raw with { A = a.Reversed(), B = b.Reversed() })
        .Where(c => c.NormalVelocity() != 0 && (c.NormalVelocity() < 0) == approaching);

    /// <summary>
    /// A scene for the detectors: 2..40 bodies with radii log-uniform in 0.01..10 m, most in a cluster of
    /// ±20 m, some far away (≈ 1e4 m, beyond any other), some at exactly the centre of an earlier body
    /// (coincident centres); a quarter static or kinematic.
    /// </summary>
    public static Gen<DetectionScene> DetectionScene { get; } =
        from count in Gen.Choose(2, 40)
        from seeds in Gen.ArrayOf(SceneBody, count)
        select new DetectionScene(Place(seeds));

    private static Gen<(BodySpec Body, int Placement, double Choice)> SceneBody { get; } =
        from type in Gen.Elements(BodyType.Dynamic, BodyType.Dynamic, BodyType.Dynamic, BodyType.Dynamic, BodyType.Dynamic, BodyType.Static, BodyType.Kinematic)
        from radius in LogUniform(0.01, 10)
        from near in Vector(20)
        from far in Vector(1e4)
        from placement in Gen.Choose(0, 9)
        from choice in Unit
        from body in Body(type, near, radius)
        select (body with { Position = placement == 9 ? far : near }, placement, choice);

    private static BodySpec[] Place((BodySpec Body, int Placement, double Choice)[] seeds)
    {
        var bodies = new BodySpec[seeds.Length];
        for (int i = 0; i < seeds.Length; i++)
        {
            (BodySpec body, int placement, double choice) = seeds[i];
            if (placement == 8 && i > 0)
            {
                body = body with { Position = bodies[(int)(choice * i)].Position }; // coincident centre
            }

            bodies[i] = body;
        }

        return bodies;
    }
}
