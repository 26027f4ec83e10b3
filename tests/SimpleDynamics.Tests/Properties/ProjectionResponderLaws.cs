using System;
using System.Numerics;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// Law 8 for <see cref="ProjectionResponder"/> (listing 2 split by inverse mass) on contacts made by the
/// library's own narrow phase, <see cref="ContactGeometry.TryCollide(RigidBody, RigidBody, out Contact)"/>.
/// </summary>
/// <remarks>
/// Tolerance: positions are floats of size up to ≈ 10 m, so the new separation is exact only to a few ulps of
/// the coordinates; 1e-5 × (|c_A| + |c_B| + r_A + r_B) bounds that with a wide margin (≈ 100 ulps).
/// </remarks>
public class ProjectionResponderLaws
{
    /// <summary>Two overlapping bodies, from "just touching" to coincident centres (a tenth of the cases).</summary>
    private static FsCheck.Gen<ContactCase> Overlapping(InfiniteMass infinite) =>
        from c in Generators.Contact(infinite: infinite)
        from depth in Generators.Uniform(0.001, 1)
        from coincident in FsCheck.Fluent.Gen.Choose(0, 9)
        let radii = c.A.Radius + c.B.Radius
        let centreA = coincident == 0 ? c.B.Position : c.B.Position + c.Normal * (float)(radii * (1 - depth))
        select c with { A = c.A with { Position = centreA } };

    [Theory]
    [InlineData(InfiniteMass.None)]
    [InlineData(InfiniteMass.One)]
    public void Removes_the_penetration_exactly_and_changes_no_velocity(InfiniteMass infinite) =>
        PropertyCheck.Run(Overlapping(infinite), c =>
        {
            (RigidBody a, RigidBody b) = c.BuildBodies();
            Law.Holds(ContactGeometry.TryCollide(a, b, out Contact contact), "the generated bodies overlap");
            new ProjectionResponder().ResolvePosition(ref contact);

            float penetration = ContactGeometry.CirclePenetration(a.Position, a.Radius, b.Position, b.Radius, out _);
            double scale = a.Position.Length() + b.Position.Length() + a.Radius + b.Radius;
            Law.Near(0, penetration, 1e-5 * scale, "penetration re-measured after projection");
            Law.Holds(contact.Penetration == 0, "the contact records no penetration left");
            Law.Holds(a.LinearVelocity == c.A.Velocity && b.LinearVelocity == c.B.Velocity, "linear velocities unchanged");
            Law.Holds(a.AngularVelocity == c.A.AngularVelocity && b.AngularVelocity == c.B.AngularVelocity, "angular velocities unchanged");
            if (!a.IsDynamic)
            {
                ImpulseResponderLaws.AssertUnchanged(c.A, a);
            }

            if (!b.IsDynamic)
            {
                ImpulseResponderLaws.AssertUnchanged(c.B, b);
            }
        }, seed: 301);

    [Fact]
    public void Splits_the_displacement_by_inverse_mass_so_the_lighter_body_moves_more() =>
        PropertyCheck.Run(Overlapping(InfiniteMass.None), c =>
        {
            (RigidBody a, RigidBody b) = c.BuildBodies();
            Law.Holds(ContactGeometry.TryCollide(a, b, out Contact contact), "the generated bodies overlap");
            D3 n = D3.From(contact.Normal);
            double depth = contact.Penetration;
            new ProjectionResponder().ResolvePosition(ref contact);

            D3 moveA = D3.From(a.Position) - D3.From(c.A.Position), moveB = D3.From(b.Position) - D3.From(c.B.Position);
            double mA = a.Mass, mB = b.Mass;
            double tolerance = 1e-5 * (a.Position.Length() + b.Position.Length() + a.Radius + b.Radius);
            Law.Near(depth * mB / (mA + mB) * n, moveA, tolerance, "A moves along +n by d·w_A/(w_A + w_B)");
            Law.Near(-(depth * mA / (mA + mB)) * n, moveB, tolerance, "B moves along −n by d·w_B/(w_A + w_B)");
            if (mA < mB)
            {
                Law.Holds(moveA.Length >= moveB.Length, $"lighter A moved {moveA.Length:R}, heavier B {moveB.Length:R}");
            }
            else if (mB < mA)
            {
                Law.Holds(moveB.Length >= moveA.Length, $"lighter B moved {moveB.Length:R}, heavier A {moveA.Length:R}");
            }
        }, seed: 302);
}
