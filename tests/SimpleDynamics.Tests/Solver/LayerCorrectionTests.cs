using System;
using System.Globalization;
using System.Numerics;
using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using SimpleDynamics.Tests.Properties;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// A deep pile's layer correction (SequentialImpulseSolver.Layers.cs): between extra sweeps each horizontal band of
/// the pile scales its normal impulses by one factor. It must keep the laws of every impulse (no kinetic energy added,
/// momentum changed only through the ground and walls, no contact pulling), and it must help the sweeps converge.
/// </summary>
public class LayerCorrectionTests
{
    private const float Dt = 1f / 60f;

    /// <summary>The gradient a correction taken whole may leave, as a fraction of the largest before it (float velocities).</summary>
    private const double GradientLeft = 1e-3;

    private readonly ITestOutputHelper _output;

    public LayerCorrectionTests(ITestOutputHelper output) => _output = output;

    /// <summary>
    /// A generated deep pile, standing at rest from its first step: <see cref="Deep"/> layers packed as densely as
    /// equal bodies pack (in 2-D each row in the hollows of the row below, √3 r above it; in 3-D each square layer in the
    /// hollows of the one below, √2 r above it), <see cref="Wide"/> bodies across (per side, in 3-D), in a box that
    /// just holds them. Radii spread up to <see cref="RadiusSpread"/> times the smallest (the lattice is that of the
    /// largest: smaller bodies drop a little into place), masses log-uniformly over a factor <see cref="MassSpread"/>
    /// either way. Its support must reach the floor through every layer from impulses that start at zero: the deep
    /// pile's problem, at once.
    /// </summary>
    public sealed record DeepPile(
        bool Planar, int Wide, int Deep, float RadiusSpread, float MassSpread,
        float Friction, float Restitution, int Substeps, int ExtraIterations, float Tolerance, int Seed)
    {
        private const float Radius = 0.1f;

        /// <summary>
        /// The pile in a world of its own, stepped by <paramref name="solver"/> (given its <see cref="ExtraIterations"/>
        /// and tolerance); with <paramref name="lift"/>, its bottom row is kinematic and moves at that velocity.
        /// </summary>
        public World Build(SequentialImpulseSolver solver, Vector3? lift = null)
        {
            solver.ExtraIterations = ExtraIterations;
            solver.ConvergenceTolerance = Tolerance;
            float largest = Radius * RadiusSpread, spacing = 2 * largest * 1.0001f;
            float rise = (Planar ? MathF.Sqrt(3) : MathF.Sqrt(2)) * largest * 1.0001f;
            var world = new World(Scenes.EarthGravity, solver) { Substeps = Substeps, SleepingEnabled = false };
            float across = Wide * spacing + 0.01f * largest;
            world.AddPlanes(StaticPlane.Box(Vector3.Zero, new Vector3(across, 2 * Deep * spacing, Planar ? 0 : across), Planar));
            var random = new Random(Seed);
            for (int layer = 0; layer < Deep; layer++)
            {
                bool shifted = layer % 2 == 1; // in the hollows of the layer below: half a spacing along (and across, in 3-D)
                int count = shifted ? Wide - 1 : Wide;
                for (int i = 0; i < count; i++)
                {
                    for (int k = 0; k < (Planar ? 1 : count); k++)
                    {
                        float radius = Radius * (1 + (float)random.NextDouble() * (RadiusSpread - 1));
                        float mass = radius * radius * MathF.Pow(MassSpread, 2 * (float)random.NextDouble() - 1);
                        float offset = shifted ? spacing : spacing / 2;
                        var position = new Vector3(offset + i * spacing, radius + layer * rise, Planar ? 0 : offset + k * spacing);
                        world.Add(layer == 0 && lift is Vector3 velocity
                            ? RigidBody.CreateKinematic(radius, position, velocity)
                            : new RigidBody(mass, radius, position, Planar ? Inertia.Disc(mass, radius) : Inertia.SolidSphere(mass, radius)));
                    }
                }
            }

            return world;
        }

        public override string ToString() => string.Create(CultureInfo.InvariantCulture,
            $"{(Planar ? "2-D" : "3-D")} {Wide} wide, {Deep} deep, radii ×{RadiusSpread:R}, masses ×{MassSpread:R}, " +
            $"mu={Friction:R} eps={Restitution:R} substeps={Substeps} extra iterations={ExtraIterations} tolerance={Tolerance:R} seed={Seed}");
    }

