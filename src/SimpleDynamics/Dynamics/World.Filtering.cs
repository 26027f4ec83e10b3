using System;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics;

// The game's say over which pairs collide, beyond the bodies' CollisionFilter bits.
public sealed partial class World
{
    /// <summary>
    /// Optional: asked during detection for each pair of bodies close enough to become a contact whose
    /// <see cref="RigidBody.Filter"/>s let them collide (neither a sensor); return false and the pair passes
    /// through, as if filtered. Null (the default) lets every such pair collide.
    /// </summary>
    /// <remarks>
    /// It runs inside <see cref="Step"/> for every nearby pair, so keep it quick, make it depend only on the two
    /// bodies, and do not add or remove bodies from it. The order of the two bodies is the detector's.
    /// </remarks>
    public Func<RigidBody, RigidBody, bool>? ShouldCollide { get; set; }

    /// <summary>
    /// Optional: asked during detection for each body close enough to a plane to touch it within the step,
    /// whose filters let them collide; the second argument is the plane's index in <see cref="Planes"/>.
    /// Return false and the body passes through the plane. Null (the default) lets every such pair collide.
    /// </summary>
    public Func<RigidBody, int, bool>? ShouldCollideWithPlane { get; set; }
}
