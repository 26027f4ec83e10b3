using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Numerics;
using System.Text;
using System.Text.RegularExpressions;
using FsCheck;
using FsCheck.Fluent;
using Microsoft.FSharp.Core;
using SimpleDynamics.Bodies;
using SimpleDynamics.Response;

namespace SimpleDynamics.Laws;

/// <summary>
/// Checks a collision responder against the laws of the collision-response tutorial on generated two-body
/// collisions, with FsCheck. From an xunit test:
/// <code>
/// [Fact]
/// public void My_responder_keeps_the_laws() => ResponderLaws.Check(e => new MyResponder(e));
/// </code>
/// A broken law throws <see cref="ResponderLawException"/> naming the law, the smallest failing collision (the
/// generators shrink every number towards a simple value) and the replay seed.
/// </summary>
/// <remarks>
/// Each collision is two solid spheres touching (or one sphere and a static one), in a
/// <c>new World(Vector3.Zero) { Responder = factory(ε), Substeps = 1 }</c>, advanced by one
/// <see cref="World.Step"/>; the bodies are measured before and after in double precision. The responder is
/// reached only through the public <see cref="World"/> API, so any <see cref="ICollisionResponder"/> can be
/// checked: the tutorial's pairwise responders, a whole-world solver, or yours. Restitution ε comes from the
/// factory; friction is set on the bodies (<see cref="RigidBody.Friction"/>, 0 for frictionless cases), which the
/// library's responders combine by <see cref="MaterialMixing"/>.
/// </remarks>
public static class ResponderLaws
{
    /// <summary>The environment variable that replays a run: FSCHECK_REPLAY="seed,gamma" as printed on failure.</summary>
    public const string ReplayVariable = "FSCHECK_REPLAY";

    /// <summary>The laws of the tutorial's impulse method (eq. 5–16): every law but <see cref="ResponderLaw.CommonVelocity"/>.</summary>
    public const ResponderLaw ImpulseLaws = ResponderLaw.LinearMomentum | ResponderLaw.AngularMomentum | ResponderLaw.ElasticEnergy
        | ResponderLaw.EnergyLoss | ResponderLaw.Bounce | ResponderLaw.SeparatingUntouched | ResponderLaw.StaticUnmoved
        | ResponderLaw.EnergyNeverRises;

    /// <summary>
    /// The laws of a perfectly inelastic responder (eq. 2, listing 1): momentum, the common velocity, energy never
    /// rises, separating contacts untouched, static bodies unmoved. (Eq. 2 does not act along the normal, so it
    /// keeps angular momentum only for head-on collisions; ε is ignored.)
    /// </summary>
    public const ResponderLaw PerfectlyInelasticLaws = ResponderLaw.LinearMomentum | ResponderLaw.CommonVelocity
        | ResponderLaw.EnergyNeverRises | ResponderLaw.SeparatingUntouched | ResponderLaw.StaticUnmoved;

    private const ulong DefaultGamma = 0x9E3779B97F4A7C15UL;

    private static readonly Dictionary<ResponderLaw, string> s_statements = new()
    {
        [ResponderLaw.LinearMomentum] = "linear momentum is conserved: m_A v_A + m_B v_B is the same after the collision (eq. 1, 6)",
        [ResponderLaw.AngularMomentum] = "angular momentum about any point O is conserved: sum of I w + (c - O) x m v (eq. 11, 15)",
        [ResponderLaw.ElasticEnergy] = "for eps = 1 without friction, kinetic energy is conserved (eq. 1)",
        [ResponderLaw.EnergyLoss] = "for eps < 1 without friction, kinetic energy falls by 1/2 (1 - eps^2) m_eff v_n^2, m_eff = 1 / (1/m_A + 1/m_B)",
        [ResponderLaw.Bounce] = "the relative normal velocity at the contact reverses and scales by eps: v_n' = -eps v_n (eq. 9)",
        [ResponderLaw.SeparatingUntouched] = "a separating contact (v_n > 0) gets no impulse: every velocity is unchanged",
        [ResponderLaw.StaticUnmoved] = "a static body (infinite mass) does not move",
        [ResponderLaw.EnergyNeverRises] = "kinetic energy never rises (eps <= 1, friction only takes energy away)",
        [ResponderLaw.CommonVelocity] = "perfectly inelastic: both bodies leave with (m_A v_A + m_B v_B) / (m_A + m_B) (eq. 2); against a static body, at rest",
    };

