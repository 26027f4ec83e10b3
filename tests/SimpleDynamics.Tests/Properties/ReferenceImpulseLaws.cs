using System;
using MathNet.Numerics.LinearAlgebra;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// Law 10: an independent reference. The frictionless contact is written as a 13×13 linear system in double
/// precision and solved with MathNet.Numerics; its solution must match <see cref="ImpulseCollisionResponder"/>.
/// </summary>
/// <remarks>
/// Unknowns x = (Δv_A, Δω_A, Δv_B, Δω_B, J). Equations, from eq. 5, 6, 15 and 9/14 directly, with the world
/// inertia tensors I (not their inverses, so the library's eq. 16 denominator is not reused).
/// J is compared relative to <see cref="Measure.ImpulseScale"/> (a small approach speed is a float difference
/// of larger speeds), the velocities relative to their own size:
/// <code>
///   m_A Δv_A − J n           = 0      (eq. 5)       m_B Δv_B + J n           = 0
///   I_A Δω_A − J (r_A × n)   = 0      (eq. 15)      I_B Δω_B + J (r_B × n)   = 0
///   n·(Δv_A + Δω_A × r_A − Δv_B − Δω_B × r_B) = −(1 + ε) (v_12·n)   (eq. 9, 14: v_12'·n = −ε v_12·n)
/// </code>
/// An infinite-mass body's rows become Δv = 0, Δω = 0. Tolerance: the library works in float with results
/// of size |J| and |Δv|; 1e-4 relative covers float rounding through a tensor inverse of condition ≤ 25.
/// </remarks>
public class ReferenceImpulseLaws
{
    private const double Tolerance = 1e-4;

    [Theory]
    [InlineData(Generators.RandomRestitution, InfiniteMass.Any)]
    [InlineData(0f, InfiniteMass.None)]
    [InlineData(0.25f, InfiniteMass.Any)]
    [InlineData(0.5f, InfiniteMass.One)]
    [InlineData(0.75f, InfiniteMass.None)]
    [InlineData(1f, InfiniteMass.Any)]
    public void Impulse_matches_a_MathNet_solution_of_the_contact_equations(float restitution, InfiniteMass infinite) =>
        PropertyCheck.Run(Generators.Contact(restitution, friction: false, infinite), c =>
        {
            (RigidBody a, RigidBody b) = c.BuildBodies();
            Vector<double> x = SolveReference(c, a, b);
            double impulseScale = Measure.ImpulseScale(a, b, D3.From(c.Point), D3.From(c.Normal), c.Restitution);
            D3 vA = D3.From(a.LinearVelocity), wA = D3.From(a.AngularVelocity);
            D3 vB = D3.From(b.LinearVelocity), wB = D3.From(b.AngularVelocity);

            Contact contact = c.BuildContact(a, b);
            new ImpulseCollisionResponder(c.Restitution, 0f).ResolveVelocity(ref contact);

            double j = x[12];
            Law.Near(j, contact.NormalImpulse, Tolerance * impulseScale, "normal impulse J");
            Compare(vA, Slice(x, 0), a.LinearVelocity, "v_A'");
            Compare(wA, Slice(x, 3), a.AngularVelocity, "ω_A'");
            Compare(vB, Slice(x, 6), b.LinearVelocity, "v_B'");
            Compare(wB, Slice(x, 9), b.AngularVelocity, "ω_B'");
        }, seed: 1001);

    private static void Compare(D3 before, D3 change, System.Numerics.Vector3 actual, string what) =>
        Law.Near(before + change, D3.From(actual), Tolerance * (before.Length + change.Length) + 1e-12, what);

    private static D3 Slice(Vector<double> x, int i) => new(x[i], x[i + 1], x[i + 2]);

    private static Vector<double> SolveReference(ContactCase c, RigidBody a, RigidBody b)
    {
        Matrix<double> m = Matrix<double>.Build.Dense(13, 13);
        Vector<double> rhs = Vector<double>.Build.Dense(13);
        D3 n = D3.From(c.Normal), p = D3.From(c.Point);
        D3 rA = p - D3.From(a.Position), rB = p - D3.From(b.Position);

        Body(m, a, 0, rA, n, sign: -1);
        Body(m, b, 6, rB, n, sign: +1);

        // Row 12: n·Δv_A + n·(Δω_A × r_A) − n·Δv_B − n·(Δω_B × r_B) = −(1 + ε) v_n.
        // n·(ω × r) = ω·(r × n).
        D3 rAxn = D3.Cross(rA, n), rBxn = D3.Cross(rB, n);
        double[] row =
        {
            n.X, n.Y, n.Z, rAxn.X, rAxn.Y, rAxn.Z,
            -n.X, -n.Y, -n.Z, -rBxn.X, -rBxn.Y, -rBxn.Z, 0,
        };
        for (int k = 0; k < 13; k++)
        {
            m[12, k] = row[k];
        }

        D3 u = Measure.VelocityAt(a, p) - Measure.VelocityAt(b, p);
        rhs[12] = -(1 + (double)c.Restitution) * D3.Dot(u, n);
        return m.Solve(rhs);
    }

    /// <summary>Rows for one body: m Δv + sign·J n = 0 and I Δω + sign·J (r × n) = 0, or Δv = Δω = 0 if infinite.</summary>
    private static void Body(Matrix<double> m, RigidBody body, int at, D3 r, D3 n, int sign)
    {
        if (!body.IsDynamic)
        {
            for (int k = 0; k < 6; k++)
            {
                m[at + k, at + k] = 1;
            }

            return;
        }

        DMat3 inertia = Measure.InertiaWorld(body);
        D3 rxn = D3.Cross(r, n);
        double[] nn = { n.X, n.Y, n.Z }, rr = { rxn.X, rxn.Y, rxn.Z };
        for (int i = 0; i < 3; i++)
        {
            m[at + i, at + i] = body.Mass;
            m[at + i, 12] = sign * nn[i];
            for (int k = 0; k < 3; k++)
            {
                m[at + 3 + i, at + 3 + k] = inertia[i, k];
            }

            m[at + 3 + i, 12] = sign * rr[i];
        }
    }
}
