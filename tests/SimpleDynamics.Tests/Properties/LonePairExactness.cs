using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Numerics;
using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Properties;

/// <summary>How a generated lone pair was set up, so that a failing case says what it is meant to show.</summary>
public enum PairSetup
{
    /// <summary>Aimed to meet at a chosen time, at a chosen angle (grazing included).</summary>
    Hit,

    /// <summary>Aimed to pass each other (or the plane) at a chosen gap, near-misses included.</summary>
    Miss,

    /// <summary>Touching at the start and separating: nothing may happen.</summary>
    TouchingSeparating,

    /// <summary>Touching at the start and approaching: a collision at t = 0.</summary>
    TouchingApproaching,

    /// <summary>Anywhere, any velocities: they may meet or not.</summary>
    Random,
}

/// <summary>
/// A generated lone pair without gravity: two balls, or a ball (A) and a plane. Plain data, so that FsCheck prints a
/// failing case readably and it can be pasted into a closed-form test.
/// </summary>
public sealed record LonePairCase(
    PairSetup Setup,
    bool Planar,
    bool WithPlane,
    float Restitution,
    float Threshold,
    float Dt,
    int Substeps,
    int Steps,
    float MassA,
    float RadiusA,
    Vector3 PositionA,
    Vector3 VelocityA,
    float MassB,
    float RadiusB,
    Vector3 PositionB,
    Vector3 VelocityB,
    Vector3 PlaneNormal,
    Vector3 PlanePoint)
{
    /// <summary>The world: no gravity, μ = 0, the case's ε, restitution threshold and substeps.</summary>
    public World Build(out RigidBody a, out RigidBody? b)
    {
        var solver = new SequentialImpulseSolver(Restitution, friction: 0f) { RestitutionThreshold = Threshold };
        var world = new World(Vector3.Zero, solver) { Substeps = Substeps };
        a = world.Add(Ball(MassA, RadiusA, PositionA, VelocityA));
        b = null;
        if (WithPlane)
        {
            world.AddPlane(new StaticPlane(PlaneNormal, PlanePoint));
        }
        else
        {
            b = world.Add(Ball(MassB, RadiusB, PositionB, VelocityB));
        }

        return world;
    }

    private RigidBody Ball(float mass, float radius, Vector3 position, Vector3 velocity) =>
        new(mass, radius, position, Planar ? Inertia.Disc(mass, radius) : Inertia.SolidSphere(mass, radius)) { LinearVelocity = velocity };

    public override string ToString()
    {
        string other = WithPlane
            ? string.Create(CultureInfo.InvariantCulture, $"plane n={PlaneNormal} through {PlanePoint}")
            : string.Create(CultureInfo.InvariantCulture, $"B: m={MassB:R} r={RadiusB:R} c={PositionB} v={VelocityB}");
        return string.Create(CultureInfo.InvariantCulture,
            $"{Setup} {(Planar ? "2-D" : "3-D")} eps={Restitution:R} threshold={Threshold:R} dt={Dt:R} substeps={Substeps} steps={Steps}{Environment.NewLine}" +
            $"  A: m={MassA:R} r={RadiusA:R} c={PositionA} v={VelocityA}{Environment.NewLine}  {other}");
    }
}

/// <summary>
/// One body's exact motion: free flight with velocity V0 from X0 until the impact at time TImpact (+∞ if none), at
/// XImpact, then free flight with V1. Without gravity this piecewise-linear path is the whole truth.
/// </summary>
internal readonly record struct ExactFlight(D3 X0, D3 V0, double TImpact, D3 XImpact, D3 V1)
{
    public static ExactFlight Free(D3 x0, D3 v0) => new(x0, v0, double.PositiveInfinity, x0, v0);

    public D3 Position(double t) => t <= TImpact ? X0 + t * V0 : XImpact + (t - TImpact) * V1;

    public D3 Velocity(double t) => t <= TImpact ? V0 : V1;

    /// <summary>Distance travelled by time t (the length of the path, not the displacement).</summary>
    public double Path(double t) => t <= TImpact ? t * V0.Length : TImpact * V0.Length + (t - TImpact) * V1.Length;
}

/// <summary>
/// The exact motion of a lone pair, computed here in double precision from the case's float inputs, independently of
/// the library: free flight to the time of impact t*, the smooth-sphere impulse of the tutorial's eq. 5–10 along the
/// line of centres (the plane's normal) with restitution ε, then free flight. Two balls in free space meet at most
/// once (after the impulse their centres separate along n and free flight keeps them separating), and so does a ball
/// and a plane.
/// </summary>
internal sealed class ExactLonePair
{
    /// <summary>2⁻²⁴: the relative rounding of a float32 number (half an ulp of 1).</summary>
    public const double FloatUnit = 1.0 / (1 << 24);

    private ExactLonePair(ExactFlight a, ExactFlight b, double incidence, double missGap, double approachSpeed, double conditioning)
    {
        A = a;
        B = b;
        Incidence = incidence;
        MissGap = missGap;
        ApproachSpeed = approachSpeed;
        Conditioning = conditioning;
    }

    public ExactFlight A { get; }

    /// <summary>Ball B's flight; for a plane, a body at rest at the origin (never compared).</summary>
    public ExactFlight B { get; }

    /// <summary>cos θ between the approach velocity and the normal at the impact (1 head-on, → 0 grazing); NaN if no impact.</summary>
    public double Incidence { get; }

    /// <summary>For two balls that approach and pass by: their closest distance minus r_A + r_B, as a fraction of r_A + r_B.</summary>
    public double MissGap { get; }

    /// <summary>−v₁₂·n at the impact (eq. 8), 0 if no impact.</summary>
    public double ApproachSpeed { get; }