    /// <summary>Checks <see cref="ImpulseLaws"/> for the responders <paramref name="factory"/> makes for each ε.</summary>
    /// <exception cref="ResponderLawException">A law is broken; the message holds the smallest failing collision.</exception>
    public static void Check(Func<float, ICollisionResponder> factory) => Check(factory, new LawOptions());

    /// <summary>Checks <see cref="LawOptions.Laws"/> for the responders <paramref name="factory"/> makes for each ε.</summary>
    /// <exception cref="ResponderLawException">A law is broken; the message holds the smallest failing collision.</exception>
    /// <exception cref="ArgumentException">The options are out of range.</exception>
    public static void Check(Func<float, ICollisionResponder> factory, LawOptions options)
    {
        if (factory is null)
        {
            throw new ArgumentNullException(nameof(factory));
        }

        if (options is null)
        {
            throw new ArgumentNullException(nameof(options));
        }

        options.Validate();
        Rnd rnd = ReplayFromEnvironment() ?? new Rnd(options.Seed, DefaultGamma);
        string replay = rnd.Seed.ToString(CultureInfo.InvariantCulture) + "," + rnd.Gamma.ToString(CultureInfo.InvariantCulture);
        var failures = new List<string>();
        ResponderLaw failed = ResponderLaw.None;
        Exception? firstInner = null;
        foreach (ResponderLaw law in Enum.GetValues(typeof(ResponderLaw)).Cast<ResponderLaw>())
        {
            if (law == ResponderLaw.None || (options.Laws & law) == 0)
            {
                continue;
            }

            string? failure = CheckOne(law, factory, options, rnd, out Exception? inner);
            if (failure is not null)
            {
                failures.Add(failure);
                failed |= law;
                firstInner ??= inner;
            }
        }

        if (failures.Count > 0)
        {
            var message = new StringBuilder();
            message.Append("The responder breaks ").Append(failures.Count == 1 ? "a law" : failures.Count.ToString(CultureInfo.InvariantCulture) + " laws")
                .Append(" of the collision-response tutorial.").AppendLine();
            foreach (string failure in failures)
            {
                message.AppendLine().Append(failure).AppendLine();
            }

            message.AppendLine().Append("Replay seed: ").Append(replay).Append(". To replay: ").Append(ReplayVariable).Append('=').Append(replay)
                .Append(" dotnet test --filter <this test>");
            throw new ResponderLawException(failed, replay, message.ToString(), firstInner);
        }
    }

    /// <summary>The statement of <paramref name="law"/>, as failure messages print it.</summary>
    public static string Statement(ResponderLaw law) =>
        s_statements.TryGetValue(law, out string? statement) ? statement : throw new ArgumentOutOfRangeException(nameof(law), law, "Not a single law.");

