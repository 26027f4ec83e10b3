using System;
using System.Collections.Generic;
using System.Linq;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// Law 9: each detector finds exactly the overlapping pairs of a brute-force oracle written here in double
/// precision, each once, with A the earlier body, a unit normal from B to A and penetration r_A + r_B − d.
/// </summary>
/// <remarks>
/// <para><b>Borderline cases.</b> The library decides overlap in float; a pair whose distance lies within
/// float rounding of r_A + r_B (or of the coincidence threshold) could honestly go either way, so scenes with
/// such a pair are not generated: the margin is 1e-5 × (r_A + r_B) plus 1e-6 × (|c_A| + |c_B|), about ten
/// times the float error of a difference of the coordinates. Nothing else is excluded.</para>
/// <para><b>Tolerances</b> for normal and penetration follow from the same error: the float difference
/// c_A − c_B is off by ≈ ε_f (|c_A| + |c_B|), which divided by d is the error of the normal.</para>
/// </remarks>
public class DetectionLaws
{
    private static FsCheck.Gen<DetectionScene> Scenes { get; } = Generators.DetectionScene.Where(NoBorderlinePair);

    [Fact]
    public void BruteForceDetector_finds_exactly_the_overlapping_pairs() =>
        _ = Check(new BruteForceDetector(), seed: 401);

    [Fact]
    public void SpatialHashDetector_finds_exactly_the_overlapping_pairs()
    {
        (_, int hashed) = Check(new SpatialHashDetector(), seed: 402); // one instance for every scene: its reused buffers are tested too
        Assert.True(hashed >= 100, $"only {hashed} scenes hashed");
    }

    /// <summary>
    /// The same scenes crowded four times closer, with the far bodies brought into the crowd: most are then compact
    /// enough for the spatial hash's dense grid (see its remarks), whose cell numbering must find exactly the same pairs.
    /// </summary>
    [Fact]
    public void SpatialHashDetector_finds_exactly_the_overlapping_pairs_in_crowded_worlds()
    {
        (int dense, _) = Check(new SpatialHashDetector(), seed: 405, flatten: p => p.Length() > 1000 ? p * 1e-3f : p * 0.25f);
        Assert.True(dense >= 100, $"only {dense} scenes on the dense grid");
    }

    /// <summary>
    /// The same scenes flattened onto the plane z = 0 and onto the line y = z = 0: the grid then keeps one layer of
    /// cells along each flat axis (see <see cref="SpatialHashDetector"/>), and must still find exactly the pairs.
    /// </summary>
    [Fact]
    public void SpatialHashDetector_finds_exactly_the_overlapping_pairs_in_flat_worlds()
    {
        var detector = new SpatialHashDetector();
        Check(detector, seed: 403, flatten: p => new System.Numerics.Vector3(p.X, p.Y, 0));
        Check(detector, seed: 404, flatten: p => new System.Numerics.Vector3(p.X, 0, 0));
    }

    [Fact]
    public void A_2D_pit_is_entered_in_one_layer_of_cells()
    {
        RigidBody[] bodies = SimpleDynamics.Scenes.BallPit(300, planar: true).Bodies.ToArray();
        var detector = new SpatialHashDetector();
        detector.FindContacts(bodies, new CollisionData());
        // A box two cells wide at most covers 2 × 2 cells in the plane; two layers along z would double that.
        Assert.InRange(detector.LastEntryCount, bodies.Length, 4 * bodies.Length);
        Assert.True(detector.LastUsedDenseGrid, "a pit is compact: its cells are numbered as a dense grid");
    }

    /// <summary>
    /// Bodies a million metres out lie beyond the spatial hash's clamped cell range (2^20 cells of 0.7 m): they
    /// share edge cells, and each overlapping pair must still be found exactly once, and nothing else.
    /// </summary>
    [Fact]
    public void Far_away_bodies_beyond_the_grid_limit_are_found_once()
    {
        var bodies = new System.Collections.Generic.List<RigidBody>();
        for (int i = 0; i < 20; i++)
        {
            bodies.Add(new RigidBody(1f, 0.3f, new System.Numerics.Vector3(i, 0, 0)));
        }

        var a = new RigidBody(1f, 0.5f, new System.Numerics.Vector3(1e6f, 0, 0));
        var b = new RigidBody(1f, 0.5f, new System.Numerics.Vector3(1e6f + 0.75f, 0, 0));
        var c = new RigidBody(1f, 0.5f, new System.Numerics.Vector3(1e6f, 5, 0));
        var d = new RigidBody(1f, 0.5f, new System.Numerics.Vector3(2e6f, 0, 0));
        var e = RigidBody.CreateStatic(0.5f, new System.Numerics.Vector3(-3e6f, 0.25f, 0));
        var f = new RigidBody(1f, 0.5f, new System.Numerics.Vector3(-3e6f, 0, 0));
        bodies.AddRange(new[] { a, b, c, d, e, f });
        foreach (ICollisionDetector detector in new ICollisionDetector[] { new BruteForceDetector(), new SpatialHashDetector() })
        {
            var collisions = new CollisionData();
            detector.FindContacts(bodies.ToArray(), collisions);
            Assert.Equal(2, collisions.Count);
            Assert.Same(a, collisions[0].BodyA.Position.X > 0 ? collisions[0].BodyA : collisions[1].BodyA);
            var pairs = collisions.Contacts.ToArray().Select(x => (x.BodyA, x.BodyB)).ToList();
            Assert.Contains((a, b), pairs);
            Assert.Contains((e, f), pairs);
            Assert.False(detector is SpatialHashDetector { LastUsedDenseGrid: true }, "millions of cells apart: hashed, not a dense grid");
        }
    }

