using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>
/// The engine's responder: all contacts of a step solved together by sequential impulses with accumulated-impulse
/// clamping and warm starting (E. Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005; "Fast and
/// Simple Physics using Sequential Impulses", GDC 2006), built on the tutorial's eq. 13–16.
/// </summary>
/// <remarks>
/// <para><b>Velocity pass.</b> Each iteration visits every contact and applies the impulse that would make its
/// constraint hold, given what the other contacts did so far (Gauss–Seidel). Per contact, the <i>accumulated</i>
/// normal impulse is clamped to ≥ 0 (a contact pushes, never pulls) and the accumulated friction impulse to the
/// disc of radius μ × normal impulse (Coulomb). Warm starting applies last step's accumulated impulses first (and,
/// within a step, the previous substep's), so a resting pile starts almost solved. <see cref="VelocityIterations"/>
/// sweeps are always done, then up to <see cref="ExtraIterations"/> more until the impulses stop changing.</para>
/// <para><b>Memory order.</b> Contacts are prepared once per step (normals, lever arms, effective masses and the
/// spin each unit impulse causes) and kept for its substeps. They are put in the order they are solved, bottom-up
/// along gravity, and the bodies' working copies in the same order, so that a sweep walks memory front to back
/// instead of jumping around a large world.</para>
/// <para><b>Speculative contacts.</b> A contact whose bodies have not met yet (negative penetration, see
/// <see cref="World.ContactMargin"/>) may close its gap within the substep but no more, so the bodies meet
/// exactly instead of overlapping.</para>
/// <para><b>Collisions first, then contacts</b> (Guendelman, Bridson and Fedkiw, "Nonconvex Rigid Bodies with
/// Stacking", SIGGRAPH 2003). Restitution (eq. 9) is given in a collision pass before the contact sweeps: every
/// contact that approaches faster than <see cref="RestitutionThreshold"/> (and, if speculative, would close its
/// gap within the substep) is answered like the tutorial's impulse responder, with the approach speed it has
/// before the solve: the impulse of eq. 16 that turns its relative normal velocity into −ε times itself, with
/// Coulomb friction. Contacts are visited in sweeps until none is left approaching, so a collision that throws a
/// body against a third one is answered too (a row of touching balls passes a blow along). Each such impulse is
/// a whole two-body collision: for ε = 1 it keeps the kinetic energy exactly, for ε &lt; 1 it loses some, so no
/// amount of simultaneous collisions adds energy, converged or not. The contact sweeps after it have ε = 0: they
/// only keep slow and resting contacts from approaching. A resting ball, which gravity pulls into the ground by
/// g·h each substep, is under the threshold and is stopped instead of hopping.</para>
/// <para><b>Position pass.</b> After positions are integrated, penetration deeper than <see cref="Slop"/> is
/// removed by the projection of listing 2, split by inverse mass, over <see cref="PositionIterations"/>
/// Gauss–Seidel sweeps (Box2D's non-linear Gauss–Seidel), each moving a contact by at most
/// <see cref="MaxCorrection"/>. It moves positions only: unlike a Baumgarte velocity bias, it cannot turn into
/// kinetic energy. For circles the normal passes through both centres, so r × n = 0 and no rotation is needed.</para>
/// </remarks>
public sealed class SequentialImpulseSolver : ICollisionResponder
{
    /// <summary>
    /// At most this many collision sweeps per substep; what still approaches after them is stopped by the contact
    /// sweeps (ε = 0).
    /// </summary>
    private const int MaxCollisionSweeps = 32;

    private readonly ContactCache _cache = new();
    private readonly HeightOrder _heightOrder = new();
    private VelocityState[] _bodies = new VelocityState[16];
    private Vector3[] _positions = new Vector3[16];
    private Constraint[] _constraints = new Constraint[16];
    private int[] _order = new int[16];
    private int[] _bodyOrder = new int[16];
    private int[] _slotOf = new int[16];
    private float[] _bodyHeights = new float[16];
    private float[] _radii = new float[16];
    private Contact[] _arranged = new Contact[16];
    private float[] _heights = new float[16];
    private int[] _collidedInSweep = new int[16];

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
    /// Velocity iterations (Gauss–Seidel sweeps) per substep, always done (≥ 1, default 4). More iterations:
    /// stiffer piles, more time.
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
    /// a pile being hit spends them where it needs them.
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
    /// A sweep has converged when no normal impulse changed by more than this fraction of the largest normal
    /// impulse (≥ 0, default 1e-3; 0 spends every extra iteration).
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