    private static string? CheckOne(ResponderLaw law, Func<float, ICollisionResponder> factory, LawOptions options, Rnd rnd, out Exception? inner)
    {
        inner = null;
        CollisionCase? lastCase = null;
        string? lastMessage = null;
        int failuresSeen = 0;
        Arbitrary<CollisionCase> cases = Arb.From(CollisionCase.Generator(law, options), c => c.Shrink(law, options));
        Action<CollisionCase> property = c =>
        {
            string? broken = Evaluate(law, c, factory, options);
            if (broken is not null)
            {
                lastCase = c; // FsCheck keeps the first failing shrink, so the last failure is the smallest case
                lastMessage = broken;
                failuresSeen++;
                throw new LawBrokenException(broken);
            }
        };
        Config config = Config.QuickThrowOnFailure
            .WithMaxTest(options.MaxTest)
            .WithQuietOnSuccess(true)
            .WithName(law.ToString())
            .WithReplay(FSharpOption<Replay>.Some(new Replay(rnd, FSharpOption<int>.None)));
        try
        {
            FsCheck.Check.One(config, Prop.ForAll(cases, property));
            return null;
        }
        catch (Exception e) when (lastCase is not null)
        {
            inner = e;
            Match counts = Regex.Match(e.Message, @"after \d+ tests? \(\d+ shrinks?\)");
            return $"Law {law}: {Statement(law)}." + Environment.NewLine
                + $"Smallest failing collision (FsCheck: falsifiable {(counts.Success ? counts.Value : $"after {failuresSeen - 1} shrinks")}):" + Environment.NewLine
                + lastCase.Describe(law, options.TimeStep) + Environment.NewLine
                + "Measured: " + lastMessage;
        }
    }

    /// <summary>Builds the case's world, steps it once and measures the law; null if it holds, else what broke.</summary>
    private static string? Evaluate(ResponderLaw law, CollisionCase c, Func<float, ICollisionResponder> factory, LawOptions options)
    {
        ICollisionResponder responder;
        try
        {
            responder = factory((float)c.Restitution);
        }
        catch (Exception e)
        {
            return $"the factory threw {e.GetType().Name} for eps = {Text.Number(c.Restitution)}: {e.Message}";
        }

        if (responder is null)
        {
            return $"the factory returned null for eps = {Text.Number(c.Restitution)}";
        }

        var world = new World(Vector3.Zero) { Responder = responder, Substeps = 1 };
        var a = new RigidBody((float)c.MassA, (float)c.RadiusA, c.CentreA.ToVector3())
        {
            LinearVelocity = c.ActualVelocityA.ToVector3(),
            AngularVelocity = c.SpinA.ToVector3(),
            Friction = (float)c.Friction,
        };
        RigidBody b = c.StaticB
            ? RigidBody.CreateStatic((float)c.RadiusB, c.CentreB.ToVector3())
            : new RigidBody((float)c.MassB, (float)c.RadiusB, c.CentreB.ToVector3())
            {
                LinearVelocity = c.ActualVelocityB.ToVector3(),
                AngularVelocity = c.ActualSpinB.ToVector3(),
            };
        b.Friction = (float)c.Friction;
        world.Add(a);
        world.Add(b);

        var before = new Pair(a, b);
        Vector3 staticPosition = b.Position;
        Quaternion staticOrientation = b.Orientation;
        try
        {
            world.Step(options.TimeStep);
        }
        catch (Exception e)
        {
            return $"World.Step threw {e.GetType().Name}: {e.Message}";
        }

        var after = new Pair(a, b);
        double tol = options.Tolerance;
        Vec n = c.Normal, point = c.ContactPoint;
        // The impulse acts at one instant: everything is measured with the centres before the step.
        double speedScale = before.SpeedScale(point, before) + after.SpeedScale(point, before);
        switch (law)
        {
            case ResponderLaw.LinearMomentum:
                return Near("total linear momentum m_A v_A + m_B v_B (kg m/s)", before.Momentum, after.Momentum, tol * (before.MomentumScale + after.MomentumScale));
            case ResponderLaw.AngularMomentum:
                Vec l0 = before.AngularMomentum(c.Pivot, before), l1 = after.AngularMomentum(c.Pivot, before);
                return Near("total angular momentum about O (kg m^2/s)", l0, l1, tol * (before.AngularScale(c.Pivot, before) + after.AngularScale(c.Pivot, before)));
            case ResponderLaw.ElasticEnergy:
                return Near("kinetic energy (J)", before.KineticEnergy, after.KineticEnergy, tol * before.KineticEnergy);
            case ResponderLaw.EnergyLoss:
            {
                double massEffective = 1 / (1 / c.MassA + (c.StaticB ? 0 : 1 / c.MassB));
                double loss = 0.5 * (1 - c.Restitution * c.Restitution) * massEffective * c.Speed * c.Speed;
                return Near(
                    $"kinetic energy (J) after a loss of 1/2 (1 - eps^2) m_eff v_n^2 = {Text.Number(loss)} J (m_eff = {Text.Number(massEffective)} kg) from {Text.Number(before.KineticEnergy)} J",
                    before.KineticEnergy - loss, after.KineticEnergy, tol * before.KineticEnergy);
            }

            case ResponderLaw.Bounce:
                return Near("relative normal velocity after, v_n' = -eps v_n (m/s)", c.Restitution * c.Speed, after.NormalVelocity(point, n, before), tol * speedScale,
                    $" (v_n before: {Text.Number(before.NormalVelocity(point, n, before))} m/s)");
            case ResponderLaw.SeparatingUntouched:
                return Near("A's velocity (m/s)", before.VelocityA, after.VelocityA, tol * speedScale)
                    ?? Near("B's velocity (m/s)", before.VelocityB, after.VelocityB, tol * speedScale)
                    ?? Near("A's angular velocity (rad/s)", before.SpinA, after.SpinA, tol * speedScale / c.RadiusA)
                    ?? Near("B's angular velocity (rad/s)", before.SpinB, after.SpinB, tol * speedScale / c.RadiusB);
            case ResponderLaw.StaticUnmoved:
                if (b.Position != staticPosition || b.Orientation != staticOrientation || b.LinearVelocity != Vector3.Zero || b.AngularVelocity != Vector3.Zero)
                {
                    return $"the static body B moved: centre {Vec.From(staticPosition)} -> {Vec.From(b.Position)}, v = {Vec.From(b.LinearVelocity)} m/s, w = {Vec.From(b.AngularVelocity)} rad/s";
                }

                return null;
            case ResponderLaw.EnergyNeverRises:
                return after.KineticEnergy <= before.KineticEnergy * (1 + tol)
                    ? null
                    : $"kinetic energy rose from {Text.Number(before.KineticEnergy)} J to {Text.Number(after.KineticEnergy)} J";
            case ResponderLaw.CommonVelocity:
            {
                Vec common = c.StaticB ? Vec.Zero : (c.MassA * before.VelocityA + c.MassB * before.VelocityB) / (c.MassA + c.MassB);
                return Near("A's velocity, the common velocity (m/s)", common, after.VelocityA, tol * speedScale)
                    ?? (c.StaticB ? null : Near("B's velocity, the common velocity (m/s)", common, after.VelocityB, tol * speedScale));
            }

            default:
                throw new ArgumentOutOfRangeException(nameof(law), law, "Not a single law.");
        }
    }