    /// <summary>
    /// How much float32 storage of the positions alone can change the outcome, relative to the pair's speed:
    /// κ = ρ* / ((r_A + r_B) c), with ρ* = 2⁻²⁴ (2 s + 2) k* X the rounding the positions may have gathered by the
    /// moment that matters: X is the largest distance from the origin of either centre at the start and at the impact
    /// (or the closest approach), and k* the steps up to it, each writing a position at most 2 s + 2 times (s substeps;
    /// the same count as the position tolerance's ρ). For an impact, c = cos θ (the incidence): an error across the path
    /// moves the point of contact along the sphere 1/c times as far (near grazing the spheres slide past each other),
    /// which turns the line of centres by ρ* / ((r_A + r_B) c) and the velocities after eq. 10 by about |v₁₂| times that.
    /// For a pair that passes by, c is its miss gap: a rounding as large as the gap turns the miss into a grazing hit.
    /// 0 for a pair separating from the start and for a plane (its normal is given exactly: no line of centres to round).
    /// </summary>
    public double Conditioning { get; }

    public static ExactLonePair Of(LonePairCase c)
    {
        D3 xA = D3.From(c.PositionA), vA = D3.From(c.VelocityA);
        double e = c.Restitution, threshold = c.Threshold;
        if (c.WithPlane)
        {
            // The plane as the library stores it (normal normalised in float, offset n·p in float): those are its inputs.
            var plane = new StaticPlane(c.PlaneNormal, c.PlanePoint);
            D3 n = D3.From(plane.Normal);
            n = n / n.Length;
            double gap = D3.Dot(n, xA) - plane.Offset - c.RadiusA; // distance to the plane minus r
            double vn = D3.Dot(n, vA);
            if (vn >= 0)
            {
                return new ExactLonePair(ExactFlight.Free(xA, vA), ExactFlight.Free(D3.Zero, D3.Zero), double.NaN, double.PositiveInfinity, 0, 0);
            }

            double t = Math.Max(0, gap) / -vn;
            double eps = -vn > threshold ? e : 0; // no bounce below the restitution threshold
            D3 v1 = vA - (1 + eps) * vn * n; // eq. 6 and 10 with an immovable plane (1/m = 0): J/m_A = −(1+ε) v·n
            var flight = new ExactFlight(xA, vA, t, xA + t * vA, v1);
            return new ExactLonePair(flight, ExactFlight.Free(D3.Zero, D3.Zero), -vn / vA.Length, double.NaN, -vn, 0);
        }

        D3 xB = D3.From(c.PositionB), vB = D3.From(c.VelocityB);
        double reach = (double)c.RadiusA + c.RadiusB;
        D3 d = xA - xB, w = vA - vB; // relative position, and relative velocity (eq. 7)
        double dw = D3.Dot(d, w), ww = D3.Dot(w, w), excess = D3.Dot(d, d) - reach * reach;
        double startFar = Math.Max(xA.Length, xB.Length);
        if (dw >= 0)
        {
            // Separating (or at rest relative to each other): no impact, ever.
            return new ExactLonePair(ExactFlight.Free(xA, vA), ExactFlight.Free(xB, vB), double.NaN, double.PositiveInfinity, 0, 0);
        }

        double discriminant = dw * dw - ww * excess;
        if (excess > 0 && discriminant < 0)
        {
            // Passing by: the closest approach is at t = −d·w / |w|², where the centres are d − (d·w/|w|²) w apart.
            double tClosest = -dw / ww;
            double missGap = ((d + tClosest * w).Length - reach) / reach;
            double far = Math.Max(startFar, Math.Max((xA + tClosest * vA).Length, (xB + tClosest * vB).Length));
            return new ExactLonePair(ExactFlight.Free(xA, vA), ExactFlight.Free(xB, vB), double.NaN, missGap, 0,
                Rounding(c, far, tClosest) / (reach * missGap));
        }

        // |d + w t| = r_A + r_B, the smaller root, written to avoid cancellation; touching already: t* = 0.
        double tImpact = excess <= 0 ? 0 : excess / (-dw + Math.Sqrt(discriminant));
        D3 xAImpact = xA + tImpact * vA, xBImpact = xB + tImpact * vB;
        D3 normal = xAImpact - xBImpact; // from B to A, along the line of centres at contact
        normal = normal / normal.Length;
        double v12n = D3.Dot(w, normal); // eq. 8 (negative: approaching)
        double restitution = -v12n > threshold ? e : 0; // no bounce below the restitution threshold
        double j = -(1 + restitution) * v12n / (1 / (double)c.MassA + 1 / (double)c.MassB); // eq. 10, |n| = 1
        D3 vA1 = vA + j / c.MassA * normal, vB1 = vB - j / c.MassB * normal; // eq. 6
        double incidence = -v12n / Math.Sqrt(ww);
        double farthest = Math.Max(startFar, Math.Max(xAImpact.Length, xBImpact.Length));
        return new ExactLonePair(
            new ExactFlight(xA, vA, tImpact, xAImpact, vA1),
            new ExactFlight(xB, vB, tImpact, xBImpact, vB1),
            incidence, double.NaN, -v12n, Rounding(c, farthest, tImpact) / (reach * incidence));
    }

    /// <summary>ρ* = 2⁻²⁴ (2 s + 2) k* X: the rounding float32 positions at distance X may gather in the k* steps up to time t.</summary>
    private static double Rounding(LonePairCase c, double far, double time)
    {
        double steps = Math.Min(c.Steps, Math.Floor(time / c.Dt) + 1);
        return FloatUnit * (2 * c.Substeps + 2) * steps * far;
    }
}


