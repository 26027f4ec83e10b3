using System;
using System.Numerics;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// Laws 1–6 for <see cref="ImpulseCollisionResponder"/> (eq. 5–16 plus Coulomb friction), over generated contacts.
/// </summary>
/// <remarks>
/// <para><b>Tolerances.</b> The library computes in float (ε_f ≈ 6e-8); the tests measure in double. Every
/// comparison is relative to the magnitude of the terms that are summed, never to the (possibly tiny)
/// difference: a float result carries a rounding error of a few ε_f times the largest term that went into it.
/// Impulses go through the world-frame inverse inertia (condition number ≤ 25 here, see
/// <see cref="Generators.InertiaTensor"/>) and a handful of products, so 1e-5 relative (≈ 150 ε_f) is a
/// generous bound for linear quantities; angular quantities pass through one more tensor product and the
/// float inverse, and get 1e-4 relative.</para>
/// </remarks>
public class ImpulseResponderLaws
{
    private const double LinearTolerance = 1e-5;
    private const double AngularTolerance = 1e-4;

    private static (RigidBody A, RigidBody B, Contact Contact) Respond(ContactCase c)
    {
        (RigidBody a, RigidBody b) = c.BuildBodies();
        Contact contact = c.BuildContact(a, b);
        new ImpulseCollisionResponder(c.Restitution, c.Friction).ResolveVelocity(ref contact);
        return (a, b, contact);
    }

    [Theory]
    [InlineData(Generators.RandomRestitution, false)]
    [InlineData(Generators.RandomRestitution, true)]
    [InlineData(0f, false)]
    [InlineData(0.25f, true)]
    [InlineData(0.5f, false)]
    [InlineData(0.75f, true)]
    [InlineData(1f, false)]
    public void Linear_momentum_is_conserved(float restitution, bool friction) =>
        PropertyCheck.Run(Generators.Contact(restitution, friction), c =>
        {
            (RigidBody a, RigidBody b) = c.BuildBodies();
            D3 before = Measure.Momentum(a, b);
            double scale = Measure.MomentumScale(a, b);
            Contact contact = c.BuildContact(a, b);
            new ImpulseCollisionResponder(c.Restitution, c.Friction).ResolveVelocity(ref contact);
            scale += Measure.MomentumScale(a, b);
            Law.Near(before, Measure.Momentum(a, b), LinearTolerance * scale, "total linear momentum");
        }, seed: 101);

    [Theory]
    [InlineData(Generators.RandomRestitution, false)]
    [InlineData(Generators.RandomRestitution, true)]
    [InlineData(0f, true)]
    [InlineData(1f, false)]
    public void Angular_momentum_about_any_fixed_point_is_conserved(float restitution, bool friction) =>
        PropertyCheck.Run(
            from c in Generators.Contact(restitution, friction)
            from o in Generators.Vector(10)
            select (c, o),
            x =>
            {
                (ContactCase c, Vector3 origin) = x;
                D3 o = D3.From(origin);
                (RigidBody a, RigidBody b) = c.BuildBodies();
                D3 before = Measure.AngularMomentum(o, a, b);
                double scale = Measure.AngularMomentumScale(o, a, b);
                Contact contact = c.BuildContact(a, b);
                new ImpulseCollisionResponder(c.Restitution, c.Friction).ResolveVelocity(ref contact);
                scale += Measure.AngularMomentumScale(o, a, b);
                Law.Near(before, Measure.AngularMomentum(o, a, b), AngularTolerance * scale, $"angular momentum about {o}");
            }, seed: 102);

    [Theory]
    [InlineData(InfiniteMass.None)]
    [InlineData(InfiniteMass.One)]
    public void Elastic_frictionless_impulse_conserves_kinetic_energy(InfiniteMass infinite) =>
        PropertyCheck.Run(Generators.Contact(1f, friction: false, infinite), c =>
        {
            (RigidBody a, RigidBody b) = c.BuildBodies();
            double before = Measure.KineticEnergy(c.RestFrame, a, b);
            Contact contact = c.BuildContact(a, b);
            new ImpulseCollisionResponder(1f, 0f).ResolveVelocity(ref contact);
            double after = Measure.KineticEnergy(c.RestFrame, a, b);
            Law.Near(before, after, LinearTolerance * (before + after), "kinetic energy with ε = 1, μ = 0");
        }, seed: 103);