    /// <summary>Forgets the stored impulses (e.g. after teleporting bodies).</summary>
    public void ResetWarmStart() => _cache.Clear();

    /// <inheritdoc />
    /// <remarks>
    /// Called once per substep; <paramref name="dt"/> is the substep. The contacts' geometry (normals, lever arms,
    /// effective masses, order) is prepared on the first substep of a step and kept for the step, as Box2D v3
    /// does; each substep measures only the gaps again. Outside <see cref="World.Step"/> every call is a step.
    /// The contacts of <paramref name="collisions"/> are put in the order they are solved (bottom-up along gravity).
    /// </remarks>
    public void ResolveVelocities(World world, CollisionData collisions, float dt)
    {
        Guard.NotNull(world, nameof(world));
        Guard.NotNull(collisions, nameof(collisions));
        ReadOnlySpan<RigidBody> bodies = world.BodySpan;
        Span<Contact> contacts = collisions.Contacts;
        if (world.IsFirstSubstep)
        {
            GatherBodies(bodies, world.Gravity);
            OrderAlongGravity(contacts, world.Gravity);
            ArrangeContacts(contacts);
            PrepareConstraints(contacts);
        }
        else
        {
            GatherVelocities(bodies);
        }

        MeasureGaps(contacts, dt);
        ResolveCollisions(contacts.Length);
        WarmStart(contacts.Length);
        Sweeps(contacts.Length);
        AddToStepTotals(contacts.Length);
        if (world.IsLastSubstep)
        {
            StoreImpulses(contacts);
        }

        ScatterVelocities(bodies);
    }

    /// <inheritdoc />
    public void ResolvePositions(World world, CollisionData collisions, float dt)
    {
        Guard.NotNull(world, nameof(world));
        Guard.NotNull(collisions, nameof(collisions));
        if (_positionIterations == 0 || collisions.Count == 0)
        {
            return;
        }

        ReadOnlySpan<RigidBody> bodies = world.BodySpan;
        for (int i = 0; i < bodies.Length; i++)
        {
            _positions[_slotOf[i]] = bodies[i].position;
        }

        int count = collisions.Count;
        for (int iteration = 0; iteration < _positionIterations; iteration++)
        {
            for (int k = 0; k < count; k++)
            {
                CorrectPosition(ref _constraints[k]);
            }
        }

        for (int i = 0; i < bodies.Length; i++)
        {
            if (bodies[i].IsDynamic)
            {
                bodies[i].position = _positions[_slotOf[i]];
            }
        }
    }

    /// <summary>
    /// Copies the world's bodies into a contiguous array; slot 0 is the ground (all zero). The slots follow the
    /// bodies' height along gravity, like the contacts (<see cref="OrderAlongGravity"/>), so that a sweep finds the
    /// bodies of neighbouring contacts close together in memory instead of anywhere in a large world.
    /// </summary>
    private void GatherBodies(ReadOnlySpan<RigidBody> bodies, Vector3 gravity)
    {
        int n = bodies.Length;
        Buffers.EnsureCapacity(ref _bodies, n + 1);
        Buffers.EnsureCapacity(ref _positions, n + 1);
        Buffers.EnsureCapacity(ref _bodyOrder, n);
        Buffers.EnsureCapacity(ref _slotOf, n);
        Buffers.EnsureCapacity(ref _bodyHeights, n);
        Buffers.EnsureCapacity(ref _radii, n + 1);
        for (int i = 0; i < n; i++)
        {
            _bodyHeights[i] = -Vector3.Dot(bodies[i].position, gravity);
        }

        _heightOrder.Sort(_bodyHeights.AsSpan(0, n), _bodyOrder.AsSpan(0, n));
        for (int k = 0; k < n; k++)
        {
            _slotOf[_bodyOrder[k]] = k + 1;
        }

        _bodies[0] = default;
        _positions[0] = Vector3.Zero;
        _radii[0] = 0;
        for (int i = 0; i < n; i++)
        {
            int slot = _slotOf[i];
            _bodies[slot] = VelocityState.Of(bodies[i]);
            _positions[slot] = bodies[i].position;
            _radii[slot] = bodies[i].radius;
        }
    }

