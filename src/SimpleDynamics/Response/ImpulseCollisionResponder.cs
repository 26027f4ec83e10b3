using System;
using System.Numerics;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// The impulse method of the tutorial (§2.3, eq. 5–16, listing 3), with the tangential impulse the tutorial
/// leaves as an exercise: Coulomb friction. Each contact is answered once, on its own.
/// </summary>
/// <remarks>
/// <para><b>Normal impulse</b> (eq. 16): J = −(1 + ε) v_12·n / (1/m_1 + 1/m_2 + J_α), applied as +J n to A and
/// −J n to B (eq. 6, 15). Afterwards the relative normal velocity is −ε times what it was (eq. 9, 14).</para>
/// <para><b>In a world</b> it is called at each collision's time of impact, with the velocities the bodies have
/// at that moment, so the bounce of eq. 9 returns exactly the speed they arrive with.</para>
/// <para><b>Tangential impulse.</b> With the sliding velocity v_t = v_12' − (v_12'·n) n left after the normal
/// impulse and its direction t = v_t/|v_t|, the impulse that stops the sliding along t is computed like the
/// normal one, J_t = −|v_t| / k_t with k_t the denominator of eq. 16 taken along t, then clamped to
/// |J_t| ≤ μ J (Coulomb). It opposes the sliding and at most stops it, never reverses it, so friction
/// never adds kinetic energy.</para>
/// <para>ε and μ come from <see cref="Restitution"/> and <see cref="Friction"/>, unless the bodies set their own;
/// <see cref="Mixing"/> combines them.</para>
/// </remarks>
public sealed class ImpulseCollisionResponder : PairwiseResponder
{
    private float _restitution;
    private float _friction;
    private MaterialMixing _mixing = MaterialMixing.Default;

    /// <summary>Creates a responder with restitution ε ∈ [0, 1] and friction μ ≥ 0.</summary>
    /// <exception cref="ArgumentOutOfRangeException">ε outside [0, 1] or μ negative or not finite.</exception>
    public ImpulseCollisionResponder(float restitution = 0.5f, float friction = 0f)
    {
        Guard.UnitInterval(restitution, nameof(restitution));
        Guard.NonNegative(friction, nameof(friction));
        Restitution = restitution;
        Friction = friction;
    }

    /// <summary>Coefficient of restitution ε ∈ [0, 1] (eq. 9): 1 perfectly elastic, 0 no bounce.</summary>
    public float Restitution
    {
        get => _restitution;
        set
        {
            Guard.UnitInterval(value, nameof(Restitution));
            _restitution = value;
        }
    }

    /// <summary>Coulomb friction coefficient μ ≥ 0; 0 is frictionless.</summary>
    public float Friction
    {
        get => _friction;
        set
        {
            Guard.NonNegative(value, nameof(Friction));
            _friction = value;
        }
    }

    /// <summary>How per-body ε and μ combine; <see cref="MaterialMixing.Default"/> unless set.</summary>
    public MaterialMixing Mixing
    {
        get => _mixing;
        set
        {
            Guard.NotNull(value, nameof(Mixing));
            _mixing = value;
        }
    }

    /// <inheritdoc />
    public override void ResolveVelocity(ref Contact contact)
    {
        Guard.ContactBodies(contact, nameof(contact));
        var a = VelocityState.Of(contact.BodyA);
        var b = VelocityState.Of(contact.BodyB);
        Vector3 n = contact.Normal;
        Vector3 rA = contact.Point - contact.BodyA.position; // eq. 16: r_1 = p − c_1
        Vector3 rB = contact.Point - contact.BodyB.position; //          r_2 = p − c_2

        Vector3 relative = ImpulseMath.RelativeVelocity(a, b, rA, rB); // eq. 13–14
        float normalVelocity = Vector3.Dot(relative, n);
        float denominator = ImpulseMath.EffectiveMassDenominator(a, b, rA, rB, n);
        if (normalVelocity >= 0 || !(denominator > 0))
        {
            return; // separating or resting (listing 3), or two infinite masses
        }

        // 1. Normal impulse, eq. 16 (|n|² = 1 for a unit normal): J = −(1 + ε) v_12·n / denominator, the impulse
        //    that leaves the relative normal velocity at −ε v_12·n (the bounce of eq. 9).
        float restitution = Mixing.Restitution(contact, Restitution);
        float bounce = -restitution * normalVelocity;

        // 2. Then the tangential impulse (the tutorial's exercise): Coulomb friction along the sliding direction.
        float friction = Mixing.Friction(contact, Friction);
        float normalImpulse = ImpulseMath.Collide(ref a, ref b, rA, rB, n, normalVelocity, bounce, 1f / denominator, friction, out float tangentImpulse);

        a.StoreTo(contact.BodyA);
        b.StoreTo(contact.BodyB);
        contact.NormalImpulse += normalImpulse;
        contact.TangentImpulse += tangentImpulse;
    }
}
