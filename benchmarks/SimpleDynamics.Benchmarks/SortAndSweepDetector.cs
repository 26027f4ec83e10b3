using System;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// Sort-and-sweep on x, the broadphase the spatial hash is measured against (issue 4: choose by measurement).
/// Each call sorts the bodies' bounding intervals by their minimum x and sweeps: a body is tested against the
/// following ones while their intervals still start before its interval ends. The y and z extents are checked
/// from the same contiguous array before the exact test, so a pair that only overlaps on x costs no body access.
/// </summary>
/// <remarks>
/// Cost: O(n log n) for the sort plus the number of overlapping x-intervals, about √n per body in a settled
/// 2-D pit (a body's x-interval meets every body of its column). The sort starts from scratch every call: a
/// real engine would re-sort last step's order by insertion sort, which the benchmark, timing one detection on
/// a fixed snapshot, could not show anyway. Arrays are kept between calls, so a warm call allocates nothing.
/// </remarks>
public sealed class SortAndSweepDetector : ICollisionDetector
{
    private float[] _keys = new float[16];
    private Interval[] _intervals = new Interval[16];

    /// <inheritdoc />
    public void FindContacts(ReadOnlySpan<RigidBody> bodies, CollisionData collisions, float margin = 0f, float lookahead = 0f)
    {
        ArgumentNullException.ThrowIfNull(collisions);
        int n = bodies.Length;
        if (_keys.Length < n)
        {
            _keys = new float[Math.Max(n, 2 * _keys.Length)];
            _intervals = new Interval[_keys.Length];
        }

        for (int i = 0; i < n; i++)
        {
            RigidBody body = bodies[i];
            // The same sphere the exact test uses: around the middle of the path over the lookahead, of the radius, half
            // the margin and half the distance travelled.
            float r = body.Radius + 0.5f * margin + 0.5f * lookahead * body.LinearVelocity.Length();
            System.Numerics.Vector3 c = body.Position + body.LinearVelocity * (0.5f * lookahead);
            // Grown by a rounding allowance: pairs that touch to within float rounding must still reach the exact test.
            r += 1e-6f * (MathF.Abs(c.X) + MathF.Abs(c.Y) + MathF.Abs(c.Z) + r);
            _keys[i] = c.X - r;
            _intervals[i] = new Interval
            {
                MaxX = c.X + r, MinY = c.Y - r, MaxY = c.Y + r, MinZ = c.Z - r, MaxZ = c.Z + r, Body = i,
            };
        }

        Array.Sort(_keys, _intervals, 0, n);

        for (int a = 0; a < n; a++)
        {
            ref Interval first = ref _intervals[a];
            for (int b = a + 1; b < n && _keys[b] < first.MaxX; b++)
            {
                ref Interval second = ref _intervals[b];
                if (second.MinY >= first.MaxY || first.MinY >= second.MaxY || second.MinZ >= first.MaxZ || first.MinZ >= second.MaxZ)
                {
                    continue;
                }

                // The interface's order: A is the body earlier in the given list.
                int i = Math.Min(first.Body, second.Body), j = Math.Max(first.Body, second.Body);
                if (ContactGeometry.Unchecked.TryCollide(bodies[i], bodies[j], margin, lookahead, out Contact contact))
                {
                    collisions.Add(contact);
                }
            }
        }
    }

    private struct Interval
    {
        public float MaxX, MinY, MaxY, MinZ, MaxZ;
        public int Body;
    }
}
