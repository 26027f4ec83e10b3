using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// Where a ray, from an origin along a translation, first meets a body or a plane
/// (<see cref="World.RayCastClosest"/>, <see cref="World.RayCastAll"/>).
/// </summary>
public readonly struct RayHit
{
    internal RayHit(RigidBody? body, int planeIndex, Vector3 point, Vector3 normal, float fraction)
    {
        Body = body;
        PlaneIndex = planeIndex;
        Point = point;
        Normal = normal;
        Fraction = fraction;
    }

    /// <summary>The body hit, or null when the ray hit a plane.</summary>
    public RigidBody? Body { get; }

    /// <summary>The plane's index in <see cref="World.Planes"/> when the ray hit a plane, else −1.</summary>
    public int PlaneIndex { get; }

    /// <summary>True when the ray hit a plane.</summary>
    public bool IsPlane => PlaneIndex >= 0;

    /// <summary>The hit point, world coordinates: origin + <see cref="Fraction"/> · translation.</summary>
    public Vector3 Point { get; }

    /// <summary>The surface's outward unit normal at the hit point.</summary>
    public Vector3 Normal { get; }

    /// <summary>How far along the translation the hit lies, in [0, 1].</summary>
    public float Fraction { get; }

    /// <inheritdoc />
    public override string ToString() => $"{(IsPlane ? $"plane {PlaneIndex}" : Body?.ToString())} at {Point}, fraction {Fraction}";
}
