using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// A pair that began or ended touching in the last step (<see cref="ContactEvents.BeginTouch"/>,
/// <see cref="ContactEvents.EndTouch"/>), or touches now (<see cref="ContactEvents.Touching"/>): two bodies, or
/// a body and a plane.
/// </summary>
public readonly struct ContactEvent
{
    internal ContactEvent(RigidBody bodyA, RigidBody? bodyB, int planeIndex)
    {
        BodyA = bodyA;
        BodyB = bodyB;
        PlaneIndex = planeIndex;
    }

    /// <summary>The first body of the pair (for a plane contact, the body).</summary>
    public RigidBody BodyA { get; }

    /// <summary>The second body, or null when the pair is a body and a plane.</summary>
    public RigidBody? BodyB { get; }

    /// <summary>The plane's index in <see cref="World.Planes"/> for a plane contact, else −1.</summary>
    public int PlaneIndex { get; }

    /// <summary>Whether this is the pair of these bodies (or body and plane), the same way round.</summary>
    internal bool Is(RigidBody bodyA, RigidBody? bodyB, int planeIndex) =>
        ReferenceEquals(BodyA, bodyA) && ReferenceEquals(BodyB, bodyB) && PlaneIndex == planeIndex;

    /// <summary>True when the pair is a body and a plane.</summary>
    public bool IsPlaneContact => PlaneIndex >= 0;

    /// <summary>Whether <paramref name="body"/> is one of the pair.</summary>
    public bool Involves(RigidBody body)
    {
        Guard.NotNull(body, nameof(body));
        return BodyA == body || BodyB == body;
    }

    /// <summary>The other member of the pair when <paramref name="body"/> is one of two bodies; null for a plane.</summary>
    public RigidBody? Other(RigidBody body)
    {
        Guard.NotNull(body, nameof(body));
        return BodyA == body ? BodyB : BodyA;
    }

    /// <inheritdoc />
    public override string ToString() => IsPlaneContact ? $"{BodyA} – plane {PlaneIndex}" : $"{BodyA} – {BodyB}";
}
