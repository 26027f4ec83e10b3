using System;
using System.Collections.Generic;
using System.Linq;
using FsCheck;
using FsCheck.Fluent;

namespace SimpleDynamics.Laws;

/// <summary>
/// One generated two-body collision: solid spheres A and B touching along the unit normal n (from B to A, the
/// library's convention), no gravity. Every number lies on a grid of 0.01 and shrinks towards a simple value
/// (ε 0.5, μ 0, B static, masses 1 kg, radii 0.5 m, n = (1, 0, 0), positions, spins and extra velocities 0, approach speed 1 m/s), so a
/// failure is reported as a small, readable collision.
/// </summary>
/// <remarks>
/// The velocities are built so that the relative normal velocity (v_A − v_B)·n is exactly −<see cref="Speed"/>
/// (approaching) or +<see cref="Speed"/> (separating): the generated <see cref="VelocityA"/> loses its normal
/// part relative to <see cref="VelocityB"/>, which then is set. Spin does not change the normal velocity of two
/// spheres (ω × r is perpendicular to n when r lies along n).
/// </remarks>
internal sealed class CollisionCase
{
    private const double Steps = 100; // values are multiples of 1 / Steps

    public double Restitution { get; private set; }

    public double Friction { get; private set; }

    public double MassA { get; private set; }

    public double RadiusA { get; private set; }

    /// <summary>B's mass, or 0 when B is static.</summary>
    public double MassB { get; private set; }

    public double RadiusB { get; private set; }

    /// <summary>The direction of n before normalising (shrinks towards (1, 0, 0)).</summary>
    public Vec Direction { get; private set; }

    public Vec CentreB { get; private set; }

    /// <summary>|v_n| in m/s: the approach speed, or the separation speed of a separating case.</summary>
    public double Speed { get; private set; }

    public bool Separating { get; private set; }

    public Vec VelocityA { get; private set; }

    public Vec VelocityB { get; private set; }

    public Vec SpinA { get; private set; }

    public Vec SpinB { get; private set; }

    /// <summary>The point O that angular momentum is measured about.</summary>
    public Vec Pivot { get; private set; }

    public bool StaticB => MassB == 0;

    public Vec Normal => Direction / Direction.Length;

    /// <summary>
    /// A's centre: at distance r_A + r_B from B's along n, less an overlap of 1e-4 of the smaller radius so that
    /// float rounding of the centres cannot part them (the bodies touch; a pairwise responder skips contacts with
    /// negative penetration).
    /// </summary>
    public Vec CentreA => CentreB + (RadiusA + RadiusB - 1e-4 * Math.Min(RadiusA, RadiusB)) * Normal;

    /// <summary>The contact point on the line of centres, on B's surface.</summary>
    public Vec ContactPoint => CentreB + RadiusB * Normal;

    /// <summary>A's velocity as used: <see cref="VelocityA"/> with the normal part that gives v_n = ∓<see cref="Speed"/>.</summary>
    public Vec ActualVelocityA
    {
        get
        {
            Vec n = Normal;
            Vec vB = ActualVelocityB;
            double vn = Vec.Dot(VelocityA - vB, n);
            double target = Separating ? Speed : -Speed;
            return VelocityA + (target - vn) * n;
        }
    }

    public Vec ActualVelocityB => StaticB ? Vec.Zero : VelocityB;

    public Vec ActualSpinB => StaticB ? Vec.Zero : SpinB;

    /// <summary>The generator of cases for <paramref name="law"/>.</summary>
    public static Gen<CollisionCase> Generator(ResponderLaw law, LawOptions options)
    {
        Shape shape = Shape.For(law, options);
        Gen<double> restitution = shape.ElasticOnly
            ? Gen.Constant(1.0)
            : shape.InelasticOnly
                ? Gen.OneOf(Gen.Constant(0.0), Gen.Constant(0.5), Grid(0, 0.99))
                : Gen.OneOf(Gen.Constant(0.0), Gen.Constant(0.5), Gen.Constant(1.0), Grid(0, 1));
        Gen<double> friction = shape.Frictionless ? Gen.Constant(0.0) : Gen.OneOf(Gen.Constant(0.0), Grid(0.01, 1));
        Gen<double> massB = shape.StaticB == true
            ? Gen.Constant(0.0)
            : shape.StaticB == false ? Grid(0.1, 10) : Gen.Frequency((3, Grid(0.1, 10)), (1, Gen.Constant(0.0)));
        Gen<Vec> direction = Vector(-1, 1).Where(d => d.Length >= 0.1);

        return
            from e in restitution
            from mu in friction
            from mA in Grid(0.1, 10)
            from rA in Grid(0.1, 1)
            from mB in massB
            from rB in Grid(0.1, 1)
            from d in direction
            from cB in Vector(-5, 5)
            from speed in Grid(options.MinApproachSpeed, options.MaxApproachSpeed)
            from vA in Vector(-5, 5)
            from vB in Vector(-5, 5)
            from wA in Vector(-5, 5)
            from wB in Vector(-5, 5)
            from pivot in Vector(-5, 5)
            select new CollisionCase
            {
                Restitution = e, Friction = mu, MassA = mA, RadiusA = rA, MassB = mB, RadiusB = rB, Direction = d,
                CentreB = cB, Speed = speed, Separating = shape.Separating, VelocityA = vA, VelocityB = vB,
                SpinA = wA, SpinB = wB, Pivot = pivot,
            };
    }

