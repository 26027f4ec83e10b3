using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics;

// Queries a game asks between steps: what a ray hits, what lies under a point, what overlaps a circle or a box.
public sealed partial class World
{
    private readonly QueryGrid _queryGrid = new();

    // Bumped by every step and by RefreshQueries; the grid is rebuilt when its version differs.
    private long _queryVersion;

    /// <summary>
    /// Tells the queries that bodies were moved, resized, added or removed by hand since the last step, so the
    /// next query rebuilds its grid. A step does this by itself.
    /// </summary>
    /// <remarks>
    /// Queries find bodies through a grid built on the first query after each step and reused until the next
    /// step. A body moved by hand (<see cref="RigidBody.Position"/>, <see cref="RigidBody.Radius"/>) between
    /// steps is tested where it is, but found through the cells of where it was: call this after moving bodies
    /// and before querying. Removed bodies are never reported, and a change in the number of bodies rebuilds
    /// the grid without it; adding one body while removing another (the same count) needs it too.
    /// </remarks>
    public void RefreshQueries() => _queryVersion++;

    /// <summary>
    /// The nearest body or plane the segment from <paramref name="origin"/> to origin + <paramref name="translation"/>
    /// enters. A ray that starts inside a body does not hit that body; one that starts behind a plane does not hit it.
    /// </summary>
    /// <param name="origin">Where the ray starts (m).</param>
    /// <param name="translation">The ray's direction and length (m); not zero.</param>
    /// <param name="hit">The hit, if any: body or plane, point, outward normal and fraction of the translation.</param>
    /// <param name="filter">Which bodies and planes count; by default all but sensors.</param>
    /// <returns>Whether anything was hit.</returns>
    /// <exception cref="ArgumentException">An argument is not finite, or the translation is zero.</exception>
    public bool RayCastClosest(Vector3 origin, Vector3 translation, out RayHit hit, QueryFilter filter = default)
    {
        CheckRay(origin, translation);
        hit = default;
        QueryGrid grid = CurrentQueryGrid();
        int slot = grid.RayClosest(origin, translation, filter, this, out float best);
        bool found = slot >= 0;
        if (found)
        {
            RigidBody body = grid.BodyAt(slot);
            hit = BodyHit(body, origin, translation, best);
        }

        ReadOnlySpan<StaticPlane> planes = Planes;
        for (int p = 0; p < planes.Length; p++)
        {
            if (filter.Accepts(planes[p]) && QueryGeometry.RayPlane(origin, translation, planes[p], out float t)
                && t <= 1f && (!found || t < best))
            {
                found = true;
                best = t;
                hit = new RayHit(null, p, origin + t * translation, planes[p].Normal, t);
            }
        }

        return found;
    }

    /// <summary>
    /// Every body and plane the segment from <paramref name="origin"/> to origin + <paramref name="translation"/>
    /// enters, nearest first. When there are more than <paramref name="hits"/> holds, it keeps the nearest.
    /// </summary>
    /// <returns>How many bodies and planes the ray hits; may exceed <paramref name="hits"/>.Length.</returns>
    /// <exception cref="ArgumentException">An argument is not finite, or the translation is zero.</exception>
    public int RayCastAll(Vector3 origin, Vector3 translation, Span<RayHit> hits, QueryFilter filter = default)
    {
        CheckRay(origin, translation);
        QueryGrid grid = CurrentQueryGrid();
        grid.GatherRay(origin, translation);
        int total = 0;
        foreach (int slot in grid.Candidates)
        {
            RigidBody body = grid.BodyAt(slot);
            if (body.World == this && filter.Accepts(body)
                && QueryGeometry.RayCircle(origin, translation, body.position, body.radius, out float t) && t <= 1f)
            {
                InsertByFraction(hits, total++, BodyHit(body, origin, translation, t));
            }
        }

        ReadOnlySpan<StaticPlane> planes = Planes;
        for (int p = 0; p < planes.Length; p++)
        {
            if (filter.Accepts(planes[p]) && QueryGeometry.RayPlane(origin, translation, planes[p], out float t) && t <= 1f)
            {
                InsertByFraction(hits, total++, new RayHit(null, p, origin + t * translation, planes[p].Normal, t));
            }
        }

        return total;
    }

    /// <summary>
    /// The bodies containing <paramref name="point"/> (|point − centre| ≤ radius) and the planes it lies behind
    /// (in their solid side), written into <paramref name="results"/> as far as it holds.
    /// </summary>
    /// <returns>How many were found; may exceed <paramref name="results"/>.Length.</returns>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite.</exception>
    public int QueryPoint(Vector3 point, Span<Overlap> results, QueryFilter filter = default)
    {
        Guard.Finite(point, nameof(point));
        QueryGrid grid = CurrentQueryGrid();
        grid.GatherBox(point, point);
        int total = 0;
        foreach (int slot in grid.Candidates)
        {
            RigidBody body = grid.BodyAt(slot);
            if (body.World == this && filter.Accepts(body)
                && Vector3.DistanceSquared(point, body.position) <= body.radius * body.radius)
            {
                Append(results, ref total, new Overlap(body, -1));
            }
        }

        ReadOnlySpan<StaticPlane> planes = Planes;
        for (int p = 0; p < planes.Length; p++)
        {
            if (filter.Accepts(planes[p]) && planes[p].DistanceTo(point) <= 0)
            {
                Append(results, ref total, new Overlap(null, p));
            }
        }

        return total;
    }

