using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Tests.Properties;
using Xunit;

namespace SimpleDynamics.Tests.Game;

/// <summary>Ray casts, point and overlap queries, checked against brute force over generated scenes.</summary>
public class QueryTests
{
    /// <summary>A query scene: bodies of very different sizes (some span many grid cells), planes, and probes.</summary>
    public sealed record QueryScene(GameBodySpec[] Bodies, StaticPlane[] Planes, (Vector3 Origin, Vector3 Translation)[] Rays, (Vector3 Centre, float Radius)[] Probes, int Steps)
    {
        public World Build(out RigidBody[] bodies)
        {
            var world = new World(new Vector3(0, -9.81f, 0));
            world.AddPlanes(Planes);
            bodies = Bodies.Select(b => world.Add(b.Build())).ToArray();
            for (int i = 0; i < Steps; i++)
            {
                world.Step(1f / 60f);
            }

            return world;
        }

        public override string ToString() =>
            $"{Bodies.Length} bodies, {Planes.Length} planes, {Steps} steps{Environment.NewLine}  " + string.Join(Environment.NewLine + "  ", Bodies.Select(b => b.ToString()));
    }

    private static Gen<Vector3> Flat(Gen<Vector3> vectors, bool planar) => vectors.Select(v => planar ? v with { Z = 0 } : v);

    private static Gen<QueryScene> Scenes { get; } =
        from planar in Gen.Elements(true, false)
        from count in Gen.Choose(0, 60)
        from bodies in (
            from type in Gen.Elements(BodyType.Dynamic, BodyType.Static, BodyType.Kinematic)
            from radius in Gen.OneOf(Generators.LogUniform(0.05, 1), Generators.LogUniform(1, 8))
            from position in Flat(Generators.Vector(10), planar)
            from filter in GameGenerators.Filter
            from sensor in Gen.Choose(0, 9)
            select new GameBodySpec(type, radius, position, Vector3.Zero, filter, sensor == 0)).ArrayOf(count)
        from planeCount in Gen.Choose(0, 3)
        from planes in (
            from normal in Flat(Generators.UnitVector, planar).Where(n => n.LengthSquared() > 0.01f)
            from point in Flat(Generators.Vector(12), planar)
            select new StaticPlane(Vector3.Normalize(normal), point)).ArrayOf(planeCount)
        from rays in (
            from origin in Flat(Generators.Vector(14), planar)
            from translation in Flat(Generators.Vector(30), planar).Where(t => t.LengthSquared() > 1e-4f)
            select (origin, translation)).ArrayOf(8)
        from probes in (
            from centre in Flat(Generators.Vector(12), planar)
            from radius in Generators.LogUniform(0.01, 5)
            select (centre, radius)).ArrayOf(8)
        from steps in Gen.Elements(0, 0, 3)
        select new QueryScene(bodies, planes, rays, probes, steps);

    private static Gen<QueryFilter> Filters { get; } = Gen.Elements(QueryFilter.Default, QueryFilter.Everything, new QueryFilter(0b010), new QueryFilter(0b101, includeSensors: true));

    /// <summary>Brute force: every body and plane the ray enters, by the same exact tests, nearest first.</summary>
    private static List<RayHit> AllHitsByBruteForce(World world, Vector3 origin, Vector3 translation, QueryFilter filter)
    {
        var hits = new List<RayHit>();
        foreach (RigidBody body in world.Bodies)
        {
            if (filter.Accepts(body) && QueryGeometry.RayCircle(origin, translation, body.Position, body.Radius, out float t) && t <= 1f)
            {
                hits.Add(new RayHit(body, -1, origin + t * translation, Vector3.Zero, t));
            }
        }

        for (int p = 0; p < world.Planes.Length; p++)
        {
            if (filter.Accepts(world.Planes[p]) && QueryGeometry.RayPlane(origin, translation, world.Planes[p], out float t) && t <= 1f)
            {
                hits.Add(new RayHit(null, p, origin + t * translation, world.Planes[p].Normal, t));
            }
        }

        return hits.OrderBy(h => h.Fraction).ToList();
    }

