using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// Perfectly inelastic collision (tutorial eq. 2, listing 1): both bodies leave with the common velocity
/// v' = (m_1 v_1 + m_2 v_2) / (m_1 + m_2). Linear momentum is conserved; kinetic energy is lost.
/// </summary>
/// <remarks>
/// <para>Against an infinite-mass (static or kinematic) body this is eq. 2's limit m_2 → ∞: the dynamic body
/// takes the other body's velocity, so it sticks to a static body (velocity zero) or rides a kinematic one.</para>
/// <para>Like listing 1 it changes linear velocities only; angular velocities are left as they are. Because
/// eq. 2 does not act along the contact normal, it conserves angular momentum only when the relative velocity
/// lies along the line of centres. A separating contact, (v_pA − v_pB)·n ≥ 0, is left untouched.</para>
/// </remarks>
public sealed class PerfectlyInelasticResponder : PairwiseResponder
{
    /// <inheritdoc />
    public override void ResolveVelocity(ref Contact contact)
    {
        Guard.ContactBodies(contact, nameof(contact));
        RigidBody a = contact.BodyA, b = contact.BodyB;
        if (!a.IsDynamic && !b.IsDynamic)
        {
            return;
        }

        if (Vector3.Dot(contact.RelativeVelocity, contact.Normal) >= 0)
        {
            return; // separating or resting
        }

        Vector3 common;
        if (!b.IsDynamic)
        {
            common = b.linearVelocity; // eq. 2 with m_2 → ∞
        }
        else if (!a.IsDynamic)
        {
            common = a.linearVelocity;
        }
        else
        {
            common = (a.mass * a.linearVelocity + b.mass * b.linearVelocity) / (a.mass + b.mass); // eq. 2
        }

        Vector3 impulse = a.IsDynamic ? a.mass * (common - a.linearVelocity) : b.mass * (b.linearVelocity - common);
        float normalImpulse = Vector3.Dot(impulse, contact.Normal);
        contact.NormalImpulse += normalImpulse;
        contact.TangentImpulse += (impulse - normalImpulse * contact.Normal).Length();
        if (a.IsDynamic)
        {
            a.linearVelocity = common;
        }

        if (b.IsDynamic)
        {
            b.linearVelocity = common;
        }
    }
}
