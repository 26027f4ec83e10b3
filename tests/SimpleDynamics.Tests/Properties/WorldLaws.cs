using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Numerics;
using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>A generated world: plain data, so that FsCheck prints a failing case readably.</summary>
public sealed record WorldCase(
    bool Planar,
    bool ClosedBox,
    bool WithGravity,
    float Restitution,
    float Friction,
    float Threshold,
    float Dt,
    int Substeps,
    BodySpec[] Bodies)
{
    public const float BoxSize = 4f;

    /// <summary>
    /// Where a generated body of <paramref name="radius"/> goes in the box, from a seed (u, v, w) in the unit cube (w
    /// ignored in the plane); false if it would overlap one of <paramref name="placed"/> (its seed is then dropped).
    /// </summary>
    public static bool TryPlace(IEnumerable<BodySpec> placed, bool planar, (float U, float V, float W) seed, float radius, out Vector3 position)
    {
        float room = BoxSize - 2 * radius;
        position = new Vector3(radius + seed.U * room, radius + seed.V * room, planar ? 0 : radius + seed.W * room);
        Vector3 at = position;
        return !placed.Any(b => Vector3.Distance(b.Position, at) < b.Radius + radius + 1e-3f);
    }

    public World Build(out RigidBody[] bodies)
    {
        var solver = new SequentialImpulseSolver(Restitution, Friction) { RestitutionThreshold = Threshold };
        var world = new World(WithGravity ? Scenes.EarthGravity : Vector3.Zero, solver) { Substeps = Substeps };
        if (ClosedBox)
        {
            world.AddPlanes(StaticPlane.Box(Vector3.Zero, new Vector3(BoxSize, BoxSize, Planar ? 0 : BoxSize), Planar));
        }

        bodies = Bodies.Select(b => world.Add(b.Build())).ToArray();
        return world;
    }

    public override string ToString() => string.Create(CultureInfo.InvariantCulture,
        $"{(Planar ? "2-D" : "3-D")} {(ClosedBox ? "closed box" : "free space")} {(WithGravity ? "gravity" : "no gravity")} eps={Restitution:R} mu={Friction:R} threshold={Threshold:R} dt={Dt:R} substeps={Substeps}{Environment.NewLine}{string.Join(Environment.NewLine, Bodies.Select((b, i) => $"  [{i}] {b}"))}");
}

/// <summary>
/// The laws of the tutorial over whole <see cref="World.Step"/>s of generated worlds with the default solver, checked
/// after every step: 2-D and 3-D, free space and closed boxes, with and without gravity, masses 1e-2…1e3 kg, speeds up
/// to 100 m/s, ε ∈ {0, 0.25, 0.5, 0.75, 1} or random, μ ∈ {0, 0.3}, dt ∈ {1/30, 1/60, 1/240}, 1…8 substeps.
/// </summary>
/// <remarks>
/// Bodies are solid spheres (3-D) or discs spinning about z (2-D): World.Step leaves out the gyroscopic term ω × I ω,
/// which is zero for them, so angular momentum changes only through collisions. The bodies start apart: a world
/// that starts overlapping is pushed apart by the position pass, which conserves linear momentum but not angular.
/// </remarks>
public class WorldLaws
{
    private const int Steps = 40;

    private static Gen<float> Speed { get; } = Gen.OneOf(Generators.UniformF(0, 5), Generators.LogUniform(0.1, 100));

    private static Gen<WorldCase> Worlds { get; } =
        from planar in Gen.Elements(true, false)
        from closedBox in Gen.Elements(true, false)
        from gravity in Gen.Elements(true, false)
        from restitution in Gen.OneOf(Gen.Elements(0f, 0.25f, 0.5f, 0.75f, 1f), Generators.UniformF(0, 1))
        from friction in Gen.Elements(0f, 0.3f)
        from threshold in Gen.Elements(0f, 0.5f)
        from dt in Gen.Elements(1f / 30, 1f / 60, 1f / 240)
        from substeps in Gen.Choose(1, 8)
        from count in Gen.Choose(2, 10)
        from seeds in (
            from radius in Generators.LogUniform(0.05, 0.5)
            from mass in Generators.Mass
            from position in Generators.UniformF(0, 1).Three()
            from direction in Generators.UnitVector
            from speed in Speed
            from spin in Generators.Vector(5)
            select (radius, mass, position, direction, speed, spin)).ArrayOf(count)
        select new WorldCase(planar, closedBox, gravity, restitution, friction, threshold, dt, substeps, Place(planar, seeds));

