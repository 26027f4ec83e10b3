using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics;

public sealed partial class World
{
    private readonly ImpactStepper _impacts = new();
    private StepContext? _stepContext;

    /// <summary>
    /// Advances the world by <paramref name="dt"/> seconds.
    /// </summary>
    /// <remarks>
    /// The pipeline, each stage named below:
    /// <list type="number">
    /// <item>wake the sleeping islands that awake bodies touch or close on (<see cref="SleepingEnabled"/>); the
    ///   stages below see the awake bodies only;</item>
    /// <item>detect: bounding circles against each other and against the planes (§2.1), including every pair that
    ///   may touch within the step at the speeds the bodies have (see <see cref="ContactMargin"/>); the pairs of a
    ///   crowd moving together that cannot meet while both keep to its motion are left out, and become contacts again
    ///   as soon as one of the two does not (a collision, or the crowd landing, changed its velocity);</item>
    /// <item>the responder's <see cref="ICollisionResponder.BeginStep"/>;</item>
    /// <item>then <see cref="Substeps"/> times, with h = dt / substeps:
    ///   integrate velocities (gravity, forces, torques),
    ///   the responder's <see cref="ICollisionResponder.SolveVelocities"/> (resting contacts),
    ///   move with impacts (every collision answered at its time of impact by
    ///   <see cref="ICollisionResponder.Collide"/>, see below),
    ///   measure the contacts (unless the responder is the default solver, which measures its own), and the
    ///   responder's <see cref="ICollisionResponder.SolvePositions"/> (listing 2);</item>
    /// <item>the responder's <see cref="ICollisionResponder.EndStep"/>, then measure the contacts for
    ///   <see cref="Collisions"/>, report the contact events (<see cref="ContactEvents"/>) and clear the forces;</item>
    /// <item>put to sleep the islands that have rested long enough, and shrink working arrays that have long been far
    ///   larger than needed (see <see cref="TrimExcess"/>).</item>
    /// </list>
    /// <para><b>Collisions at their time of impact.</b> Within a substep each body's velocity goes uniformly from
    /// where it started to where gravity, forces and resting contacts take it, which is exact for free flight. Two
    /// bodies that meet are moved to the moment they touch, the responder answers the collision there with the
    /// velocities they have at that moment (eq. 9 bounces the speed they arrive with), and both travel the rest of
    /// the substep with their new velocities; the next impact is then found given what changed. A lone pair without
    /// gravity therefore follows its exact piecewise-linear motion, and nothing passes through anything: a pair that
    /// still approaches after the responder's answer is stopped along its normal, and a body sent further than
    /// detection looked is looked up again (details in the impact pass's documentation, ImpactStepper.cs).</para>
    /// <para>Substeps make piles stiff: a body sinks into its support by about g·h² per substep before the solver
    /// catches it, so four substeps sink sixteen times less than one step ("Small Steps in Physics Simulation",
    /// Macklin et al., SCA 2019; Box2D v3 steps the same way).</para>
    /// <para>While a step runs, the world's bodies and planes cannot be changed (see <see cref="Add"/>).</para>
    /// </remarks>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="dt"/> is not a positive, finite number; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">Called while this world is stepping (from a responder).</exception>
    public void Step(float dt)
    {
        Guard.Positive(dt, nameof(dt));
        if (_stepping)
        {
            throw new InvalidOperationException("World.Step was called while the world is stepping (from a responder or detector).");
        }

        StepContext step = _stepContext ??= new StepContext(this);
        _stepping = true;
        if (_workers is not null)
        {
            _workers.Busy = true; // see ThreadCount
        }

        try
        {
            step.Begin(dt, _substeps);
            WakeWhatAwakeBodiesReach(dt);
            DetectCollisions(dt);
            Run(step, StepStage.BeginStep);
            float h = dt / _substeps;
            for (int substep = 0; substep < _substeps; substep++)
            {
                step.EnterSubstep(substep);
                IntegrateVelocities(h);
                Run(step, StepStage.SolveVelocities);
                _impacts.Move(step, Responder, h, (_substeps - substep) * h);
                MeasureContactsFor(Responder);
                Run(step, StepStage.SolvePositions);
            }

            Run(step, StepStage.EndStep);
            MeasureContacts();
            ReportContactEvents();
            ClearForces();
            UpdateSleep(dt);
            ShrinkIdleBuffers();
            Time += dt;
        }
        finally
        {
            step.End();
            _stepping = false;
            if (_workers is not null)
            {
                _workers.Busy = false;
            }
        }
    }

    /// <summary>Impacts answered in the last step (the impact pass), for tests and diagnostics.</summary>
    internal int ImpactCount => _impacts.ImpactCount;

    /// <summary>Substeps of the last step that predicted only the contacts that can come near their limits (ImpactStepper.Quiet.cs), for tests.</summary>
    internal int QuietSubsteps => _impacts.QuietSubsteps;

    /// <summary>For tests: whether quiet substeps predict only the contacts that can come near their limits (default true).</summary>
    internal bool PredictQuietly
    {
        get => _impacts.PredictQuietly;
        set => _impacts.PredictQuietly = value;
    }

