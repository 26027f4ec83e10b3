using System;
using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// The broad phase of the world's queries: a dense uniform grid over the bodies' current bounding boxes, each
/// cell listing the bodies whose box touches it (compressed rows: one array of entries, one of cell starts).
/// </summary>
/// <remarks>
/// Detection's own grid (<see cref="SpatialHashDetector"/>) is built from the positions at the start of a step,
/// so after the step it is out of date; this one is built lazily by the world from the positions at the time
/// of the first query after a step, and kept until the next step. Cells are about a body across, grown until
/// there are no more than about two cells per body, so a ray walks few empty cells and a small box touches
/// few cells. A body whose box spans more than <see cref="MaxCellsPerBody"/> cells is kept on a short list
/// and tested by every query instead. All arrays only grow, so a warm grid allocates nothing.
/// </remarks>
internal sealed class QueryGrid
{
    private const int MaxCellsPerBody = 64;

    private const int InitialBodies = 16;
    private const int InitialCells = 64;
    private const int InitialOversized = 4;

    private RigidBody[] _bodies = new RigidBody[InitialBodies];
    private Cell[] _low = new Cell[InitialBodies];
    private Cell[] _high = new Cell[InitialBodies];
    private int _count;
    private int[] _cellStart = new int[InitialCells + 1];
    private int _cellCount;
    private int[] _entries = new int[InitialBodies];
    private int _entryCount;
    private int[] _oversized = new int[InitialOversized];
    private int _oversizedCount;
    private int[] _candidates = new int[InitialBodies];
    private int _candidateCount;
    private int _candidatePeak; // the most candidates one query gathered since the last build

    // _testedBy[slot] == _query marks a body already gathered by the current query.
    private int[] _testedBy = new int[InitialBodies];
    private int _query;

    // The ShrinkPolicy, applied at each build (at most once per step).
    private ShrinkPolicy _bodyRoom, _cellRoom, _entryRoom, _oversizedRoom, _candidateRoom;

    private Vector3 _origin;
    private float _cellSize = 1f;
    private float _inverseCellSize = 1f;
    private int _nx, _ny, _nz;

    /// <summary>The world's position version this grid was built for.</summary>
    public long Version { get; private set; } = -1;

    /// <summary>How many bodies the grid was built over.</summary>
    public int BodyCount => _count;

    /// <summary>The bodies gathered by the last <see cref="GatherBox"/> or <see cref="GatherRay"/>, as slots.</summary>
    public ReadOnlySpan<int> Candidates => _candidates.AsSpan(0, _candidateCount);

    public RigidBody BodyAt(int slot) => _bodies[slot];

