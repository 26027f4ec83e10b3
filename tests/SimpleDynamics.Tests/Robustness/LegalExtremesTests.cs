using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
using Xunit;

namespace SimpleDynamics.Tests.Robustness;

/// <summary>
/// Masses of 10⁻⁶…10⁶ kg and radii of 10⁻⁴…10⁴ m, in any combination, construct and step without NaN; what float
/// cannot hold is rejected by an <see cref="ArgumentException"/> naming the argument, before anything changes.
/// </summary>
public class LegalExtremesTests
{
    public static TheoryData<float, float> Extremes()
    {
        var data = new TheoryData<float, float>();
        foreach (float mass in new[] { 1e-6f, 1f, 1e6f })
        {
            foreach (float radius in new[] { 1e-4f, 1f, 1e4f })
            {
                data.Add(mass, radius);
            }
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Extremes))]
    public void A_body_at_the_legal_extremes_has_a_finite_inverse_inertia(float mass, float radius)
    {
        var sphere = new RigidBody(mass, radius, Vector3.Zero);
        var disc = new RigidBody(mass, radius, Vector3.Zero, Inertia.Disc(mass, radius));
        foreach (RigidBody body in new[] { sphere, disc })
        {
            Assert.True(body.InverseInertiaWorld.IsFinite(), body.InverseInertiaWorld.ToString());
            Assert.True(body.InverseInertiaWorld.M11 > 0, body.InverseInertiaWorld.ToString());
            Assert.Equal(1f / body.Inertia.M33, body.InverseInertiaWorld.M33, 1e-6f * body.InverseInertiaWorld.M33);
        }
    }

    [Theory]
    [MemberData(nameof(Extremes))]
    public void A_pile_of_extreme_bodies_steps_without_NaN(float mass, float radius)
    {
        var world = new World(Scenes.EarthGravity);
        world.AddPlane(StaticPlane.Ground());
        // A column of three touching bodies on the ground, and a spinning one beside it.
        for (int i = 0; i < 3; i++)
        {
            world.Add(new RigidBody(mass, radius, new Vector3(0, radius * (1 + 2 * i), 0)));
        }

        world.Add(new RigidBody(mass, radius, new Vector3(3 * radius, 2 * radius, 0), Inertia.Disc(mass, radius))
        {
            AngularVelocity = new Vector3(0, 0, 1), LinearVelocity = new Vector3(-1, 0, 0),
        });
        StepAndAssertFinite(world, 20);
    }

    [Fact]
    public void Bodies_of_every_extreme_together_step_without_NaN()
    {
        var world = new World(Scenes.EarthGravity);
        world.AddPlane(StaticPlane.Ground());
        float x = 0;
        foreach (float mass in new[] { 1e-6f, 1e6f })
        {
            foreach (float bigRadius in new[] { 1e-4f, 1e4f })
            {
                // A body of one extreme with one of the other extreme resting on top of it.
                var below = world.Add(new RigidBody(mass, bigRadius, new Vector3(x + bigRadius, bigRadius, 0)));
                float other = bigRadius == 1e4f ? 1e-4f : 1e4f;
                float otherMass = mass == 1e6f ? 1e-6f : 1e6f;
                world.Add(new RigidBody(otherMass, other, below.Position + new Vector3(0, bigRadius + other, 0), Inertia.Disc(otherMass, other))
                {
                    AngularVelocity = new Vector3(0, 0, 2),
                });
                x += 3 * MathF.Max(bigRadius, other);
            }
        }

        StepAndAssertFinite(world, 20);
    }

    [Theory]
    [InlineData(1e-8f, 1e-4f)]
    [InlineData(1e30f, 1f)]
    [InlineData(1e6f, 1e4f)]
    [InlineData(1e-6f, 1e-4f)]
    public void Masses_and_radii_that_used_to_make_the_inertia_singular_are_accepted(float mass, float radius)
    {
        var body = new RigidBody(mass, radius, Vector3.Zero);
        Assert.True(body.InverseInertiaWorld.IsFinite());
        Assert.True(body.InverseInertiaWorld.M11 > 0);
        body.SetMass(mass, Inertia.SolidSphere(mass, radius));
        Assert.True(body.InverseInertiaWorld.IsFinite());
    }

    [Theory]
    [InlineData(1e-15f)]
    [InlineData(1f)]
    [InlineData(1e13f)]
    [InlineData(1e30f)]
    public void A_full_tensor_is_inverted_at_any_scale(float scale)
    {
        // A box's tensor rotated off its axes: non-diagonal, so the general path is taken.
        Quaternion q = Quaternion.CreateFromYawPitchRoll(0.3f, 0.7f, -0.4f);
        Matrix3 tensor = Matrix3.Diagonal(1f * scale, 2f * scale, 3f * scale).RotatedBy(q);
        Matrix3 product = tensor.Inverse() * tensor;
        AssertNear(Matrix3.Identity, product, 1e-5f);
        var body = new RigidBody(1f, 1f, Vector3.Zero, tensor);
        AssertNear(Matrix3.Identity, body.InverseInertiaWorld * tensor, 1e-5f);
    }

    [Fact]
    public void An_inertia_whose_inverse_overflows_float_is_rejected_naming_it_and_changes_nothing()
    {
        Matrix3 tiny = Matrix3.Diagonal(1, 1, 1e-39f);
        Assert.Equal("inertia", Assert.ThrowsAny<ArgumentException>(() => new RigidBody(1f, 1f, Vector3.Zero, tiny)).ParamName);
        Assert.Equal("tensor", Assert.ThrowsAny<ArgumentException>(() => Inertia.Validate(tiny, "tensor")).ParamName);

        var body = new RigidBody(2f, 1f, Vector3.Zero);
        Matrix3 inertia = body.Inertia, inverse = body.InverseInertiaWorld;
        Assert.Equal("inertia", Assert.ThrowsAny<ArgumentException>(() => body.SetMass(5f, tiny)).ParamName);
        Assert.Equal(2f, body.Mass);
        Assert.Equal(0.5f, body.InverseMass);
        Assert.Equal(inertia, body.Inertia);
        Assert.Equal(inverse, body.InverseInertiaWorld);
    }

    [Fact]
    public void A_tiny_but_invertible_inertia_is_accepted_by_SetMass()
    {
        var body = new RigidBody(2f, 1f, Vector3.Zero);
        body.SetMass(5f, Matrix3.Diagonal(1e-20f, 1e-20f, 1e-20f));
        Assert.Equal(5f, body.Mass);
        Assert.Equal(1e20f, body.InverseInertiaWorld.M22, 1e14f);
    }

    [Fact]
    public void A_mass_whose_inverse_overflows_float_is_rejected_naming_mass()
    {
        Assert.Equal("mass", Assert.ThrowsAny<ArgumentException>(() => new RigidBody(1e-39f, 1f, Vector3.Zero, Matrix3.Identity)).ParamName);
        var body = new RigidBody(2f, 1f, Vector3.Zero);
        Assert.Equal("mass", Assert.ThrowsAny<ArgumentException>(() => body.SetMass(1e-39f, Matrix3.Identity)).ParamName);
        Assert.Equal(2f, body.Mass);
    }

    [Fact]
    public void Shape_inertias_that_float_cannot_hold_are_rejected_naming_an_argument()
    {
        Assert.Equal("radius", Assert.ThrowsAny<ArgumentException>(() => new RigidBody(1e30f, 1e10f, Vector3.Zero)).ParamName);
        Assert.Equal("radius", Assert.ThrowsAny<ArgumentException>(() => Inertia.Disc(1e-30f, 1e-10f)).ParamName);
        Assert.Equal("mass", Assert.ThrowsAny<ArgumentException>(() => Inertia.Box(1e30f, 1e10f, 1f, 1f)).ParamName);
    }

    [Fact]
    public void Orientation_is_normalised_however_large_or_small_its_components()
    {
        var body = new RigidBody(1f, 1f, Vector3.Zero);
        body.Orientation = new Quaternion(2e19f, 0, 0, 1);
        Assert.Equal(1f, body.Orientation.X, 1e-6f);
        Assert.Equal(0f, body.Orientation.W, 1e-6f);
        Assert.True(body.InverseInertiaWorld.IsFinite());

        body.Orientation = new Quaternion(0, 3e-30f, 0, 4e-30f);
        Assert.Equal(0.6f, body.Orientation.Y, 1e-6f);
        Assert.Equal(0.8f, body.Orientation.W, 1e-6f);

        Quaternion before = body.Orientation;
        foreach (Quaternion bad in new[] { default, new Quaternion(float.PositiveInfinity, 0, 0, 1), new Quaternion(0, 0, float.NaN, 1) })
        {
            Assert.Equal(nameof(RigidBody.Orientation), Assert.ThrowsAny<ArgumentException>(() => body.Orientation = bad).ParamName);
            Assert.Equal(before, body.Orientation);
        }

        var world = new World(Scenes.EarthGravity);
        world.Add(body);
        body.AngularVelocity = new Vector3(1, 2, 3);
        body.Orientation = new Quaternion(2e19f, 0, 0, 1);
        StepAndAssertFinite(world, 5);
    }

    [Fact]
    public void A_force_whose_sum_or_acceleration_overflows_is_rejected_and_changes_nothing()
    {
        var body = new RigidBody(1f, 1f, Vector3.Zero);
        var big = new Vector3(float.MaxValue, 0, 0);
        body.ApplyForce(big);
        Assert.Equal("force", Assert.ThrowsAny<ArgumentException>(() => body.ApplyForce(big)).ParamName);
        Assert.Equal("force", Assert.ThrowsAny<ArgumentException>(() => body.ApplyForce(big, Vector3.Zero)).ParamName);
        Assert.Equal(big, body.Force);
        Assert.Equal(Vector3.Zero, body.Torque);

        // Finite, but 10³⁵ N on a microgram body is an acceleration of 10⁴¹ m/s², beyond float.
        var light = new RigidBody(1e-6f, 1f, Vector3.Zero);
        Assert.Equal("force", Assert.ThrowsAny<ArgumentException>(() => light.ApplyForce(new Vector3(0, 1e35f, 0))).ParamName);
        Assert.Equal(Vector3.Zero, light.Force);

        // A finite force at a finite point whose torque overflows: nothing is added, force included.
        var body2 = new RigidBody(1f, 1f, Vector3.Zero);
        Assert.Equal("force", Assert.ThrowsAny<ArgumentException>(() => body2.ApplyForce(new Vector3(0, 1e30f, 0), new Vector3(1e10f, 0, 0))).ParamName);
        Assert.Equal(Vector3.Zero, body2.Force);
        Assert.Equal(Vector3.Zero, body2.Torque);

        // Two finite points more than float's range apart.
        var far = new RigidBody(1f, 1f, new Vector3(float.MaxValue, 0, 0));
        Assert.Equal("point", Assert.ThrowsAny<ArgumentException>(() => far.ApplyForce(Vector3.UnitY, new Vector3(-float.MaxValue, 0, 0))).ParamName);
        Assert.Equal(Vector3.Zero, far.Force);
    }

    [Fact]
    public void A_torque_whose_sum_or_angular_acceleration_overflows_is_rejected_and_changes_nothing()
    {
        var body = new RigidBody(1f, 1f, Vector3.Zero);
        var big = new Vector3(0, 0, float.MaxValue);
        Assert.Equal("torque", Assert.ThrowsAny<ArgumentException>(() => body.ApplyTorque(big)).ParamName);
        body.ApplyTorque(new Vector3(0, 0, 1e30f));
        Assert.Equal("torque", Assert.ThrowsAny<ArgumentException>(() => body.ApplyTorque(big)).ParamName);
        Assert.Equal(new Vector3(0, 0, 1e30f), body.Torque);
    }

    [Fact]
    public void An_impulse_whose_velocities_overflow_is_rejected_and_changes_nothing()
    {
        var body = new RigidBody(1e-6f, 1e-4f, Vector3.Zero) { LinearVelocity = Vector3.UnitX, AngularVelocity = Vector3.UnitZ };
        Assert.Equal("impulse", Assert.ThrowsAny<ArgumentException>(() => body.ApplyImpulse(new Vector3(1e35f, 0, 0), Vector3.Zero)).ParamName);
        Assert.Equal("impulse", Assert.ThrowsAny<ArgumentException>(() => body.ApplyImpulse(new Vector3(0, 1e30f, 0), new Vector3(1e-4f, 0, 0))).ParamName);
        Assert.Equal(Vector3.UnitX, body.LinearVelocity);
        Assert.Equal(Vector3.UnitZ, body.AngularVelocity);

        var far = new RigidBody(1f, 1f, new Vector3(float.MaxValue, 0, 0));
        Assert.Equal("point", Assert.ThrowsAny<ArgumentException>(() => far.ApplyImpulse(Vector3.UnitY, new Vector3(-float.MaxValue, 0, 0))).ParamName);
        Assert.Equal(Vector3.Zero, far.LinearVelocity);
    }

    private static void StepAndAssertFinite(World world, int steps)
    {
        for (int i = 0; i < steps; i++)
        {
            world.Step(1f / 60f);
            foreach (RigidBody body in world.Bodies)
            {
                Assert.True(Vectors.IsFinite(body.Position), $"step {i}: {body} position");
                Assert.True(Vectors.IsFinite(body.LinearVelocity), $"step {i}: {body} velocity {body.LinearVelocity}");
                Assert.True(Vectors.IsFinite(body.AngularVelocity), $"step {i}: {body} spin {body.AngularVelocity}");
                Assert.True(Vectors.IsFinite(body.Orientation), $"step {i}: {body} orientation {body.Orientation}");
                Assert.True(body.InverseInertiaWorld.IsFinite(), $"step {i}: {body} inverse inertia");
            }
        }
    }

    private static void AssertNear(Matrix3 expected, Matrix3 actual, float tolerance)
    {
        float[] e = { expected.M11, expected.M12, expected.M13, expected.M21, expected.M22, expected.M23, expected.M31, expected.M32, expected.M33 };
        float[] a = { actual.M11, actual.M12, actual.M13, actual.M21, actual.M22, actual.M23, actual.M31, actual.M32, actual.M33 };
        for (int i = 0; i < 9; i++)
        {
            Assert.True(MathF.Abs(e[i] - a[i]) <= tolerance, $"entry {i}: expected {expected}, got {actual}");
        }
    }
}