    private static string? Near(string what, double expected, double actual, double tolerance, string extra = "")
    {
        double diff = Math.Abs(actual - expected);
        return diff <= tolerance
            ? null
            : $"{what}: expected {Text.Number(expected)}, got {Text.Number(actual)} (difference {Text.Number(diff)} > tolerance {Text.Number(tolerance)}){extra}";
    }

    private static string? Near(string what, Vec expected, Vec actual, double tolerance)
    {
        double diff = (actual - expected).Length;
        return diff <= tolerance
            ? null
            : $"{what}: expected {expected}, got {actual} (difference {Text.Number(diff)} > tolerance {Text.Number(tolerance)})";
    }

    private static Rnd? ReplayFromEnvironment()
    {
        string? text = Environment.GetEnvironmentVariable(ReplayVariable);
        if (text is null || text.Trim().Length == 0)
        {
            return null;
        }

        string[] parts = text.Trim().Trim('(', ')').Split(',');
        ulong seed = ulong.Parse(parts[0].Trim(), CultureInfo.InvariantCulture);
        ulong gamma = parts.Length > 1 ? ulong.Parse(parts[1].Trim(), CultureInfo.InvariantCulture) : DefaultGamma;
        return new Rnd(seed, gamma);
    }

    /// <summary>Both bodies' state in double precision.</summary>
    private sealed class Pair
    {
        private readonly double _massA, _massB; // 0 for a static body
        private readonly Vec _centreA, _centreB;
        private readonly double[,] _inertiaA, _inertiaB;

