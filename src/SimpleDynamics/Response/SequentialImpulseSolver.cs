using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// The engine's responder: resting contacts solved together by sequential impulses with accumulated-impulse clamping
/// and warm starting (E. Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005; "Fast and Simple Physics
/// using Sequential Impulses", GDC 2006), built on the tutorial's eq. 13–16, and each collision answered at its time
/// of impact like the tutorial's impulse responder.
/// </summary>
/// <remarks>
/// <para><b>Collisions</b> (<see cref="Collide"/>): the world brings the two bodies to the moment they touch; the
/// solver gives the impulse of eq. 16 that turns their relative normal velocity v_n into −ε v_n (eq. 9), then Coulomb
/// friction, exactly as <see cref="ImpulseCollisionResponder"/>. Below <see cref="RestitutionThreshold"/> a collision
/// does not bounce (ε = 0), so a dropped ball with ε &lt; 1 comes to rest instead of bouncing forever. For ε = 1 a
/// collision keeps kinetic energy exactly, for ε &lt; 1 it loses ½ (1 − ε²) m_eff v_n².</para>
/// <para><b>Resting contacts</b> (<see cref="SolveVelocities"/>): the contacts that touch and approach no faster than
/// the threshold after gravity (a pile, a ball rolling on the ground). Each iteration visits every such contact and
/// applies the impulse that would stop its approach given what the other contacts did so far (Gauss–Seidel). Per
/// contact the <i>accumulated</i> normal impulse is clamped to ≥ 0 (a contact pushes, never pulls) and the accumulated
/// friction impulse to the disc of radius μ × normal impulse (Coulomb). Warm starting applies last step's accumulated
/// impulses first (and, within a step, the previous substep's), so a resting pile starts almost solved.
/// <see cref="VelocityIterations"/> sweeps are done, then up to <see cref="ExtraIterations"/> more until the
/// impulses stop changing; a pile that the warm start has already solved stops after the first. Under gravity, while
/// only a few bodies still change, the extra sweeps visit only their contacts (the rest are solved already: see
/// SequentialImpulseSolver.LocalSweeps.cs), and so do the fixed sweeps after a first one that left a 3-D pile nearly
/// solved. The contacts' normals
/// and lever arms are measured again every substep, so the equal and opposite impulses act along the current line of
/// contact and conserve angular momentum.</para>
/// <para><b>Shock propagation</b> (Guendelman, Bridson and Fedkiw, "Nonconvex Rigid Bodies with Stacking",
/// SIGGRAPH 2003, https://physbam.stanford.edu/~fedkiw/papers/stanford2003-01.pdf). Under gravity, after the sweeps,
/// one more bottom-up pass over the resting contacts that carry weight treats the lower body of each as immovable
/// and stops any sinking the sweeps left by slowing the upper body alone (never throwing it up), in velocity, and
/// after the position sweeps removes their depth beyond the slop by lifting the upper body alone.
/// A few sweeps cannot carry the weight of a heavy body down through a light one (mass ratios of 1e3 converge
/// slowly); this pass makes such stacks hold, at the price of momentum that gravity and the ground do not conserve
/// anyway. Without gravity there is no up and down, and the pass is skipped.</para>
/// <para><b>Memory order.</b> Contacts are put in the order they are solved, bottom-up along gravity, and the bodies'
/// working copies in the same order, so that a sweep walks memory front to back and carries support up a pile.</para>
/// <para><b>Four at once.</b> Once a planar substep's first sweep has found the contacts unsolved, its sweeps solve
/// runs of four consecutive contacts that move eight different bodies in the lanes of one vector: the same order and
/// the same arithmetic, so the same result bit for bit (SequentialImpulseSolver.Fours.cs).</para>
/// <para><b>Strips</b> (<see cref="Strips"/>, off by default). A pile of at least 8,192 contacts may be cut into vertical
/// strips that share no moving body; its contacts are then solved strip after strip, each bottom-up, and the contacts
/// between strips last, so that <see cref="World.ThreadCount"/> threads can sweep the strips at once with exactly the
/// result of one (SweepStrips.cs).</para>
/// <para><b>Position pass</b> (<see cref="SolvePositions"/>): penetration deeper than <see cref="Slop"/> is removed by
/// the projection of listing 2, split by inverse mass, over <see cref="PositionIterations"/> Gauss–Seidel sweeps
/// (Box2D's non-linear Gauss–Seidel), each moving a contact by at most <see cref="MaxCorrection"/>. It moves positions
/// only: unlike a Baumgarte velocity bias it cannot turn into kinetic energy. For circles the normal passes through
/// both centres, so r × n = 0 and no rotation is needed.</para>
/// <para><b>State and ownership.</b> The solver keeps last step's impulses per world, so one solver may serve several
/// worlds stepped one after the other, each with its own warm start. Its stages check that they run in the order
/// <see cref="World.Step"/> calls them, within one step: see <see cref="ICollisionResponder"/>.</para>
/// </remarks>
public sealed partial class SequentialImpulseSolver : ICollisionResponder
{
    private readonly ConditionalWeakTable<World, ContactCache> _caches = new();
    private ContactCache _cache = new();
    private float _warmStartScale = 1f; // this step's substep length over the one the cached impulses were stored for
    private StepContext? _step;
    private long _stepNumber;