    /// <summary>Copies the velocities again on later substeps (gravity and forces changed them); masses stay.</summary>
    private void GatherVelocities(ReadOnlySpan<RigidBody> bodies)
    {
        for (int i = 0; i < bodies.Length; i++)
        {
            ref VelocityState state = ref _bodies[_slotOf[i]];
            state.Linear = bodies[i].linearVelocity;
            state.Angular = bodies[i].angularVelocity;
        }
    }

    /// <summary>
    /// Puts the contacts in the order they are solved (<see cref="OrderAlongGravity"/>), so that every pass over
    /// contacts and constraints walks both arrays front to back: constraint k is contact k.
    /// </summary>
    private void ArrangeContacts(Span<Contact> contacts)
    {
        Buffers.EnsureCapacity(ref _arranged, contacts.Length);
        for (int k = 0; k < contacts.Length; k++)
        {
            _arranged[k] = contacts[_order[k]];
        }

        _arranged.AsSpan(0, contacts.Length).CopyTo(contacts);
    }

    /// <summary>
    /// Everything about a contact that stays the same during a step: bodies, normal and tangents, lever arms, the
    /// spins and effective masses of eq. 15–16, material (ε, μ) and last step's impulses for the warm start.
    /// </summary>
    private void PrepareConstraints(Span<Contact> contacts)
    {
        Buffers.EnsureCapacity(ref _constraints, contacts.Length);
        for (int k = 0; k < contacts.Length; k++)
        {
            ref Contact contact = ref contacts[k];
            ref Constraint c = ref _constraints[k];
            c.A = SlotOf(contact.BodyA);
            c.B = SlotOf(contact.BodyB);
            ref VelocityState a = ref _bodies[c.A];
            ref VelocityState b = ref _bodies[c.B];

            c.Normal = contact.Normal;
            Vectors.Tangents(c.Normal, out c.Tangent1, out c.Tangent2);
            c.RA = contact.Point - _positions[c.A]; // r_1 = p − c_1 (eq. 16)
            c.RB = contact.Point - _positions[c.B];
            // What a unit impulse along n, t1, t2 does to each body's spin, I⁻¹ (r × d) (eq. 15), computed once per
            // step so that the sweeps need no matrix products.
            c.SpinA = a.InverseInertia.Transform(Vector3.Cross(c.RA, c.Normal));
            c.SpinB = b.InverseInertia.Transform(Vector3.Cross(c.RB, c.Normal));
            c.SpinA1 = a.InverseInertia.Transform(Vector3.Cross(c.RA, c.Tangent1));
            c.SpinB1 = b.InverseInertia.Transform(Vector3.Cross(c.RB, c.Tangent1));
            c.SpinA2 = a.InverseInertia.Transform(Vector3.Cross(c.RA, c.Tangent2));
            c.SpinB2 = b.InverseInertia.Transform(Vector3.Cross(c.RB, c.Tangent2));
            float inverseMassSum = a.InverseMass + b.InverseMass;
            c.NormalMass = InverseOrZero(ImpulseMath.EffectiveMassDenominator(inverseMassSum, c.SpinA, c.RA, c.SpinB, c.RB, c.Normal)); // eq. 16
            c.TangentMass1 = InverseOrZero(ImpulseMath.EffectiveMassDenominator(inverseMassSum, c.SpinA1, c.RA, c.SpinB1, c.RB, c.Tangent1));
            c.TangentMass2 = InverseOrZero(ImpulseMath.EffectiveMassDenominator(inverseMassSum, c.SpinA2, c.RA, c.SpinB2, c.RB, c.Tangent2));
            c.Friction = _mixing.Friction(contact, _friction);

            c.RadiusA = _radii[c.A];
            c.RadiusB = _radii[c.B];
            c.PlaneOffset = contact.IsPlaneContact ? contact.PlaneOffset : float.NaN;
            c.Restitution = _mixing.Restitution(contact, _restitution);
            c.StepNormalImpulse = 0;
            c.StepFrictionImpulse = 0;

            c.NormalImpulse = 0;
            c.FrictionImpulse1 = 0;
            c.FrictionImpulse2 = 0;
            if (WarmStarting && _cache.TryGet(contact.Key, out float normalImpulse, out Vector3 frictionImpulse))
            {
                c.NormalImpulse = normalImpulse;
                c.FrictionImpulse1 = Vector3.Dot(frictionImpulse, c.Tangent1);
                c.FrictionImpulse2 = Vector3.Dot(frictionImpulse, c.Tangent2);
                ClampFriction(ref c);
            }
        }
    }