    /// <summary>Simpler cases of the same kind, simplest first; each is closer to the simple values.</summary>
    public IEnumerable<CollisionCase> Shrink(ResponderLaw law, LawOptions options)
    {
        Shape shape = Shape.For(law, options);
        foreach (double e in Towards(Restitution, 0.5, 0, shape.InelasticOnly ? 0.99 : 1).Where(_ => !shape.ElasticOnly))
        {
            yield return With(c => c.Restitution = e);
        }

        foreach (double mu in Towards(Friction, 0, 0, 1))
        {
            yield return With(c => c.Friction = mu);
        }

        if (shape.StaticB is null && !StaticB)
        {
            yield return With(c => c.MassB = 0); // a static B is simpler: one body moves
        }

        foreach (double x in Towards(MassA, 1, 0.1, 10))
        {
            yield return With(c => c.MassA = x);
        }

        foreach (double x in StaticB ? Enumerable.Empty<double>() : Towards(MassB, 1, 0.1, 10))
        {
            yield return With(c => c.MassB = x);
        }

        foreach (double x in Towards(RadiusA, 0.5, 0.1, 1))
        {
            yield return With(c => c.RadiusA = x);
        }

        foreach (double x in Towards(RadiusB, 0.5, 0.1, 1))
        {
            yield return With(c => c.RadiusB = x);
        }

        foreach (Vec d in Towards(Direction, new Vec(1, 0, 0), -1, 1).Where(d => d.Length >= 0.1))
        {
            yield return With(c => c.Direction = d);
        }

        foreach (double x in Towards(Speed, Math.Max(1, options.MinApproachSpeed), options.MinApproachSpeed, options.MaxApproachSpeed))
        {
            yield return With(c => c.Speed = x);
        }

        foreach (Vec v in Towards(CentreB, Vec.Zero, -5, 5))
        {
            yield return With(c => c.CentreB = v);
        }

        foreach (Vec v in Towards(VelocityA, Vec.Zero, -5, 5))
        {
            yield return With(c => c.VelocityA = v);
        }

        foreach (Vec v in StaticB ? Enumerable.Empty<Vec>() : Towards(VelocityB, Vec.Zero, -5, 5))
        {
            yield return With(c => c.VelocityB = v);
        }

        foreach (Vec v in Towards(SpinA, Vec.Zero, -5, 5))
        {
            yield return With(c => c.SpinA = v);
        }

        foreach (Vec v in StaticB ? Enumerable.Empty<Vec>() : Towards(SpinB, Vec.Zero, -5, 5))
        {
            yield return With(c => c.SpinB = v);
        }

        foreach (Vec v in (law & ResponderLaw.AngularMomentum) != 0 ? Towards(Pivot, Vec.Zero, -5, 5) : Enumerable.Empty<Vec>())
        {
            yield return With(c => c.Pivot = v);
        }
    }

    /// <summary>The case as a person reads it, with the velocities as the bodies get them.</summary>
    public string Describe(ResponderLaw law, float dt)
    {
        var lines = new List<string>
        {
            $"  eps = {Text.Number(Restitution)}, mu = {Text.Number(Friction)} (set on both bodies), no gravity, one World.Step({Text.Number(dt)}) with Substeps = 1",
            $"  normal n (from B to A) = {Normal}" + (Direction.ToString() == Normal.ToString() ? string.Empty : $" (direction {Direction})"),
            $"  A: dynamic solid sphere, m = {Text.Number(MassA)} kg, r = {Text.Number(RadiusA)} m, centre {CentreA}, v = {ActualVelocityA} m/s, w = {SpinA} rad/s",
            StaticB
                ? $"  B: static, r = {Text.Number(RadiusB)} m, centre {CentreB}"
                : $"  B: dynamic solid sphere, m = {Text.Number(MassB)} kg, r = {Text.Number(RadiusB)} m, centre {CentreB}, v = {ActualVelocityB} m/s, w = {ActualSpinB} rad/s",
            Separating
                ? $"  separating: v_n = (v_A - v_B).n = +{Text.Number(Speed)} m/s"
                : $"  approaching: v_n = (v_A - v_B).n = -{Text.Number(Speed)} m/s",
        };
        if ((law & ResponderLaw.AngularMomentum) != 0)
        {
            lines.Add($"  angular momentum measured about O = {Pivot}");
        }

        return string.Join(Environment.NewLine, lines);
    }

