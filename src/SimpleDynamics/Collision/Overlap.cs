using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// A body or a plane found by a point or overlap query (<see cref="World.QueryPoint"/>,
/// <see cref="World.OverlapCircle"/>, <see cref="World.OverlapBox"/>).
/// </summary>
public readonly struct Overlap
{
    internal Overlap(RigidBody? body, int planeIndex)
    {
        Body = body;
        PlaneIndex = planeIndex;
    }

    /// <summary>The body found, or null for a plane.</summary>
    public RigidBody? Body { get; }

    /// <summary>The plane's index in <see cref="World.Planes"/> for a plane, else −1.</summary>
    public int PlaneIndex { get; }

    /// <summary>True when a plane was found.</summary>
    public bool IsPlane => PlaneIndex >= 0;

    /// <inheritdoc />
    public override string ToString() => IsPlane ? $"plane {PlaneIndex}" : Body?.ToString() ?? "nothing";
}
