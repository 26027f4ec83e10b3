using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Collision;

/// <summary>
/// Broad phase on a uniform grid stored in a spatial hash: each body is entered in every cell its bounding box
/// touches, and only bodies sharing a cell are tested. Expected O(n) for bodies of similar size.
/// </summary>
/// <remarks>
/// <para><b>Why a grid</b> (measured in <c>benchmarks/</c>, see its README). Timing one detection on a settled
/// 2-D pit, sort-and-sweep (in the benchmark project) beats this grid by 3–3.6× at 1,000 bodies and by 1–1.6× at
/// 4,000 (equal or ten-fold mixed radii), but grows faster with N (14–19× against 6× from 1,000 to 4,000); both
/// beat brute force by 12–50×. Timing whole steps at 16,000 bodies (with an earlier solver), sort-and-sweep
/// was faster on the 2-D pit and the smash but almost three times slower on the 3-D pit (28 → 77 ms), because a
/// sweep along one axis meets every body in a slab, about n^(2/3) of them in 3-D, while a grid cell holds a few.
/// The grid is kept as the default for its even behaviour in 2-D and 3-D; its constant factor is the next thing
/// to improve.</para>
/// <para><b>A dense grid when the world is compact.</b> When the cells the bodies' boxes span are no more than the
/// hash table would have buckets (a pit, a pile, a crowd), every cell gets a bucket of its own, numbered row by row
/// (x, then y, then z), instead of a hashed one. No two cells share a bucket then, and the pairs are found cell by
/// cell through the world, so the bodies they read follow one another in space instead of jumping across it. A
/// world with a body far from the rest would need too many cells, and is hashed.</para>
/// <para><b>Exactly once.</b> A pair is reported only in the cell that holds the minimum corner of the
/// intersection of the two bounding boxes, the one cell both bodies are certain to share; so no pair is found
/// twice and no set of seen pairs is needed.</para>
/// <para><b>Cell size</b> is twice the mean radius of the grid's spheres (each body's reach grown by a skin), chosen
/// anew at each build; along an axis the whole world spans no more than two cells of, there is one layer (a 2-D world
/// in z = 0 would otherwise straddle two). A body that would cover more than <see cref="MaxCellsPerBody"/> cells (a
/// huge ground disc, say) is kept out of the grid and tested against every body instead.</para>
/// <para><b>Kept pairs.</b> The pairs whose grown spheres meet are kept, and a later call in which every body still
/// lies inside its grown sphere tests only those instead of building the grid (a Verlet neighbour list, see
/// SpatialHashDetector.KeptPairs.cs): a resting pile keeps them step after step. Either way the same contacts are
/// reported.</para>
/// <para>All working arrays are kept and reused: once warm, a step allocates nothing. They shrink when asked
/// (<see cref="TrimExcess"/>) or once calls have long needed far less than they hold (120 calls using less than a
/// quarter: see <see cref="World.TrimExcess"/>).</para>
/// </remarks>
public sealed partial class SpatialHashDetector : ICollisionDetector, ITrimmable
{
    /// <summary>A body covering more cells than this is tested directly against all others.</summary>
    public const int MaxCellsPerBody = 64;

    private const int CellLimit = 1 << 20; // cell coordinates are clamped here: far-away bodies share edge cells

    private const int InitialBodies = 16;
    private const int InitialBuckets = 16;
    private const int InitialOversized = 4;

    private Bounds[] _bounds = new Bounds[InitialBodies];
    private Entry[] _entries = new Entry[InitialBodies];
    private int[] _bucketStart = new int[InitialBuckets + 1];
    private int[] _oversized = new int[InitialOversized];
    private int _oversizedCount;
    private int _entriesReserved, _bucketStartsReserved; // by the last call that built the grid (PrepareBuckets)
    private bool _dense; // whether this call numbers cells as a dense grid (PrepareBuckets)
    private Cell _gridLow; // the dense grid's first cell, and its size in cells along x and y
    private int _gridColumns, _gridRows;
    private ShrinkPolicy _boundsRoom, _entryRoom, _bucketRoom, _oversizedRoom;

    /// <summary>The (cell, body) entries of the grid the last call with two bodies or more built or kept pairs from, for tests.</summary>
    internal int LastEntryCount { get; private set; }

    /// <summary>Whether the grid the last call with two bodies or more built or kept pairs from was dense (see the remarks), for tests.</summary>
    internal bool LastUsedDenseGrid => _dense;