    private static (int, int) Key(RayHit hit) => hit.IsPlane ? (-1, hit.PlaneIndex) : (hit.Body!.Id, -1);

    private static (int, int) Key(Overlap found) => found.IsPlane ? (-1, found.PlaneIndex) : (found.Body!.Id, -1);

    [Fact]
    public void Ray_casts_find_what_brute_force_finds()
    {
        int rayHits = 0;
        PropertyCheck.Run(Scenes.SelectMany(s => Filters, (s, f) => (Scene: s, Filter: f)), x =>
        {
            World world = x.Scene.Build(out _);
            Span<RayHit> buffer = new RayHit[100];
            foreach ((Vector3 origin, Vector3 translation) in x.Scene.Rays)
            {
                List<RayHit> expected = AllHitsByBruteForce(world, origin, translation, x.Filter);
                bool found = world.RayCastClosest(origin, translation, out RayHit closest, x.Filter);
                Law.Holds(found == expected.Count > 0, $"ray {origin} + {translation}: found {found}, brute force {expected.Count} hits");
                if (found)
                {
                    Law.Holds(closest.Fraction == expected[0].Fraction, $"ray {origin} + {translation}: closest at {closest.Fraction}, brute force {expected[0].Fraction} ({expected[0]})");
                    Law.Near(Vector3.Distance(origin + closest.Fraction * translation, closest.Point), 0, 1e-4 * (1 + origin.Length() + translation.Length()), "hit point");
                    Law.Near(closest.Normal.Length(), 1, 1e-5, "unit normal");
                    Law.Holds(Vector3.Dot(closest.Normal, translation) <= 1e-4f * translation.Length(), $"the normal {closest.Normal} faces the ray {translation}");
                }

                int total = world.RayCastAll(origin, translation, buffer, x.Filter);
                rayHits += total;
                Law.Holds(total == expected.Count, $"ray {origin} + {translation}: RayCastAll {total}, brute force {expected.Count}");
                Law.Holds(buffer[..total].ToArray().Select(Key).ToHashSet().SetEquals(expected.Select(Key)), "RayCastAll finds other bodies than brute force");
                for (int i = 1; i < total; i++)
                {
                    Law.Holds(buffer[i - 1].Fraction <= buffer[i].Fraction, "RayCastAll is not nearest first");
                }

                // A short buffer keeps the nearest.
                Span<RayHit> two = new RayHit[2];
                int again = world.RayCastAll(origin, translation, two, x.Filter);
                Law.Holds(again == total, "the count does not depend on the buffer");
                for (int i = 0; i < Math.Min(2, total); i++)
                {
                    Law.Holds(two[i].Fraction == expected[i].Fraction, $"short buffer slot {i}: {two[i].Fraction}, nearest {expected[i].Fraction}");
                }
            }
        }, seed: 1104, maxTest: 150);
        Assert.True(rayHits > 500, $"only {rayHits} hits in all: the scenes test too little");
    }

