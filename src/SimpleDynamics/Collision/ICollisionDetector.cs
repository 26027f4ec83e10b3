using System;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// Finds every pair of bodies whose bounding circles overlap, once each, and adds a contact for it with
/// A = the body earlier in the given order. Pairs of two infinite-mass bodies are skipped.
/// </summary>
public interface ICollisionDetector
{
    /// <summary>
    /// Adds to <paramref name="collisions"/> one contact per pair of <paramref name="bodies"/> that
    /// <see cref="ContactGeometry.TryCollide(RigidBody, RigidBody, float, float, out Contact)"/> accepts: with
    /// <paramref name="margin"/> (m) and <paramref name="lookahead"/> (s) both 0 (the defaults), exactly the
    /// overlapping pairs; otherwise also those whose spheres around the middles of their paths over the lookahead
    /// overlap (see that method). A detector may report more pairs than that, never fewer.
    /// </summary>
    void FindContacts(ReadOnlySpan<RigidBody> bodies, CollisionData collisions, float margin = 0f, float lookahead = 0f);
}