    public void Build(ReadOnlySpan<RigidBody> bodies, long version)
    {
        Array.Clear(_bodies, 0, _count);
        _count = bodies.Length;
        Version = version;
        _oversizedCount = 0;
        Buffers.EnsureCapacity(ref _bodies, _count);
        Buffers.EnsureCapacity(ref _low, _count);
        Buffers.EnsureCapacity(ref _high, _count);
        Buffers.EnsureCapacity(ref _testedBy, _count);
        Array.Clear(_testedBy, 0, _count);
        _query = 0;
        if (_count == 0)
        {
            _nx = _ny = _nz = 0;
            _cellCount = _entryCount = 0;
            ShrinkIfIdle();
            return;
        }

        Vector3 min = new(float.MaxValue), max = new(float.MinValue);
        double radiusSum = 0;
        for (int i = 0; i < _count; i++)
        {
            RigidBody body = bodies[i];
            _bodies[i] = body;
            float reach = Reach(body);
            min = Vector3.Min(min, body.position - new Vector3(reach));
            max = Vector3.Max(max, body.position + new Vector3(reach));
            radiusSum += body.radius;
        }

        ChooseCells(min, max, (float)(2 * radiusSum / _count));
        int cellCount = _nx * _ny * _nz;
        Buffers.EnsureCapacity(ref _cellStart, cellCount + 1);
        Array.Clear(_cellStart, 0, cellCount + 1);

        // Counting sort of (cell, body) entries by cell: count, prefix sum, fill.
        int entryCount = 0;
        for (int i = 0; i < _count; i++)
        {
            RigidBody body = _bodies[i];
            float reach = Reach(body);
            _low[i] = CellOf(body.position - new Vector3(reach));
            _high[i] = CellOf(body.position + new Vector3(reach));
            long cells = (long)(_high[i].X - _low[i].X + 1) * (_high[i].Y - _low[i].Y + 1) * (_high[i].Z - _low[i].Z + 1);
            if (cells > MaxCellsPerBody)
            {
                Buffers.EnsureCapacity(ref _oversized, _oversizedCount + 1);
                _oversized[_oversizedCount++] = i;
                _high[i] = new Cell(-1, -1, -1); // an empty range: the fill below skips it
                continue;
            }

            entryCount += (int)cells;
            for (int z = _low[i].Z; z <= _high[i].Z; z++)
            for (int y = _low[i].Y; y <= _high[i].Y; y++)
            for (int x = _low[i].X; x <= _high[i].X; x++)
            {
                _cellStart[CellIndex(x, y, z) + 1]++;
            }
        }

        for (int c = 0; c < cellCount; c++)
        {
            _cellStart[c + 1] += _cellStart[c];
        }

        Buffers.EnsureCapacity(ref _entries, entryCount);
        for (int i = 0; i < _count; i++)
        {
            // _cellStart[c] advances as cell c fills; afterwards it holds the start of cell c + 1 ...
            for (int z = _low[i].Z; z <= _high[i].Z; z++)
            for (int y = _low[i].Y; y <= _high[i].Y; y++)
            for (int x = _low[i].X; x <= _high[i].X; x++)
            {
                _entries[_cellStart[CellIndex(x, y, z)]++] = i;
            }
        }

        // ... so shift the starts back by one cell.
        for (int c = cellCount; c > 0; c--)
        {
            _cellStart[c] = _cellStart[c - 1];
        }

        _cellStart[0] = 0;
        _cellCount = cellCount;
        _entryCount = entryCount;
        ShrinkIfIdle();
    }

    /// <summary>
    /// Applies the <see cref="ShrinkPolicy"/> after a build, keeping what the queries until the next build read. A build
    /// happens at most once per step, when the world is first queried (or has sensors), so an unqueried world's grid
    /// keeps its arrays until <see cref="TrimExcess"/>.
    /// </summary>
    private void ShrinkIfIdle()
    {
        int room = _bodyRoom.Observe(_count, _bodies.Length, InitialBodies);
        if (room > 0)
        {
            Buffers.ShrinkTo(ref _bodies, room, _count);
            Buffers.ShrinkTo(ref _low, room, _count);
            Buffers.ShrinkTo(ref _high, room, _count);
            Buffers.ShrinkTo(ref _testedBy, room, _count);
        }

        Buffers.ShrinkIfIdle(ref _cellStart, _cellCount + 1, ref _cellRoom, InitialCells + 1);
        Buffers.ShrinkIfIdle(ref _entries, _entryCount, ref _entryRoom, InitialBodies);
        Buffers.ShrinkIfIdle(ref _oversized, _oversizedCount, ref _oversizedRoom, InitialOversized);
        // A query may gather every body: the candidates' use is the bodies, not what the queries since happened to gather.
        Buffers.ShrinkIfIdle(ref _candidates, Math.Max(_candidatePeak, _count), ref _candidateRoom, InitialBodies);
        _candidatePeak = 0;
    }

    /// <summary>Gives back all the spare room; the grid is built afresh at the next query.</summary>
    public void TrimExcess()
    {
        Array.Clear(_bodies, 0, _count);
        _count = _cellCount = _entryCount = _oversizedCount = _candidateCount = _candidatePeak = 0;
        _nx = _ny = _nz = 0;
        Version = -1;
        _bodies = new RigidBody[InitialBodies];
        _low = new Cell[InitialBodies];
        _high = new Cell[InitialBodies];
        _testedBy = new int[InitialBodies];
        _cellStart = new int[InitialCells + 1];
        _entries = new int[InitialBodies];
        _oversized = new int[InitialOversized];
        _candidates = new int[InitialBodies];
    }

