using System;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// The tutorial's detection (<c>WorldPart1.cs</c>): test the bounding circles of every pair, O(n²). Kept for
/// teaching, for small worlds, and as the oracle the faster detector is tested against.
/// </summary>
public sealed class BruteForceDetector : ICollisionDetector
{
    /// <inheritdoc />
    public void FindContacts(ReadOnlySpan<RigidBody> bodies, CollisionData collisions)
    {
        Guard.NotNull(collisions, nameof(collisions));
        for (int i = 0; i < bodies.Length; i++)
        {
            for (int j = i + 1; j < bodies.Length; j++)
            {
                if (ContactGeometry.TryCollide(bodies[i], bodies[j], out Contact contact))
                {
                    collisions.Add(contact);
                }
            }
        }
    }
}
