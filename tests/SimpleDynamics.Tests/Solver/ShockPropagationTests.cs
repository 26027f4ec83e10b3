using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The default solver's velocity stage in a deep pile: what it leaves for the impact pass. A resting contact that
/// still approaches faster than the pile may creep (the impact pass's held-depth tolerance per substep) becomes an
/// impact, a pairwise push that knows nothing of the rest of the pile; a few hundred of them a step keep a deep pile
/// restless.
/// </summary>
public class ShockPropagationTests
{
    private const float Dt = 1f / 60f;
    private readonly ITestOutputHelper _output;

    public ShockPropagationTests(ITestOutputHelper output) => _output = output;

    /// <summary>
    /// A 2,000-disc pit (45 discs deep) settling, 6 to 8 s after its pour began: after every velocity stage, the
    /// touching contacts that approach faster than the creep tolerance. The shock pass slows an upper disc along its
    /// tilted contact normal, which turns it into neighbours the pass leaves alone; the sweep after the pass stops
    /// those approaches. Measured without that sweep: up to 7 such contacts after one velocity stage (22 in the 480
    /// substeps), which the impact pass answered one pair at a time; with it, none.
    /// </summary>
    [Fact]
    public void A_settling_deep_pit_leaves_almost_no_contact_approaching_after_the_velocity_stage()
    {
        var watcher = new ApproachWatcher(new SequentialImpulseSolver());
        World world = Scenes.BallPit(2000, planar: true, responder: watcher);
        world.SleepingEnabled = false;
        for (int i = 0; i < 480; i++)
        {
            watcher.Watching = i >= 360; // once the pile has formed

            world.Step(Dt);
        }

        _output.WriteLine($"from 6 to 8 s: at most {watcher.Worst} contacts approaching after a velocity stage, {watcher.Total} in all");
        Assert.True(watcher.Worst <= 2, $"{watcher.Worst} contacts approached after one velocity stage ({watcher.Total} in 480 substeps)");
    }

    /// <summary>Runs the default solver and counts the contacts its velocity stage leaves approaching too fast.</summary>
    private sealed class ApproachWatcher : ICollisionResponder
    {
        private readonly SequentialImpulseSolver _solver;

        public ApproachWatcher(SequentialImpulseSolver solver) => _solver = solver;

        public bool Watching { get; set; }

        public int Worst { get; private set; }

        public int Total { get; private set; }

        public void BeginStep(StepContext step) => _solver.BeginStep(step);

        public void SolveVelocities(StepContext step)
        {
            _solver.SolveVelocities(step);
            if (!Watching)
            {
                return;
            }

            int approaching = 0;
            foreach (ref Contact contact in step.Contacts.Contacts)
            {
                if (contact.Penetration < 0)
                {
                    continue;
                }

                float smaller = contact.IsPlaneContact ? contact.BodyA.Radius : MathF.Min(contact.BodyA.Radius, contact.BodyB.Radius);
                float approach = -Vector3.Dot(contact.BodyA.LinearVelocity - contact.BodyB.LinearVelocity, contact.Normal);
                if (approach * step.SubstepLength > ImpactStepper.HeldDepthTolerance * smaller)
                {
                    approaching++;
                }
            }

            Worst = Math.Max(Worst, approaching);
            Total += approaching;
        }

        public void Collide(StepContext step, ref Contact contact) => _solver.Collide(step, ref contact);

        public void SolvePositions(StepContext step) => _solver.SolvePositions(step);

        public void EndStep(StepContext step) => _solver.EndStep(step);
    }
}
