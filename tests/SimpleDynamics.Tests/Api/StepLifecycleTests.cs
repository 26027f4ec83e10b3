using System;
using System.Collections.Generic;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Api;

/// <summary>
/// The responder's stages run only inside <see cref="World.Step"/>, in order, with the world's own context; a solver
/// shared by two worlds keeps each world's state; a responder written with public types only can do what the
/// default one does.
/// </summary>
public class StepLifecycleTests
{
    /// <summary>Records the stages it is called in, using only public types.</summary>
    private sealed class RecordingResponder : ICollisionResponder
    {
        public List<string> Calls { get; } = new();

        public StepContext? Context { get; private set; }

        public void BeginStep(StepContext step)
        {
            step.Expect(StepStage.BeginStep);
            Context = step;
            Calls.Add($"begin {step.StepNumber} dt={step.TimeStep} substeps={step.Substeps} contacts={step.Contacts.Count}");
        }

        public void SolveVelocities(StepContext step)
        {
            step.Expect(StepStage.SolveVelocities);
            Calls.Add($"velocities {step.Substep}");
        }

        public void Collide(StepContext step, ref Contact contact)
        {
            step.Expect(StepStage.Collide);
            Calls.Add($"collide {step.Substep}");
            // eq. 16 with ε = 1 for two free spheres: J = −2 v_n / (1/m_A + 1/m_B), along the normal.
            float j = -2 * contact.ApproachVelocity / (contact.BodyA.InverseMass + contact.BodyB.InverseMass);
            contact.BodyA.ApplyImpulse(j * contact.Normal, contact.Point);
            contact.BodyB.ApplyImpulse(-j * contact.Normal, contact.Point);
        }

        public void SolvePositions(StepContext step)
        {
            step.Expect(StepStage.SolvePositions);
            Calls.Add($"positions {step.Substep}");
        }

        public void EndStep(StepContext step)
        {
            step.Expect(StepStage.EndStep);
            Calls.Add("end");
        }
    }

    [Fact]
    public void World_step_calls_the_stages_in_order_with_one_context()
    {
        var responder = new RecordingResponder();
        var world = new World(Vector3.Zero, responder) { Substeps = 2 };
        var a = world.Add(new RigidBody(1f, 0.5f, new Vector3(-0.6f, 0, 0)) { LinearVelocity = new Vector3(30, 0, 0) });
        var b = world.Add(new RigidBody(1f, 0.5f, new Vector3(0.6f, 0, 0)) { LinearVelocity = new Vector3(-30, 0, 0) });
        world.Step(1f / 60f);
        Assert.Equal(new[]
        {
            "begin 1 dt=0.016666668 substeps=2 contacts=1", "velocities 0", "collide 0", "positions 0",
            "velocities 1", "positions 1", "end",
        }, responder.Calls);

        // The student's elastic collision, at the time of impact: the balls swapped velocities and never overlapped.
        Assert.Equal(-30f, a.LinearVelocity.X, 1e-4f);
        Assert.Equal(30f, b.LinearVelocity.X, 1e-4f);
        Assert.True(Vector3.Distance(a.Position, b.Position) >= 1f - 1e-5f);
        Assert.Equal(StepStage.None, responder.Context!.Stage);
    }

    [Fact]
    public void A_stage_called_on_its_own_or_out_of_order_throws_a_clear_exception()
    {
        var solver = new SequentialImpulseSolver();
        World world = Scenes.BallPit(50, planar: true, responder: solver);
        var recorder = new RecordingResponder();
        var other = new World(Vector3.Zero, recorder);
        other.Step(1f / 60f);
        StepContext context = recorder.Context!;

        var error = Assert.Throws<InvalidOperationException>(() => solver.SolveVelocities(context));
        Assert.Contains("outside World.Step", error.Message);
        Assert.Throws<InvalidOperationException>(() => solver.SolvePositions(context));
        Assert.Throws<InvalidOperationException>(() => solver.EndStep(context));
        Assert.Throws<InvalidOperationException>(() => solver.BeginStep(context));
        Assert.Throws<ArgumentNullException>(() => solver.BeginStep(null!));

        // The world it belongs to still steps normally afterwards.
        world.Step(1f / 60f);
    }

    [Fact]
    public void A_stage_of_the_solver_run_with_another_steps_context_throws()
    {
        var solver = new SequentialImpulseSolver();
        World first = Scenes.BallPit(20, planar: true, responder: solver);
        var spy = new SpyResponder(solver);
        var second = new World(Scenes.EarthGravity, spy);
        second.Add(new RigidBody(1f, 0.1f, new Vector3(0, 1, 0)));
        second.AddPlane(StaticPlane.Ground());
        first.Step(1f / 60f);
        var error = Assert.Throws<InvalidOperationException>(() => second.Step(1f / 60f));
        Assert.Contains("BeginStep", error.Message);
    }

    /// <summary>Forwards every stage but BeginStep to a solver, as a buggy wrapper would.</summary>
    private sealed class SpyResponder : ICollisionResponder
    {
        private readonly SequentialImpulseSolver _inner;

        public SpyResponder(SequentialImpulseSolver inner) => _inner = inner;

        public void BeginStep(StepContext step)
        {
        }

        public void SolveVelocities(StepContext step) => _inner.SolveVelocities(step);

        public void Collide(StepContext step, ref Contact contact) => _inner.Collide(step, ref contact);

        public void SolvePositions(StepContext step) => _inner.SolvePositions(step);

        public void EndStep(StepContext step) => _inner.EndStep(step);
    }

    [Fact]
    public void One_solver_shared_by_two_worlds_keeps_each_worlds_warm_start()
    {
        var solver = new SequentialImpulseSolver();
        World first = Scenes.BallPit(300, planar: true, seed: 2, responder: solver);
        World second = Scenes.BallPit(300, planar: true, seed: 3, responder: solver);
        float worst = 0;
        for (int i = 0; i < 600; i++)
        {
            first.Step(1f / 60f);
            second.Step(1f / 60f);
            if (i >= 500)
            {
                worst = MathF.Max(worst, MathF.Max(first.Diagnostics.MaxPenetration, second.Diagnostics.MaxPenetration));
            }
        }

        Assert.True(worst <= 1.5f * solver.Slop, $"piles sharing a solver penetrate {worst} m (slop {solver.Slop} m)");
    }

    [Fact]
    public void A_responder_cannot_change_the_world_while_it_steps()
    {
        var world = new World(Vector3.Zero, new MutatingResponder());
        world.Add(new RigidBody(1f, 0.5f, Vector3.Zero));
        world.Add(new RigidBody(1f, 0.5f, new Vector3(0.9f, 0, 0)));
        var error = Assert.Throws<InvalidOperationException>(() => world.Step(1f / 60f));
        Assert.Equal(2, world.Bodies.Count);
        world.Responder = new SequentialImpulseSolver();
        world.Step(1f / 60f); // the world is usable again: the failed step left no stepping flag behind
    }

    private sealed class MutatingResponder : PairwiseResponder
    {
        public override void ResolvePosition(ref Contact contact) => contact.BodyA.World!.Remove(contact.BodyA);
    }
}