    /// <summary>Places the generated bodies in the box where they do not overlap (a seed that would is dropped).</summary>
    private static BodySpec[] Place(bool planar, (float Radius, float Mass, (float, float, float) Position, Vector3 Direction, float Speed, Vector3 Spin)[] seeds)
    {
        var placed = new List<BodySpec>();
        foreach (var s in seeds)
        {
            float r = s.Radius;
            if (!WorldCase.TryPlace(placed, planar, s.Position, r, out Vector3 position))
            {
                continue;
            }

            Vector3 direction = planar ? new Vector3(s.Direction.X, s.Direction.Y, 0) : s.Direction;
            direction = direction.LengthSquared() > 1e-6f ? Vector3.Normalize(direction) : Vector3.UnitX;
            Vector3 spin = planar ? new Vector3(0, 0, s.Spin.Z) : s.Spin;
            Matrix3 inertia = planar ? Inertia.Disc(s.Mass, r) : Inertia.SolidSphere(s.Mass, r);
            placed.Add(new BodySpec(BodyType.Dynamic, s.Mass, r, position, Quaternion.Identity, inertia, s.Speed * direction, spin));
        }

        return placed.ToArray();
    }

    [Fact]
    public void Every_step_of_a_generated_world_keeps_the_laws() =>
        PropertyCheck.Run(Worlds, c => KeepsTheLaws(c, inStrips: false), seed: 801, maxTest: 2000);

    /// <summary>
    /// The same laws over the same generated worlds with the contacts cut into up to 8 strips however few they are
    /// (<see cref="SequentialImpulseSolver.Strips"/>, SweepStrips.cs: seam contacts swept last) and swept on two
    /// threads; and every step bit for bit what one thread does with the same strips.
    /// </summary>
    [Fact]
    public void Every_step_of_a_generated_world_in_strips_on_two_threads_keeps_the_laws_and_matches_one_thread()
    {
        int worlds = 0, withSeams = 0;
        PropertyCheck.Run(Worlds, c =>
        {
            worlds++;
            withSeams += KeepsTheLaws(c, inStrips: true) ? 1 : 0;
        }, seed: 801, maxTest: 2000);
        Assert.True(withSeams > worlds / 4, $"only {withSeams} of {worlds} worlds had a contact across a cut in some step");
    }

    /// <summary>Checks the laws at every step; returns whether some step had a seam contact (in strips).</summary>
    internal static bool KeepsTheLaws(WorldCase c, bool inStrips)
    {
        World world = c.Build(out RigidBody[] bodies);
        World? oneThread = null;
        if (inStrips)
        {
            CutIntoStrips(world).ThreadCount = 2;
            oneThread = CutIntoStrips(c.Build(out _));
        }

        try
        {
            var solver = (SequentialImpulseSolver)world.Responder;
            bool seams = false;
            bool free = !c.ClosedBox && !c.WithGravity;
            D3 origin = new(0.7, -1.3, 0.4);
            D3 p0 = Measure.Momentum(bodies), l0 = Measure.AngularMomentum(origin, bodies);
            double pScale = Measure.MomentumScale(bodies), lScale = Measure.AngularMomentumScale(origin, bodies);
            double e0 = Energy(world, bodies);
            double eScale = Measure.KineticEnergy(bodies) + bodies.Sum(b => b.Mass * world.Gravity.Length() * (WorldCase.BoxSize + 1.0)) + 1e-12;
            Vector3[] before = bodies.Select(b => b.Position).ToArray();
            double rounding = 0, energyRounding = 0;
            for (int step = 0; step < Steps; step++)
            {
                double roundingBefore = StateRounding(bodies, origin), energyRoundingBefore = EnergyRounding(world, bodies);
                world.Step(c.Dt);
                oneThread?.Step(c.Dt);
                if (oneThread is not null)
                {
                    Law.Holds(Solver.WorldMeasure.FirstDifference(oneThread, world) is null, $"step {step}: two threads moved a body otherwise than one thread");
                    seams |= solver.SeamContacts > 0;
                }

                int updates = c.Substeps + 2 * world.ImpactCount;
                rounding += updates * Math.Max(roundingBefore, StateRounding(bodies, origin));
                energyRounding += updates * Math.Max(energyRoundingBefore, EnergyRounding(world, bodies));
                string at = $"step {step}";
                Law.Holds(bodies.All(b => Vectors3.Finite(b.Position) && Vectors3.Finite(b.LinearVelocity) && Vectors3.Finite(b.AngularVelocity)), $"{at}: NaN");
                if (free)
                {
                    pScale = Math.Max(pScale, Measure.MomentumScale(bodies));
                    lScale = Math.Max(lScale, Measure.AngularMomentumScale(origin, bodies));
                    Law.Near(p0, Measure.Momentum(bodies), 1e-5 * pScale, $"{at}: linear momentum");
                    Law.Near(l0, Measure.AngularMomentum(origin, bodies), 1e-5 * lScale + rounding, $"{at}: angular momentum about {origin}");
                }

                double energy = Energy(world, bodies);
                Law.Holds(energy <= e0 + 1e-5 * eScale + energyRounding, $"{at}: mechanical energy rose from {e0:R} to {energy:R} J (scale {eScale:R}, float32 rounding budget {energyRounding:R} J)");
                CheckNothingPassedThrough(c, world, bodies, before, solver.Slop, at);
                for (int i = 0; i < bodies.Length; i++)
                {
                    before[i] = bodies[i].Position;
                }
            }

            return seams;
        }
        finally
        {
            world.ThreadCount = 1;
        }
    }

