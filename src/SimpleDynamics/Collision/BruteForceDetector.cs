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
    public void FindContacts(ReadOnlySpan<RigidBody> bodies, CollisionData collisions, float margin = 0f, float lookahead = 0f)
    {
        Guard.NotNull(collisions, nameof(collisions));
        Guard.NonNegative(margin, nameof(margin));
        Guard.NonNegative(lookahead, nameof(lookahead));
        Guard.NoNullElements(bodies, nameof(bodies));
        for (int i = 0; i < bodies.Length; i++)
        {
            for (int j = i + 1; j < bodies.Length; j++)
            {
                if (ContactGeometry.Unchecked.TryCollide(bodies[i], bodies[j], margin, lookahead, out Contact contact))
                {
                    collisions.Add(contact);
                }
            }
        }
    }
}