    /// <summary>
    /// The depth, in bodies, up to which a pile's extra sweeps are <see cref="ExtraIterations"/>; a pile k times as
    /// deep may spend k² times as many. The weight of a pile reaches its floor through every layer, and Gauss–Seidel
    /// sweeps carry it down only a few layers each, so a deep pile that is given a fixed budget never converges; and
    /// as a chain's, the sweeps a pile needs grow with the square of its depth, not the depth.
    /// Measured on the 8,000-disc 2-D pit (about 76 diameters deep), 15–18 s after its pour began: with 8 extra sweeps
    /// it still moved, its position pass lifting back by 8–10 J a second what sank through unconverged contacts; with
    /// 19 it still crept (1–1.5 J a second), with 16 nearly not (0.03–0.2 J a second, falling); with 38 it lay still.
    /// On the 16,000-disc pit (126 deep), the budget grown with the depth alone (63) never let it rest: every step
    /// spent all of it, and 9–18 s after the pour began it stirred ever more (root-mean-square speed 4e-3 rising to
    /// 6.5e-2 m/s, 26 rising to 170 impacts a step, deepest overlap up to 3.5 mm); with 109 it came to rest at about
    /// 8 s but stirred again now and then; with 218 it lay still from 9 s (6e-6 m/s, 0.50 mm, 23–28 sweeps a step).
    /// 8 × (126 / 24)² is 221. A settled pile converges within the fixed sweeps and spends none of them. The depth is
    /// that of the bodies at rest (both bodies of a contact slower than g dt), not of a crowd still falling onto them.
    /// </summary>
    public const float DeepPileLayers = 24f;

    private int _velocityIterations = 4;
    private int _extraIterations = 8;
    private float _convergenceTolerance = 1e-3f;
    private int _positionIterations = 2;
    private float _restitution;
    private float _friction;
    private float _restitutionThreshold = 0.5f;
    private float _slop = 0.0005f;
    private float _correctionFactor = 0.4f;
    private float _maxCorrection = 0.2f;
    private MaterialMixing _mixing = MaterialMixing.Default;

    /// <summary>Creates a solver with default restitution ε and friction μ for surfaces that set none.</summary>
    public SequentialImpulseSolver(float restitution = 0.5f, float friction = 0.3f)
    {
        Guard.UnitInterval(restitution, nameof(restitution));
        Guard.NonNegative(friction, nameof(friction));
        Restitution = restitution;
        Friction = friction;
    }