    /// <summary>
    /// Visits contacts from the bottom of a pile upwards (along gravity), so that each Gauss–Seidel sweep carries
    /// support up through a stack instead of down through it.
    /// </summary>
    private void OrderAlongGravity(Span<Contact> contacts, Vector3 gravity)
    {
        Buffers.EnsureCapacity(ref _order, contacts.Length);
        Buffers.EnsureCapacity(ref _heights, contacts.Length);
        for (int i = 0; i < contacts.Length; i++)
        {
            _heights[i] = -Vector3.Dot(contacts[i].Point, gravity);
        }

        _heightOrder.Sort(_heights.AsSpan(0, contacts.Length), _order.AsSpan(0, contacts.Length));
    }

    /// <summary>
    /// A contact still open (penetration &lt; 0, speculative) may close its gap within this substep but no more;
    /// a touching one may not approach. Measured again every substep, as the gaps close.
    /// </summary>
    private void MeasureGaps(Span<Contact> contacts, float dt)
    {
        for (int i = 0; i < contacts.Length; i++)
        {
            ref Constraint c = ref _constraints[i];
            float penetration = contacts[i].Penetration;
            c.SpeculativeVelocity = penetration < 0 ? penetration / dt : 0f;
        }
    }

    /// <summary>
    /// Applies the impulses accumulated so far (last step's from the cache on the first substep, the previous
    /// substep's after that), so that a resting pile starts each substep almost solved. Without warm starting they
    /// start from zero.
    /// </summary>
    private void WarmStart(int count)
    {
        if (!WarmStarting)
        {
            for (int i = 0; i < count; i++)
            {
                _constraints[i].NormalImpulse = 0;
                _constraints[i].FrictionImpulse1 = 0;
                _constraints[i].FrictionImpulse2 = 0;
            }

            return;
        }

        for (int i = 0; i < count; i++)
        {
            ref Constraint c = ref _constraints[i];
            Apply(ref c, c.NormalImpulse, c.FrictionImpulse1, c.FrictionImpulse2);
        }
    }

    /// <summary>
    /// <see cref="VelocityIterations"/> Gauss–Seidel sweeps over every contact, bottom-up, then up to
    /// <see cref="ExtraIterations"/> more until one has converged.
    /// </summary>
    private void Sweeps(int count)
    {
        for (int iteration = 0; iteration < _velocityIterations; iteration++)
        {
            Sweep(count);
        }

        for (int extra = 0; extra < _extraIterations && !Sweep(count); extra++)
        {
        }
    }

    /// <summary>
    /// One Gauss–Seidel sweep over every contact, bottom-up. Returns whether it converged: no normal impulse
    /// changed by more than <see cref="ConvergenceTolerance"/> times the largest one.
    /// </summary>
    private bool Sweep(int count)
    {
        float largestChange = 0, largestImpulse = 0;
        for (int k = 0; k < count; k++)
        {
            ref Constraint c = ref _constraints[k];
            float before = c.NormalImpulse;
            SolveContact(ref c);
            largestChange = MathF.Max(largestChange, MathF.Abs(c.NormalImpulse - before));
            largestImpulse = MathF.Max(largestImpulse, c.NormalImpulse);
        }

        return largestChange <= _convergenceTolerance * largestImpulse;
    }

    /// <summary>
    /// One contact's impulses given what all others did so far: friction (Coulomb, accumulated and clamped to
    /// the disc |P_t| ≤ μ P_n), then the normal impulse of eq. 16 that brings the relative normal velocity to the
    /// target (0, or for a speculative contact the speed that just closes its gap), accumulated and clamped to
    /// ≥ 0 (a contact pushes, never pulls).
    /// </summary>
    private void SolveContact(ref Constraint c)
    {
        ref VelocityState a = ref _bodies[c.A];
        ref VelocityState b = ref _bodies[c.B];

        // A contact that pushes nothing has no friction either (|P_t| ≤ μ P_n = 0): skip the work, which is
        // most of it for the many speculative contacts that never close.
        if (c.NormalImpulse > 0 || c.FrictionImpulse1 != 0 || c.FrictionImpulse2 != 0)
        {
            Vector3 relative = ImpulseMath.RelativeVelocity(a, b, c.RA, c.RB); // eq. 13–14
            float old1 = c.FrictionImpulse1, old2 = c.FrictionImpulse2;
            c.FrictionImpulse1 -= c.TangentMass1 * Vector3.Dot(relative, c.Tangent1);
            c.FrictionImpulse2 -= c.TangentMass2 * Vector3.Dot(relative, c.Tangent2);
            ClampFriction(ref c);
            Apply(ref c, 0f, c.FrictionImpulse1 - old1, c.FrictionImpulse2 - old2);
        }

        float normalVelocity = Vector3.Dot(ImpulseMath.RelativeVelocity(a, b, c.RA, c.RB), c.Normal);
        float oldNormal = c.NormalImpulse;
        c.NormalImpulse = MathF.Max(oldNormal - c.NormalMass * (normalVelocity - c.SpeculativeVelocity), 0f);
        if (c.NormalImpulse != oldNormal)
        {
            Apply(ref c, c.NormalImpulse - oldNormal, 0f, 0f);
        }
    }

