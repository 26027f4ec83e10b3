using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Collision;

/// <summary>
/// The pairs kept from one call to the next: a Verlet neighbour list (L. Verlet, "Computer 'Experiments' on Classical
/// Fluids. I.", <i>Physical Review</i> 159, 98–103, 1967, https://doi.org/10.1103/PhysRev.159.98).
/// </summary>
/// <remarks>
/// <para>A call that builds the grid lays it over every body's sphere grown by a skin (a quarter of its reach) and keeps
/// the pairs whose grown spheres meet, by the bodies' places in the order, with each grown sphere as it was. A later
/// call over as many bodies, in which the sphere of the body in each place still lies inside the grown sphere kept for
/// that place, needs no grid: two spheres that meet now lie inside grown spheres that met then, so every pair that can
/// be reported now is among those kept. Those pairs alone are tested, by the exact test that the grid's pairs end with
/// (<see cref="ContactGeometry.TryCollide(RigidBody, RigidBody, float, float, out Contact)"/>): the same contacts are
/// reported, in the order of the call that kept them. A body added or removed, or one out of its place's grown sphere
/// (moved far, a teleport, a fast body, a body that grew), makes the call build the grid again; another body put in a
/// place, inside its grown sphere, does not, and needs not.</para>
/// <para><b>Rounding.</b> The spheres are compared in float. A body counts as inside only if it is so by 10⁻⁶ of its
/// grown sphere's size and distance from the origin, about sixteen times the float rounding of the distances involved
/// (of the centres' differences, then and now): so two spheres that meet by the float test now always met by the
/// float test then. Far from the origin that allowance eats the skin (a body 250,000 reaches out can never stay
/// inside), and such a world builds its grid at every call, as before pairs were kept.</para>
/// <para>A settled pile moves by micrometres a step and keeps its pairs for as long as it rests: a step's detection is
/// then a pass over the bodies and one over the kept pairs. A pile still landing outruns its skins in a step or two and
/// pays for keeping the pairs at each build.</para>
/// <para>A body too large for the grid (<see cref="MaxCellsPerBody"/>) is tested against every other at each call, as
/// when the grid is built; the pairs kept are those of the bodies in the grid. Which bodies those are is decided when
/// the grid is built, and kept with the pairs: every pair is then tested exactly once, one way or the other.</para>
/// </remarks>
public sealed partial class SpatialHashDetector
{
    /// <summary>
    /// How much the grid's spheres are grown beyond the reach the exact test may accept, as a fraction of it. A quarter
    /// keeps the nearest neighbours of a packed pile only (in a hexagonal packing of discs the next ring lies at 1.73
    /// times the nearest), while a body may move by a quarter of its reach (its radius and half the margin, when at rest),
    /// less the rounding allowance, before the pairs are found again.
    /// </summary>
    private const float Skin = 0.25f;

    private KeptSphere[] _keptSpheres = new KeptSphere[InitialBodies];
    private KeptPair[] _keptPairs = new KeptPair[InitialBodies];
    private int _keptSphereCount = -1; // the bodies the kept pairs were found among; −1 when none are kept
    private int _keptPairCount;
    private ShrinkPolicy _keptSphereRoom, _keptPairRoom;

    /// <summary>Whether the last call with two bodies or more tested the kept pairs instead of building the grid, for tests.</summary>
    internal bool LastCallKeptPairs { get; private set; }

    /// <summary>
    /// Whether the sphere of <paramref name="reach"/> around <paramref name="centre"/> of the body in place
    /// <paramref name="i"/> lies inside the grown sphere kept for that place, by the rounding allowance (see the remarks).
    /// </summary>
    private bool StillInside(int i, Vector3 centre, float reach)
    {
        ref KeptSphere kept = ref _keptSpheres[i];
        return Vectors.Distance(centre, kept.Centre) + reach <= kept.Limit;
    }

    /// <summary>Forgets the kept pairs: the next call builds the grid (internal for the benchmarks, which time a build).</summary>
    internal void ForgetKeptPairs()
    {
        _keptSphereCount = -1;
        _keptPairCount = 0;
    }

    /// <summary>Keeps a pair whose grown spheres meet (i &lt; j).</summary>
    private void KeepPair(int i, int j)
    {
        Buffers.EnsureCapacity(ref _keptPairs, _keptPairCount + 1);
        _keptPairs[_keptPairCount++] = new KeptPair { First = i, Second = j };
    }

    /// <summary>Keeps each body's grown sphere with the pairs found.</summary>
    private void EndKeeping(int n)
    {
        Buffers.EnsureCapacity(ref _keptSpheres, n);
        for (int i = 0; i < n; i++)
        {
            ref Bounds b = ref _bounds[i];
            float allowance = 1e-6f * (MathF.Abs(b.Centre.X) + MathF.Abs(b.Centre.Y) + MathF.Abs(b.Centre.Z) + b.Radius);
            _keptSpheres[i] = new KeptSphere { Centre = b.Centre, Limit = b.Radius - allowance };
        }

        _keptSphereCount = n;
        // Half as much room again: a later build, over the same bodies shifted, may keep a few more pairs, and then
        // finds room instead of allocating (builds are rare once pairs are kept).
        Buffers.EnsureCapacity(ref _keptPairs, _keptPairCount + _keptPairCount / 2);
    }

    /// <summary>
    /// Tests the kept pairs, in the order they were found, by the exact test alone: the grid's test of the spheres
    /// before it, which the exact test repeats, is left out, since in a resting pile nearly every kept pair passes it
    /// (the settled 2-D pits stepped 3 % faster without it, the 3-D pit no slower). The bodies too large for the grid when
    /// it was built are marked so again, for <see cref="FindPairsWithOversized"/> to test against every other.
    /// </summary>
    private void FindKeptPairs(ReadOnlySpan<RigidBody> bodies, CollisionData collisions, float margin, float lookahead)
    {
        foreach (int big in _oversized.AsSpan(0, _oversizedCount))
        {
            _bounds[big].Oversized = true;
        }

        foreach (KeptPair pair in _keptPairs.AsSpan(0, _keptPairCount))
        {
            Collide(bodies, pair.First, pair.Second, collisions, margin, lookahead);
        }
    }

    private struct KeptSphere
    {
        public Vector3 Centre;
        public float Limit; // the grown radius less the rounding allowance: how far the sphere may reach from the centre
    }

    private struct KeptPair
    {
        public int First, Second;
    }
}
