using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// Answers the contacts of a step. <see cref="World.Step"/> calls the stages in this order, and only it can:
/// <list type="number">
/// <item><see cref="BeginStep"/> once, after detection and before anything moves: the contacts are new;</item>
/// <item>then for each substep: <see cref="SolveVelocities"/> after forces and gravity have changed the velocities
///   (resting contacts); <see cref="Collide"/> for each collision while the bodies move through the substep, at its
///   time of impact; <see cref="SolvePositions"/> after the bodies have moved (penetration, listing 2);</item>
/// <item><see cref="EndStep"/> once, before the contacts are measured for <see cref="World.Collisions"/>.</item>
/// </list>
/// Every stage receives the same <see cref="StepContext"/>, which holds everything about the step in progress
/// (bodies, planes, gravity, time step, contacts). A stage called with a context that is not in that stage — on its
/// own, out of order, or from another step — throws <see cref="System.InvalidOperationException"/> from
/// <see cref="StepContext.Expect"/>, which every stage of the library's responders calls first.
/// </summary>
/// <remarks>
/// <para><b>Ownership.</b> A responder belongs to one world at a time (it may keep state from one step to the next,
/// e.g. warm-start impulses): giving it to a second world while the first still uses it throws.</para>
/// <para>During <see cref="Collide"/> the two bodies of the contact hold their position and velocity at the moment
/// of impact; other bodies may still show the values from the start of the substep.</para>
/// </remarks>
public interface ICollisionResponder
{
    /// <summary>Once per step, after detection, before gravity or any stage has changed a body.</summary>
    void BeginStep(StepContext step);

    /// <summary>
    /// Per substep, after forces and gravity: change velocities so that resting contacts do not approach (impulses,
    /// eq. 5–16). Contacts that collide are answered by <see cref="Collide"/> at their time of impact instead.
    /// </summary>
    void SolveVelocities(StepContext step);

    /// <summary>
    /// A collision at its time of impact: the bodies of <paramref name="contact"/> have just met (penetration 0,
    /// normal along their line of centres) and approach with relative normal velocity
    /// <see cref="Contact.ApproachVelocity"/> &lt; 0. Change their velocities (eq. 2 or eq. 5–16). If they still
    /// approach afterwards, the world stops their approach (ε = 0) so that nothing passes through anything.
    /// </summary>
    void Collide(StepContext step, ref Contact contact);

    /// <summary>Per substep, after positions moved: remove penetration by moving bodies (listing 2).</summary>
    void SolvePositions(StepContext step);

    /// <summary>Once per step, after the last substep.</summary>
    void EndStep(StepContext step);
}