/// <summary>
/// Issue 8, point 1: "For a lone pair without gravity (two balls, or a ball and a plane), positions and velocities after
/// each step match the exact piecewise-linear motion to 1e-4 relative, for any dt from 1e-4 to 1 s and any speed, in
/// 2-D and 3-D." Generated lone pairs are stepped with <see cref="World.Step"/> and the default solver (μ = 0, so the
/// exact motion is that of smooth spheres: no friction, no spin) and compared after every step with the exact motion
/// computed here in double precision (<see cref="ExactLonePair"/>), plus closed-form scenarios that pin the numbers.
/// </summary>
/// <remarks>
/// <para><b>What is generated.</b> Masses 1e-2…1e3 kg, radii 0.05…2 m, speeds 1 mm/s…1 km/s log-uniform (and 0 and
/// 1 km/s on purpose), 2-D (z = 0) and 3-D, ε ∈ {0, 0.25, 0.5, 0.75, 1} or uniform, dt log-uniform in [1e-4, 1] s (and
/// both ends on purpose), 1…8 substeps, 2…12 steps. Two balls are aimed to meet at a chosen time and incidence (cos θ
/// down to 1e-6: grazing), aimed to pass at a chosen gap (down to 1e-6 of r_A + r_B: near-misses), touching at the
/// start and separating, touching and approaching, or placed anywhere. A ball and a plane likewise.</para>
/// <para><b>Restitution threshold.</b> The solver does not bounce a collision slower than
/// <see cref="SequentialImpulseSolver.RestitutionThreshold"/>. The properties over the whole domain draw it as 0 three
/// times in four and as the default 0.5 m/s otherwise, and the oracle accounts for it (ε = 0 below it; a case whose
/// approach speed is within 0.1 % of it is not judged, since float rounding decides the side).</para>
/// <para><b>Tolerances: what "1e-4 relative" means here.</b> Velocities: |Δv| ≤ 1e-4 V, V the largest speed of
/// either ball before or after the impact: eq. 10 mixes both balls' velocities, so the pair's speed is the scale of
/// either ball's error (a light ball at rest struck by a heavy one has no speed of its own to compare with).
/// Positions: |Δx| ≤ 1e-4 (r_A + r_B + L_A + L_B) + ρ, L the length of the exact path travelled so far: the time of
/// impact and the normal come from the pair's relative motion, so their errors scale with the pair's size and how far
/// it has moved, and an error of 1e-4 V in velocity grows into 1e-4 of the path after it. ρ = 2⁻²⁴ |x|max is the
/// rounding of the reported float32 <see cref="RigidBody.Position"/> alone, once: the centre is kept in double
/// precision between steps, so no rounding gathers from step to step (with float32 state it did, by up to 2⁻²⁴ |x| at
/// each of the 2 s + 2 writes of a step, and the tolerance had to allow for that). The velocity jumps by v₁ − v₀ at t*: a step that ends
/// within s of t*, with |v₁ − v₀| s inside the position tolerance, may show either side's velocity (an impact that
/// early or late keeps the path within tolerance; even exact arithmetic lands on either side of a nearby step end).</para>
/// <para><b>Findings.</b> With float32 state, a survey of 3000 generated cases over the whole domain found 94 failures
/// in two classes. (1) Float32 positions, 51 cases: with the threshold at 0 every failure was two balls whose contact
/// is finer than the rounding their positions gather, κ ≥ 2.1e-4 (<see cref="ExactLonePair.Conditioning"/>: far from
/// the origin, grazing, near-misses closer than the rounding, or many substeps of small moves before a grazing
/// impact), missing the law by up to a few per cent of their speed: no float32 state can meet 1e-4 there. Fixed:
/// without gravity, bodies move in double precision between impacts and steps, and pairs are predicted and measured
/// in double (the impact pass's remarks, "Precision"), and so is the resting-contact pass's
/// decision whether a slow pair touches (a pair slower than the threshold passing within float rounding of touching
/// was taken for a resting contact and pushed). Surveyed again over 15,000 cases of two balls (seeds 2, 5, 7, 11, 13,
/// 17) and 4,000 of a ball and a plane: none fails. A ball sliding along a plane a kilometre out still sank 72 µm
/// into it: the plane's float normal is unit only to about 6e-8; it is made exactly unit in double. (2) The restitution threshold, 43 cases: a pair that approached
/// slower than it was stopped by the resting-contact pass as soon as it came within
/// <see cref="SequentialImpulseSolver.Slop"/> (0.5 mm) of touching, before it touched, and even when it would only
/// have passed by within 0.5 mm. Fixed: the resting-contact pass now holds a pair that is apart only if it pushed in
/// the last substep (a pile's contact that the position pass left just apart); any other approach is the impact
/// pass's, at its time of impact. <c>FSCHECK_MAXTEST=n</c> runs the properties over n cases each.</para>
/// </remarks>
public class LonePairExactness
{
    private const double Relative = 1e-4;

    /// <summary>
    /// κ (<see cref="ExactLonePair.Conditioning"/>) above which float32 positions alone cannot resolve a contact: with
    /// float32 state, every failure of 6000 cases surveyed had κ ≥ 2.1e-4 and none had κ ≤ 1e-4.
    /// </summary>
    private const double BeyondFloat32 = 2e-4;

    private readonly ITestOutputHelper _output;

    public LonePairExactness(ITestOutputHelper output) => _output = output;

    // ---- Generators ------------------------------------------------------------------------------------------------

    /// <summary>dt log-uniform in [1e-4, 1] s, with both ends drawn on purpose.</summary>
    private static Gen<float> Dt { get; } = Gen.OneOf(Generators.LogUniform(1e-4, 1), Generators.LogUniform(1e-4, 1), Gen.Elements(1e-4f, 1f));

    /// <summary>Speeds from 1 mm/s to 1 km/s, log-uniform, with rest and 1 km/s (a 1 km path at dt = 1) drawn on purpose.</summary>
    private static Gen<float> Speed { get; } = Gen.OneOf(Generators.LogUniform(1e-3, 1e3), Generators.LogUniform(1e-3, 1e3), Gen.Elements(0f, 1e3f));

    private static Gen<float> Restitution { get; } = Gen.OneOf(Gen.Elements(0f, 0.25f, 0.5f, 0.75f, 1f), Generators.UniformF(0, 1));

    /// <summary>0 three times in four, else the solver's default 0.5 m/s (the oracle accounts for it).</summary>
    private static Gen<float> AnyThreshold { get; } = Gen.Elements(0f, 0f, 0f, 0.5f);