    [Theory]
    [InlineData(Generators.RandomRestitution, false, InfiniteMass.Any)]
    [InlineData(Generators.RandomRestitution, true, InfiniteMass.Any)]
    [InlineData(0f, false, InfiniteMass.Any)]
    [InlineData(0.25f, true, InfiniteMass.None)]
    [InlineData(0.5f, false, InfiniteMass.One)]
    [InlineData(0.75f, true, InfiniteMass.Any)]
    [InlineData(1f, true, InfiniteMass.Any)]
    public void Kinetic_energy_never_increases(float restitution, bool friction, InfiniteMass infinite) =>
        PropertyCheck.Run(Generators.Contact(restitution, friction, infinite), c =>
        {
            (RigidBody a, RigidBody b) = c.BuildBodies();
            double before = Measure.KineticEnergy(c.RestFrame, a, b);
            Contact contact = c.BuildContact(a, b);
            new ImpulseCollisionResponder(c.Restitution, c.Friction).ResolveVelocity(ref contact);
            double after = Measure.KineticEnergy(c.RestFrame, a, b);
            Law.Holds(after <= before * (1 + LinearTolerance), $"kinetic energy rose from {before:R} to {after:R}");
        }, seed: 104);

    [Theory]
    [InlineData(Generators.RandomRestitution, InfiniteMass.Any)]
    [InlineData(0f, InfiniteMass.Any)]
    [InlineData(0.25f, InfiniteMass.None)]
    [InlineData(0.5f, InfiniteMass.One)]
    [InlineData(0.75f, InfiniteMass.Any)]
    public void Frictionless_energy_loss_is_half_one_minus_eps_squared_m_eff_vn_squared(float restitution, InfiniteMass infinite) =>
        PropertyCheck.Run(Generators.Contact(restitution, friction: false, infinite), c =>
        {
            (RigidBody a, RigidBody b) = c.BuildBodies();
            double before = Measure.KineticEnergy(c.RestFrame, a, b);
            double vn = c.NormalVelocity();
            double mEff = 1 / Measure.Eq16Denominator(a, b, D3.From(c.Point), D3.From(c.Normal));
            double expectedLoss = 0.5 * (1 - (double)c.Restitution * c.Restitution) * mEff * vn * vn;
            Contact contact = c.BuildContact(a, b);
            new ImpulseCollisionResponder(c.Restitution, 0f).ResolveVelocity(ref contact);
            double after = Measure.KineticEnergy(c.RestFrame, a, b);
            // The loss is a difference of two energies; its error is relative to them, not to the loss.
            Law.Near(expectedLoss, before - after, LinearTolerance * (before + after), "kinetic energy lost");
        }, seed: 105);

    [Theory]
    [InlineData(Generators.RandomRestitution, InfiniteMass.Any)]
    [InlineData(0f, InfiniteMass.Any)]
    [InlineData(0.25f, InfiniteMass.Any)]
    [InlineData(0.5f, InfiniteMass.Any)]
    [InlineData(0.75f, InfiniteMass.Any)]
    [InlineData(1f, InfiniteMass.Any)]
    [InlineData(Generators.RandomRestitution, InfiniteMass.One)]
    public void Frictionless_relative_normal_velocity_becomes_minus_eps_times_before(float restitution, InfiniteMass infinite) =>
        PropertyCheck.Run(Generators.Contact(restitution, friction: false, infinite), c =>
        {
            (RigidBody a, RigidBody b, Contact contact) = Respond(c);
            D3 p = D3.From(c.Point), n = D3.From(c.Normal);
            double after = D3.Dot(Measure.VelocityAt(a, p) - Measure.VelocityAt(b, p), n);
            double scale = Measure.SpeedScaleAt(a, p) + Measure.SpeedScaleAt(b, p) + Math.Abs(c.NormalVelocity());
            Law.Near(-c.Restitution * c.NormalVelocity(), after, AngularTolerance * scale, "relative normal velocity after");
            Law.Holds(contact.NormalImpulse > 0, $"a positive normal impulse, got {contact.NormalImpulse}");
        }, seed: 106);

    [Theory]
    [InlineData(false, InfiniteMass.Any)]
    [InlineData(true, InfiniteMass.Any)]
    public void Separating_contact_is_left_untouched(bool friction, InfiniteMass infinite) =>
        PropertyCheck.Run(Generators.Contact(Generators.RandomRestitution, friction, infinite, approaching: false), c =>
        {
            (RigidBody a, RigidBody b, Contact contact) = Respond(c);
            AssertUnchanged(c.A, a);
            AssertUnchanged(c.B, b);
            Law.Holds(contact.NormalImpulse == 0 && contact.TangentImpulse == 0, "no impulse recorded");
        }, seed: 107);

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void Infinite_mass_body_never_changes(bool friction) =>
        PropertyCheck.Run(Generators.Contact(Generators.RandomRestitution, friction, InfiniteMass.One), c =>
        {
            (RigidBody a, RigidBody b, _) = Respond(c);
            AssertUnchanged(c.A.Type == BodyType.Dynamic ? c.B : c.A, c.A.Type == BodyType.Dynamic ? b : a);
        }, seed: 108);