    /// <summary>Gathers, once each, the bodies whose cells the box [min, max] touches, and the oversized bodies.</summary>
    public void GatherBox(Vector3 min, Vector3 max)
    {
        StartQuery();
        if (_count == 0)
        {
            return;
        }

        GatherOversized();
        Cell low = CellOf(min), high = CellOf(max);
        for (int z = low.Z; z <= high.Z; z++)
        for (int y = low.Y; y <= high.Y; y++)
        for (int x = low.X; x <= high.X; x++)
        {
            GatherCell(CellIndex(x, y, z));
        }
    }

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

    private void StartQuery()
    {
        _candidatePeak = Math.Max(_candidatePeak, _candidateCount);
        _candidateCount = 0;
        if (++_query == int.MaxValue)
        {
            Array.Clear(_testedBy, 0, _count);
            _query = 1;
        }
    }

    private void GatherOversized()
    {
        for (int o = 0; o < _oversizedCount; o++)
        {
            Gather(_oversized[o]);
        }
    }

    private void GatherCell(int cell)
    {
        for (int e = _cellStart[cell]; e < _cellStart[cell + 1]; e++)
        {
            Gather(_entries[e]);
        }
    }

    private void Gather(int slot)
    {
        if (_testedBy[slot] != _query)
        {
            _testedBy[slot] = _query;
            Buffers.EnsureCapacity(ref _candidates, _candidateCount + 1);
            _candidates[_candidateCount++] = slot;
        }
    }

    /// <summary>
    /// Cells about a body across (the mean diameter), grown by 2^(1/3) until there are at most about two cells
    /// per body, so that one far-away body cannot make the grid huge.
    /// </summary>
    private void ChooseCells(Vector3 min, Vector3 max, float meanDiameter)
    {
        Vector3 extent = max - min;
        float size = MathF.Max(meanDiameter, 1e-6f * MathF.Max(extent.X, MathF.Max(extent.Y, extent.Z)));
        long limit = Math.Max(64, 2L * _count);
        while (true)
        {
            long nx = (long)(extent.X / size) + 1, ny = (long)(extent.Y / size) + 1, nz = (long)(extent.Z / size) + 1;
            if (nx * ny * nz <= limit)
            {
                _nx = (int)nx;
                _ny = (int)ny;
                _nz = (int)nz;
                break;
            }

            size *= 1.26f;
        }

        _origin = min;
        _cellSize = size;
        _inverseCellSize = 1f / size;
    }

    /// <summary>A body's half-width in the grid: its radius plus a rounding allowance, as the detector grows its boxes.</summary>
    private static float Reach(RigidBody body)
    {
        Vector3 c = body.position;
        return body.radius + 1e-5f * (MathF.Abs(c.X) + MathF.Abs(c.Y) + MathF.Abs(c.Z) + body.radius);
    }

    /// <summary>The cell holding a point, clamped into the grid.</summary>
    private Cell CellOf(Vector3 point)
    {
        Vector3 local = (point - _origin) * _inverseCellSize;
        return new Cell(Clamp(local.X, _nx), Clamp(local.Y, _ny), Clamp(local.Z, _nz));
    }

    private static int Clamp(float coordinate, int cells) =>
        coordinate <= 0 ? 0 : coordinate >= cells - 1 ? cells - 1 : (int)coordinate;

    private int CellIndex(int x, int y, int z) => (z * _ny + y) * _nx + x;

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

    private readonly struct Cell
    {
        public readonly int X;
        public readonly int Y;
        public readonly int Z;

        public Cell(int x, int y, int z)
        {
            X = x;
            Y = y;
            Z = z;
        }
    }
}