    /// <summary>cos θ of the incidence: uniform, or log-uniform down to 1e-6 (grazing).</summary>
    private static Gen<double> Incidence { get; } = Gen.OneOf(Generators.Uniform(0.01, 1), Generators.Unit.Select(u => Math.Pow(10, -6 * u)));

    /// <summary>The closest distance beyond contact, as a fraction of r_A + r_B: up to 3, or log-uniform down to 1e-6 (near-miss).</summary>
    private static Gen<double> MissGap { get; } = Gen.OneOf(Generators.Uniform(0, 3), Generators.Unit.Select(u => Math.Pow(10, -6 * u)));

    /// <summary>When the moment that matters comes, as a fraction of the run: anywhere up to 1.2 (after the run), or early (1e-6…1, log-uniform).</summary>
    private static Gen<double> When { get; } = Gen.OneOf(Generators.Uniform(0, 1.2), Generators.Unit.Select(u => Math.Pow(10, -6 * u)));

    /// <summary>Where it happens: within ±10 m of the origin, or within ±0.1 m.</summary>
    private static Gen<D3> Place { get; } =
        from spread in Gen.Elements(0.01, 1.0)
        from v in Generators.Vector(10)
        select spread * D3.From(v);

    private static Gen<double> Radius { get; } = Generators.Uniform(0.05, 2);

    private static Vector3 Flat(bool planar, Vector3 v) => planar ? new Vector3(v.X, v.Y, 0) : v;

    private static D3 Flat(bool planar, D3 v) => planar ? v with { Z = 0 } : v;

    private static D3 Direction(bool planar, Vector3 v)
    {
        Vector3 f = Flat(planar, v);
        return D3.From(f.LengthSquared() > 1e-6f ? Vector3.Normalize(f) : Vector3.UnitX);
    }

    /// <summary>A unit vector perpendicular to u (in the plane z = 0 when planar), built from a random direction.</summary>
    private static D3 Across(bool planar, D3 u, Vector3 random)
    {
        D3 r = Direction(planar, random);
        D3 w = r - D3.Dot(r, u) * u;
        if (w.Length < 1e-3)
        {
            w = planar ? new D3(-u.Y, u.X, 0) : D3.Cross(u, Math.Abs(u.X) < 0.9 ? new D3(1, 0, 0) : new D3(0, 1, 0));
        }

        return w / w.Length;
    }

    private static Vector3 F(D3 v) => new((float)v.X, (float)v.Y, (float)v.Z);

    private sealed record Common(bool Planar, float Restitution, float Threshold, float Dt, int Substeps, int Steps);

    private static Gen<Common> Commons(Gen<float> threshold) =>
        from planar in Gen.Elements(true, false)
        from restitution in Restitution
        from t in threshold
        from dt in Dt
        from substeps in Gen.Choose(1, 8)
        from steps in Gen.Choose(2, 12)
        select new Common(planar, restitution, t, dt, substeps, steps);

    private static Gen<PairSetup> Setups { get; } =
        Gen.Elements(PairSetup.Hit, PairSetup.Hit, PairSetup.Miss, PairSetup.TouchingSeparating, PairSetup.TouchingApproaching, PairSetup.Random);

    /// <summary>cos θ or miss gap for contacts finer than the general draw: log-uniform in [1e-6, 1e-1].</summary>
    private static Gen<double> Fine { get; } = Generators.Unit.Select(u => Math.Pow(10, -6 + 5 * u));

    /// <summary>
    /// Two balls. Aimed cases are built backwards from the moment that matters (the impact, or the closest approach):
    /// B's centre there, A's at the chosen distance in the chosen direction, then both moved back by their velocities.
    /// <paramref name="fine"/> draws only grazing hits and near-misses (cos θ or gap 1e-6…1e-1); <paramref name="place"/>
    /// says where they happen and start.
    /// </summary>
    private static Gen<LonePairCase> TwoBalls(Gen<float> threshold, bool fine = false, Where place = Where.Anywhere) =>
        from c in Commons(threshold)
        from setup in fine ? Gen.Elements(PairSetup.Hit, PairSetup.Miss) : Setups
        from massA in Generators.Mass
        from massB in Generators.Mass
        from radiusA in Radius
        from radiusB in Radius
        from speedA in Speed
        from speedB in Speed
        from directionA in Generators.UnitVector
        from directionB in Generators.UnitVector
        from side in Generators.UnitVector
        from centre in Place
        from other in Generators.Vector(10)
        from when in When
        from incidence in fine ? Fine : Incidence
        from gap in fine ? Fine : MissGap
        let time = when * c.Steps * c.Dt
        select TwoBallCase(c, setup, massA, massB, radiusA, radiusB, speedA * Direction(c.Planar, directionA), speedB * Direction(c.Planar, directionB),
            side, Flat(c.Planar, place switch { Where.NearOrigin => 0.01 * centre, Where.FarOut => 100 * centre, _ => centre }), D3.From(Flat(c.Planar, other)),
            place == Where.NearOrigin ? Math.Min(time, 1 / Math.Max(1e-3, Math.Max(speedA, speedB))) : time, incidence, gap);

    /// <summary>
    /// Where the moment that matters happens: within ±10 m of the origin (or ±0.1 m, as <see cref="Place"/> draws); within
    /// ±0.1 m, the pair starting within about 1 m; or within ±1 km (or ±10 m), where float32 positions are up to 61 µm apart.
    /// </summary>
    private enum Where
    {
        Anywhere,
        NearOrigin,
        FarOut,
    }