    /// <summary>Up to 8 strips however few the contacts (one contact a strip at least), for the property in strips.</summary>
    private static World CutIntoStrips(World world)
    {
        var solver = (SequentialImpulseSolver)world.Responder;
        solver.Strips = 8;
        solver.Cut.ContactsPerStrip = 1;
        return world;
    }

    /// <summary>
    /// How much rounding the float32 state can add to the angular momentum about <paramref name="origin"/> in one
    /// update of every body's position and velocity: rounding x moves it by up to √3·2⁻²⁴|x| (half an ulp per
    /// component), which changes m x × v by up to that times m|v|; rounding v, ω changes m (x − o) × v and I ω by
    /// √3·2⁻²⁴ m|x − o||v| and √3·2⁻²⁴|I||ω|. A step makes one such update per substep, and two more bodies' worth
    /// per impact (both bodies are advanced to it), so the bound on the angular momentum grows by that many of these.
    /// (Measured in world 272 of 2,000, seed 801: four spheres with friction drifted by 1.01e-5 of Σ m|r||v| over 38
    /// steps of 8 substeps, within this budget; the fixed 1e-5 alone is below what float32 state can keep.)
    /// </summary>
    private static double StateRounding(RigidBody[] bodies, D3 origin)
    {
        const double halfUlp = 1.0 / (1 << 24);
        double sum = 0;
        foreach (RigidBody b in bodies)
        {
            double speed = D3.From(b.LinearVelocity).Length;
            sum += b.Mass * speed * (D3.From(b.Position).Length + (D3.From(b.Position) - origin).Length)
                + Measure.InertiaWorld(b).Norm() * D3.From(b.AngularVelocity).Length;
        }

        return Math.Sqrt(3) * halfUlp * sum;
    }

    /// <summary>
    /// The same for the mechanical energy: rounding x changes m g·x by up to √3·2⁻²⁴ m|g||x|, rounding v and ω change
    /// ½ m v² and ½ ω·I ω by up to √3·2⁻²⁴ m v² and √3·2⁻²⁴ |I| ω². (Measured in world 868 of 2,000, seed 801: eight
    /// spheres up to 760 kg falling freely for 34 steps of 8 substeps gained 0.9 J of 48,566 J, 1.9e-5 of it.)
    /// </summary>
    private static double EnergyRounding(World world, RigidBody[] bodies)
    {
        const double halfUlp = 1.0 / (1 << 24);
        double g = world.Gravity.Length(), sum = 0;
        foreach (RigidBody b in bodies)
        {
            double speed = D3.From(b.LinearVelocity).Length, spin = D3.From(b.AngularVelocity).Length;
            sum += b.Mass * (g * D3.From(b.Position).Length + speed * speed) + Measure.InertiaWorld(b).Norm() * spin * spin;
        }

        return Math.Sqrt(3) * halfUlp * sum;
    }

