using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// A pair that struck in the last step: the responder pushed it apart (<see cref="NormalImpulse"/> &gt; 0) and
/// it approached at least at <see cref="World.HitSpeedThreshold"/>. Play a sound as loud as <see cref="Speed"/>.
/// </summary>
public readonly struct HitEvent
{
    internal HitEvent(in Contact contact, RigidBody? bodyB, int planeIndex)
    {
        BodyA = contact.BodyA;
        BodyB = bodyB;
        PlaneIndex = planeIndex;
        Point = contact.Point;
        Normal = contact.Normal;
        Speed = -contact.ApproachVelocity;
        NormalImpulse = contact.NormalImpulse;
    }

    /// <summary>The first body (for a plane contact, the body).</summary>
    public RigidBody BodyA { get; }

    /// <summary>The second body, or null when <see cref="BodyA"/> hit a plane.</summary>
    public RigidBody? BodyB { get; }

    /// <summary>The plane's index in <see cref="World.Planes"/> for a plane contact, else −1.</summary>
    public int PlaneIndex { get; }

    /// <summary>True when a body hit a plane.</summary>
    public bool IsPlaneContact => PlaneIndex >= 0;

    /// <summary>Contact point at the end of the step, world coordinates (m).</summary>
    public Vector3 Point { get; }

    /// <summary>Unit contact normal, from B (or the plane) to A, as in <see cref="Contact.Normal"/>.</summary>
    public Vector3 Normal { get; }

    /// <summary>Approach speed (m/s, positive): −<see cref="Contact.ApproachVelocity"/>, the normal speed at which the pair closed.</summary>
    public float Speed { get; }

    /// <summary>The normal impulse (N·s) the responder applied to the pair over the step.</summary>
    public float NormalImpulse { get; }

    /// <inheritdoc />
    public override string ToString() =>
        $"{BodyA} hit {(IsPlaneContact ? $"plane {PlaneIndex}" : BodyB?.ToString())} at {Speed} m/s, impulse {NormalImpulse} N·s";
}
