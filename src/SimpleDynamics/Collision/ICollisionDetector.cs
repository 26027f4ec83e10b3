using System;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// Finds every pair of bodies whose bounding circles overlap, once each, and adds a contact for it with
/// A = the body earlier in the given order. Pairs of two infinite-mass bodies are skipped.
/// </summary>
public interface ICollisionDetector
{
    /// <summary>Adds one contact per overlapping pair of <paramref name="bodies"/> to <paramref name="collisions"/>.</summary>
    void FindContacts(ReadOnlySpan<RigidBody> bodies, CollisionData collisions);
}