    /// <summary>
    /// The most vertical strips a pile of at least 8,192 contacts is cut into, so that <see cref="World.ThreadCount"/>
    /// threads can share its velocity sweeps: 1 (default: never cut), 2, 4 or 8, one strip per 4,096 contacts at most.
    /// The strips are swept one after another, each bottom-up, then the contacts between them; the result is the same,
    /// bit for bit, on any number of threads, but it is not the result without strips: support crosses a cut a sweep
    /// late, and a deep pile needs more sweeps to settle (SweepStrips.cs). Set it to the thread count for a world that
    /// steps on several threads; with 1 the world's threads have nothing to share. With more strips than threads, a
    /// thread that is done with its own takes over those another has not begun, but every cut costs sweeps.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is not 1, 2, 4 or 8; nothing changes.</exception>
    public int Strips
    {
        get => _strips.Most;
        set
        {
            if (value is not (1 or 2 or 4 or 8))
            {
                throw new ArgumentOutOfRangeException(nameof(Strips), value, $"{nameof(Strips)} must be 1, 2, 4 or 8.");
            }

            _strips.Most = value;
        }
    }

    /// <summary>
    /// Velocity iterations (Gauss–Seidel sweeps) per substep (≥ 1, default 4), done unless the first finds the contacts
    /// already solved: a sweep that changes no contact by more than a quarter of the <see cref="ConvergenceTolerance"/>
    /// ends the substep's sweeps (a pile at rest, warm-started, then spends one sweep a substep). Under gravity in 3-D,
    /// a first sweep within half of it is followed by sweeps over the contacts of the bodies it changed only.
    /// More iterations: stiffer piles, more time.
    /// </summary>
    public int VelocityIterations
    {
        get => _velocityIterations;
        set
        {
            Guard.AtLeast(value, 1, nameof(VelocityIterations));
            _velocityIterations = value;
        }
    }

    /// <summary>
    /// Further sweeps per substep (≥ 0, default 8), done only while the last sweep has not converged (see
    /// <see cref="ConvergenceTolerance"/>). A pile at rest converges in one or two of them and then lies still;
    /// a pile being hit spends them where it needs them: under gravity, while few bodies still change, a sweep
    /// visits only the contacts of those (so in a deep pile that a few contacts keep stirring it costs a few percent
    /// of a full sweep). Under gravity this is the budget of a pile up to
    /// <see cref="DeepPileLayers"/> bodies deep; a deeper one may spend more, with the square of its depth (0 stays 0).
    /// </summary>
    public int ExtraIterations
    {
        get => _extraIterations;
        set
        {
            Guard.AtLeast(value, 0, nameof(ExtraIterations));
            _extraIterations = value;
        }
    }

    /// <summary>
    /// A sweep has converged when, under gravity, no contact's normal velocity changed by more than this fraction of
    /// g h, the speed gravity adds in a substep of length h; without gravity, when no normal impulse changed by more
    /// than this fraction of the largest normal impulse (≥ 0, default 1e-3; 0 spends every extra iteration).
    /// Under gravity the sweeps after a substep's first converge within half of it, and the first finds the pile
    /// already solved within a quarter of it; in a pile more than 56 bodies deep both allowances are smaller, the
    /// first's in proportion to the depth and the others' with its cube: in a pile the contacts' leftover approach
    /// adds up from the floor to the top, and a deep pile held only to the tolerance itself kept creeping and never
    /// came to rest.
    /// </summary>
    public float ConvergenceTolerance
    {
        get => _convergenceTolerance;
        set
        {
            Guard.NonNegative(value, nameof(ConvergenceTolerance));
            _convergenceTolerance = value;
        }
    }

    /// <summary>Position-correction sweeps per substep (≥ 0, default 2; 0 turns the correction off).</summary>
    public int PositionIterations
    {
        get => _positionIterations;
        set
        {
            Guard.AtLeast(value, 0, nameof(PositionIterations));
            _positionIterations = value;
        }
    }

    /// <summary>Whether last step's impulses seed this step's (default on).</summary>
    public bool WarmStarting { get; set; } = true;