    /// <summary>
    /// The bodies whose circle (sphere in 3-D) overlaps the circle of <paramref name="radius"/> about
    /// <paramref name="centre"/> (d &lt; r + r_body), and the planes it reaches into.
    /// </summary>
    /// <returns>How many were found; may exceed <paramref name="results"/>.Length.</returns>
    /// <exception cref="ArgumentException">The centre is not finite or the radius is not positive and finite.</exception>
    public int OverlapCircle(Vector3 centre, float radius, Span<Overlap> results, QueryFilter filter = default)
    {
        Guard.Finite(centre, nameof(centre));
        Guard.Positive(radius, nameof(radius));
        QueryGrid grid = CurrentQueryGrid();
        grid.GatherBox(centre - new Vector3(radius), centre + new Vector3(radius));
        int total = 0;
        foreach (int slot in grid.Candidates)
        {
            RigidBody body = grid.BodyAt(slot);
            float reach = radius + body.radius;
            if (body.World == this && filter.Accepts(body) && Vector3.DistanceSquared(centre, body.position) < reach * reach)
            {
                Append(results, ref total, new Overlap(body, -1));
            }
        }

        ReadOnlySpan<StaticPlane> planes = Planes;
        for (int p = 0; p < planes.Length; p++)
        {
            if (filter.Accepts(planes[p]) && planes[p].DistanceTo(centre) < radius)
            {
                Append(results, ref total, new Overlap(null, p));
            }
        }

        return total;
    }

    /// <summary>
    /// The bodies whose circle (sphere) overlaps the axis-aligned box from <paramref name="min"/> to
    /// <paramref name="max"/>, and the planes the box reaches behind. For a 2-D scene give min.Z ≤ 0 ≤ max.Z.
    /// </summary>
    /// <returns>How many were found; may exceed <paramref name="results"/>.Length.</returns>
    /// <exception cref="ArgumentException">A corner is not finite, or max is below min on some axis.</exception>
    public int OverlapBox(Vector3 min, Vector3 max, Span<Overlap> results, QueryFilter filter = default)
    {
        Guard.Finite(min, nameof(min));
        Guard.Finite(max, nameof(max));
        if (!(max.X >= min.X && max.Y >= min.Y && max.Z >= min.Z))
        {
            throw new ArgumentException($"max must be at least min on every axis, but min was {min} and max {max}.", nameof(max));
        }

        QueryGrid grid = CurrentQueryGrid();
        grid.GatherBox(min, max);
        int total = 0;
        foreach (int slot in grid.Candidates)
        {
            RigidBody body = grid.BodyAt(slot);
            if (body.World == this && filter.Accepts(body) && QueryGeometry.BoxOverlapsCircle(min, max, body.position, body.radius))
            {
                Append(results, ref total, new Overlap(body, -1));
            }
        }

        ReadOnlySpan<StaticPlane> planes = Planes;
        for (int p = 0; p < planes.Length; p++)
        {
            if (filter.Accepts(planes[p]) && QueryGeometry.BoxOverlapsPlane(min, max, planes[p]))
            {
                Append(results, ref total, new Overlap(null, p));
            }
        }

        return total;
    }

    /// <summary>The query grid, rebuilt if a step ran, <see cref="RefreshQueries"/> was called or the body count changed.</summary>
    private QueryGrid CurrentQueryGrid()
    {
        if (_queryGrid.Version != _queryVersion || _queryGrid.BodyCount != _bodyCount)
        {
            _queryGrid.Build(AllBodies, _queryVersion);
        }

        return _queryGrid;
    }

    private static void CheckRay(Vector3 origin, Vector3 translation)
    {
        Guard.Finite(origin, nameof(origin));
        Guard.Finite(translation, nameof(translation));
        if (translation == Vector3.Zero)
        {
            throw new ArgumentException("translation must not be zero: it gives the ray's direction and length.", nameof(translation));
        }
    }

    private static RayHit BodyHit(RigidBody body, Vector3 origin, Vector3 translation, float t)
    {
        Vector3 point = origin + t * translation;
        return new RayHit(body, -1, point, Vector3.Normalize(point - body.position), t);
    }

    private static void Append(Span<Overlap> results, ref int total, in Overlap found)
    {
        if (total < results.Length)
        {
            results[total] = found;
        }

        total++;
    }

    /// <summary>
    /// Inserts a hit into the first min(<paramref name="countSoFar"/>, length) slots of <paramref name="hits"/>,
    /// kept sorted by fraction; when full, the farthest falls off the end (insertion sort: rays hit few bodies).
    /// </summary>
    private static void InsertByFraction(Span<RayHit> hits, int countSoFar, in RayHit hit)
    {
        int filled = Math.Min(countSoFar, hits.Length);
        int at = filled;
        while (at > 0 && hits[at - 1].Fraction > hit.Fraction)
        {
            at--;
        }

        if (at >= hits.Length)
        {
            return;
        }

        for (int k = Math.Min(filled, hits.Length - 1); k > at; k--)
        {
            hits[k] = hits[k - 1];
        }

        hits[at] = hit;
    }
}