    /// <summary>For tests: whether quiet substeps check the contacts they leave out (ImpactStepper.Quiet.cs).</summary>
    internal bool CheckQuietSubsteps
    {
        get => _impacts.CheckQuietSubsteps;
        set => _impacts.CheckQuietSubsteps = value;
    }

    /// <summary>For tests: contacts left out by quiet substeps that their chords could bring near their limits (none, if sound).</summary>
    internal long UnpredictedNearLimits => _impacts.UnpredictedNearLimits;

    /// <summary>Substeps of the last step whose impacts reached the impact pass's limit.</summary>
    internal int SaturatedSubsteps => _impacts.SaturatedSubsteps;

    /// <summary>Bodies looked up again in the last step because a collision sent them further than detection looked.</summary>
    internal int ImpactSearches => _impacts.Searches;

    /// <summary>Pairs of a crowd moving together left out of the last step's contacts (ImpactStepper.Crowd.cs), for tests.</summary>
    internal int CrowdPairsLeftOut => _impacts.PairsLeftOut;

    /// <summary>Of those, the pairs made contacts again in the step because a body left the crowd's motion.</summary>
    internal int CrowdPairsRestored => _impacts.PairsRestored;

    /// <summary>For tests: whether the pairs of a crowd may be left out (default true); false keeps every pair detection reports.</summary>
    internal bool LeaveOutCrowdPairs
    {
        get => _impacts.LeaveOutCrowdPairs;
        set => _impacts.LeaveOutCrowdPairs = value;
    }

    private void Run(StepContext step, StepStage stage)
    {
        step.Enter(stage);
        switch (stage)
        {
            case StepStage.BeginStep: Responder.BeginStep(step); break;
            case StepStage.SolveVelocities: Responder.SolveVelocities(step); break;
            case StepStage.SolvePositions: Responder.SolvePositions(step); break;
            case StepStage.EndStep: Responder.EndStep(step); break;
        }

        step.Enter(StepStage.None);
    }

    /// <summary>
    /// Finds the contacts of the step: every pair and every body–plane pair that may touch within dt. Each body is
    /// given the sphere around the middle of its straight path over the step, x + v dt / 2, of its radius plus half
    /// its path's length |v| dt / 2 plus half the margin, which holds the ½ |g| dt² that gravity bends the path by (so
    /// a ball at rest with a long step is still caught by the ground); see ContactGeometry.TryCollide.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // inlined into Step, it left the JIT no budget to inline the vector maths
    private void DetectCollisions(float dt)
    {
        Collisions.Clear();
        float margin = _contactMargin + Gravity.Length() * dt * dt;
        Detector.FindContacts(BodySpan, Collisions, margin, dt);
        ReadOnlySpan<StaticPlane> planes = Planes;
        foreach (RigidBody body in BodySpan)
        {
            if (!body.IsDynamic)
            {
                continue;
            }

            for (int p = 0; p < planes.Length; p++)
            {
                if (ContactGeometry.Unchecked.TryCollide(body, planes[p], p, Ground, margin, dt, out Contact contact))
                {
                    Collisions.Add(contact);
                }
            }
        }

        _impacts.BeginStep(BodySpan, Collisions, Gravity, margin, dt);
    }

    /// <summary>Velocity half of semi-implicit Euler: v += (g + F/m) h, ω += I_w⁻¹ τ h.</summary>
    /// <remarks>
    /// The gyroscopic term ω × (I ω) is left out, as in most game engines; it is zero for spheres and discs,
    /// the shapes this library collides. The impact pass is given each body's velocity before and after: within the
    /// substep the body moves from one to the other at a uniform rate, exactly as free flight under gravity does.
    /// </remarks>
    private void IntegrateVelocities(float h)
    {
        ReadOnlySpan<RigidBody> bodies = BodySpan;
        Span<Vector3> before = _impacts.StartVelocities, after = _impacts.ForcedVelocities;
        for (int i = 0; i < bodies.Length; i++)
        {
            RigidBody body = bodies[i];
            before[i] = body.linearVelocity;
            if (body.IsDynamic)
            {
                body.linearVelocity += (Gravity + body.force * body.inverseMass) * h;
                if (body.torque != Vector3.Zero)
                {
                    body.angularVelocity += body.inverseInertiaWorld.Transform(body.torque) * h;
                }
            }

            after[i] = body.linearVelocity;
        }
    }

    /// <summary>
    /// Measures the contacts at the bodies' new positions for the responder's position stage; the default solver
    /// measures them itself from its own copies of the positions, so they are not measured for it.
    /// </summary>
    private void MeasureContactsFor(ICollisionResponder responder)
    {
        if (responder is not SequentialImpulseSolver)
        {
            MeasureContacts();
        }
    }

    private void MeasureContacts()
    {
        foreach (ref Contact contact in Collisions.Contacts)
        {
            ContactGeometry.Unchecked.Refresh(ref contact);
        }
    }

    private void ClearForces()
    {
        foreach (RigidBody body in BodySpan)
        {
            body.ClearAccumulators();
        }
    }
}