    /// <summary>Default coefficient of restitution ε ∈ [0, 1].</summary>
    public float Restitution
    {
        get => _restitution;
        set
        {
            Guard.UnitInterval(value, nameof(Restitution));
            _restitution = value;
        }
    }

    /// <summary>Default Coulomb friction coefficient μ ≥ 0.</summary>
    public float Friction
    {
        get => _friction;
        set
        {
            Guard.NonNegative(value, nameof(Friction));
            _friction = value;
        }
    }

    /// <summary>Approach speed (m/s, ≥ 0) below which a contact does not bounce. Default 0.5 m/s.</summary>
    public float RestitutionThreshold
    {
        get => _restitutionThreshold;
        set
        {
            Guard.NonNegative(value, nameof(RestitutionThreshold));
            _restitutionThreshold = value;
        }
    }

    /// <summary>Penetration (m, ≥ 0) left uncorrected, so resting contacts stay in touch. Default 0.5 mm.</summary>
    public float Slop
    {
        get => _slop;
        set
        {
            Guard.NonNegative(value, nameof(Slop));
            _slop = value;
        }
    }

    /// <summary>Fraction (0, 1] of the excess penetration removed per position sweep. Default 0.4.</summary>
    public float CorrectionFactor
    {
        get => _correctionFactor;
        set
        {
            Guard.Positive(value, nameof(CorrectionFactor));
            Guard.UnitInterval(value, nameof(CorrectionFactor));
            _correctionFactor = value;
        }
    }

    /// <summary>Largest correction (m, &gt; 0) of one contact in one sweep. Default 0.2 m.</summary>
    public float MaxCorrection
    {
        get => _maxCorrection;
        set
        {
            Guard.Positive(value, nameof(MaxCorrection));
            _maxCorrection = value;
        }
    }

    /// <summary>How per-body ε and μ combine.</summary>
    public MaterialMixing Mixing
    {
        get => _mixing;
        set
        {
            Guard.NotNull(value, nameof(Mixing));
            _mixing = value;
        }
    }

    /// <summary>Forgets the stored impulses of every world (e.g. after teleporting bodies).</summary>
    public void ResetWarmStart()
    {
        // Emptied in place, not dropped: a world that steps on keeps its buffers and allocates nothing.
        foreach (var entry in _caches)
        {
            entry.Value.Clear();
        }

        _cache.Clear();
    }

    /// <inheritdoc />
    /// <remarks>
    /// Orders the bodies and contacts bottom-up along gravity (the contacts of <see cref="StepContext.Contacts"/> are
    /// put in that order), combines each contact's ε and μ (<see cref="Mixing"/>; a rule that returns values out of
    /// range throws here, before anything has moved) and looks up last step's impulses for the warm start.
    /// </remarks>
    public void BeginStep(StepContext step)
    {
        Guard.NotNull(step, nameof(step));
        step.Expect(StepStage.BeginStep);
        _step = step;
        _stepNumber = step.StepNumber;
        _threads = step.World.Workers;
        _cache = _caches.GetOrCreateValue(step.World);
        _warmStartScale = _cache.SubstepLength > 0 ? step.SubstepLength / _cache.SubstepLength : 1f;
        Span<Contact> contacts = step.Contacts.Contacts;
        _strips.Cut(step.Bodies, contacts, step.Gravity);
        GatherBodies(step.Bodies, step.Gravity);
        OrderAlongGravity(contacts, step.Gravity);
        ArrangeContacts(contacts);
        _prepared = 0;
        _detectedPushed = false;
        SweepsThisStep = 0;
        LocalSweepsThisStep = 0;
        SubstepsFinishedLocallyThisStep = 0;
        LayerCorrectionsThisStep = 0;
        LocalSolvesThisStep = 0;
        PositionVisitsThisStep = 0;
        ResidualVisitsThisStep = 0;
        PositionSweepsInStripsThisStep = 0;
        PlannedInFoursThisStep = 0;
        _positionListsCount = -1; // the contacts are new: list them again (SequentialImpulseSolver.Positions.cs)
        PrepareConstraints(contacts);
    }

