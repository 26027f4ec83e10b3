using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// The projection method (tutorial §2.2, listing 2): moves the two bodies apart along the contact normal by
/// the penetration depth and changes no velocity.
/// </summary>
/// <remarks>
/// Listing 2 moves both bodies by the full depth. Here the displacement is split by inverse mass, so the
/// separation grows by exactly the depth: A moves by n·d·w_A/(w_A + w_B) and B by −n·d·w_B/(w_A + w_B), with
/// w = 1/m. A static body (w = 0) does not move, and a light body moves more than a heavy one. Because no
/// velocity changes, bodies that keep approaching meet again next step: the oscillation the tutorial warns of.
/// </remarks>
public sealed class ProjectionResponder : PairwiseResponder
{
    /// <inheritdoc />
    public override void ResolvePosition(ref Contact contact)
    {
        Guard.ContactBodies(contact, nameof(contact));
        RigidBody a = contact.BodyA, b = contact.BodyB;
        float inverseMassSum = a.inverseMass + b.inverseMass;
        if (contact.Penetration <= 0 || inverseMassSum == 0)
        {
            return;
        }

        float share = contact.Penetration / inverseMassSum;
        a.position += contact.Normal * (share * a.inverseMass);
        b.position -= contact.Normal * (share * b.inverseMass);
        contact.Penetration = 0;
    }
}