    [Fact]
    public void Point_circle_and_box_queries_find_what_brute_force_finds()
    {
        int overlaps = 0;
        PropertyCheck.Run(Scenes.SelectMany(s => Filters, (s, f) => (Scene: s, Filter: f)), x =>
        {
            World world = x.Scene.Build(out _);
            var buffer = new Overlap[200];
            ReadOnlySpan<StaticPlane> planes = world.Planes;
            foreach ((Vector3 centre, float radius) in x.Scene.Probes)
            {
                var expectedPoint = world.Bodies.Where(b => x.Filter.Accepts(b) && Vector3.DistanceSquared(centre, b.Position) <= b.Radius * b.Radius).Select(b => (b.Id, -1)).ToHashSet();
                var expectedCircle = world.Bodies.Where(b => x.Filter.Accepts(b) && Vector3.DistanceSquared(centre, b.Position) < (radius + b.Radius) * (radius + b.Radius)).Select(b => (b.Id, -1)).ToHashSet();
                Vector3 min = centre - new Vector3(radius, 0.5f * radius, 2 * radius), max = centre + new Vector3(radius, 2 * radius, 0.5f * radius);
                var expectedBox = world.Bodies.Where(b => x.Filter.Accepts(b) && QueryGeometry.BoxOverlapsCircle(min, max, b.Position, b.Radius)).Select(b => (b.Id, -1)).ToHashSet();
                for (int p = 0; p < planes.Length; p++)
                {
                    if (!x.Filter.Accepts(planes[p]))
                    {
                        continue;
                    }

                    if (planes[p].DistanceTo(centre) <= 0)
                    {
                        expectedPoint.Add((-1, p));
                    }

                    if (planes[p].DistanceTo(centre) < radius)
                    {
                        expectedCircle.Add((-1, p));
                    }

                    if (QueryGeometry.BoxOverlapsPlane(min, max, planes[p]))
                    {
                        expectedBox.Add((-1, p));
                    }
                }

                int n = world.QueryPoint(centre, buffer, x.Filter);
                Law.Holds(n == expectedPoint.Count && buffer.Take(n).Select(Key).ToHashSet().SetEquals(expectedPoint), $"point {centre}: {n} found, brute force {expectedPoint.Count}");
                n = world.OverlapCircle(centre, radius, buffer, x.Filter);
                Law.Holds(n == expectedCircle.Count && buffer.Take(n).Select(Key).ToHashSet().SetEquals(expectedCircle), $"circle {centre} r {radius}: {n} found, brute force {expectedCircle.Count}");
                n = world.OverlapBox(min, max, buffer, x.Filter);
                Law.Holds(n == expectedBox.Count && buffer.Take(n).Select(Key).ToHashSet().SetEquals(expectedBox), $"box {min}–{max}: {n} found, brute force {expectedBox.Count}");
                Law.Holds(world.OverlapCircle(centre, radius, Span<Overlap>.Empty, x.Filter) == expectedCircle.Count, "the count with an empty buffer");
                overlaps += expectedPoint.Count + expectedCircle.Count + expectedBox.Count;
            }
        }, seed: 1105, maxTest: 150);
        Assert.True(overlaps > 1000, $"only {overlaps} overlaps in all: the scenes test too little");
    }

    [Fact]
    public void The_ray_circle_test_agrees_with_the_quadratic_in_double_precision() =>
        PropertyCheck.Run(
            from origin in Generators.Vector(10)
            from translation in Generators.Vector(20).Where(t => t.LengthSquared() > 1e-2f)
            from centre in Generators.Vector(10)
            from radius in Generators.LogUniform(0.05, 5)
            select (origin, translation, centre, radius),
            x =>
            {
                D3 m = D3.From(x.origin) - D3.From(x.centre), d = D3.From(x.translation);
                double a = D3.Dot(d, d), b = D3.Dot(m, d), c = D3.Dot(m, m) - (double)x.radius * x.radius;
                double disc = b * b - a * c;
                bool hit = QueryGeometry.RayCircle(x.origin, x.translation, x.centre, x.radius, out float t);
                if (c > 1e-3 && b < 0 && disc > 1e-3 * a)
                {
                    double expected = (-b - Math.Sqrt(disc)) / a;
                    Law.Holds(hit, $"a clear hit at t = {expected} missed");
                    Law.Near(expected, t, 1e-4 * (1 + Math.Abs(expected)), "entry fraction");
                }
                else if (c < -1e-3 || b > 1e-3 || disc < -1e-3 * a)
                {
                    Law.Holds(!hit, $"a clear miss hit at {t} (c {c}, b {b}, disc {disc})");
                }
            }, seed: 1106, maxTest: 2000);

