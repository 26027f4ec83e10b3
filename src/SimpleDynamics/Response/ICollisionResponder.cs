using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// Answers the contacts detection found. <see cref="World.Step"/> calls <see cref="ResolveVelocities"/> after
/// forces have been integrated and <see cref="ResolvePositions"/> after positions have been integrated (the
/// separate velocity and position passes of Millington's Cyclone).
/// </summary>
public interface ICollisionResponder
{
    /// <summary>Changes velocities to answer the contacts (impulses, eq. 2 or eq. 5–16).</summary>
    void ResolveVelocities(World world, CollisionData collisions, float dt);

    /// <summary>Moves bodies to remove penetration (listing 2). The contacts hold the geometry found at detection.</summary>
    void ResolvePositions(World world, CollisionData collisions, float dt);
}