    private static LonePairCase TwoBallCase(Common c, PairSetup setup, float massA, float massB, double radiusA, double radiusB,
        D3 vA, D3 vB, Vector3 side, D3 centre, D3 other, double when, double incidence, double gap)
    {
        double reach = radiusA + radiusB;
        D3 w = vA - vB;
        D3 u = w.Length > 0 ? w / w.Length : new D3(1, 0, 0); // the direction of A's motion relative to B
        D3 across = Across(c.Planar, u, side);
        D3 xA, xB;
        switch (setup)
        {
            case PairSetup.Hit:
            {
                // At the impact the normal n (from B to A) makes angle θ with −u: n = −cos θ u + sin θ across.
                D3 n = -incidence * u + Math.Sqrt(1 - incidence * incidence) * across;
                xB = centre - when * vB;
                xA = centre + reach * n - when * vA;
                break;
            }

            case PairSetup.Miss:
                // At the closest approach A is beside B, across the relative velocity, at (1 + gap)(r_A + r_B).
                xB = centre - when * vB;
                xA = centre + (1 + gap) * reach * across - when * vA;
                break;
            case PairSetup.TouchingSeparating:
            case PairSetup.TouchingApproaching:
            {
                D3 n = Direction(c.Planar, side);
                bool approaching = D3.Dot(w, n) < 0;
                if (approaching != (setup == PairSetup.TouchingApproaching))
                {
                    (vA, vB) = (vB, vA); // reverses the relative velocity
                }

                xB = centre;
                xA = centre + reach * n;
                break;
            }

            default:
                xB = centre;
                xA = (other - centre).Length < reach * 1.001 ? centre + 1.5 * reach * Direction(c.Planar, side) : other;
                break;
        }

        return new LonePairCase(setup, c.Planar, false, c.Restitution, c.Threshold, c.Dt, c.Substeps, c.Steps,
            massA, (float)radiusA, F(xA), F(vA), massB, (float)radiusB, F(xB), F(vB), Vector3.UnitY, Vector3.Zero);
    }

    /// <summary>
    /// A ball and a plane with a random normal: aimed to hit at a chosen time and incidence (grazing included), moving
    /// along it or away at a chosen gap, touching and leaving, touching and approaching, or anywhere in front of it.
    /// </summary>
    private static Gen<LonePairCase> BallAndPlane(Gen<float> threshold, Where place = Where.Anywhere) =>
        from c in Commons(threshold)
        from setup in Setups
        from mass in Generators.Mass
        from radius in Radius
        from speed in Speed
        from normal in Generators.UnitVector
        from direction in Generators.UnitVector
        from side in Generators.UnitVector
        from point in Place
        from along in Generators.Vector(10)
        from away in Gen.Elements(true, false)
        from when in When
        from incidence in Incidence
        from gap in MissGap
        select PlaneCase(c, setup, mass, radius, speed, Direction(c.Planar, normal), Direction(c.Planar, direction),
            side, Flat(c.Planar, place == Where.FarOut ? 100 * point : point), D3.From(Flat(c.Planar, along)), away, when * c.Steps * c.Dt, incidence, gap);

    private static LonePairCase PlaneCase(Common c, PairSetup setup, float mass, double radius, float speed, D3 n, D3 direction,
        Vector3 side, D3 point, D3 along, bool away, double when, double incidence, double gap)
    {
        D3 tangent = Across(c.Planar, n, side);
        D3 onPlane = point + (along - D3.Dot(along, n) * n); // a point of the plane, somewhere along it
        double sine = Math.Sqrt(1 - incidence * incidence);
        D3 v, x;
        switch (setup)
        {
            case PairSetup.Hit:
                v = speed * (-incidence * n + sine * tangent);
                x = onPlane + radius * n - when * v;
                break;
            case PairSetup.Miss:
                v = speed * ((away ? incidence : 0) * n + sine * tangent); // along the plane, or leaving it
                x = onPlane + (1 + gap) * radius * n;
                break;
            case PairSetup.TouchingSeparating:
            case PairSetup.TouchingApproaching:
                double vn = Math.Abs(D3.Dot(direction, n)) * (setup == PairSetup.TouchingApproaching ? -1 : 1);
                v = speed * (direction - D3.Dot(direction, n) * n + vn * n);
                x = onPlane + radius * n;
                break;
            default:
                v = speed * direction;
                x = onPlane + (radius + 3 * gap) * n;
                break;
        }

        return new LonePairCase(setup, c.Planar, true, c.Restitution, c.Threshold, c.Dt, c.Substeps, c.Steps,
            mass, (float)radius, F(x), F(v), 0, 0, Vector3.Zero, Vector3.Zero, F(n), F(point));
    }

    // ---- The law ---------------------------------------------------------------------------------------------------

