using System;
using System.Numerics;

namespace SimpleDynamics.Collision;

/// <summary>
/// The grid itself: each body's range of cells, the buckets (a dense grid numbered row by row, or a hash), a counting
/// sort of the (cell, body) entries into them, and the one cell in which a pair is reported.
/// </summary>
public sealed partial class SpatialHashDetector
{
    /// <summary>
    /// Computes each body's cell range; counts grid entries and sets oversized bodies aside.
    /// <paramref name="mostEntries"/> is the most entries the same boxes could make at this cell size wherever they lay
    /// (a box of width w covers at most ⌈w / cell⌉ + 1 cells along an axis, and a body in the grid at most
    /// <see cref="MaxCellsPerBody"/>).
    /// </summary>
    private int CountEntries(int n, Vector3 inverseCellSize, out int mostEntries)
    {
        _oversizedCount = 0;
        int entries = 0;
        long most = 0;
        for (int i = 0; i < n; i++)
        {
            ref Bounds b = ref _bounds[i];
            Vector3 min = b.Centre - new Vector3(b.Radius), max = b.Centre + new Vector3(b.Radius);
            b.Min = CellOf(min, inverseCellSize);
            b.Max = CellOf(max, inverseCellSize);
            long cells = (long)(b.Max.X - b.Min.X + 1) * (b.Max.Y - b.Min.Y + 1) * (b.Max.Z - b.Min.Z + 1);
            if (cells > MaxCellsPerBody)
            {
                b.Oversized = true;
                Buffers.EnsureCapacity(ref _oversized, _oversizedCount + 1);
                _oversized[_oversizedCount++] = i;
            }
            else
            {
                b.Oversized = false;
                entries += (int)cells;
                most += Math.Min(MostCells(b.Radius, inverseCellSize.X) * MostCells(b.Radius, inverseCellSize.Y) * MostCells(b.Radius, inverseCellSize.Z), MaxCellsPerBody);
            }
        }

        mostEntries = (int)Math.Min(most, int.MaxValue / 4);
        return entries;
    }

    /// <summary>The most cells a box of half-width <paramref name="radius"/> can cover along an axis (1 along a flat one).</summary>
    private static long MostCells(float radius, float inverseCellSize) =>
        inverseCellSize == 0 ? 1 : (long)Math.Min(MathF.Ceiling(2 * radius * inverseCellSize) + 1, MaxCellsPerBody);

    /// <summary>A power of two at least twice the entries: the hashed grid's buckets.</summary>
    private static int BucketsFor(int entries)
    {
        int buckets = 16;
        while (buckets < 2 * entries)
        {
            buckets <<= 1;
        }

        return buckets;
    }

    /// <summary>
    /// Chooses the buckets and clears their counts; returns the last bucket's number. Hashed, there are a power of two
    /// at least twice the entries, and the last bucket's number masks the hash; as a dense grid, one per cell of the
    /// box around all bodies, when those are no more (see the remarks). The arrays get room for the most entries the
    /// bodies' boxes could make (<paramref name="mostEntries"/>): builds are rare once pairs are kept
    /// (SpatialHashDetector.KeptPairs.cs), and a later one over the same bodies shifted then finds room instead of
    /// allocating.
    /// </summary>
    private int PrepareBuckets(int entryCount, int mostEntries, Vector3 inverseCellSize, Vector3 lowest, Vector3 highest)
    {
        int buckets = BucketsFor(entryCount);

        Cell low = CellOf(lowest, inverseCellSize), high = CellOf(highest, inverseCellSize);
        long columns = high.X - low.X + 1L, rows = high.Y - low.Y + 1L, layers = high.Z - low.Z + 1L;
        _dense = columns * rows <= buckets && columns * rows * layers <= buckets; // in that order, so it cannot overflow
        if (_dense)
        {
            buckets = (int)(columns * rows * layers);
            _gridLow = low;
            _gridColumns = (int)columns;
            _gridRows = (int)rows;
        }

        _entriesReserved = Math.Max(entryCount, mostEntries);
        _bucketStartsReserved = Math.Max(buckets, BucketsFor(mostEntries)) + 1; // a dense grid has no more cells than hashed buckets
        Buffers.EnsureCapacity(ref _entries, _entriesReserved);
        Buffers.EnsureCapacity(ref _bucketStart, _bucketStartsReserved);
        Array.Clear(_bucketStart, 0, buckets + 1);
        return buckets - 1;
    }

