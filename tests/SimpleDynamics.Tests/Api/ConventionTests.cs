using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Api;

/// <summary>The conventions stated in the XML docs: normal from B to A, sign of approach, infinite mass.</summary>
public class ConventionTests
{
    [Fact]
    public void Detected_normal_is_a_unit_vector_from_B_to_A_and_A_is_the_earlier_body()
    {
        var first = new RigidBody(1f, 1f, new Vector3(3, 0, 0));
        var second = new RigidBody(1f, 1f, new Vector3(1.5f, 0, 0));
        var collisions = new CollisionData();
        new BruteForceDetector().FindContacts(new[] { first, second }, collisions);
        Contact c = Assert.Single(collisions.Contacts.ToArray());
        Assert.Same(first, c.BodyA);
        Assert.Same(second, c.BodyB);
        Assert.Equal(Vector3.UnitX, c.Normal); // from B (x = 1.5) to A (x = 3)
        Assert.Equal(0.5f, c.Penetration);
        Assert.Equal(new Vector3(2.25f, 0, 0), c.Point); // middle of the overlap
    }

    [Fact]
    public void Approaching_bodies_have_negative_relative_normal_velocity_and_get_a_positive_impulse()
    {
        var a = new RigidBody(1f, 1f, new Vector3(1.9f, 0, 0)) { LinearVelocity = new Vector3(-1, 0, 0) };
        var b = new RigidBody(1f, 1f, Vector3.Zero) { LinearVelocity = new Vector3(1, 0, 0) };
        Assert.True(ContactGeometry.TryCollide(a, b, out Contact c));
        Assert.Equal(-2f, c.ApproachVelocity);
        Assert.Equal(-2f, Vector3.Dot(c.RelativeVelocity, c.Normal));
        new ImpulseCollisionResponder(1f, 0f).ResolveVelocity(ref c);
        Assert.True(c.NormalImpulse > 0);
        Assert.Equal(new Vector3(1, 0, 0), a.LinearVelocity); // A pushed along +n
        Assert.Equal(new Vector3(-1, 0, 0), b.LinearVelocity); // B along −n
    }

    [Fact]
    public void Static_body_has_infinite_mass_zero_inverses_and_never_moves()
    {
        var s = RigidBody.CreateStatic(1f, new Vector3(0, -1, 0));
        Assert.Equal(BodyType.Static, s.Type);
        Assert.False(s.IsDynamic);
        Assert.Equal(float.PositiveInfinity, s.Mass);
        Assert.Equal(0f, s.InverseMass);
        Assert.Equal(Matrix3.Zero, s.InverseInertiaWorld);
        Assert.Throws<InvalidOperationException>(() => s.LinearVelocity = Vector3.UnitX);
        Assert.Throws<InvalidOperationException>(() => s.AngularVelocity = Vector3.UnitX);
        Assert.Throws<InvalidOperationException>(() => s.SetMass(1f, Matrix3.Identity));
        s.ApplyForce(new Vector3(0, 100, 0));
        s.ApplyImpulse(new Vector3(0, 100, 0), new Vector3(1, 0, 0));
        Assert.Equal(Vector3.Zero, s.LinearVelocity);

        var world = new World(new Vector3(0, -9.81f, 0), new ImpulseCollisionResponder(1f, 0.5f));
        world.Add(s);
        var ball = world.Add(new RigidBody(1f, 0.5f, new Vector3(0.3f, 1, 0)) { LinearVelocity = new Vector3(0, -3, 0) });
        bool bounced = false;
        for (int i = 0; i < 120; i++)
        {
            world.Step(1f / 60f);
            bounced |= ball.LinearVelocity.Y > 0;
            Assert.Equal(new Vector3(0, -1, 0), s.Position);
            Assert.Equal(Vector3.Zero, s.LinearVelocity);
            Assert.Equal(Vector3.Zero, s.AngularVelocity);
            Assert.Equal(Quaternion.Identity, s.Orientation);
        }

        Assert.True(bounced, "the ball bounced off the static body");
    }

    [Fact]
    public void Kinematic_body_moves_with_its_velocity_and_ignores_impulses()
    {
        var k = RigidBody.CreateKinematic(1f, Vector3.Zero, new Vector3(2, 0, 0));
        Assert.Equal(0f, k.InverseMass);
        var world = new World(new Vector3(0, -9.81f, 0));
        world.Add(k);
        var ball = world.Add(new RigidBody(1f, 0.5f, new Vector3(1.4f, 0, 0)));
        for (int i = 0; i < 30; i++)
        {
            world.Step(1f / 60f);
            Assert.Equal(new Vector3(2, 0, 0), k.LinearVelocity);
        }

        Assert.Equal(1f, k.Position.X, 4);
        Assert.True(ball.LinearVelocity.X > 0, "the kinematic body pushed the ball");
    }

    [Fact]
    public void World_inverse_inertia_is_R_Iinv_Rt()
    {
        var inertia = new Matrix3(2, 0.3f, -0.1f, 0.3f, 3, 0.2f, -0.1f, 0.2f, 4);
        var body = new RigidBody(1f, 1f, Vector3.Zero, inertia) { Orientation = Quaternion.CreateFromYawPitchRoll(0.3f, -1.1f, 2f) };
        Matrix3 product = body.Inertia.RotatedBy(body.Orientation) * body.InverseInertiaWorld;
        Matrix3 identity = Matrix3.Identity;
        foreach ((float x, float y) in new[]
        {
            (product.M11, identity.M11), (product.M12, identity.M12), (product.M13, identity.M13),
            (product.M21, identity.M21), (product.M22, identity.M22), (product.M23, identity.M23),
            (product.M31, identity.M31), (product.M32, identity.M32), (product.M33, identity.M33),
        })
        {
            Assert.Equal(y, x, 5);
        }
    }
}