    /// <summary>
    /// Steps the case and compares every step end with the exact motion; returns the largest error as a multiple of
    /// its tolerance (≤ 1: the law holds) with where it was, or null if the case is not judged.
    /// </summary>
    private static (double Ratio, string Where)? Compare(LonePairCase c)
    {
        ExactLonePair exact = ExactLonePair.Of(c);
        if (c.Threshold > 0 && Math.Abs(exact.ApproachSpeed - c.Threshold) <= 1e-3 * c.Threshold)
        {
            return null; // which side of the threshold float rounding puts it decides the bounce
        }

        World world = c.Build(out RigidBody a, out RigidBody? b);
        double speedScale = Math.Max(Math.Max(exact.A.V0.Length, exact.A.V1.Length), Math.Max(exact.B.V0.Length, exact.B.V1.Length));
        double size = c.RadiusA + (c.WithPlane ? 0 : c.RadiusB);
        double worst = 0;
        string where = "";
        for (int step = 1; step <= c.Steps; step++)
        {
            world.Step(c.Dt);
            double t = step * (double)c.Dt;
            double lengthScale = size + exact.A.Path(t) + (c.WithPlane ? 0 : exact.B.Path(t));
            Check(a, exact.A, "A");
            if (b is not null)
            {
                Check(b, exact.B, "B");
            }

            void Check(RigidBody body, ExactFlight flight, string name)
            {
                D3 position = D3.From(body.Position), velocity = D3.From(body.LinearVelocity);
                D3 x = flight.Position(t), v = flight.Velocity(t);
                double largest = Math.Max(Math.Max(flight.X0.Length, x.Length), position.Length);
                double positionTolerance = Relative * lengthScale + ExactLonePair.FloatUnit * largest;
                double velocityTolerance = Relative * speedScale;
                double dx = (position - x).Length, dv = (velocity - v).Length;
                if (Math.Abs(t - flight.TImpact) * (flight.V1 - flight.V0).Length <= positionTolerance)
                {
                    // The velocity jumps at t*. An impact early or late by s moves the body off its exact path by
                    // |v₁ − v₀| s; if the step ends closer to t* than the s that keeps this within the position
                    // tolerance, the impact may fall on either side of the step end (even in exact arithmetic, for any
                    // rounding of t*), so either side's velocity is right. A grazing impact, whose jump is small, is
                    // thus timed only as well as its effect on the path can tell.
                    dv = Math.Min(dv, (velocity - (t <= flight.TImpact ? flight.V1 : flight.V0)).Length);
                }

                double ratio = Math.Max(dx / positionTolerance, velocityTolerance > 0 ? dv / velocityTolerance : dv > 0 ? double.PositiveInfinity : 0);
                if (!(ratio <= worst))
                {
                    worst = double.IsNaN(ratio) ? double.PositiveInfinity : ratio;
                    where = string.Create(CultureInfo.InvariantCulture,
                        $"step {step} (t = {t:R} s), ball {name}: position {body.Position} vs exact {x}, |dx| {dx:G3} (tolerance {positionTolerance:G3}); " +
                        $"velocity {body.LinearVelocity} vs exact {v}, |dv| {dv:G3} (tolerance {velocityTolerance:G3}); exact impact at t* = {flight.TImpact:R} s, " +
                        $"cos θ {exact.Incidence:G3}, miss gap {exact.MissGap:G3}, conditioning κ {exact.Conditioning:G3}");
                }
            }
        }

        return (worst, where);
    }

    private static void FollowsExactMotion(LonePairCase c)
    {
        if (Compare(c) is (double ratio, string where))
        {
            Law.Holds(ratio <= 1, $"error {ratio:G3} × the tolerance at {where}");
        }
    }

    /// <summary>
    /// The whole domain, grazing hits and near-misses included, with and without the restitution threshold: two balls
    /// move in double precision between impacts (ImpactStepper's remarks, "Precision"), so a contact finer than float32
    /// positions can resolve is still timed and aimed as the exact motion has it.
    /// </summary>
    [Fact]
    public void Two_balls_follow_their_exact_motion() =>
        PropertyCheck.Run(TwoBalls(AnyThreshold), FollowsExactMotion, seed: 8101, maxTest: 1000);

    /// <summary>
    /// Grazing hits and near-misses (cos θ or gap 1e-6…1e-1) near the origin, with and without the restitution
    /// threshold: the general draw makes few of them.
    /// </summary>
    [Fact]
    public void Grazing_balls_and_near_misses_near_the_origin_follow_their_exact_motion() =>
        PropertyCheck.Run(TwoBalls(AnyThreshold, fine: true, Where.NearOrigin), FollowsExactMotion, seed: 8105, maxTest: 500);

    /// <summary>
    /// Grazing hits and near-misses up to a kilometre from the origin, with and without the restitution threshold: the
    /// contacts float32 positions cannot resolve (see <see cref="Far_out_fine_contacts_are_beyond_float32"/>).
    /// </summary>
    [Fact]
    public void Grazing_balls_and_near_misses_far_from_the_origin_follow_their_exact_motion() =>
        PropertyCheck.Run(TwoBalls(AnyThreshold, fine: true, Where.FarOut), FollowsExactMotion, seed: 8103, maxTest: 500);

    /// <summary>
    /// The far-out draw above is what it claims to be: most of its contacts are finer than float32 positions resolve
    /// (κ above <see cref="BeyondFloat32"/>), where float32 state missed the law.
    /// </summary>
    [Fact]
    public void Far_out_fine_contacts_are_beyond_float32()
    {
        LonePairCase[] cases = Gen.Sample(TwoBalls(AnyThreshold, fine: true, Where.FarOut), 200, new Rnd(8107, 0x9E3779B97F4A7C15UL), 100);
        int beyond = cases.Count(c => ExactLonePair.Of(c).Conditioning > BeyondFloat32);
        _output.WriteLine($"{beyond} of {cases.Length} drawn contacts have kappa > {BeyondFloat32}");
        Assert.True(beyond > cases.Length / 2, $"only {beyond} of {cases.Length} drawn contacts are beyond float32");
    }

    /// <summary>
    /// The whole domain, grazing included, with and without the restitution threshold: a ball that approaches slower
    /// than the threshold is stopped where it touches, not where it comes within the slop.
    /// </summary>
    [Fact]
    public void A_ball_and_a_plane_follow_their_exact_motion() =>
        PropertyCheck.Run(BallAndPlane(AnyThreshold), FollowsExactMotion, seed: 8102, maxTest: 500);

    /// <summary>The same where the ball meets (or passes) the plane up to a kilometre from the origin.</summary>
    [Fact]
    public void A_ball_and_a_plane_far_from_the_origin_follow_their_exact_motion() =>
        PropertyCheck.Run(BallAndPlane(AnyThreshold, Where.FarOut), FollowsExactMotion, seed: 8104, maxTest: 500);

    // ---- Closed-form scenarios -------------------------------------------------------------------------------------

