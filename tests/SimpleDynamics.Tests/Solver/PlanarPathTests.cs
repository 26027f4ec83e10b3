using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The solver's shortcuts for planar steps (one tangent, spins along z) and for inertia tensors that rotations leave
/// unchanged: they must give the motion the general path gives.
/// </summary>
public class PlanarPathTests
{
    private const float Dt = 1f / 60f;

    /// <summary>
    /// A disc sliding on the ground until it rolls, and two discs that strike each other off-centre in the air, then
    /// land spinning and roll (friction turns all three), stepped twice: once in the plane, and once with one more disc
    /// 10 m away in z, which
    /// falls far above them, touching nothing, but makes the step non-planar, so the general 3-D path solves it.
    /// </summary>
    [Fact]
    public void Planar_steps_move_discs_as_the_general_path_does()
    {
        (World planar, RigidBody[] a) = RubbingDiscs(offPlaneWitness: false);
        (World general, RigidBody[] b) = RubbingDiscs(offPlaneWitness: true);
        var planarSolver = (SequentialImpulseSolver)planar.Responder;
        var generalSolver = (SequentialImpulseSolver)general.Responder;
        float largestGap = 0, largestSpinGap = 0, largestSpin = 0;
        for (int step = 0; step < 90; step++)
        {
            planar.Step(Dt);
            general.Step(Dt);
            Assert.True(planarSolver.SolvedPlanar);
            Assert.False(generalSolver.SolvedPlanar);
            for (int i = 0; i < a.Length; i++)
            {
                largestGap = MathF.Max(largestGap, Vector3.Distance(a[i].Position, b[i].Position));
                largestSpinGap = MathF.Max(largestSpinGap, Vector3.Distance(a[i].AngularVelocity, b[i].AngularVelocity));
                largestSpin = MathF.Max(largestSpin, a[i].AngularVelocity.Length());
                Assert.Equal(0f, a[i].Position.Z);
                Assert.Equal(0f, a[i].AngularVelocity.X);
                Assert.Equal(0f, a[i].AngularVelocity.Y);

                // On the general path too, contacts whose normals lie in the plane keep their discs in it: their
                // tangents are t1 in the plane and t2 = ∓z exactly, so friction pushes nothing out of it.
                Assert.Equal(0f, b[i].Position.Z);
                Assert.Equal(0f, b[i].LinearVelocity.Z);
                Assert.Equal(0f, b[i].AngularVelocity.X);
                Assert.Equal(0f, b[i].AngularVelocity.Y);
            }
        }

        Assert.True(largestSpin > 1f, $"the discs must spin for the test to mean anything (largest spin {largestSpin} rad/s)");
        // The paths differ only in rounding (a clamp to ±μ P_n against a scale onto the disc, t₁ built or normalised).
        Assert.True(largestGap < 1e-6f, $"planar and general paths drift {largestGap} m apart");
        Assert.True(largestSpinGap < 1e-4f * largestSpin, $"spins differ by {largestSpinGap} rad/s");
    }

    /// <summary>
    /// The contact constraint the passes stream through holds what a planar step needs in one cache line (64 bytes); a
    /// 3-D step reads its tangents and spins from a parallel array (ContactConstraint's remarks).
    /// </summary>
    [Fact]
    public void A_contact_constraint_fills_one_cache_line()
    {
        Assert.Equal(64, Unsafe.SizeOf<ContactConstraint>());
        Assert.Equal(72, Unsafe.SizeOf<TangentFrame>());
    }

    /// <summary>
    /// A step that begins planar and turns general part-way: a disc at 20 m/s strikes a resting disc, which flies into a
    /// sphere that sleeps 5 cm off the plane, 10 cm further on, within the same step. The sphere wakes in the impact
    /// pass, so the substeps after it solve on the general path the contacts the planar path measured, in whose layout
    /// the spins about z lie where the general path keeps the second tangent's impulse and mass (ContactConstraint).
    /// Another disc slides on the ground far away, and must follow what it follows when the sphere is awake from the
    /// start and every step is general.
    /// </summary>
    [Fact]
    public void A_step_that_turns_general_when_a_body_off_the_plane_wakes_solves_its_contacts_as_the_general_path()
    {
        (World world, RigidBody slider, RigidBody sphere) = StruckSleeper(sleeperAwake: false);
        (World general, RigidBody generalSlider, RigidBody generalSphere) = StruckSleeper(sleeperAwake: true);
        var solver = (SequentialImpulseSolver)world.Responder;
        var generalSolver = (SequentialImpulseSolver)general.Responder;
        int turned = 0;
        float largestGap = 0;
        for (int step = 0; step < 60; step++)
        {
            world.Step(Dt);
            general.Step(Dt);
            Assert.False(generalSolver.BeganPlanar);
            turned += solver.BeganPlanar && !solver.SolvedPlanar ? 1 : 0;
            Assert.Equal(0f, slider.Position.Z);
            Assert.Equal(0f, slider.LinearVelocity.Z);
            Assert.Equal(0f, slider.AngularVelocity.X);
            Assert.Equal(0f, slider.AngularVelocity.Y);
            largestGap = MathF.Max(largestGap, Vector3.Distance(slider.Position, generalSlider.Position));
        }

        Assert.Equal(1, turned);
        Assert.True(sphere.LinearVelocity.X > 1f && generalSphere.LinearVelocity.X > 1f, "the sphere must have been struck");
        Assert.True(slider.AngularVelocity.Z < -1f, $"the slider must roll for its friction to mean anything (ω = {slider.AngularVelocity})");
        Assert.True(largestGap < 1e-5f, $"the slider drifts {largestGap} m from the general path");
    }