        public Pair(RigidBody a, RigidBody b)
        {
            _massA = a.IsDynamic ? a.Mass : 0;
            _massB = b.IsDynamic ? b.Mass : 0;
            _centreA = Vec.From(a.Position);
            _centreB = Vec.From(b.Position);
            _inertiaA = WorldInertia(a);
            _inertiaB = WorldInertia(b);
            VelocityA = Vec.From(a.LinearVelocity);
            VelocityB = Vec.From(b.LinearVelocity);
            SpinA = Vec.From(a.AngularVelocity);
            SpinB = Vec.From(b.AngularVelocity);
        }

        public Vec VelocityA { get; }

        public Vec VelocityB { get; }

        public Vec SpinA { get; }

        public Vec SpinB { get; }

        public Vec Momentum => _massA * VelocityA + _massB * VelocityB;

        public double MomentumScale => _massA * VelocityA.Length + _massB * VelocityB.Length;

        public double KineticEnergy =>
            0.5 * _massA * Vec.Dot(VelocityA, VelocityA) + 0.5 * Vec.Dot(SpinA, Times(_inertiaA, SpinA))
            + 0.5 * _massB * Vec.Dot(VelocityB, VelocityB) + 0.5 * Vec.Dot(SpinB, Times(_inertiaB, SpinB));

        /// <summary>Σ I_w ω + (c − O) × m v, with the centres and inertia of <paramref name="at"/>.</summary>
        public Vec AngularMomentum(Vec pivot, Pair at) =>
            Times(at._inertiaA, SpinA) + Vec.Cross(at._centreA - pivot, _massA * VelocityA)
            + Times(at._inertiaB, SpinB) + Vec.Cross(at._centreB - pivot, _massB * VelocityB);

        public double AngularScale(Vec pivot, Pair at) =>
            Times(at._inertiaA, SpinA).Length + (at._centreA - pivot).Length * _massA * VelocityA.Length
            + Times(at._inertiaB, SpinB).Length + (at._centreB - pivot).Length * _massB * VelocityB.Length;

        /// <summary>(v_pA − v_pB)·n at <paramref name="point"/>, v_p = v + ω × (p − c) with the centres of <paramref name="at"/> (eq. 13–14).</summary>
        public double NormalVelocity(Vec point, Vec normal, Pair at) =>
            Vec.Dot(VelocityA + Vec.Cross(SpinA, point - at._centreA) - VelocityB - Vec.Cross(SpinB, point - at._centreB), normal);

        public double SpeedScale(Vec point, Pair at) =>
            VelocityA.Length + VelocityB.Length + SpinA.Length * (point - at._centreA).Length + SpinB.Length * (point - at._centreB).Length;

        private static double[,] WorldInertia(RigidBody body)
        {
            if (!body.IsDynamic)
            {
                return new double[3, 3];
            }

            Mathematics.Matrix3 i = body.Inertia.RotatedBy(body.Orientation);
            return new double[,] { { i.M11, i.M12, i.M13 }, { i.M21, i.M22, i.M23 }, { i.M31, i.M32, i.M33 } };
        }

        private static Vec Times(double[,] m, Vec v) => new(
            m[0, 0] * v.X + m[0, 1] * v.Y + m[0, 2] * v.Z,
            m[1, 0] * v.X + m[1, 1] * v.Y + m[1, 2] * v.Z,
            m[2, 0] * v.X + m[2, 1] * v.Y + m[2, 2] * v.Z);
    }

    private sealed class LawBrokenException : Exception
    {
        public LawBrokenException(string message)
            : base(message)
        {
        }
    }
}