    /// <summary>
    /// Contacts finer than float32 positions can resolve, which float32 state got wrong (found by the properties above;
    /// κ is <see cref="ExactLonePair.Conditioning"/>), each with what the exact motion says it is.
    /// </summary>
    private static readonly Dictionary<string, (LonePairCase Case, string Kind, double Fineness)> FineContacts = new()
    {
        // Exactly, B misses A by 1.3 µm (2.1e-6 of r_A + r_B, κ 3e3) after coming 1.2 km, where float32 rounds its
        // position by up to 61 µm: float32 state hit, and after step 4 B's velocity was off by 9.98 m/s (2.8 %).
        ["near-miss by 1.3 um after 1.2 km"] = (new LonePairCase(PairSetup.Miss, false, false, 0.5f, 0f, 1f, 6, 6,
            265.4599f, 0.4582839f, new Vector3(6.608555f, 2.508443f, -3.302624f), Vector3.Zero,
            0.43703952f, 0.16042775f, new Vector3(405.26724f, 763.9054f, 803.0141f), new Vector3(-119.12176f, -227.31654f, -240.99304f),
            Vector3.UnitY, Vector3.Zero), "miss", 2.1e-6),

        // A grazing hit (cos θ 3.85e-4, κ 3.3e-3) at t* = 0.0894 s: float32 state sent B off by 0.0057 m/s, 1.09 × 1e-4 V.
        ["grazing hit, cos 3.85e-4"] = (new LonePairCase(PairSetup.Hit, true, false, 0.25f, 0f, 0.10490437f, 1, 2,
            0.33209103f, 0.7855704f, new Vector3(-3.3584716f, -4.4598203f, 0), new Vector3(-52.17023f, 7.4250193f, 0),
            0.032399565f, 1.2279525f, new Vector3(-9.417612f, -4.783566f, 0), new Vector3(9.245796f, -10.559802f, 0),
            Vector3.UnitY, Vector3.Zero), "hit", 3.85e-4),

        // Slower than the restitution threshold, B passes A by 3.4e-8 of r_A + r_B (κ 941): from float32 positions the
        // resting-contact pass took it for touching and pushed, A's velocity off by 5.3 × the tolerance.
        ["slow near-miss by 3.4e-8 under the threshold"] = (new LonePairCase(PairSetup.Hit, false, false, 0.33645117f, 0.5f, 0.0014319562f, 7, 7,
            1.394114f, 0.2759816f, new Vector3(-9.153085f, 4.252767f, 8.053149f), new Vector3(-0.6678906f, 0.4665997f, 0.8660719f),
            5.183036f, 1.7392597f, new Vector3(-8.69162f, 3.321814f, 9.779899f), new Vector3(0.1840387f, -0.4546999f, 0.13375182f),
            Vector3.UnitY, Vector3.Zero), "miss", 3.4e-8),
    };

    public static TheoryData<string> FineContactNames => new(FineContacts.Keys);

    [Theory]
    [MemberData(nameof(FineContactNames))]
    public void A_contact_finer_than_float32_positions_resolve_follows_its_exact_motion(string name)
    {
        (LonePairCase c, string kind, double fineness) = FineContacts[name];
        ExactLonePair exact = ExactLonePair.Of(c);
        _output.WriteLine($"{c}{Environment.NewLine}exact: t* {exact.A.TImpact:R}, cos {exact.Incidence:G3}, miss gap {exact.MissGap:G3}, kappa {exact.Conditioning:G3}");
        Assert.Equal(kind, double.IsPositiveInfinity(exact.A.TImpact) ? "miss" : "hit");
        Assert.InRange(kind == "miss" ? exact.MissGap : exact.Incidence, 0.9 * fineness, 1.1 * fineness);
        Assert.True(exact.Conditioning > BeyondFloat32, $"kappa {exact.Conditioning:G3}: float32 would resolve it");
        (double ratio, string where) = Compare(c) ?? throw new InvalidOperationException("the case must be judged");
        Assert.True(ratio <= 1, $"error {ratio:G3} x the tolerance at {where}");
    }

    /// <summary>
    /// A body far from the origin moving slower than float32 can resolve per step: at 1 km a position rounds to
    /// 61 µm, and 10 µm a step would round away every time, freezing it. Its centre in double precision keeps it moving
    /// at its velocity; when its position is set, it goes on from there, not from the centre it had.
    /// </summary>
    [Fact]
    public void A_slow_body_a_kilometre_out_moves_at_its_velocity_and_a_set_position_replaces_its_centre()
    {
        World world = FreeWorld(1f, 4);
        RigidBody ball = world.Add(new RigidBody(1f, 0.5f, new Vector3(1000, 0, 0)) { LinearVelocity = new Vector3(1e-4f, 0, 0) });
        for (int step = 0; step < 100; step++)
        {
            world.Step(0.1f); // 10 µm a step
        }

        _output.WriteLine($"after 10 s: {ball.Position.X:R} (exact 1000.001)");
        Assert.Equal(1000.001, ball.Position.X, 3.1e-5); // half a float32 ulp at 1 km
        ball.Position = new Vector3(2, 0, 0);
        world.Step(0.1f);
        Assert.Equal(2.00001f, ball.Position.X, 1e-6f);
    }


    private static World FreeWorld(float restitution, int substeps) =>
        new(Vector3.Zero, new SequentialImpulseSolver(restitution, friction: 0f) { RestitutionThreshold = 0f }) { Substeps = substeps };

    /// <summary>
    /// Equal masses, head-on, ε = 1: eq. 10 gives J = −m v₁₂·n, so the balls exchange velocities. A at x = −5 moving at
    /// +6 m/s, B at x = +5 moving at −2 m/s, radii 0.5: the gap of 9 m closes at 8 m/s, so they touch at t* = 1.125 s, A at
    /// 1.75 and B at 2.75; then A moves at −2 and B at +6 for 0.875 s, ending the second 1-second step at 0 and 8 exactly.
    /// </summary>
    [Theory]
    [InlineData(1)]
    [InlineData(4)]
    public void Equal_balls_head_on_exchange_velocities_at_the_exact_place_with_a_one_second_step(int substeps)
    {
        World world = FreeWorld(1f, substeps);
        RigidBody a = world.Add(new RigidBody(2f, 0.5f, new Vector3(-5, 0, 0)) { LinearVelocity = new Vector3(6, 0, 0) });
        RigidBody b = world.Add(new RigidBody(2f, 0.5f, new Vector3(5, 0, 0)) { LinearVelocity = new Vector3(-2, 0, 0) });
        world.Step(1f);
        Assert.Equal(1f, a.Position.X, 1e-5f); // free flight: −5 + 6
        Assert.Equal(3f, b.Position.X, 1e-5f); //              5 − 2
        world.Step(1f);
        _output.WriteLine($"after 2 s: A {a.Position} v {a.LinearVelocity}, B {b.Position} v {b.LinearVelocity}");
        Assert.Equal(-2f, a.LinearVelocity.X, 1e-5f);
        Assert.Equal(6f, b.LinearVelocity.X, 1e-5f);
        Assert.Equal(0f, a.Position.X, 1e-5f); // 1.75 − 2 × 0.875
        Assert.Equal(8f, b.Position.X, 1e-5f); // 2.75 + 6 × 0.875
        Assert.Equal(0f, a.Position.Y);
        Assert.Equal(0f, b.Position.Y);
    }