    /// <summary>
    /// Checks the law over generated scenes; returns how many the spatial hash found on its dense grid and how many
    /// hashed (compact scenes, and scenes with a body far out), so that tests can see both ways of numbering cells tested.
    /// </summary>
    private static (int Dense, int Hashed) Check(ICollisionDetector detector, ulong seed, Func<System.Numerics.Vector3, System.Numerics.Vector3>? flatten = null, [System.Runtime.CompilerServices.CallerMemberName] string name = "")
    {
        int dense = 0, hashed = 0;
        PropertyCheck.Run(Flattened(flatten), scene =>
        {
            RigidBody[] bodies = scene.Bodies.Select(s => s.Build()).ToArray();
            var index = new Dictionary<RigidBody, int>(ReferenceEqualityComparer.Instance);
            for (int i = 0; i < bodies.Length; i++)
            {
                index[bodies[i]] = i;
            }

            var collisions = new CollisionData(capacity: 1); // grows as needed
            detector.FindContacts(bodies, collisions);
            if (detector is SpatialHashDetector grid && bodies.Length >= 2)
            {
                _ = grid.LastUsedDenseGrid ? dense++ : hashed++;
            }

            var found = new HashSet<(int, int)>();
            foreach (Contact contact in collisions.Contacts)
            {
                int i = index[contact.BodyA], j = index[contact.BodyB];
                Law.Holds(i < j, $"A [{i}] is the earlier body of the pair, B [{j}] the later");
                Law.Holds(found.Add((i, j)), $"pair ({i}, {j}) reported more than once");
                CheckContact(contact, bodies[i], bodies[j], $"pair ({i}, {j})");
            }

            var expected = Oracle(bodies);
            var missing = expected.Except(found).ToList();
            var extra = found.Except(expected).ToList();
            Law.Holds(missing.Count == 0 && extra.Count == 0,
                $"missing pairs [{string.Join(", ", missing)}], extra pairs [{string.Join(", ", extra)}]");
        }, seed, maxTest: 400, name: name);

        return (dense, hashed);
    }

    private static FsCheck.Gen<DetectionScene> Flattened(Func<System.Numerics.Vector3, System.Numerics.Vector3>? flatten) =>
        flatten is null
            ? Scenes
            : Generators.DetectionScene
                .Select(s => new DetectionScene(s.Bodies.Select(b => b with { Position = flatten(b.Position) }).ToArray()))
                .Where(NoBorderlinePair);

    /// <summary>Every pair i &lt; j with at least one dynamic body whose centres are closer than r_i + r_j.</summary>
    private static HashSet<(int, int)> Oracle(RigidBody[] bodies)
    {
        var pairs = new HashSet<(int, int)>();
        for (int i = 0; i < bodies.Length; i++)
        {
            for (int j = i + 1; j < bodies.Length; j++)
            {
                if ((bodies[i].IsDynamic || bodies[j].IsDynamic) && Distance(bodies[i], bodies[j]) < (double)bodies[i].Radius + bodies[j].Radius)
                {
                    pairs.Add((i, j));
                }
            }
        }

        return pairs;
    }

    private static void CheckContact(Contact contact, RigidBody a, RigidBody b, string what)
    {
        double radii = (double)a.Radius + b.Radius;
        double d = Distance(a, b);
        double coordinates = a.Position.Length() + b.Position.Length();
        D3 n = D3.From(contact.Normal);
        Law.Near(1, n.Length, 1e-6, $"{what}: |n|");
        D3 expectedNormal = d * d <= 1e-12 * radii * radii
            ? new D3(0, 1, 0) // coincident centres: the documented defined normal
            : (D3.From(a.Position) - D3.From(b.Position)) / d;
        Law.Near(expectedNormal, n, 1e-5 + 1e-6 * coordinates / Math.Max(d, 1e-30), $"{what}: unit normal from B to A");
        Law.Near(radii - d, contact.Penetration, 1e-5 * radii + 1e-6 * coordinates, $"{what}: penetration r_A + r_B − d");
        D3 point = D3.From(a.Position) - (a.Radius - 0.5 * contact.Penetration) * n;
        Law.Near(point, D3.From(contact.Point), 1e-5 * radii + 1e-6 * coordinates, $"{what}: contact point mid-overlap");
    }

    private static double Distance(RigidBody a, RigidBody b) => (D3.From(a.Position) - D3.From(b.Position)).Length;

    private static bool NoBorderlinePair(DetectionScene scene)
    {
        BodySpec[] s = scene.Bodies;
        for (int i = 0; i < s.Length; i++)
        {
            for (int j = i + 1; j < s.Length; j++)
            {
                double radii = (double)s[i].Radius + s[j].Radius;
                double d = (D3.From(s[i].Position) - D3.From(s[j].Position)).Length;
                double margin = 1e-5 * radii + 1e-6 * (s[i].Position.Length() + s[j].Position.Length());
                if (Math.Abs(d - radii) < margin || (d > 0 && d < 1e-5 * radii))
                {
                    return false;
                }
            }
        }

        return true;
    }
}
