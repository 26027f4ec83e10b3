using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics;

/// <summary>
/// Ready-made scenes: the sample shows them, the tests check them, the benchmarks time them — all with the
/// same geometry. Each returns a new world; randomness comes only from a seed argument. Each validates its own
/// arguments and names the one at fault (restitution in [0, 1], friction ≥ 0, counts ≥ 1, radii positive, the
/// rest finite).
/// </summary>
public static class Scenes
{
    /// <summary>Standard gravity, (0, −9.81, 0) m/s².</summary>
    public static readonly Vector3 EarthGravity = new(0, -9.81f, 0);

    /// <summary>A ball of radius 0.5 m dropped from <paramref name="height"/> onto the ground.</summary>
    public static World DroppedBall(float restitution, float height = 3f, ICollisionResponder? responder = null)
    {
        Guard.UnitInterval(restitution, nameof(restitution));
        Guard.Finite(height, nameof(height));
        var world = new World(EarthGravity, responder);
        world.AddPlane(new StaticPlane(Vector3.UnitY, Vector3.Zero, restitution));
        world.Add(new RigidBody(1f, 0.5f, new Vector3(0, height, 0), Inertia.Disc(1f, 0.5f)) { Restitution = restitution });
        return world;
    }

    /// <summary>
    /// Two discs meeting off-centre in the plane, so that friction sets them spinning; no gravity.
    /// </summary>
    public static World OffCentreCollision(float restitution, float friction, ICollisionResponder? responder = null)
    {
        Guard.UnitInterval(restitution, nameof(restitution));
        Guard.NonNegative(friction, nameof(friction));
        var world = new World(Vector3.Zero, responder);
        var left = new RigidBody(1f, 0.5f, new Vector3(-2, 0.3f, 0), Inertia.Disc(1f, 0.5f))
        {
            LinearVelocity = new Vector3(3, 0, 0), Restitution = restitution, Friction = friction,
        };
        var right = new RigidBody(2f, 0.5f, new Vector3(2, -0.3f, 0), Inertia.Disc(2f, 0.5f))
        {
            LinearVelocity = new Vector3(-1, 0, 0), Restitution = restitution, Friction = friction,
        };
        world.Add(left);
        world.Add(right);
        return world;
    }

    /// <summary>
    /// A row of <paramref name="count"/> touching balls on the ground, struck at one end by a ball moving at
    /// <paramref name="speed"/> (Newton's cradle on a table).
    /// </summary>
    public static World StruckRow(int count, float speed, float restitution = 1f, ICollisionResponder? responder = null)
    {
        Guard.AtLeast(count, 1, nameof(count));
        Guard.Finite(speed, nameof(speed));
        Guard.UnitInterval(restitution, nameof(restitution));
        var world = new World(EarthGravity, responder);
        world.AddPlane(new StaticPlane(Vector3.UnitY, Vector3.Zero, restitution, 0f));
        const float r = 0.5f;
        for (int i = 0; i < count; i++)
        {
            world.Add(new RigidBody(1f, r, new Vector3(i * 2 * r, r, 0), Inertia.Disc(1f, r)) { Restitution = restitution, Friction = 0f });
        }

        world.Add(new RigidBody(1f, r, new Vector3(-3, r, 0), Inertia.Disc(1f, r))
        {
            LinearVelocity = new Vector3(speed, 0, 0), Restitution = restitution, Friction = 0f,
        });
        return world;
    }

    /// <summary>
    /// A solid ball of radius <paramref name="radius"/> set sliding at <paramref name="speed"/> along rough
    /// ground (friction <paramref name="friction"/>) with no spin; friction slows it and spins it up until it rolls.
    /// </summary>
    public static World SlidingBall(float speed, float friction, float radius = 0.5f, ICollisionResponder? responder = null)
    {
        Guard.Finite(speed, nameof(speed));
        Guard.NonNegative(friction, nameof(friction));
        Guard.Positive(radius, nameof(radius));
        var world = new World(EarthGravity, responder);
        world.AddPlane(new StaticPlane(Vector3.UnitY, Vector3.Zero, 0f, friction));
        world.Add(new RigidBody(1f, radius, new Vector3(0, radius, 0))
        {
            LinearVelocity = new Vector3(speed, 0, 0), Restitution = 0f, Friction = friction,
        });
        return world;
    }