    public override string ToString() => Describe(ResponderLaw.None, 1f / 60f);

    private CollisionCase With(Action<CollisionCase> change)
    {
        var copy = (CollisionCase)MemberwiseClone();
        change(copy);
        return copy;
    }

    private static Gen<double> Grid(double lo, double hi) =>
        Gen.Choose((int)Math.Ceiling(lo * Steps - 1e-9), (int)Math.Floor(hi * Steps + 1e-9)).Select(i => i / Steps);

    private static Gen<Vec> Vector(double lo, double hi) =>
        from x in Grid(lo, hi)
        from y in Grid(lo, hi)
        from z in Grid(lo, hi)
        select new Vec(x, y, z);

    /// <summary>
    /// Simpler values than <paramref name="x"/> in [lo, hi]: the target, then x rounded to a whole number and to
    /// one decimal, then halfway to the target. Each candidate is closer to the target, or as close with fewer
    /// decimals, so shrinking ends.
    /// </summary>
    private static IEnumerable<double> Towards(double x, double target, double lo, double hi)
    {
        var seen = new HashSet<double> { x };
        foreach (double candidate in new[] { target, Math.Round(x), Math.Round(x, 1), Math.Round(target + (x - target) / 2, 2) })
        {
            bool closer = Math.Abs(candidate - target) < Math.Abs(x - target) - 1e-12;
            bool asCloseButShorter = Math.Abs(candidate - target) <= Math.Abs(x - target) + 1e-12 && Decimals(candidate) < Decimals(x);
            if (candidate >= lo && candidate <= hi && (closer || asCloseButShorter) && seen.Add(candidate))
            {
                yield return candidate;
            }
        }
    }

    private static IEnumerable<Vec> Towards(Vec v, Vec target, double lo, double hi)
    {
        if (v.X != target.X || v.Y != target.Y || v.Z != target.Z)
        {
            yield return target;
        }

        foreach (double x in Towards(v.X, target.X, lo, hi))
        {
            yield return new Vec(x, v.Y, v.Z);
        }

        foreach (double y in Towards(v.Y, target.Y, lo, hi))
        {
            yield return new Vec(v.X, y, v.Z);
        }

        foreach (double z in Towards(v.Z, target.Z, lo, hi))
        {
            yield return new Vec(v.X, v.Y, z);
        }
    }

    private static int Decimals(double x)
    {
        for (int decimals = 0; decimals < 2; decimals++)
        {
            if (Math.Abs(Math.Round(x, decimals) - x) < 1e-9)
            {
                return decimals;
            }
        }

        return 2;
    }

    /// <summary>Which collisions a law is checked on.</summary>
    private sealed class Shape
    {
        public bool ElasticOnly { get; set; }

        public bool InelasticOnly { get; set; }

        public bool Frictionless { get; set; }

        /// <summary>true: B static; false: both dynamic; null: either.</summary>
        public bool? StaticB { get; set; }

        public bool Separating { get; set; }

        public static Shape For(ResponderLaw law, LawOptions options) => law switch
        {
            ResponderLaw.LinearMomentum or ResponderLaw.AngularMomentum => new Shape { StaticB = false, Frictionless = !options.WithFriction },
            ResponderLaw.ElasticEnergy => new Shape { ElasticOnly = true, Frictionless = true },
            ResponderLaw.EnergyLoss => new Shape { InelasticOnly = true, Frictionless = true },
            ResponderLaw.SeparatingUntouched => new Shape { Separating = true, Frictionless = !options.WithFriction },
            ResponderLaw.StaticUnmoved => new Shape { StaticB = true, Frictionless = !options.WithFriction },
            ResponderLaw.CommonVelocity => new Shape { Frictionless = !options.WithFriction },
            _ => new Shape { Frictionless = !options.WithFriction }, // Bounce, EnergyNeverRises
        };
    }
}