    private static Gen<DeepPile> Piles { get; } =
        from planar in Gen.Elements(true, true, false)
        from wide in Gen.Choose(planar ? 3 : 2, planar ? 8 : 3)
        from deep in Gen.Choose(36, 56)
        from radiusSpread in Gen.OneOf(Gen.Constant(1f), Gen.Constant(1f), Generators.UniformF(1, 1.25))
        from massSpread in Gen.OneOf(Gen.Constant(1f), Generators.LogUniform(1, 30))
        from friction in Gen.OneOf(Gen.Elements(0f, 0.3f), Generators.UniformF(0, 1))
        from restitution in Gen.OneOf(Gen.Elements(0f, 0.5f), Generators.UniformF(0, 1))
        from substeps in Gen.Choose(1, 4)
        from extraIterations in Gen.Elements(1, 2, 4, 8)
        from tolerance in Gen.Elements(1e-3f, 1e-4f, 1e-5f) // the tighter, the more substeps go unconverged and are corrected
        from seed in Gen.Choose(0, 1_000_000)
        select new DeepPile(planar, wide, deep, radiusSpread, massSpread, friction, restitution, substeps, extraIterations, tolerance, seed);

    /// <summary>
    /// Over generated deep piles, for two seconds from their first step, every layer correction lowers (or keeps) the
    /// bodies' kinetic energy, changes their momentum only by what it gave through the ground and walls, and leaves
    /// every normal impulse ≥ 0: the step along the band factors is on the segment from 0 to the minimiser of the
    /// convex energy, and no impulse is scaled by less than ½. A correction taken whole (no factor limited, a full
    /// step) lands on that minimiser: no band's −Σ λ_i v_n,i is left (measured: at most 1.6e-4 of the largest before it;
    /// 1.3 with the band system's off-diagonal left out).
    /// </summary>
    [Fact]
    public void Every_layer_correction_of_a_generated_deep_pile_keeps_the_laws_of_impulses()
    {
        int piles = 0, corrected = 0, corrections = 0, unlimited = 0;
        double largestFall = 0, largestGradient = 0;
        PropertyCheck.Run(Piles, pile =>
        {
            var solver = new SequentialImpulseSolver(pile.Restitution, pile.Friction) { AuditLayerCorrections = true };
            World world = pile.Build(solver);
            for (int step = 0; step < 120; step++)
            {
                world.Step(Dt);
            }

            var audit = solver.Audit;
            piles++;
            corrected += audit.Count > 0 ? 1 : 0;
            corrections += audit.Count;
            largestFall = Math.Max(largestFall, audit.LargestEnergyFall);
            unlimited += audit.Unlimited;
            largestGradient = Math.Max(largestGradient, audit.LargestGradientLeft);
            Law.Holds(audit.Count == 0 || audit.LargestEnergyRise <= 1e-6,
                $"a correction raised the kinetic energy by {audit.LargestEnergyRise:E2} of itself");
            Law.Holds(audit.Count == 0 || audit.LargestMomentumError <= 1e-4,
                $"a correction changed the momentum by {audit.LargestMomentumError:E2} of the impulse it moved, beyond the walls'");
            Law.Holds(audit.Count == 0 || audit.SmallestImpulse >= 0, $"a correction left a normal impulse of {audit.SmallestImpulse}");
            Law.Holds(audit.Count == 0 || audit.LargestResidualError <= 1e-4,
                $"a band's right-hand side differed from −Σ λ_i v_n,i by {audit.LargestResidualError:E2} of its terms");
            Law.Holds(audit.Unlimited == 0 || audit.LargestGradientLeft <= GradientLeft,
                $"after a correction taken whole, a band's −Σ λ_i v_n,i was {audit.LargestGradientLeft:E2} of the largest before it: not the least energy");
        }, seed: 1601, maxTest: 40);

        _output.WriteLine($"{corrected} of {piles} piles corrected, {corrections} corrections; the largest fall of the energy {largestFall:P1}; " +
            $"{unlimited} taken whole, leaving at most {largestGradient:E1} of the gradient");
        Assert.True(unlimited > corrections / 4, $"only {unlimited} of {corrections} corrections were taken whole: the least-energy check checks too little");
        Assert.True(corrected > piles / 3, $"only {corrected} of {piles} piles had a layer correction: the property checks too little");
        Assert.True(largestFall > 1e-3, "no correction lowered the energy by as much as 0.1 %: it does nothing");
    }