    /// <summary>
    /// A ball (r = 0.5) at (0, 2, 0) moving at (2, −5, 1) onto the ground, ε = 0.6, dt = 0.5: it touches at t* = 1.5/5 =
    /// 0.3 s at (0.6, 0.5, 0.3); eq. 10 with an immovable plane turns the normal velocity −5 into +0.6 × 5 = 3 and leaves
    /// the tangential one, so at t = 0.5 it is at (1, 0.5 + 3 × 0.2, 0.5) = (1, 1.1, 0.5), and at t = 1 at (2, 2.6, 1).
    /// </summary>
    [Fact]
    public void A_ball_hitting_the_ground_obliquely_with_a_half_second_step_bounces_from_the_exact_place()
    {
        World world = FreeWorld(0.6f, 1);
        world.AddPlane(StaticPlane.Ground());
        RigidBody ball = world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 2, 0)) { LinearVelocity = new Vector3(2, -5, 1) });
        world.Step(0.5f);
        _output.WriteLine($"t = 0.5: {ball.Position} v {ball.LinearVelocity}");
        AssertNear(new Vector3(2, 3, 1), ball.LinearVelocity, 1e-5f);
        AssertNear(new Vector3(1, 1.1f, 0.5f), ball.Position, 1e-5f);
        world.Step(0.5f);
        AssertNear(new Vector3(2, 2.6f, 1), ball.Position, 1e-5f);
    }

    /// <summary>
    /// Unequal masses, oblique, in 3-D, ε = 0.5, dt = 0.25 with 2 substeps. A (3 kg, r 0.3) at the origin moving at
    /// (4, 0, 0); B (1 kg, r 0.2) at rest at (2, 0.24, 0.18), 0.3 m off A's path. |d + w t| = 0.5 gives (4t − 2)² = 0.16,
    /// t* = 0.4 s, A at (1.6, 0, 0), n = (A − B)/0.5 = (−0.8, −0.48, −0.36), v₁₂·n = −3.2 (eq. 8). Eq. 10:
    /// J = 1.5 × 3.2 / (1/3 + 1) = 3.6, so (eq. 6) v_A' = (4, 0, 0) + 1.2 n = (3.04, −0.576, −0.432) and
    /// v_B' = −3.6 n = (2.88, 1.728, 1.296). At t = 1: A at (1.6, 0, 0) + 0.6 v_A', B at (2, 0.24, 0.18) + 0.6 v_B'.
    /// </summary>
    [Fact]
    public void Unequal_balls_meeting_obliquely_in_3d_leave_with_the_exact_velocities_and_positions()
    {
        World world = FreeWorld(0.5f, 2);
        RigidBody a = world.Add(new RigidBody(3f, 0.3f, Vector3.Zero) { LinearVelocity = new Vector3(4, 0, 0) });
        RigidBody b = world.Add(new RigidBody(1f, 0.2f, new Vector3(2, 0.24f, 0.18f)));
        for (int step = 0; step < 4; step++)
        {
            world.Step(0.25f);
        }

        _output.WriteLine($"t = 1: A {a.Position} v {a.LinearVelocity}, B {b.Position} v {b.LinearVelocity}");
        AssertNear(new Vector3(3.04f, -0.576f, -0.432f), a.LinearVelocity, 1e-5f);
        AssertNear(new Vector3(2.88f, 1.728f, 1.296f), b.LinearVelocity, 1e-5f);
        AssertNear(new Vector3(3.424f, -0.3456f, -0.2592f), a.Position, 1e-5f);
        AssertNear(new Vector3(3.728f, 1.2768f, 0.9576f), b.Position, 1e-5f);
    }

    /// <summary>
    /// 1 km/s into a wall 100 m away with dt = 1 s (a 1 km path in one step), ε = 1: the ball (r 0.5) touches at x = 99.5
    /// at t* = 0.0995 s and comes back at −1000 m/s for 0.9005 s, to x = 99.5 − 900.5 = −801. 1e-4 of the path is 0.1 m.
    /// </summary>
    [Fact]
    public void A_ball_at_a_kilometre_per_second_with_a_one_second_step_turns_at_the_wall()
    {
        World world = FreeWorld(1f, 1);
        world.AddPlane(new StaticPlane(-Vector3.UnitX, new Vector3(100, 0, 0)));
        RigidBody ball = world.Add(new RigidBody(1f, 0.5f, Vector3.Zero) { LinearVelocity = new Vector3(1000, 0, 0) });
        world.Step(1f);
        _output.WriteLine($"x = {ball.Position.X} (exact −801), v = {ball.LinearVelocity.X}");
        Assert.Equal(-1000f, ball.LinearVelocity.X, 1e-4f * 1000);
        Assert.Equal(-801f, ball.Position.X, 1e-4f * 1000);
    }

    private static void AssertNear(Vector3 expected, Vector3 actual, float tolerance) =>
        Assert.True(Vector3.Distance(expected, actual) <= tolerance, $"expected {expected}, got {actual} (|diff| {Vector3.Distance(expected, actual)} > {tolerance})");
}

