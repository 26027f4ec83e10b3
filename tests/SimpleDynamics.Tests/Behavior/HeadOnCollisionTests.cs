using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Behavior;

/// <summary>
/// A head-on 1-D collision of unequal masses against the textbook answer
/// v1' = (m1 v1 + m2 v2 + m2 ε (v2 − v1)) / (m1 + m2), v2' = (m1 v1 + m2 v2 + m1 ε (v1 − v2)) / (m1 + m2).
/// Tolerance 1e-5 relative to the speeds: a handful of float operations.
/// </summary>
public class HeadOnCollisionTests
{
    private const float M1 = 2f, M2 = 5f, V1 = 3f, V2 = -1f;

    private static (double V1, double V2) Textbook(double e) =>
        ((M1 * V1 + M2 * V2 + M2 * e * (V2 - V1)) / (M1 + M2), (M1 * V1 + M2 * V2 + M1 * e * (V1 - V2)) / (M1 + M2));

    private static (RigidBody Left, RigidBody Right) Bodies()
    {
        // Overlapping by 2 cm, centres on the x axis: the contact point lies on the line of centres, so no spin.
        var left = new RigidBody(M1, 0.5f, new Vector3(-0.49f, 0, 0)) { LinearVelocity = new Vector3(V1, 0, 0) };
        var right = new RigidBody(M2, 0.5f, new Vector3(0.49f, 0, 0)) { LinearVelocity = new Vector3(V2, 0, 0) };
        return (left, right);
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(0.25f)]
    [InlineData(0.5f)]
    [InlineData(0.75f)]
    [InlineData(1f)]
    public void Impulse_responder_gives_the_textbook_velocities(float restitution)
    {
        (RigidBody left, RigidBody right) = Bodies();
        Assert.True(ContactGeometry.TryCollide(left, right, out Contact contact));
        new ImpulseCollisionResponder(restitution, friction: 0f).ResolveVelocity(ref contact);
        AssertTextbook(restitution, left, right);
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(0.25f)]
    [InlineData(0.5f)]
    [InlineData(0.75f)]
    [InlineData(1f)]
    public void World_step_with_the_impulse_responder_gives_the_textbook_velocities(float restitution)
    {
        var world = new World(Vector3.Zero, new ImpulseCollisionResponder(restitution, friction: 0f));
        (RigidBody left, RigidBody right) = Bodies();
        world.Add(left);
        world.Add(right);

        world.Step(1f / 60f);
        AssertTextbook(restitution, left, right);

        // Afterwards the bodies separate (or, for ε = 0, move together) and nothing changes any more.
        Vector3 l = left.LinearVelocity, r = right.LinearVelocity;
        for (int i = 0; i < 60; i++)
        {
            world.Step(1f / 60f);
        }

        Assert.Equal(l, left.LinearVelocity);
        Assert.Equal(r, right.LinearVelocity);
        Assert.Equal(Vector3.Zero, left.AngularVelocity);
        Assert.Equal(Vector3.Zero, right.AngularVelocity);
    }

    private static void AssertTextbook(float restitution, RigidBody left, RigidBody right)
    {
        (double v1, double v2) = Textbook(restitution);
        const double tolerance = 1e-5 * (3 + 1);
        Assert.InRange(left.LinearVelocity.X, v1 - tolerance, v1 + tolerance);
        Assert.InRange(right.LinearVelocity.X, v2 - tolerance, v2 + tolerance);
        Assert.Equal(0f, left.LinearVelocity.Y);
        Assert.Equal(0f, left.LinearVelocity.Z);
        Assert.Equal(0f, right.LinearVelocity.Y);
        Assert.Equal(0f, right.LinearVelocity.Z);
    }
}
