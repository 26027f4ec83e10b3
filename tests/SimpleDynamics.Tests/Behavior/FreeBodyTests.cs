using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;

namespace SimpleDynamics.Tests.Behavior;

/// <summary>Closed-form motion of a lone body under World.Step, and a body resting on a plane.</summary>
public class FreeBodyTests
{
    [Fact]
    public void Free_body_moves_in_a_straight_line_x0_plus_v_t()
    {
        var world = new World(Vector3.Zero);
        var x0 = new Vector3(1, -2, 3);
        var v = new Vector3(0.7f, 1.3f, -2.1f);
        var body = world.Add(new RigidBody(3f, 0.5f, x0) { LinearVelocity = v });
        const float dt = 1f / 60f;
        const int steps = 300;
        for (int i = 0; i < steps; i++)
        {
            world.Step(dt);
        }

        double t = steps * (double)dt;
        // x += v dt in float, 300 times: rounding of about one ulp of |x| per step.
        double tolerance = steps * 2e-7 * (x0.Length() + v.Length() * t);
        Assert.InRange(body.Position.X, x0.X + v.X * t - tolerance, x0.X + v.X * t + tolerance);
        Assert.InRange(body.Position.Y, x0.Y + v.Y * t - tolerance, x0.Y + v.Y * t + tolerance);
        Assert.InRange(body.Position.Z, x0.Z + v.Z * t - tolerance, x0.Z + v.Z * t + tolerance);
        Assert.Equal(v, body.LinearVelocity);
        Assert.Equal(Quaternion.Identity, body.Orientation);
        Assert.Equal(t, world.Time, 1e-9);
    }

    /// <summary>
    /// Spin at constant ω about z: the orientation angle after time t is ωt. The integrator
    /// q ← normalise(q + ½ h (ω, 0) q) turns by 2 atan(ω h / 2) per substep h = dt / substeps, not ω h; that truncation
    /// is ≈ (ω h)³/12 per substep, so the closed form ωt holds to N (ω h)³/12 over N substeps, and the discrete
    /// value N·2 atan(ω h/2) to float rounding. Both are checked.
    /// </summary>
    [Theory]
    [InlineData(2f)]
    [InlineData(-1.5f)]
    public void Spin_about_z_turns_by_omega_t(float omega)
    {
        var world = new World(Vector3.Zero);
        var body = world.Add(new RigidBody(1f, 0.5f, Vector3.Zero, Inertia.Disc(1f, 0.5f)) { AngularVelocity = new Vector3(0, 0, omega) });
        const float dt = 1f / 60f;
        const int steps = 90;
        double angle = 0;
        double previous = 0;
        for (int i = 0; i < steps; i++)
        {
            world.Step(dt);
            Quaternion q = body.Orientation;
            Assert.Equal(0f, q.X);
            Assert.Equal(0f, q.Y);
            double current = 2 * Math.Atan2(q.Z, q.W);
            double delta = Math.IEEERemainder(current - previous, 2 * Math.PI); // unwrap
            angle += delta;
            previous = current;
        }

        int substeps = steps * world.Substeps;
        double x = omega * (double)dt / world.Substeps;
        double truncation = substeps * Math.Abs(x * x * x) / 12;
        Assert.Equal(substeps * 2 * Math.Atan(x / 2), angle, 1e-5);
        Assert.InRange(angle, omega * steps * dt - 1.5 * truncation - 1e-5, omega * steps * dt + 1.5 * truncation + 1e-5);
        Assert.Equal(new Vector3(0, 0, omega), body.AngularVelocity);
        Assert.Equal(Vector3.Zero, body.Position);
    }

    [Fact]
    public void Body_resting_on_a_plane_stays_at_rest()
    {
        var solver = new Response.SequentialImpulseSolver();
        var world = new World(new Vector3(0, -9.81f, 0), solver);
        world.AddPlane(StaticPlane.Ground());
        const float r = 0.5f;
        var ball = world.Add(new RigidBody(1f, r, new Vector3(0, r, 0)));
        for (int i = 0; i < 600; i++)
        {
            world.Step(1f / 60f);
            // Resting: the ball may sink by at most the solver's slop plus one step of gravity, and never rises.
            Assert.InRange(ball.Position.Y, r - solver.Slop - 9.81f / 3600f, r + 1e-6f);
        }

        Assert.True(ball.LinearVelocity.Length() < 1e-3f, $"v = {ball.LinearVelocity}");
        Assert.Equal(0f, ball.Position.X);
        Assert.Equal(0f, ball.Position.Z);
    }
}
