using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// Base of the tutorial's responders, which answer one pair at a time: each collision at its time of impact
/// (<see cref="ResolveVelocity"/>, called by <see cref="Collide"/>), and each contact's penetration after the bodies
/// have moved (<see cref="ResolvePosition"/>, called by <see cref="SolvePositions"/>). Each can also be used on a
/// single <see cref="Contact"/> directly.
/// </summary>
/// <remarks>
/// A single-pair responder has no resting-contact stage: a body lying on the ground meets it again in every
/// substep as gravity pulls it in, and each meeting is a collision at almost no speed.
/// </remarks>
public abstract class PairwiseResponder : ICollisionResponder
{
    /// <summary>Answers one collision: changes the two bodies' velocities; does nothing unless overridden.</summary>
    public virtual void ResolveVelocity(ref Contact contact)
    {
    }

    /// <summary>Answers one contact in the position pass: moves the bodies; does nothing unless overridden.</summary>
    public virtual void ResolvePosition(ref Contact contact)
    {
    }

    /// <inheritdoc />
    public void BeginStep(StepContext step)
    {
        Guard.NotNull(step, nameof(step));
        step.Expect(StepStage.BeginStep);
    }

    /// <inheritdoc />
    public void SolveVelocities(StepContext step)
    {
        Guard.NotNull(step, nameof(step));
        step.Expect(StepStage.SolveVelocities);
    }

    /// <inheritdoc />
    public void Collide(StepContext step, ref Contact contact)
    {
        Guard.NotNull(step, nameof(step));
        step.Expect(StepStage.Collide);
        ResolveVelocity(ref contact);
    }

    /// <inheritdoc />
    public void SolvePositions(StepContext step)
    {
        Guard.NotNull(step, nameof(step));
        step.Expect(StepStage.SolvePositions);
        foreach (ref Contact contact in step.Contacts.Contacts)
        {
            ResolvePosition(ref contact);
        }
    }

    /// <inheritdoc />
    public void EndStep(StepContext step)
    {
        Guard.NotNull(step, nameof(step));
        step.Expect(StepStage.EndStep);
    }
}