    /// <inheritdoc />
    public void FindContacts(ReadOnlySpan<RigidBody> bodies, CollisionData collisions, float margin = 0f, float lookahead = 0f)
    {
        Guard.NotNull(collisions, nameof(collisions));
        Guard.NonNegative(margin, nameof(margin));
        Guard.NonNegative(lookahead, nameof(lookahead));
        Guard.NoNullElements(bodies, nameof(bodies));
        int n = bodies.Length;
        if (n < 2)
        {
            ForgetKeptPairs();
            ShrinkIfIdle(0, 0, 0);
            return;
        }

        Vector3 inverseCellSize = GatherBounds(bodies, 0.5f * margin, lookahead, out Vector3 lowest, out Vector3 highest, out bool keptPairsHold);
        LastCallKeptPairs = keptPairsHold;
        if (keptPairsHold)
        {
            FindKeptPairs(bodies, collisions, margin, lookahead); // see SpatialHashDetector.KeptPairs.cs
            FindPairsWithOversized(bodies, collisions, margin, lookahead);
            ShrinkIfIdle(n, _entriesReserved, _bucketStartsReserved); // the grid's arrays as the call that built it used them
            return;
        }

        int entryCount = LastEntryCount = CountEntries(n, inverseCellSize, out int mostEntries);
        int lastBucket = PrepareBuckets(entryCount, mostEntries, inverseCellSize, lowest, highest);
        FillBuckets(n, lastBucket);
        // The kept pairs are forgotten before the build refills them: a build cut short (a game's collision filter that
        // throws) then leaves no partial list that a later call could trust.
        ForgetKeptPairs();
        FindPairsInBuckets(bodies, lastBucket, collisions, margin, lookahead);
        FindPairsWithOversized(bodies, collisions, margin, lookahead);
        EndKeeping(n);
        ShrinkIfIdle(n, _entriesReserved, _bucketStartsReserved);
    }

    /// <summary>
    /// Releases the spare room of the working arrays, and forgets the kept pairs (the next call builds the grid). The
    /// arrays are shared by every world the detector serves, and the kept pairs only save work, so all of it goes,
    /// whichever <paramref name="world"/> asks. <see cref="World.TrimExcess"/> calls it.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="world"/> is null.</exception>
    public void TrimExcess(World world)
    {
        Guard.NotNull(world, nameof(world));
        Buffers.ShrinkTo(ref _bounds, InitialBodies, 0);
        Buffers.ShrinkTo(ref _entries, InitialBodies, 0);
        Buffers.ShrinkTo(ref _bucketStart, InitialBuckets + 1, 0);
        Buffers.ShrinkTo(ref _oversized, InitialOversized, 0);
        ForgetKeptPairs();
        Buffers.ShrinkTo(ref _keptSpheres, InitialBodies, 0);
        Buffers.ShrinkTo(ref _keptPairs, InitialBodies, 0);
    }

    /// <summary>Applies the <see cref="ShrinkPolicy"/> after each call, one call being one step of a world.</summary>
    private void ShrinkIfIdle(int bodies, int entries, int bucketStarts)
    {
        Buffers.ShrinkIfIdle(ref _bounds, bodies, ref _boundsRoom, InitialBodies);
        Buffers.ShrinkIfIdle(ref _entries, entries, ref _entryRoom, InitialBodies);
        Buffers.ShrinkIfIdle(ref _bucketStart, bucketStarts, ref _bucketRoom, InitialBuckets + 1);
        Buffers.ShrinkIfIdle(ref _oversized, _oversizedCount, ref _oversizedRoom, InitialOversized);
        Buffers.ShrinkIfIdle(ref _keptSpheres, Math.Max(_keptSphereCount, 0), ref _keptSphereRoom, InitialBodies);
        Buffers.ShrinkIfIdle(ref _keptPairs, _keptPairCount, ref _keptPairRoom, InitialBodies);
    }

    /// <summary>
    /// Copies centres and reaches, each radius grown by half the margin and by the distance the body travels in
    /// the lookahead, so that every pair the exact test may accept has meeting spheres; the grid is laid over those
    /// spheres grown by the skin (see SpatialHashDetector.KeptPairs.cs), so that the pairs whose grown spheres meet
    /// share a cell. Returns the inverse cell size along each axis: 0 along an axis the bodies' boxes span no more
    /// than two cells of (all of them share one layer of cells there), so that a flat world, a 2-D one in the plane
    /// z = 0 above all, is not entered twice, once in each of two layers that its boxes straddle.
    /// <paramref name="lowest"/> and <paramref name="highest"/> are the corners of the box around every body's grown
    /// sphere. <paramref name="keptPairsHold"/> tells whether the pairs kept from an earlier call still hold every
    /// pair of bodies in the grid whose spheres meet now (see <see cref="StillInside"/>; the bodies too large for the
    /// grid are tested against all).
    /// </summary>
    private Vector3 GatherBounds(ReadOnlySpan<RigidBody> bodies, float halfMargin, float lookahead, out Vector3 lowest, out Vector3 highest, out bool keptPairsHold)
    {
        Buffers.EnsureCapacity(ref _bounds, bodies.Length);
        double radiusSum = 0;
        var low = new Vector3(float.PositiveInfinity);
        var high = new Vector3(float.NegativeInfinity);
        bool hold = bodies.Length == _keptSphereCount;
        for (int i = 0; i < bodies.Length; i++)
        {
            RigidBody body = bodies[i];
            // The sphere around the middle of the body's path (see ContactGeometry.TryCollide).
            float speed = Vectors.Length(body.linearVelocity);
            float reach = body.radius + halfMargin + 0.5f * lookahead * speed;
            // Grown by a rounding allowance, so that pairs that touch to within float rounding share a cell.
            Vector3 c = ContactGeometry.Unchecked.PathMiddle(body, lookahead);
            reach += 1e-6f * (MathF.Abs(c.X) + MathF.Abs(c.Y) + MathF.Abs(c.Z) + reach);
            float grown = (1f + Skin) * reach;
            _bounds[i] = new Bounds { Centre = c, Reach = reach, Radius = grown, Speed = speed };
            hold = hold && StillInside(i, c, reach);
            radiusSum += grown;
            low = Vector3.Min(low, c - new Vector3(grown));
            high = Vector3.Max(high, c + new Vector3(grown));
        }

        keptPairsHold = hold;

        lowest = low;
        highest = high;

        float cellSize = (float)(2 * radiusSum / bodies.Length);
        Vector3 extent = high - low;
        float inverse = 1f / cellSize;
        return new Vector3(
            extent.X <= 2 * cellSize ? 0f : inverse,
            extent.Y <= 2 * cellSize ? 0f : inverse,
            extent.Z <= 2 * cellSize ? 0f : inverse);
    }

