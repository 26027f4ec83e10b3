using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics;

/// <summary>The stages of a step, in the order <see cref="World.Step"/> runs them (see <see cref="ICollisionResponder"/>).</summary>
public enum StepStage
{
    /// <summary>No step is in progress.</summary>
    None,

    /// <summary><see cref="ICollisionResponder.BeginStep"/>: contacts found, nothing moved yet.</summary>
    BeginStep,

    /// <summary><see cref="ICollisionResponder.SolveVelocities"/>: a substep's resting contacts.</summary>
    SolveVelocities,

    /// <summary><see cref="ICollisionResponder.Collide"/>: a collision at its time of impact.</summary>
    Collide,

    /// <summary><see cref="ICollisionResponder.SolvePositions"/>: a substep's penetration.</summary>
    SolvePositions,

    /// <summary><see cref="ICollisionResponder.EndStep"/>: after the last substep.</summary>
    EndStep,
}

/// <summary>
/// Everything a responder may know about the step in progress: the world's bodies and planes, gravity, the time
/// step and its substeps, the contacts, and which stage is running. Only <see cref="World"/> creates and advances
/// it; one instance per world is reused for every step, so stepping allocates nothing.
/// </summary>
public sealed class StepContext
{
    internal StepContext(World world) => World = world;

    /// <summary>The world being stepped.</summary>
    public World World { get; }

    /// <summary>
    /// The world's awake bodies: all of them, in the world's order, while none sleeps (see
    /// <see cref="World.SleepingEnabled"/>); sleeping bodies take no part in a step. The list may grow during a step,
    /// never shrink: a body that a collision sends into a sleeping island wakes it within the step, and its bodies
    /// join at the end of the list, at rest. Read it again in each stage rather than keep its length from
    /// <see cref="ICollisionResponder.BeginStep"/>.
    /// </summary>
    public ReadOnlySpan<RigidBody> Bodies => World.BodySpan;

    /// <summary>The world's static planes; <see cref="Contact.PlaneIndex"/> indexes them.</summary>
    public ReadOnlySpan<StaticPlane> Planes => World.Planes;

    /// <summary>Gravitational acceleration (m/s²).</summary>
    public Vector3 Gravity => World.Gravity;

    /// <summary>The contacts of this step, found at its start (and any found during it, appended at the end).</summary>
    public CollisionData Contacts => World.Collisions;

    /// <summary>The whole step's length dt (s).</summary>
    public float TimeStep { get; private set; }

    /// <summary>How many substeps the step takes.</summary>
    public int Substeps { get; private set; }

    /// <summary>The length h = dt / substeps of one substep (s).</summary>
    public float SubstepLength => TimeStep / Substeps;

    /// <summary>The substep being run, 0 to <see cref="Substeps"/> − 1.</summary>
    public int Substep { get; private set; }

    /// <summary>Whether this is the first substep of the step.</summary>
    public bool IsFirstSubstep => Substep == 0;

    /// <summary>Whether this is the last substep of the step.</summary>
    public bool IsLastSubstep => Substep == Substeps - 1;

    /// <summary>The stage being run; <see cref="StepStage.None"/> between steps.</summary>
    public StepStage Stage { get; private set; }

    /// <summary>Counts the world's steps: 1 during its first step. A responder can tell a new step from an old one by it.</summary>
    public long StepNumber { get; private set; }

    /// <summary>
    /// Throws unless <paramref name="stage"/> is the stage being run: a responder calls it first in each stage, so
    /// that a stage called on its own, out of order or with another step's context fails clearly instead of
    /// running on stale state.
    /// </summary>
    /// <exception cref="InvalidOperationException">The context is in another stage (or between steps).</exception>
    public void Expect(StepStage stage)
    {
        if (Stage != stage)
        {
            throw new InvalidOperationException(Stage == StepStage.None
                ? $"{stage} was called outside World.Step; only World.Step runs the stages of a responder, in order."
                : $"{stage} was called during {Stage}; World.Step runs the stages in order: BeginStep, then per substep SolveVelocities, Collide (per collision), SolvePositions, then EndStep.");
        }
    }

    /// <summary>
    /// Whether the impact pass has pushed a contact in this step (an impact answered, or a jam settled): until then no
    /// contact's <see cref="Contact.NormalImpulse"/> has changed since detection, and the solver's measure need not read
    /// it (SequentialImpulseSolver.MeasureRange).
    /// </summary>
    internal bool ContactsPushed { get; set; }

    internal void Begin(float dt, int substeps)
    {
        TimeStep = dt;
        Substeps = substeps;
        Substep = 0;
        StepNumber++;
        ContactsPushed = false;
    }

    internal void Enter(StepStage stage) => Stage = stage;

    internal void EnterSubstep(int substep) => Substep = substep;

    internal void End()
    {
        Stage = StepStage.None;
        Substep = 0;
    }
}
