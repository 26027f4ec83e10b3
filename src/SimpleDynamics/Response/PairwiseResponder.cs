using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// Base of the tutorial's responders, which answer one pair at a time, each contact once per (sub)step, in
/// detection order. Each can also be used on a single <see cref="Contact"/> directly.
/// </summary>
/// <remarks>
/// Within a step the world measures contacts again after each substep; a contact whose bodies no longer touch
/// (penetration &lt; 0) is skipped.
/// </remarks>
public abstract class PairwiseResponder : ICollisionResponder
{
    /// <summary>Answers one contact in the velocity pass; does nothing unless overridden.</summary>
    public virtual void ResolveVelocity(ref Contact contact)
    {
    }

    /// <summary>Answers one contact in the position pass; does nothing unless overridden.</summary>
    public virtual void ResolvePosition(ref Contact contact)
    {
    }

    /// <inheritdoc />
    public void ResolveVelocities(World world, CollisionData collisions, float dt)
    {
        Guard.NotNull(collisions, nameof(collisions));
        foreach (ref Contact contact in collisions.Contacts)
        {
            if (contact.Penetration >= 0)
            {
                ResolveVelocity(ref contact);
            }
        }
    }

    /// <inheritdoc />
    public void ResolvePositions(World world, CollisionData collisions, float dt)
    {
        Guard.NotNull(collisions, nameof(collisions));
        foreach (ref Contact contact in collisions.Contacts)
        {
            ResolvePosition(ref contact);
        }
    }
}