    /// <summary>
    /// Applies the impulse P = p_n n + p_1 t_1 + p_2 t_2 to A and −P to B: eq. 6 for the velocities, eq. 15 for the
    /// spins through the prepared I⁻¹ (r × d) of each direction (the same as <see cref="ImpulseMath.Apply"/>).
    /// </summary>
    private void Apply(ref Constraint c, float normal, float tangent1, float tangent2)
    {
        ref VelocityState a = ref _bodies[c.A];
        ref VelocityState b = ref _bodies[c.B];
        Vector3 impulse = normal * c.Normal + tangent1 * c.Tangent1 + tangent2 * c.Tangent2;
        a.Linear += impulse * a.InverseMass;
        a.Angular += normal * c.SpinA + tangent1 * c.SpinA1 + tangent2 * c.SpinA2;
        b.Linear -= impulse * b.InverseMass;
        b.Angular -= normal * c.SpinB + tangent1 * c.SpinB1 + tangent2 * c.SpinB2;
    }

    /// <summary>
    /// The collision pass (Guendelman et al. 2003): sweeps over the contacts, bottom-up, answering each one that
    /// collides like the tutorial's impulse responder (eq. 16 with the bounce of eq. 9, then Coulomb friction),
    /// until a sweep finds none (at most <see cref="MaxCollisionSweeps"/>). A contact collides if it approaches
    /// faster than <see cref="RestitutionThreshold"/> and faster than its speculative speed (an open contact
    /// that would not close its gap within the substep has not met yet). After the first sweep only contacts
    /// with a body that a collision moved in the sweep before are looked at again: the others cannot have
    /// changed. These impulses are not warm-started next step: a bounce is a one-off, not a resting load.
    /// </summary>
    private void ResolveCollisions(int count)
    {
        Buffers.EnsureCapacity(ref _collidedInSweep, _bodies.Length);
        Array.Clear(_collidedInSweep, 0, _bodies.Length);
        for (int sweep = 1; sweep <= MaxCollisionSweeps; sweep++)
        {
            bool any = false;
            for (int k = 0; k < count; k++)
            {
                ref Constraint c = ref _constraints[k];
                if (c.Restitution == 0 || c.NormalMass == 0 ||
                    (sweep > 1 && _collidedInSweep[c.A] < sweep - 1 && _collidedInSweep[c.B] < sweep - 1))
                {
                    continue;
                }

                ref VelocityState a = ref _bodies[c.A];
                ref VelocityState b = ref _bodies[c.B];
                float normalVelocity = Vector3.Dot(ImpulseMath.RelativeVelocity(a, b, c.RA, c.RB), c.Normal); // eq. 13–14
                if (normalVelocity >= c.SpeculativeVelocity || -normalVelocity <= _restitutionThreshold)
                {
                    continue;
                }

                float bounce = -c.Restitution * normalVelocity; // eq. 9
                c.StepNormalImpulse += ImpulseMath.Collide(
                    ref a, ref b, c.RA, c.RB, c.Normal, normalVelocity, bounce, c.NormalMass, c.Friction, out float friction);
                c.StepFrictionImpulse += friction;
                MarkCollided(c.A, sweep);
                MarkCollided(c.B, sweep);
                any = true;
            }

            if (!any)
            {
                return;
            }
        }
    }

    /// <summary>Remembers that a body was moved by a collision in this sweep; the ground and other infinite masses never move.</summary>
    private void MarkCollided(int slot, int sweep)
    {
        if (_bodies[slot].InverseMass > 0)
        {
            _collidedInSweep[slot] = sweep;
        }
    }