    /// <summary>Counting sort of (cell, body) entries by bucket.</summary>
    private void FillBuckets(int n, int lastBucket)
    {
        // Count per bucket (shifted by one so that the prefix sum yields start offsets).
        for (int i = 0; i < n; i++)
        {
            ref Bounds b = ref _bounds[i];
            if (b.Oversized)
            {
                continue;
            }

            for (int z = b.Min.Z; z <= b.Max.Z; z++)
            for (int y = b.Min.Y; y <= b.Max.Y; y++)
            for (int x = b.Min.X; x <= b.Max.X; x++)
            {
                _bucketStart[BucketOf(x, y, z, lastBucket) + 1]++;
            }
        }

        for (int k = 1; k <= lastBucket + 1; k++)
        {
            _bucketStart[k] += _bucketStart[k - 1];
        }

        // Fill, advancing each bucket's start; afterwards _bucketStart[k] is the end of bucket k ...
        for (int i = 0; i < n; i++)
        {
            ref Bounds b = ref _bounds[i];
            if (b.Oversized)
            {
                continue;
            }

            for (int z = b.Min.Z; z <= b.Max.Z; z++)
            for (int y = b.Min.Y; y <= b.Max.Y; y++)
            for (int x = b.Min.X; x <= b.Max.X; x++)
            {
                int slot = _bucketStart[BucketOf(x, y, z, lastBucket)]++;
                _entries[slot] = new Entry { Body = i, Cell = new Cell(x, y, z) };
            }
        }

        // ... so shift back by one to restore the starts.
        for (int k = lastBucket + 1; k > 0; k--)
        {
            _bucketStart[k] = _bucketStart[k - 1];
        }

        _bucketStart[0] = 0;
    }

    /// <summary>
    /// The cell of the minimum corner of the intersection of two bounding boxes. That corner is the larger of the
    /// boxes' minimum corners along each axis, and the cell of a coordinate never decreases as it grows, so its cell
    /// is the larger of their minimum cells along each axis: integers already at hand, no rounding to redo.
    /// </summary>
    private Cell OwnerCell(int i, int j)
    {
        Cell a = _bounds[i].Min, b = _bounds[j].Min;
        return new Cell(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z));
    }

    private static Cell CellOf(Vector3 point, Vector3 inverseCellSize) =>
        new(CellOf(point.X, inverseCellSize.X), CellOf(point.Y, inverseCellSize.Y), CellOf(point.Z, inverseCellSize.Z));

    private static int CellOf(float coordinate, float inverseCellSize) =>
        (int)Math.Clamp(MathF.Floor(coordinate * inverseCellSize), -CellLimit, CellLimit);

    /// <summary>The bucket of a cell: its place in the dense grid, row by row, or its hash.</summary>
    private int BucketOf(int x, int y, int z, int lastBucket) => _dense
        ? x - _gridLow.X + _gridColumns * (y - _gridLow.Y + _gridRows * (z - _gridLow.Z))
        : Hash(x, y, z) & lastBucket;

    private static int Hash(int x, int y, int z) => unchecked((x * 73856093) ^ (y * 19349663) ^ (z * 83492791));

    private struct Entry
    {
        public int Body;
        public Cell Cell;
    }

    private readonly struct Cell : IEquatable<Cell>
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

        public bool Equals(Cell other) => X == other.X && Y == other.Y && Z == other.Z;
    }
}
