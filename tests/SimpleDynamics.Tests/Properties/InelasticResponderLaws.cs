using System;
using System.Numerics;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// Laws for <see cref="PerfectlyInelasticResponder"/> (eq. 2, listing 1): momentum, the common velocity, the
/// infinite-mass limit, separating contacts, and angular momentum only where its XML doc claims it
/// (relative velocity along the line of centres). Tolerance 1e-5 relative to Σ m|v|: eq. 2 is a few float
/// products and one division.
/// </summary>
public class InelasticResponderLaws
{
    private const double Tolerance = 1e-5;

    private static (RigidBody A, RigidBody B, Contact Contact) Respond(ContactCase c)
    {
        (RigidBody a, RigidBody b) = c.BuildBodies();
        Contact contact = c.BuildContact(a, b);
        new PerfectlyInelasticResponder().ResolveVelocity(ref contact);
        return (a, b, contact);
    }

    [Fact]
    public void Linear_momentum_is_conserved() =>
        PropertyCheck.Run(Generators.Contact(), c =>
        {
            (RigidBody a0, RigidBody b0) = c.BuildBodies();
            D3 before = Measure.Momentum(a0, b0);
            (RigidBody a, RigidBody b, _) = Respond(c);
            double scale = Measure.MomentumScale(a0, b0) + Measure.MomentumScale(a, b);
            Law.Near(before, Measure.Momentum(a, b), Tolerance * scale, "total linear momentum");
        }, seed: 201);

    [Fact]
    public void Both_bodies_leave_with_the_common_velocity_of_eq_2_and_keep_their_spin() =>
        PropertyCheck.Run(Generators.Contact(), c =>
        {
            double mA = c.A.Mass, mB = c.B.Mass;
            D3 common = (mA * D3.From(c.A.Velocity) + mB * D3.From(c.B.Velocity)) / (mA + mB);
            (RigidBody a, RigidBody b, _) = Respond(c);
            double scale = (mA * D3.From(c.A.Velocity).Length + mB * D3.From(c.B.Velocity).Length) / (mA + mB);
            Law.Near(common, D3.From(a.LinearVelocity), Tolerance * scale, "v_A' = eq. 2's common velocity");
            Law.Holds(a.LinearVelocity == b.LinearVelocity, $"v_A' {a.LinearVelocity} and v_B' {b.LinearVelocity} are the same");
            Law.Holds(a.AngularVelocity == c.A.AngularVelocity && b.AngularVelocity == c.B.AngularVelocity, "angular velocities unchanged (listing 1)");
        }, seed: 202);

    [Fact]
    public void Against_an_infinite_mass_body_the_dynamic_body_takes_its_velocity() =>
        PropertyCheck.Run(Generators.Contact(infinite: InfiniteMass.One), c =>
        {
            (RigidBody a, RigidBody b, _) = Respond(c);
            (RigidBody dynamic, RigidBody infinite, BodySpec infiniteSpec) = a.IsDynamic ? (a, b, c.B) : (b, a, c.A);
            Law.Holds(dynamic.LinearVelocity == infiniteSpec.Velocity,
                $"dynamic body's velocity {dynamic.LinearVelocity} is the {infiniteSpec.Type} body's {infiniteSpec.Velocity}");
            ImpulseResponderLaws.AssertUnchanged(infiniteSpec, infinite);
            if (infiniteSpec.Type == BodyType.Static)
            {
                Law.Holds(dynamic.LinearVelocity == Vector3.Zero, "a body hitting a static body sticks");
            }
        }, seed: 203);

    [Fact]
    public void Separating_contact_is_left_untouched() =>
        PropertyCheck.Run(Generators.Contact(infinite: InfiniteMass.Any, approaching: false), c =>
        {
            (RigidBody a, RigidBody b, Contact contact) = Respond(c);
            ImpulseResponderLaws.AssertUnchanged(c.A, a);
            ImpulseResponderLaws.AssertUnchanged(c.B, b);
            Law.Holds(contact.NormalImpulse == 0, "no impulse recorded");
        }, seed: 204);

    /// <summary>
    /// The doc's claim: angular momentum is conserved when the relative velocity lies along the line of
    /// centres (then the exchanged momentum μ(v_B − v_A) is parallel to c_A − c_B and has no moment).
    /// </summary>
    [Fact]
    public void Angular_momentum_is_conserved_when_the_relative_velocity_is_along_the_line_of_centres() =>
        PropertyCheck.Run(
            from c in Generators.Contact()
            from s in Generators.UniformF(0.1, 5)
            from o in Generators.Vector(10)
            select (c with { B = c.B with { Velocity = c.A.Velocity + s * Vector3.Normalize(c.A.Position - c.B.Position) } }, o),
            x =>
            {
                (ContactCase c, Vector3 origin) = x;
                D3 o = D3.From(origin);
                (RigidBody a0, RigidBody b0) = c.BuildBodies();
                D3 before = Measure.AngularMomentum(o, a0, b0);
                (RigidBody a, RigidBody b, _) = Respond(c);
                double scale = Measure.AngularMomentumScale(o, a0, b0) + Measure.AngularMomentumScale(o, a, b);
                Law.Near(before, Measure.AngularMomentum(o, a, b), 1e-4 * scale, $"angular momentum about {o}");
            }, seed: 205);

    [Fact]
    public void Kinetic_energy_never_increases() =>
        PropertyCheck.Run(Generators.Contact(infinite: InfiniteMass.Any), c =>
        {
            (RigidBody a0, RigidBody b0) = c.BuildBodies();
            double before = Measure.KineticEnergy(c.RestFrame, a0, b0);
            (RigidBody a, RigidBody b, _) = Respond(c);
            double after = Measure.KineticEnergy(c.RestFrame, a, b);
            Law.Holds(after <= before * (1 + Tolerance), $"kinetic energy rose from {before:R} to {after:R}");
        }, seed: 206);
}