    [Fact]
    public void A_ray_from_inside_a_body_finds_what_lies_beyond_and_planes_hit_from_the_front()
    {
        var world = new World();
        world.AddPlane(StaticPlane.Ground() with { UserData = "floor" });
        RigidBody shooter = world.Add(new RigidBody(1, 0.5f, new Vector3(0, 1, 0)));
        RigidBody target = world.Add(new RigidBody(1, 0.5f, new Vector3(5, 1, 0)));
        Assert.True(world.RayCastClosest(shooter.Position, new Vector3(10, 0, 0), out RayHit hit));
        Assert.Same(target, hit.Body);
        Assert.Equal(-1, hit.PlaneIndex);
        Assert.Equal(new Vector3(4.5f, 1, 0), hit.Point);
        Assert.Equal(-Vector3.UnitX, hit.Normal);
        Assert.Equal(0.45f, hit.Fraction, 6);

        Assert.True(world.RayCastClosest(new Vector3(2, 3, 0), new Vector3(0, -10, 0), out hit));
        Assert.True(hit.IsPlane);
        Assert.Null(hit.Body);
        Assert.Equal("floor", world.Planes[hit.PlaneIndex].UserData);
        Assert.Equal(0.3f, hit.Fraction, 6);
        Assert.False(world.RayCastClosest(new Vector3(2, -3, 0), new Vector3(0, -10, 0), out _)); // from behind the floor
        Assert.False(world.RayCastClosest(new Vector3(2, 3, 0), new Vector3(0, 1, 0), out _)); // too short
    }

    [Fact]
    public void Queries_see_bodies_after_a_step_after_a_refresh_and_never_after_removal()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        RigidBody ball = world.Add(new RigidBody(1, 0.5f, new Vector3(0, 0, 0)));
        Span<Overlap> found = new Overlap[4];
        Assert.Equal(1, world.QueryPoint(Vector3.Zero, found));
        for (int i = 0; i < 60; i++)
        {
            world.Step(1f / 60f); // falls about 5 m
        }

        Assert.Equal(0, world.QueryPoint(Vector3.Zero, found));
        Assert.Equal(1, world.QueryPoint(ball.Position, found));

        ball.Position = new Vector3(20, 0, 0);
        world.RefreshQueries();
        Assert.Equal(1, world.QueryPoint(new Vector3(20, 0.2f, 0), found));

        RigidBody added = world.Add(new RigidBody(1, 0.5f, new Vector3(-20, 0, 0)));
        Assert.Equal(1, world.QueryPoint(added.Position, found)); // a new body count rebuilds the grid
        world.Remove(ball);
        Assert.Equal(0, world.QueryPoint(new Vector3(20, 0.2f, 0), found));
    }

    [Fact]
    public void Bad_query_arguments_throw_naming_the_parameter()
    {
        var world = new World();
        world.Add(new RigidBody(1, 1, Vector3.Zero));
        Span<RayHit> hits = new RayHit[2];
        Assert.Throws<ArgumentException>("translation", () => world.RayCastClosest(Vector3.Zero, Vector3.Zero, out _));
        Assert.Throws<ArgumentException>("origin", () => world.RayCastClosest(new Vector3(float.NaN), Vector3.UnitX, out _));
        Assert.Throws<ArgumentException>("translation", () => world.RayCastAll(Vector3.Zero, new Vector3(float.PositiveInfinity, 0, 0), new RayHit[1]));
        Assert.Throws<ArgumentException>("point", () => world.QueryPoint(new Vector3(float.NaN), new Overlap[1]));
        Assert.Throws<ArgumentOutOfRangeException>("radius", () => world.OverlapCircle(Vector3.Zero, 0, new Overlap[1]));
        Assert.Throws<ArgumentOutOfRangeException>("radius", () => world.OverlapCircle(Vector3.Zero, float.NaN, new Overlap[1]));
        Assert.Throws<ArgumentException>("centre", () => world.OverlapCircle(new Vector3(float.NaN), 1, new Overlap[1]));
        Assert.Throws<ArgumentException>("max", () => world.OverlapBox(Vector3.One, Vector3.Zero, new Overlap[1]));
        Assert.Throws<ArgumentException>("min", () => world.OverlapBox(new Vector3(float.NaN), Vector3.Zero, new Overlap[1]));
    }
}