    private static (World World, RigidBody Slider, RigidBody Sphere) StruckSleeper(bool sleeperAwake)
    {
        var world = new World(new Vector3(0, -9.81f, 0), new SequentialImpulseSolver(restitution: 0.2f, friction: 0.6f));
        world.AddPlane(StaticPlane.Ground());
        RigidBody sphere = world.Add(new RigidBody(1f, 0.3f, new Vector3(0.7f, 0.3f, 0.05f)) { AllowSleep = !sleeperAwake });
        RigidBody resting = world.Add(Disc(new Vector3(0, 0.3f, 0), Vector3.Zero));
        RigidBody striker = world.Add(Disc(new Vector3(-3, 0.3f, 0), Vector3.Zero));
        RigidBody slider = world.Add(Disc(new Vector3(-20, 0.3f, 0), Vector3.Zero));
        resting.AllowSleep = striker.AllowSleep = slider.AllowSleep = false;
        for (int step = 0; step < 60; step++)
        {
            world.Step(Dt); // the sphere falls asleep, unless it may not
        }

        Assert.Equal(sleeperAwake, sphere.IsAwake);
        striker.Position = new Vector3(-0.61f, 0.3f, 0); // 1 cm from the resting disc
        striker.LinearVelocity = new Vector3(20, 0, 0);
        slider.LinearVelocity = new Vector3(3, 0, 0); // slides, then rolls
        return (world, slider, sphere);
    }

    private static (World World, RigidBody[] Discs) RubbingDiscs(bool offPlaneWitness)
    {
        var world = new World(new Vector3(0, -9.81f, 0), new SequentialImpulseSolver(restitution: 0.2f, friction: 0.6f))
        {
            SleepingEnabled = false, // a sleeping witness would leave the step planar
        };
        world.AddPlane(StaticPlane.Ground());
        var discs = new[]
        {
            Disc(new Vector3(-2, 0.3f, 0), new Vector3(3, 0, 0)), // slides, then rolls (5/7 of its speed)
            Disc(new Vector3(1, 1.5f, 0), new Vector3(2, 0, 0)), // strike the next one off-centre in the air, then
            Disc(new Vector3(2, 1.8f, 0), new Vector3(-1, 0, 0)), // both land spinning and roll
        };
        foreach (RigidBody disc in discs)
        {
            world.Add(disc);
        }

        if (offPlaneWitness)
        {
            world.Add(Disc(new Vector3(0, 1000f, 10f), Vector3.Zero));
        }

        return (world, discs);
    }

    private static RigidBody Disc(Vector3 position, Vector3 velocity) =>
        new(1f, 0.3f, position, Inertia.Disc(1f, 0.3f)) { LinearVelocity = velocity };

    [Fact]
    public void A_tumbling_sphere_keeps_its_inverse_inertia_exactly()
    {
        var world = new World(Vector3.Zero);
        RigidBody sphere = world.Add(new RigidBody(2f, 0.5f, Vector3.Zero) { AngularVelocity = new Vector3(1, -2, 3) });
        Matrix3 body = sphere.Inertia.Inverse();
        for (int i = 0; i < 200; i++)
        {
            world.Step(Dt);
        }

        Assert.NotEqual(Quaternion.Identity, sphere.Orientation);
        Assert.Equal(body, sphere.InverseInertiaWorld);
    }

    [Fact]
    public void A_disc_keeps_its_inverse_inertia_while_it_turns_about_z_and_rotates_it_when_it_tumbles()
    {
        var world = new World(Vector3.Zero);
        RigidBody turning = world.Add(new RigidBody(1f, 0.5f, Vector3.Zero, Inertia.Disc(1f, 0.5f)) { AngularVelocity = new Vector3(0, 0, 4) });
        RigidBody tumbling = world.Add(new RigidBody(1f, 0.5f, new Vector3(5, 0, 0), Inertia.Disc(1f, 0.5f)) { AngularVelocity = new Vector3(4, 0, 0) });
        for (int i = 0; i < 20; i++)
        {
            world.Step(Dt);
        }

        Assert.Equal(turning.Inertia.Inverse(), turning.InverseInertiaWorld);
        Matrix3 expected = tumbling.Inertia.Inverse().RotatedBy(tumbling.Orientation);
        Assert.NotEqual(tumbling.Inertia.Inverse(), tumbling.InverseInertiaWorld);
        Assert.Equal(expected, tumbling.InverseInertiaWorld);
    }
}