    [Theory]
    [InlineData(Generators.RandomRestitution, InfiniteMass.Any)]
    [InlineData(0f, InfiniteMass.None)]
    [InlineData(1f, InfiniteMass.One)]
    public void Friction_never_reverses_sliding_and_is_bounded_by_mu_times_normal_impulse(float restitution, InfiniteMass infinite) =>
        PropertyCheck.Run(Generators.Contact(restitution, friction: true, infinite), c =>
        {
            // The same contact answered without friction gives the state after the normal impulse alone.
            (RigidBody a0, RigidBody b0) = c.BuildBodies();
            Contact frictionless = c.BuildContact(a0, b0);
            new ImpulseCollisionResponder(c.Restitution, 0f).ResolveVelocity(ref frictionless);
            (RigidBody a, RigidBody b, Contact contact) = Respond(c);

            D3 p = D3.From(c.Point), n = D3.From(c.Normal);
            D3 u0 = Measure.VelocityAt(a0, p) - Measure.VelocityAt(b0, p);
            D3 slide0 = u0 - D3.Dot(u0, n) * n;
            D3 u1 = Measure.VelocityAt(a, p) - Measure.VelocityAt(b, p);
            double scale = Measure.SpeedScaleAt(a0, p) + Measure.SpeedScaleAt(b0, p);

            Law.Near(frictionless.NormalImpulse, contact.NormalImpulse, 1e-6 * Math.Abs(frictionless.NormalImpulse), "normal impulse is the frictionless one");
            Law.Holds(contact.TangentImpulse >= 0, $"tangent impulse size {contact.TangentImpulse} ≥ 0");
            Law.Holds(contact.TangentImpulse <= c.Friction * contact.NormalImpulse * (1 + 1e-6),
                $"|J_t| = {contact.TangentImpulse:R} ≤ μ J = {c.Friction * contact.NormalImpulse:R}");
            if (slide0.Length > AngularTolerance * scale)
            {
                D3 t = slide0 / slide0.Length;
                Law.Holds(D3.Dot(u1, t) >= -AngularTolerance * scale,
                    $"sliding reversed: along the sliding direction {t} the speed went from {slide0.Length:R} to {D3.Dot(u1, t):R}");

                // The friction impulse acts along −t: the change of A's momentum is −J_t t.
                if (a.IsDynamic)
                {
                    D3 dp = (double)a.Mass * (D3.From(a.LinearVelocity) - D3.From(a0.LinearVelocity));
                    Law.Near(-(double)contact.TangentImpulse * t, dp,
                        LinearTolerance * a.Mass * (D3.From(a.LinearVelocity).Length + D3.From(a0.LinearVelocity).Length), "friction impulse on A");
                }
            }
        }, seed: 109);

    /// <summary>
    /// Per-body ε (documented mixing: a body without one takes the responder's; the pair's ε is the maximum)
    /// decides the bounce: v_n' = −max(ε_A, ε_B) v_n.
    /// </summary>
    [Fact]
    public void Per_body_restitution_mixes_by_the_maximum() =>
        PropertyCheck.Run(
            from c in Generators.Contact(infinite: InfiniteMass.None)
            from eA in Gen.OneOf(Gen.Constant<float?>(null), Generators.UniformF(0, 1).Select(e => (float?)e))
            from eB in Gen.OneOf(Gen.Constant<float?>(null), Generators.UniformF(0, 1).Select(e => (float?)e))
            select (c, eA, eB),
            x =>
            {
                (ContactCase c, float? eA, float? eB) = x;
                (RigidBody a, RigidBody b) = c.BuildBodies();
                a.Restitution = eA;
                b.Restitution = eB;
                Contact contact = c.BuildContact(a, b);
                new ImpulseCollisionResponder(c.Restitution, 0f).ResolveVelocity(ref contact);
                double e = eA is null && eB is null ? c.Restitution : Math.Max(eA ?? c.Restitution, eB ?? c.Restitution);
                D3 p = D3.From(c.Point), n = D3.From(c.Normal);
                double after = D3.Dot(Measure.VelocityAt(a, p) - Measure.VelocityAt(b, p), n);
                double scale = Measure.SpeedScaleAt(a, p) + Measure.SpeedScaleAt(b, p) + Math.Abs(c.NormalVelocity());
                Law.Near(-e * c.NormalVelocity(), after, AngularTolerance * scale, $"v_n' with ε_A = {eA}, ε_B = {eB}, responder ε = {c.Restitution}");
            }, seed: 110);

    internal static void AssertUnchanged(BodySpec spec, RigidBody body)
    {
        Law.Holds(body.Position == spec.Position, $"position changed: {spec.Position} → {body.Position}");
        Law.Holds(body.LinearVelocity == spec.Velocity, $"velocity changed: {spec.Velocity} → {body.LinearVelocity}");
        Law.Holds(body.AngularVelocity == spec.AngularVelocity, $"angular velocity changed: {spec.AngularVelocity} → {body.AngularVelocity}");
        Law.Holds(body.Orientation == Quaternion.Normalize(spec.Orientation), $"orientation changed: {spec.Orientation} → {body.Orientation}");
    }
}
