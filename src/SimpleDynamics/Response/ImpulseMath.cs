using System.Numerics;

namespace SimpleDynamics.Response;

/// <summary>
/// The impulse equations of the tutorial's §2.3, shared by every impulse-based responder so that they are
/// written once.
/// </summary>
internal static class ImpulseMath
{
    /// <summary>
    /// Relative velocity of A with respect to B at the contact: v_12 = v_p1 − v_p2 with
    /// v_p = v + ω × r (eq. 13–14).
    /// </summary>
    public static Vector3 RelativeVelocity(in VelocityState a, in VelocityState b, Vector3 rA, Vector3 rB) =>
        a.Linear + Vector3.Cross(a.Angular, rA) - (b.Linear + Vector3.Cross(b.Angular, rB));

    /// <summary>
    /// The denominator of eq. 16 for a unit direction d:
    /// 1/m_1 + 1/m_2 + ((I_1⁻¹(r_1 × d)) × r_1 + (I_2⁻¹(r_2 × d)) × r_2) · d.
    /// Its inverse is the effective mass m_eff that the contact sees along d.
    /// </summary>
    public static float EffectiveMassDenominator(in VelocityState a, in VelocityState b, Vector3 rA, Vector3 rB, Vector3 d) =>
        EffectiveMassDenominator(
            a.InverseMass + b.InverseMass,
            a.InverseInertia.Transform(Vector3.Cross(rA, d)), rA,
            b.InverseInertia.Transform(Vector3.Cross(rB, d)), rB,
            d);

    /// <summary>
    /// The same denominator of eq. 16 when the spins a unit impulse along d causes, I⁻¹ (r × d), are already known.
    /// </summary>
    public static float EffectiveMassDenominator(float inverseMassSum, Vector3 spinA, Vector3 rA, Vector3 spinB, Vector3 rB, Vector3 d) =>
        inverseMassSum + Vector3.Dot(Vector3.Cross(spinA, rA) + Vector3.Cross(spinB, rB), d);

    /// <summary>
    /// Applies impulse P to A and −P to B at the contact: v' = v ± P/m (eq. 6) and
    /// ω' = ω ± I⁻¹ (r × P) (eq. 15).
    /// </summary>
    public static void Apply(ref VelocityState a, ref VelocityState b, Vector3 rA, Vector3 rB, Vector3 impulse)
    {
        a.Linear += impulse * a.InverseMass;
        a.Angular += a.InverseInertia.Transform(Vector3.Cross(rA, impulse));
        b.Linear -= impulse * b.InverseMass;
        b.Angular -= b.InverseInertia.Transform(Vector3.Cross(rB, impulse));
    }

    /// <summary>
    /// One collision of the tutorial's impulse method on its own: the normal impulse of eq. 16 that turns the
    /// relative normal velocity <paramref name="normalVelocity"/> (&lt; 0, approaching) into
    /// <paramref name="bounceVelocity"/> (eq. 9: −ε times the approach), then the tangential impulse the
    /// tutorial leaves as an exercise: Coulomb friction along the sliding direction t left after the normal
    /// impulse, J_t = |v_t| / k_t (k_t the denominator of eq. 16 along t) clamped to μ J. It opposes the sliding
    /// and at most stops it, so friction never adds kinetic energy.
    /// </summary>
    /// <returns>The normal impulse J; <paramref name="tangentImpulse"/> is the friction impulse's magnitude.</returns>
    public static float Collide(
        ref VelocityState a, ref VelocityState b, Vector3 rA, Vector3 rB, Vector3 n,
        float normalVelocity, float bounceVelocity, float normalMass, float friction, out float tangentImpulse)
    {
        float normalImpulse = (bounceVelocity - normalVelocity) * normalMass; // eq. 16, with m_eff = 1 / denominator
        Apply(ref a, ref b, rA, rB, normalImpulse * n); // eq. 6 and 15

        tangentImpulse = 0;
        if (friction > 0)
        {
            Vector3 relative = RelativeVelocity(a, b, rA, rB);
            Vector3 sliding = relative - Vector3.Dot(relative, n) * n;
            float slidingSpeed = sliding.Length();
            if (slidingSpeed > 1e-9f)
            {
                Vector3 t = sliding / slidingSpeed;
                float tangentDenominator = EffectiveMassDenominator(a, b, rA, rB, t);
                tangentImpulse = System.MathF.Min(slidingSpeed / tangentDenominator, friction * normalImpulse);
                Apply(ref a, ref b, rA, rB, -tangentImpulse * t);
            }
        }

        return normalImpulse;
    }
}
