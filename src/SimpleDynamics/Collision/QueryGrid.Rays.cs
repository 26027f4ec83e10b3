using System;
using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

// Rays through the query grid: the cells a segment crosses, in its order, and the nearest body it enters.
internal sealed partial class QueryGrid
{
    /// <summary>Gathers, once each, the bodies in the cells the segment from o to o + d crosses, and the oversized bodies.</summary>
    public void GatherRay(Vector3 origin, Vector3 direction)
    {
        StartQuery();
        GatherOversized();
        var unused = default(ClosestHit);
        WalkRay(origin, direction, closestOnly: false, ref unused);
    }

    /// <summary>
    /// The nearest body the segment o + t·d, t ∈ [0, 1], enters, walking the cells in the ray's order and
    /// stopping at the first cell that ends beyond the nearest hit so far. Returns its slot, or −1.
    /// </summary>
    public int RayClosest(Vector3 origin, Vector3 direction, in QueryFilter filter, World world, out float fraction)
    {
        StartQuery();
        var closest = new ClosestHit { Slot = -1, Fraction = 1f, Filter = filter, World = world };
        for (int o = 0; o < _oversizedCount; o++)
        {
            TestClosest(ref closest, _oversized[o], origin, direction);
        }

        WalkRay(origin, direction, closestOnly: true, ref closest);
        fraction = closest.Fraction;
        return closest.Slot;
    }

    private void WalkRay(Vector3 origin, Vector3 direction, bool closestOnly, ref ClosestHit closest)
    {
        if (_count == 0)
        {
            return;
        }

        // Clip the segment to the grid's box (slab test), then step cell to cell (Amanatides & Woo 1987,
        // "A Fast Voxel Traversal Algorithm for Ray Tracing").
        Vector3 gridMax = _origin + _cellSize * new Vector3(_nx, _ny, _nz);
        float enter = 0f, leave = 1f;
        if (!Clip(origin.X, direction.X, _origin.X, gridMax.X, ref enter, ref leave)
            || !Clip(origin.Y, direction.Y, _origin.Y, gridMax.Y, ref enter, ref leave)
            || !Clip(origin.Z, direction.Z, _origin.Z, gridMax.Z, ref enter, ref leave))
        {
            return;
        }

        Cell cell = CellOf(origin + enter * direction);
        int x = cell.X, y = cell.Y, z = cell.Z;
        Axis(origin.X, direction.X, _origin.X, x, out int stepX, out float nextX, out float deltaX);
        Axis(origin.Y, direction.Y, _origin.Y, y, out int stepY, out float nextY, out float deltaY);
        Axis(origin.Z, direction.Z, _origin.Z, z, out int stepZ, out float nextZ, out float deltaZ);
        int steps = _nx + _ny + _nz + 3; // a segment crosses at most this many cells; a guard against rounding
        while (steps-- > 0)
        {
            int c = CellIndex(x, y, z);
            if (!closestOnly)
            {
                GatherCell(c);
            }
            else
            {
                for (int e = _cellStart[c]; e < _cellStart[c + 1]; e++)
                {
                    TestClosest(ref closest, _entries[e], origin, direction);
                }
            }

            float exit = MathF.Min(nextX, MathF.Min(nextY, nextZ));
            // A hit point lies inside the box of the body hit, so in a cell listing that body: once the nearest
            // hit lies before this cell's exit, no later cell can hold a nearer one.
            if (exit > leave || (closestOnly && closest.Slot >= 0 && closest.Fraction <= exit))
            {
                return;
            }

            if (nextX <= nextY && nextX <= nextZ)
            {
                x += stepX;
                nextX += deltaX;
                if ((uint)x >= (uint)_nx)
                {
                    return;
                }
            }
            else if (nextY <= nextZ)
            {
                y += stepY;
                nextY += deltaY;
                if ((uint)y >= (uint)_ny)
                {
                    return;
                }
            }
            else
            {
                z += stepZ;
                nextZ += deltaZ;
                if ((uint)z >= (uint)_nz)
                {
                    return;
                }
            }
        }
    }

    private void TestClosest(ref ClosestHit closest, int slot, Vector3 origin, Vector3 direction)
    {
        if (_testedBy[slot] == _query)
        {
            return;
        }

        _testedBy[slot] = _query;
        RigidBody body = _bodies[slot];
        if (body.World == closest.World && closest.Filter.Accepts(body)
            && QueryGeometry.RayCircle(origin, direction, body.position, body.radius, out float t)
            && t <= closest.Fraction)
        {
            closest.Slot = slot;
            closest.Fraction = t;
        }
    }

    /// <summary>Narrows [enter, leave] to the part of the segment between two slabs of one axis.</summary>
    private static bool Clip(float origin, float direction, float low, float high, ref float enter, ref float leave)
    {
        if (direction == 0)
        {
            return origin >= low && origin <= high;
        }

        float t0 = (low - origin) / direction, t1 = (high - origin) / direction;
        if (t0 > t1)
        {
            (t0, t1) = (t1, t0);
        }

        enter = MathF.Max(enter, t0);
        leave = MathF.Min(leave, t1);
        return enter <= leave;
    }

    /// <summary>For one axis of the walk: the step direction, the t of the next cell boundary, and t per cell.</summary>
    private void Axis(float origin, float direction, float gridOrigin, int cell, out int step, out float next, out float delta)
    {
        if (direction > 0)
        {
            step = 1;
            next = (gridOrigin + (cell + 1) * _cellSize - origin) / direction;
            delta = _cellSize / direction;
        }
        else if (direction < 0)
        {
            step = -1;
            next = (gridOrigin + cell * _cellSize - origin) / direction;
            delta = -_cellSize / direction;
        }
        else
        {
            step = 0;
            next = float.PositiveInfinity;
            delta = float.PositiveInfinity;
        }
    }

    private struct ClosestHit
    {
        public int Slot;
        public float Fraction;
        public QueryFilter Filter;
        public World World;
    }
}