    private void FindPairsInBuckets(ReadOnlySpan<RigidBody> bodies, int lastBucket, CollisionData collisions, float margin, float lookahead)
    {
        for (int k = 0; k <= lastBucket; k++)
        {
            int start = _bucketStart[k], end = _bucketStart[k + 1];
            for (int p = start; p < end; p++)
            {
                Entry first = _entries[p];
                for (int q = p + 1; q < end; q++)
                {
                    Entry second = _entries[q];
                    if (!first.Cell.Equals(second.Cell))
                    {
                        continue; // another cell that hashed to the same bucket
                    }

                    int i = Math.Min(first.Body, second.Body), j = Math.Max(first.Body, second.Body);
                    if (!first.Cell.Equals(OwnerCell(i, j)))
                    {
                        continue; // this pair is reported in another cell (most pairs of a moving crowd share several)
                    }

                    float grown = _bounds[i].Radius + _bounds[j].Radius;
                    if (Vectors.DistanceSquared(_bounds[i].Centre, _bounds[j].Centre) >= grown * grown)
                    {
                        continue; // the grown spheres do not meet
                    }

                    KeepPair(i, j);
                    TryPair(bodies, i, j, collisions, margin, lookahead);
                }
            }
        }
    }

    private void FindPairsWithOversized(ReadOnlySpan<RigidBody> bodies, CollisionData collisions, float margin, float lookahead)
    {
        for (int o = 0; o < _oversizedCount; o++)
        {
            int big = _oversized[o];
            for (int j = 0; j < bodies.Length; j++)
            {
                // Pairs of two oversized bodies are taken once, from the one with the lower index.
                if (j == big || (_bounds[j].Oversized && j < big))
                {
                    continue;
                }

                int a = Math.Min(big, j), b = Math.Max(big, j);
                if (ContactGeometry.Unchecked.TryCollide(bodies[a], bodies[b], margin, lookahead, out Contact contact))
                {
                    collisions.Add(contact);
                }
            }
        }
    }

    /// <summary>
    /// The exact test for a pair whose grown spheres meet: whether the spheres themselves meet, then
    /// <see cref="ContactGeometry.TryCollide(RigidBody, RigidBody, float, float, out Contact)"/>.
    /// </summary>
    private void TryPair(ReadOnlySpan<RigidBody> bodies, int i, int j, CollisionData collisions, float margin, float lookahead)
    {
        float reach = _bounds[i].Reach + _bounds[j].Reach;
        if (Vectors.DistanceSquared(_bounds[i].Centre, _bounds[j].Centre) < reach * reach) // else the spheres do not meet
        {
            Collide(bodies, i, j, collisions, margin, lookahead);
        }
    }

    /// <summary>The exact test of a pair (i &lt; j), adding its contact if it passes.</summary>
    private void Collide(ReadOnlySpan<RigidBody> bodies, int i, int j, CollisionData collisions, float margin, float lookahead)
    {
        if (ContactGeometry.Unchecked.TryCollide(bodies[i], bodies[j], _bounds[i].Speed, _bounds[j].Speed, margin, lookahead, out Contact contact))
        {
            collisions.Add(contact);
        }
    }

    private struct Bounds
    {
        public Vector3 Centre;
        public float Reach; // the sphere around the middle of the body's path, as the exact test may accept it
        public float Radius; // that grown by the skin: what the grid holds
        public float Speed; // |v|, for the exact test of a pair
        public Cell Min;
        public Cell Max;
        public bool Oversized;
    }
}