    /// <inheritdoc />
    public void SolveVelocities(StepContext step)
    {
        CheckStage(step, StepStage.SolveVelocities);
        Span<Contact> contacts = step.Contacts.Contacts;
        AdmitWokenBodies(step.Bodies); // any the impact pass woke during the last substep
        PrepareConstraints(contacts); // any the impact pass added during the last substep
        GatherState(step.Bodies);
        MeasureConstraints(contacts);
        WarmStart();
        Sweeps();
        if (step.Gravity != Vector3.Zero && PropagateShock())
        {
            SweepUnmeasured(); // the contacts the shock pass turned into approaches (see PropagateShock)
        }

        AddToStepTotals();
        ScatterVelocities(step.Bodies);
    }

    /// <inheritdoc />
    /// <remarks>
    /// The impulse of eq. 16 with the bounce of eq. 9 (ε from <see cref="Mixing"/>, or 0 when the bodies meet slower
    /// than <see cref="RestitutionThreshold"/>), then Coulomb friction: the tutorial's impulse method, shared with
    /// <see cref="ImpulseCollisionResponder"/> through one implementation.
    /// </remarks>
    public void Collide(StepContext step, ref Contact contact)
    {
        CheckStage(step, StepStage.Collide);
        Guard.ContactBodies(contact, nameof(contact));
        var a = VelocityState.Of(contact.BodyA);
        var b = VelocityState.Of(contact.BodyB);
        Vector3 n = contact.Normal;
        Vector3 rA = contact.Point - contact.BodyA.position; // eq. 16: r_1 = p − c_1
        Vector3 rB = contact.Point - contact.BodyB.position; //          r_2 = p − c_2
        float normalVelocity = Vector3.Dot(ImpulseMath.RelativeVelocity(a, b, rA, rB), n); // eq. 13–14
        float denominator = ImpulseMath.EffectiveMassDenominator(a, b, rA, rB, n);
        if (normalVelocity >= 0 || !(denominator > 0))
        {
            return;
        }

        float restitution = -normalVelocity > _restitutionThreshold ? _mixing.Restitution(contact, _restitution) : 0f;
        float normalImpulse = ImpulseMath.Collide(
            ref a, ref b, rA, rB, n, normalVelocity, -restitution * normalVelocity, 1f / denominator, // eq. 9, 16
            _mixing.Friction(contact, _friction), out float tangentImpulse);
        a.StoreTo(contact.BodyA);
        b.StoreTo(contact.BodyB);
        contact.NormalImpulse += normalImpulse;
        contact.TangentImpulse += tangentImpulse;
    }

    /// <inheritdoc />
    public void SolvePositions(StepContext step)
    {
        CheckStage(step, StepStage.SolvePositions);
        AdmitWokenBodies(step.Bodies);
        CorrectPositions(step.Bodies, step.Contacts.Count);
    }

    /// <inheritdoc />
    /// <remarks>
    /// Keeps the last substep's accumulated impulses for the next step's warm start (contact persistence), and lets
    /// working arrays that have long been far larger than the steps need shrink (see <see cref="TrimExcess"/>).
    /// </remarks>
    public void EndStep(StepContext step)
    {
        CheckStage(step, StepStage.EndStep);
        StoreImpulses(step.Contacts.Contacts);
        ShrinkIdleBuffers(step.Bodies.Length, step.Contacts.Count);
        _step = null;
        _threads = null; // the world's: not kept alive by a solver that outlives it
    }

    /// <summary>Throws unless the context is in <paramref name="stage"/> of the step this solver began.</summary>
    private void CheckStage(StepContext step, StepStage stage)
    {
        Guard.NotNull(step, nameof(step));
        step.Expect(stage);
        if (!ReferenceEquals(step, _step) || step.StepNumber != _stepNumber)
        {
            throw new InvalidOperationException(
                $"{stage} was called for a step whose BeginStep this solver did not run; World.Step runs every stage of one step in order.");
        }
    }
}