    /// <summary>
    /// A deep pile carried up by a lift, its bottom row kinematic and rising at 5 cm/s, so that the contacts with the
    /// lift approach through the lift's own motion: the right-hand side of each correction's band system, −Pᵀ v_n,
    /// is built from the bodies' band sums and what the lift's velocity adds (SequentialImpulseSolver.Layers.cs); summed
    /// contact by contact from its definition, −Σ λ_i v_n,i, it is the same to rounding (measured: within 1.8e-8 of its
    /// terms in 119 corrections; 0.28 with the lift's term left out). Every impulse stays ≥ 0.
    /// </summary>
    [Fact]
    public void Every_correction_of_a_pile_on_a_rising_lift_has_the_right_hand_side_its_contacts_define()
    {
        var pile = new DeepPile(Planar: true, Wide: 8, Deep: 48, RadiusSpread: 1f, MassSpread: 3f,
            Friction: 0.3f, Restitution: 0.2f, Substeps: 1, ExtraIterations: 2, Tolerance: 1e-5f, Seed: 5);
        var solver = new SequentialImpulseSolver(pile.Restitution, pile.Friction) { AuditLayerCorrections = true };
        World world = pile.Build(solver, lift: new Vector3(0, 0.05f, 0));
        for (int step = 0; step < 120; step++)
        {
            world.Step(Dt);
        }

        var audit = solver.Audit;
        _output.WriteLine($"{audit.Count} corrections; right-hand sides within {audit.LargestResidualError:E1} of their terms");
        Assert.True(audit.Count >= 20, $"only {audit.Count} corrections: the pile did not need them");
        Assert.True(audit.LargestResidualError <= 1e-4, $"a right-hand side differed by {audit.LargestResidualError:E2} of its terms");
        Assert.True(audit.SmallestImpulse >= 0, $"a correction left a normal impulse of {audit.SmallestImpulse}");
    }

    /// <summary>
    /// 2,000 discs packed 100 deep and 20 wide, at rest, at the solver's defaults: from the first step their weight
    /// must reach the floor through every layer, from impulses that start at zero. Measured: with the layer
    /// correction the pile is held within 20 steps and spends 595 sweeps in steps 21–120 (about 6 a step), every disc
    /// slower than 2e-6 m/s at 2 s and overlaps of at most 0.19 mm; without it, 9,959 sweeps, discs at up to
    /// 1.3e-4 m/s, overlaps of 0.50 mm.
    /// </summary>
    [Fact]
    public void A_deep_pile_standing_from_its_first_step_is_held_in_far_fewer_sweeps_with_the_layer_correction()
    {
        (long sweeps, float fastest, float deepest) Run(bool correct)
        {
            var pile = new DeepPile(Planar: true, Wide: 20, Deep: 100, RadiusSpread: 1f, MassSpread: 1f,
                Friction: 0.3f, Restitution: 0f, Substeps: 4, ExtraIterations: 8, Tolerance: 1e-3f, Seed: 5);
            var solver = new SequentialImpulseSolver(pile.Restitution, pile.Friction) { LayerCorrection = correct };
            World world = pile.Build(solver);
            long sweeps = 0;
            for (int step = 1; step <= 120; step++)
            {
                world.Step(Dt);
                sweeps += step > 20 ? solver.SweepsThisStep : 0;
            }

            float fastest = 0, deepest = 0;
            foreach (RigidBody body in world.Bodies)
            {
                fastest = MathF.Max(fastest, body.LinearVelocity.Length());
            }

            foreach (Contact contact in world.Collisions.Contacts)
            {
                deepest = MathF.Max(deepest, contact.Penetration);
            }

            return (sweeps, fastest, deepest);
        }

        var with = Run(correct: true);
        var without = Run(correct: false);
        _output.WriteLine($"steps 21–120: {with.sweeps} sweeps with the correction, {without.sweeps} without; " +
            $"fastest disc at 2 s {with.fastest:E1} against {without.fastest:E1} m/s; " +
            $"deepest overlap {with.deepest * 1e3:F2} against {without.deepest * 1e3:F2} mm");
        Assert.True(with.sweeps * 4 < without.sweeps, $"{with.sweeps} sweeps with the correction, {without.sweeps} without");
        Assert.True(with.fastest < 2e-5f && with.fastest * 10 < without.fastest, $"fastest disc {with.fastest:E2} m/s with the correction, {without.fastest:E2} without");
        Assert.True(with.deepest <= without.deepest, $"deepest overlap {with.deepest} m with the correction, {without.deepest} without");
    }
}
