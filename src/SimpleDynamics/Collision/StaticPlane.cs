using System;
using System.Numerics;

namespace SimpleDynamics.Collision;

/// <summary>
/// An infinite static plane <c>n·x = offset</c>: ground or wall. Bodies collide with its front side (the side
/// <see cref="Normal"/> points to); contacts with it name <see cref="World.Ground"/> as body B and use
/// <see cref="Normal"/> as the contact normal.
/// </summary>
public readonly struct StaticPlane
{
    /// <summary>Creates a plane through <paramref name="point"/> with unit normal <paramref name="normal"/>.</summary>
    /// <exception cref="ArgumentException">The normal is not a finite unit vector, or the point is not finite.</exception>
    public StaticPlane(Vector3 normal, Vector3 point, float? restitution = null, float? friction = null)
    {
        Guard.UnitVector(normal, nameof(normal));
        Guard.Finite(point, nameof(point));
        if (restitution is float e)
        {
            Guard.UnitInterval(e, nameof(restitution));
        }

        if (friction is float mu)
        {
            Guard.NonNegative(mu, nameof(friction));
        }

        Normal = Vector3.Normalize(normal);
        Offset = Vector3.Dot(Normal, point);
        Restitution = restitution;
        Friction = friction;
    }

    /// <summary>Unit normal, pointing out of the solid side into the free space.</summary>
    public Vector3 Normal { get; }

    /// <summary>The plane's distance from the origin along <see cref="Normal"/>.</summary>
    public float Offset { get; }

    /// <summary>Restitution of the plane's surface, or null for the responder's setting.</summary>
    public float? Restitution { get; }

    /// <summary>Friction of the plane's surface, or null for the responder's setting.</summary>
    public float? Friction { get; }

    /// <summary>
    /// Anything the game wants to find from the plane (e.g. "floor"); the physics never reads it. Set it with an
    /// initializer or a <c>with</c> expression, so the plane stays immutable:
    /// <c>new StaticPlane(n, p) { UserData = "floor" }</c>.
    /// </summary>
    public object? UserData { get; init; }

    /// <summary>
    /// Which bodies collide with this plane (default <see cref="CollisionFilter.Default"/>: all). A body the
    /// filter rejects passes through the plane. Set it like <see cref="UserData"/>.
    /// </summary>
    public CollisionFilter Filter
    {
        get => _filter ?? CollisionFilter.Default;
        init => _filter = value;
    }

    // Null means the default filter: a plane made by the constructor alone (or by Box) stores none, and a
    // struct field's default cannot be CollisionFilter.Default (category 1, not 0).
    private readonly CollisionFilter? _filter;

    /// <summary>Signed distance of a point from the plane; positive on the free side.</summary>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite.</exception>
    public float DistanceTo(Vector3 point)
    {
        Guard.Finite(point, nameof(point));
        return Vector3.Dot(Normal, point) - Offset;
    }

    /// <summary>Ground at height <paramref name="y"/>, facing +y.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="y"/> is not finite.</exception>
    public static StaticPlane Ground(float y = 0f)
    {
        Guard.Finite(y, nameof(y));
        return new(Vector3.UnitY, new Vector3(0, y, 0));
    }

    /// <summary>
    /// The walls of an axis-aligned box from <paramref name="min"/> to <paramref name="max"/>, facing inward.
    /// With <paramref name="planar"/> the z walls are left out (for a 2-D, z = 0 scene).
    /// </summary>
    public static StaticPlane[] Box(Vector3 min, Vector3 max, bool planar = false)
    {
        Guard.Finite(min, nameof(min));
        Guard.Finite(max, nameof(max));
        if (!(max.X > min.X && max.Y > min.Y && (planar || max.Z > min.Z)))
        {
            throw new ArgumentException("max must exceed min on every axis of the box.", nameof(max));
        }

        var walls = new[]
        {
            new StaticPlane(Vector3.UnitX, min), new StaticPlane(-Vector3.UnitX, max),
            new StaticPlane(Vector3.UnitY, min), new StaticPlane(-Vector3.UnitY, max),
            new StaticPlane(Vector3.UnitZ, min), new StaticPlane(-Vector3.UnitZ, max),
        };
        return planar ? walls[..4] : walls;
    }
}