    /// <summary>Mechanical energy with heights measured from the floor, so that it is positive and a relative bound means something.</summary>
    private static double Energy(World world, RigidBody[] bodies) =>
        Measure.KineticEnergy(bodies) - bodies.Sum(b => b.Mass * (double)Vector3.Dot(world.Gravity, b.Position));

    /// <summary>
    /// Nobody deeper than the slop into a wall, nor any pair into each other, whatever their masses (both up to float
    /// rounding of where the bodies end, 1e-5 of their size), and no
    /// pair whose relative motion over the step went straight through: for two bodies that nothing but each other
    /// pushed in the step, a single bounce keeps both ends of the relative path on the outer side of the tangent plane
    /// at the contact, so a chord that passes within half the sum of the radii of the other centre, with both ends
    /// outside, crossed the body. (A body that bounced off a wall or a third body in the step may end anywhere: its
    /// pairs are not judged by their chord.)
    /// </summary>
    private static void CheckNothingPassedThrough(WorldCase c, World world, RigidBody[] bodies, Vector3[] before, float slop, string at)
    {
        int[][] pushedBy = PushPartners(world, bodies);
        for (int i = 0; i < bodies.Length; i++)
        {
            RigidBody a = bodies[i];
            float tolerance = slop + 1e-5f * a.Radius;
            for (int p = 0; p < world.Planes.Length; p++)
            {
                float depth = a.Radius - world.Planes[p].DistanceTo(a.Position);
                Law.Holds(depth <= tolerance, $"{at}: body {i} is {depth:R} m into plane {p}");
            }

            for (int j = i + 1; j < bodies.Length; j++)
            {
                RigidBody b = bodies[j];
                float reach = a.Radius + b.Radius;
                float depth = reach - Vector3.Distance(a.Position, b.Position);
                Law.Holds(depth <= slop + 1e-5f * reach,
                    $"{at}: bodies {i} and {j} overlap by {depth:R} m");
                Vector3 start = before[i] - before[j], end = a.Position - b.Position;
                if (!MetOnlyEachOther(pushedBy, i, j))
                {
                    continue; // a bounce off a third body or a wall bends the relative path: the chord says nothing
                }

                Law.Holds(DistanceToSegment(start, end) >= 0.5f * reach || start.Length() < reach || end.Length() < reach,
                    $"{at}: bodies {i} and {j} passed through each other (relative position {start} → {end})");
            }
        }
    }

    /// <summary>
    /// For each body, what pushed it in the last step: the indices of the bodies (and −1 − p for plane p) of its
    /// contacts whose normal impulse over the step is positive (impacts, the solver's resting contacts, jams).
    /// </summary>
    private static int[][] PushPartners(World world, RigidBody[] bodies)
    {
        var partners = bodies.Select(_ => new List<int>()).ToArray();
        foreach (Contact contact in world.Collisions.Contacts)
        {
            if (!(contact.NormalImpulse > 0))
            {
                continue;
            }

            int a = Array.IndexOf(bodies, contact.BodyA);
            int b = contact.IsPlaneContact ? -1 - contact.PlaneIndex : Array.IndexOf(bodies, contact.BodyB);
            partners[a].Add(b);
            if (b >= 0)
            {
                partners[b].Add(a);
            }
        }

        return partners.Select(list => list.ToArray()).ToArray();
    }

    /// <summary>Whether bodies i and j were pushed by nothing but each other in the step (so their relative path was a chord, or two chords with one bounce).</summary>
    private static bool MetOnlyEachOther(int[][] pushedBy, int i, int j) =>
        pushedBy[i].All(k => k == j) && pushedBy[j].All(k => k == i);

    private static float DistanceToSegment(Vector3 a, Vector3 b)
    {
        Vector3 ab = b - a;
        float t = ab.LengthSquared() > 0 ? Math.Clamp(-Vector3.Dot(a, ab) / ab.LengthSquared(), 0f, 1f) : 0f;
        return (a + t * ab).Length();
    }
}

internal static class Vectors3
{
    public static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
}
