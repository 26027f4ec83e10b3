using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Behavior;

/// <summary>
/// A 2-D game keeps z = 0: over many steps of planar scenes with off-centre collisions and friction, every z
/// component of position and velocity stays exactly 0.0f, angular velocity stays along z, and the orientation
/// stays a rotation about z (quaternion X = Y = 0 exactly).
/// </summary>
public class PlanarMotionTests
{
    public static TheoryData<string> Responders => new() { "impulse", "inelastic", "projection", "sequential" };

    private static ICollisionResponder Make(string name) => name switch
    {
        "impulse" => new ImpulseCollisionResponder(0.7f, 0.6f),
        "inelastic" => new PerfectlyInelasticResponder(),
        "projection" => new ProjectionResponder(),
        _ => new SequentialImpulseSolver(0.7f, 0.6f),
    };

    [Theory]
    [MemberData(nameof(Responders))]
    public void Off_centre_collision_stays_exactly_planar(string responder)
    {
        World world = Scenes.OffCentreCollision(restitution: 0.7f, friction: 0.6f, Make(responder));
        bool spun = false;
        for (int i = 0; i < 600; i++)
        {
            world.Step(1f / 60f);
            AssertPlanar(world, i);
            foreach (RigidBody body in world.Bodies)
            {
                spun |= body.AngularVelocity.Z != 0;
            }
        }

        if (responder is "impulse" or "sequential")
        {
            Assert.True(spun, "the off-centre collision with friction set the discs spinning");
        }
    }

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    public void Planar_ball_pit_stays_exactly_planar(int seed)
    {
        World world = Scenes.BallPit(60, planar: true, seed);
        for (int i = 0; i < 300; i++)
        {
            world.Step(1f / 60f);
            AssertPlanar(world, i);
        }
    }

    /// <summary>
    /// A planar pit stepped the general 3-D way: one more ball, 10 m off the plane, rests on the floor beside the pile
    /// and makes every step non-planar. The discs' contact normals lie in the plane, and the tangents the general path
    /// builds for them must lie in it too (t2 = ∓z exactly), or rounding in the friction pushes them out of it.
    /// </summary>
    [Fact]
    public void Planar_ball_pit_stays_exactly_planar_on_the_general_path()
    {
        World world = Scenes.BallPit(60, planar: true, seed: 1);
        world.SleepingEnabled = false; // the witness asleep would make the steps planar again
        RigidBody witness = world.Add(new RigidBody(1f, 0.1f, new Vector3(0.5f, 0.5f, 10f)));
        var solver = (SequentialImpulseSolver)world.Responder;
        for (int i = 0; i < 300; i++)
        {
            world.Step(1f / 60f);
            Assert.False(solver.SolvedPlanar);
            AssertPlanar(world, i, except: witness);
        }
    }

    private static void AssertPlanar(World world, int step, RigidBody? except = null)
    {
        foreach (RigidBody b in world.Bodies)
        {
            if (b == except)
            {
                continue;
            }

            if (b.Position.Z != 0f || b.LinearVelocity.Z != 0f || b.AngularVelocity.X != 0f || b.AngularVelocity.Y != 0f
                || b.Orientation.X != 0f || b.Orientation.Y != 0f)
            {
                Assert.Fail($"step {step}: {b} left the plane: x={b.Position} v={b.LinearVelocity} ω={b.AngularVelocity} q={b.Orientation}");
            }
        }
    }
}
