using System;
using System.Numerics;

namespace SimpleDynamics.Collision;

/// <summary>The exact tests behind the world's queries: a ray against a circle/sphere or a plane, a box against a circle.</summary>
internal static class QueryGeometry
{
    /// <summary>
    /// Where the ray o + t·d (t ≥ 0) enters the circle (c, r): solves |o + t d − c|² = r² for the smaller root.
    /// A ray that starts inside or on the circle does not hit it (as in Box2D), so a ray cast from a body's
    /// centre finds what lies beyond it.
    /// </summary>
    public static bool RayCircle(Vector3 origin, Vector3 direction, Vector3 centre, float radius, out float t)
    {
        t = 0;
        Vector3 m = origin - centre;
        float a = Vector3.Dot(direction, direction);
        float b = Vector3.Dot(m, direction);
        float c = Vector3.Dot(m, m) - radius * radius;
        if (c <= 0 || b >= 0)
        {
            return false; // starts inside, or points away
        }

        float discriminant = b * b - a * c;
        if (discriminant < 0)
        {
            return false;
        }

        // t = (−b − √disc) / a, written as c / (−b + √disc) so that nothing cancels when the origin is close
        // to the surface (both forms are equal because their product is c / a).
        t = c / (-b + MathF.Sqrt(discriminant));
        return true;
    }

    /// <summary>Where the ray o + t·d (t ≥ 0) crosses a plane from its free side; a ray starting behind it misses.</summary>
    public static bool RayPlane(Vector3 origin, Vector3 direction, in StaticPlane plane, out float t)
    {
        t = 0;
        float start = plane.DistanceTo(origin);
        float along = Vector3.Dot(plane.Normal, direction);
        if (start <= 0 || along >= 0)
        {
            return false;
        }

        t = start / -along;
        return true;
    }

    /// <summary>Whether the box [min, max] and the circle (c, r) overlap: the box point nearest c lies within r.</summary>
    public static bool BoxOverlapsCircle(Vector3 min, Vector3 max, Vector3 centre, float radius) =>
        Vector3.DistanceSquared(Vector3.Clamp(centre, min, max), centre) < radius * radius;

    /// <summary>Whether some point of the box [min, max] lies behind the plane: test its corner furthest along −n.</summary>
    public static bool BoxOverlapsPlane(Vector3 min, Vector3 max, in StaticPlane plane)
    {
        Vector3 n = plane.Normal;
        var deepest = new Vector3(n.X >= 0 ? min.X : max.X, n.Y >= 0 ? min.Y : max.Y, n.Z >= 0 ? min.Z : max.Z);
        return plane.DistanceTo(deepest) < 0;
    }
}