    /// <summary>
    /// A ball pit: <paramref name="count"/> balls poured into a closed box under gravity, in 2-D (z = 0, discs)
    /// or 3-D (spheres). The balls start on a jittered lattice above the floor with small random velocities;
    /// the box leaves them room to settle about half full. <paramref name="radiusSpread"/> &gt; 1 mixes radii
    /// uniformly in [r, r × spread].
    /// </summary>
    public static World BallPit(int count, bool planar, int seed = 1, float radius = 0.1f, float radiusSpread = 1f, ICollisionResponder? responder = null)
    {
        Guard.AtLeast(count, 1, nameof(count));
        Guard.Positive(radius, nameof(radius));
        if (!(radiusSpread >= 1f) || !float.IsFinite(radiusSpread))
        {
            throw new ArgumentOutOfRangeException(nameof(radiusSpread), radiusSpread, "radiusSpread must be finite and at least 1.");
        }

        var random = new Random(seed);
        float maxRadius = radius * radiusSpread;
        float spacing = 2.2f * maxRadius;
        int perRow = planar ? (int)MathF.Ceiling(MathF.Sqrt(count)) : (int)MathF.Ceiling(MathF.Pow(count, 1f / 3f));
        int perLayer = planar ? perRow : perRow * perRow;
        int rows = (count + perLayer - 1) / perLayer;
        float width = perRow * spacing;
        float height = 2f * rows * spacing + spacing;

        var world = new World(EarthGravity, responder);
        world.AddPlanes(StaticPlane.Box(
            new Vector3(0, 0, planar ? 0 : 0),
            new Vector3(width, height, planar ? 0 : width),
            planar));
        for (int i = 0; i < count; i++)
        {
            int layer = i / perLayer, inLayer = i % perLayer;
            int ix = inLayer % perRow, iz = inLayer / perRow;
            float jitter() => (float)(random.NextDouble() - 0.5) * 0.1f * maxRadius;
            var position = new Vector3(
                (ix + 0.5f) * spacing + jitter(),
                height - (layer + 0.5f) * spacing,
                planar ? 0f : (iz + 0.5f) * spacing + jitter());
            float r = radius * (1f + (float)random.NextDouble() * (radiusSpread - 1f));
            float mass = planar ? r * r : r * r * r; // uniform density
            var body = new RigidBody(mass, r, position, planar ? Inertia.Disc(mass, r) : Inertia.SolidSphere(mass, r))
            {
                LinearVelocity = new Vector3(jitter(), jitter(), planar ? 0f : jitter()),
            };
            world.Add(body);
        }

        return world;
    }

    /// <summary>
    /// Smash: a dense square grid of <paramref name="count"/> touching-close discs at rest, no gravity, hit by
    /// one heavy, fast disc.
    /// </summary>
    public static World Smash(int count, float radius = 0.1f, ICollisionResponder? responder = null)
    {
        Guard.AtLeast(count, 1, nameof(count));
        Guard.Positive(radius, nameof(radius));
        var world = new World(Vector3.Zero, responder);
        int perRow = (int)MathF.Ceiling(MathF.Sqrt(count));
        float spacing = 2.05f * radius;
        for (int i = 0; i < count; i++)
        {
            var position = new Vector3((i % perRow) * spacing, (i / perRow) * spacing, 0);
            world.Add(new RigidBody(1f, radius, position, Inertia.Disc(1f, radius)));
        }

        float centre = 0.5f * (perRow - 1) * spacing;
        float bigRadius = 10 * radius;
        world.Add(new RigidBody(100f, bigRadius, new Vector3(-4 * bigRadius, centre, 0), Inertia.Disc(100f, bigRadius))
        {
            LinearVelocity = new Vector3(20, 0, 0),
        });
        return world;
    }

    /// <summary>
    /// A dense gas: <paramref name="count"/> balls with random velocities in a closed box, no gravity, ε = 1 and
    /// μ = 0 on every surface (elastic, frictionless). Kinetic energy should stay constant.
    /// </summary>
    public static World ElasticGas(int count, bool planar, int seed = 1, float radius = 0.1f, float speed = 1f)
    {
        Guard.AtLeast(count, 1, nameof(count));
        Guard.Positive(radius, nameof(radius));
        Guard.Finite(speed, nameof(speed));
        var random = new Random(seed);
        var solver = new SequentialImpulseSolver(restitution: 1f, friction: 0f) { RestitutionThreshold = 0f };
        var world = new World(Vector3.Zero, solver);
        float spacing = 3f * radius;
        int perRow = planar ? (int)MathF.Ceiling(MathF.Sqrt(count)) : (int)MathF.Ceiling(MathF.Pow(count, 1f / 3f));
        float size = perRow * spacing;
        world.AddPlanes(StaticPlane.Box(Vector3.Zero, new Vector3(size, size, planar ? 0 : size), planar));
        for (int i = 0; i < count; i++)
        {
            int ix = i % perRow, iy = i / perRow % perRow, iz = i / (perRow * perRow);
            var position = new Vector3((ix + 0.5f) * spacing, (planar ? i / perRow : iy) * spacing + 0.5f * spacing, planar ? 0 : (iz + 0.5f) * spacing);
            var direction = new Vector3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, planar ? 0 : (float)random.NextDouble() - 0.5f);
            var body = new RigidBody(1f, radius, position, planar ? Inertia.Disc(1f, radius) : Inertia.SolidSphere(1f, radius))
            {
                LinearVelocity = speed * Vector3.Normalize(direction + new Vector3(1e-3f, 0, 0)),
            };
            world.Add(body);
        }

        return world;
    }
}
