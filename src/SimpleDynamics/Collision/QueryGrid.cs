using System;
using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// The broad phase of the world's queries: a dense uniform grid over the bodies' current bounding boxes, each
/// cell listing the bodies whose box touches it (compressed rows: one array of entries, one of cell starts).
/// </summary>
/// <remarks>
/// Detection's own grid (<see cref="SpatialHashDetector"/>) is built from the positions at the start of a step (or
/// of an earlier one, while its kept pairs hold), so after the step it is out of date; this one is built lazily by the world from the positions at the time
/// of the first query after a step, and kept until the next step. Cells are about a body across, grown until
/// there are no more than about two cells per body, so a ray walks few empty cells and a small box touches
/// few cells. A body whose box spans more than <see cref="MaxCellsPerBody"/> cells is kept on a short list
/// and tested by every query instead. All arrays only grow, so a warm grid allocates nothing.
/// </remarks>
internal sealed partial class QueryGrid
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