    /// <summary>Adds this substep's contact impulses to the step's totals, which the contacts report.</summary>
    private void AddToStepTotals(int count)
    {
        for (int i = 0; i < count; i++)
        {
            ref Constraint c = ref _constraints[i];
            c.StepNormalImpulse += c.NormalImpulse;
            c.StepFrictionImpulse += MathF.Sqrt(c.FrictionImpulse1 * c.FrictionImpulse1 + c.FrictionImpulse2 * c.FrictionImpulse2);
        }
    }

    /// <summary>Keeps the last substep's accumulated impulses for the next step's warm start (contact persistence).</summary>
    private void StoreImpulses(Span<Contact> contacts)
    {
        _cache.BeginStep(contacts.Length);
        for (int i = 0; i < contacts.Length; i++)
        {
            ref Constraint c = ref _constraints[i];
            Vector3 friction = c.FrictionImpulse1 * c.Tangent1 + c.FrictionImpulse2 * c.Tangent2;
            ref Contact contact = ref contacts[i];
            _cache.Store(contact.Key, c.NormalImpulse, friction);
            contact.NormalImpulse = c.StepNormalImpulse;
            contact.TangentImpulse = c.StepFrictionImpulse;
        }

        _cache.EndStep();
    }

    private void ScatterVelocities(ReadOnlySpan<RigidBody> bodies)
    {
        for (int i = 0; i < bodies.Length; i++)
        {
            _bodies[_slotOf[i]].StoreTo(bodies[i]);
        }
    }

    /// <summary>
    /// Listing 2 as a Gauss–Seidel position sweep: measure the contact at the current positions and push the
    /// bodies apart along the normal, split by inverse mass, by a bounded share of the depth beyond the slop.
    /// </summary>
    private void CorrectPosition(ref Constraint c)
    {
        float inverseMassSum = _bodies[c.A].InverseMass + _bodies[c.B].InverseMass;
        if (inverseMassSum == 0)
        {
            return;
        }

        ref Vector3 positionA = ref _positions[c.A];
        ref Vector3 positionB = ref _positions[c.B];
        float penetration;
        Vector3 normal;
        if (c.IsPlaneContact)
        {
            normal = c.Normal;
            penetration = ContactGeometry.PlanePenetration(positionA, c.RadiusA, normal, c.PlaneOffset);
        }
        else
        {
            penetration = ContactGeometry.CirclePenetration(positionA, c.RadiusA, positionB, c.RadiusB, out normal);
        }

        float correction = MathF.Min(_correctionFactor * (penetration - _slop), _maxCorrection);
        if (correction <= 0)
        {
            return;
        }

        float share = correction / inverseMassSum;
        positionA += normal * (share * _bodies[c.A].InverseMass);
        positionB -= normal * (share * _bodies[c.B].InverseMass);
    }

    private static void ClampFriction(ref Constraint c)
    {
        float limit = c.Friction * c.NormalImpulse;
        float squared = c.FrictionImpulse1 * c.FrictionImpulse1 + c.FrictionImpulse2 * c.FrictionImpulse2;
        if (squared > limit * limit)
        {
            float scale = squared > 0 ? limit / MathF.Sqrt(squared) : 0f;
            c.FrictionImpulse1 *= scale;
            c.FrictionImpulse2 *= scale;
        }
    }

    private int SlotOf(RigidBody body) => body.index < 0 ? 0 : _slotOf[body.index]; // the ground (index −1) is slot 0

    private static float InverseOrZero(float denominator) => denominator > 0 ? 1f / denominator : 0f;

    private struct Constraint
    {
        public int A, B;
        public Vector3 RA, RB;
        public Vector3 Normal, Tangent1, Tangent2;
        public Vector3 SpinA, SpinB, SpinA1, SpinB1, SpinA2, SpinB2;
        public float NormalMass, TangentMass1, TangentMass2;
        public float SpeculativeVelocity;
        public float Restitution;
        public float Friction;
        public float StepNormalImpulse, StepFrictionImpulse;
        public float RadiusA, RadiusB;
        public float PlaneOffset; // NaN unless B is the ground plane

        public readonly bool IsPlaneContact => !float.IsNaN(PlaneOffset);
        public float NormalImpulse, FrictionImpulse1, FrictionImpulse2;
    }
}
