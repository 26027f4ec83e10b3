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
/// disc of radius μ × normal impulse (Coulomb). Warm starting applies last step's accumulated impulses first, so
/// a resting pile starts each step almost solved.</para>
/// <para><b>Speculative contacts.</b> A contact whose bodies have not met yet (negative penetration, see
/// <see cref="World.ContactMargin"/>) may close its gap within the substep but no more, so the bodies meet
/// exactly instead of overlapping.</para>
/// <para><b>Restitution</b> (eq. 9) follows Poisson's hypothesis: after the sweeps that stop every approach
/// (compression), each contact gets ε times its compression impulse back, all at once. For a lone pair that is
/// exactly eq. 9; for simultaneous contacts it never adds energy when ε ≤ 1. Collisions set off by a bounce are
/// resolved in further rounds. Below <see cref="RestitutionThreshold"/> ε acts as 0, so slow contacts come to
/// rest instead of jittering.</para>
/// <para><b>Position pass.</b> After positions are integrated, penetration deeper than <see cref="Slop"/> is
/// removed by the projection of listing 2, split by inverse mass, over <see cref="PositionIterations"/>
/// Gauss–Seidel sweeps (Box2D's non-linear Gauss–Seidel), each moving a contact by at most
/// <see cref="MaxCorrection"/>. It moves positions only: unlike a Baumgarte velocity bias, it cannot turn into
/// kinetic energy. For circles the normal passes through both centres, so r × n = 0 and no rotation is needed.</para>
/// </remarks>
public sealed class SequentialImpulseSolver : ICollisionResponder
{
    /// <summary>At most this many rounds of collisions set off by bounces are resolved per substep.</summary>
    private const int MaxCollisionRounds = 4;

    /// <summary>At most this many sweeps are spent converging the stop of colliding contacts.</summary>
    private const int MaxConvergenceSweeps = 16;

    private readonly ContactCache _cache = new();
    private VelocityState[] _bodies = new VelocityState[16];
    private Vector3[] _positions = new Vector3[16];
    private Constraint[] _constraints = new Constraint[16];
    private int[] _order = new int[16];
    private float[] _heights = new float[16];

    private int _velocityIterations = 4;
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

    /// <summary>Velocity iterations per substep (≥ 1, default 4). More iterations: stiffer piles, more time.</summary>
    public int VelocityIterations
    {
        get => _velocityIterations;
        set
        {
            Guard.AtLeast(value, 1, nameof(VelocityIterations));
            _velocityIterations = value;
        }
    }

    /// <summary>Position-correction sweeps per step (≥ 0, default 2; 0 turns the correction off).</summary>
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
    /// <remarks>Called once per substep; <paramref name="dt"/> is the substep.</remarks>
    public void ResolveVelocities(World world, CollisionData collisions, float dt)
    {
        Guard.NotNull(world, nameof(world));
        Guard.NotNull(collisions, nameof(collisions));
        ReadOnlySpan<RigidBody> bodies = world.BodySpan;
        GatherBodies(bodies);
        PrepareConstraints(collisions.Contacts, dt);
        OrderAlongGravity(collisions.Contacts, world.Gravity);
        if (WarmStarting)
        {
            WarmStart(collisions.Count);
        }

        int count = collisions.Count;
        Sweeps(count);
        for (int round = 0; round < MaxCollisionRounds && Restitute(count); round++)
        {
            Sweeps(count);
        }

        StoreImpulses(collisions.Contacts);
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
            _positions[i + 1] = bodies[i].position;
        }

        Span<Contact> contacts = collisions.Contacts;
        for (int iteration = 0; iteration < _positionIterations; iteration++)
        {
            for (int k = 0; k < contacts.Length; k++)
            {
                int i = _order[k];
                CorrectPosition(ref _constraints[i], contacts[i]);
            }
        }

        for (int i = 0; i < bodies.Length; i++)
        {
            if (bodies[i].IsDynamic)
            {
                bodies[i].position = _positions[i + 1];
            }
        }
    }

    /// <summary>Copies the world's bodies into a contiguous array; slot 0 is the ground (all zero).</summary>
    private void GatherBodies(ReadOnlySpan<RigidBody> bodies)
    {
        Buffers.EnsureCapacity(ref _bodies, bodies.Length + 1);
        Buffers.EnsureCapacity(ref _positions, bodies.Length + 1);
        _bodies[0] = default;
        _positions[0] = Vector3.Zero;
        for (int i = 0; i < bodies.Length; i++)
        {
            _bodies[i + 1] = VelocityState.Of(bodies[i]);
            _positions[i + 1] = bodies[i].position;
        }
    }

    private void PrepareConstraints(Span<Contact> contacts, float dt)
    {
        Buffers.EnsureCapacity(ref _constraints, contacts.Length);
        for (int i = 0; i < contacts.Length; i++)
        {
            ref Contact contact = ref contacts[i];
            ref Constraint c = ref _constraints[i];
            c.A = SlotOf(contact.BodyA);
            c.B = SlotOf(contact.BodyB);
            ref VelocityState a = ref _bodies[c.A];
            ref VelocityState b = ref _bodies[c.B];

            c.Normal = contact.Normal;
            Vectors.Tangents(c.Normal, out c.Tangent1, out c.Tangent2);
            c.RA = contact.Point - _positions[c.A]; // r_1 = p − c_1 (eq. 16)
            c.RB = contact.Point - _positions[c.B];
            c.NormalMass = InverseOrZero(ImpulseMath.EffectiveMassDenominator(a, b, c.RA, c.RB, c.Normal)); // eq. 16
            c.TangentMass1 = InverseOrZero(ImpulseMath.EffectiveMassDenominator(a, b, c.RA, c.RB, c.Tangent1));
            c.TangentMass2 = InverseOrZero(ImpulseMath.EffectiveMassDenominator(a, b, c.RA, c.RB, c.Tangent2));
            c.Friction = _mixing.Friction(contact, _friction);

            // A contact still open (penetration < 0, speculative) may close its gap within this substep but no
            // more; a touching one may not approach. Bounces are added by Restitute.
            c.SpeculativeVelocity = contact.Penetration < 0 ? contact.Penetration / dt : 0f;
            c.TargetVelocity = c.SpeculativeVelocity;
            c.Restitution = _mixing.Restitution(contact, _restitution);
            c.CommittedImpulse = 0;

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

            c.StartImpulse = c.NormalImpulse;
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
            _order[i] = i;
            _heights[i] = -Vector3.Dot(contacts[i].Point, gravity);
        }

        if (gravity != Vector3.Zero)
        {
            Array.Sort(_heights, _order, 0, contacts.Length);
        }
    }

    private void WarmStart(int count)
    {
        for (int i = 0; i < count; i++)
        {
            ref Constraint c = ref _constraints[i];
            Vector3 impulse = c.NormalImpulse * c.Normal + c.FrictionImpulse1 * c.Tangent1 + c.FrictionImpulse2 * c.Tangent2;
            ImpulseMath.Apply(ref _bodies[c.A], ref _bodies[c.B], c.RA, c.RB, impulse);
        }
    }

    /// <summary><see cref="VelocityIterations"/> Gauss–Seidel sweeps over every contact, bottom-up.</summary>
    private void Sweeps(int count)
    {
        for (int iteration = 0; iteration < _velocityIterations; iteration++)
        {
            Sweep(count);
        }
    }

    /// <summary>
    /// Sweeps until no normal impulse changes by more than 1e-5 of the largest one (at most
    /// <see cref="MaxConvergenceSweeps"/>). Used to stop colliding contacts before they bounce: Poisson's
    /// restitution conserves energy only if the stop is complete.
    /// </summary>
    private void SweepUntilConverged(int count)
    {
        for (int sweep = 0; sweep < MaxConvergenceSweeps; sweep++)
        {
            float largestChange = 0, largestImpulse = 0;
            for (int k = 0; k < count; k++)
            {
                ref Constraint c = ref _constraints[_order[k]];
                float before = c.NormalImpulse;
                SolveContact(ref c);
                largestChange = MathF.Max(largestChange, MathF.Abs(c.NormalImpulse - before));
                largestImpulse = MathF.Max(largestImpulse, c.NormalImpulse);
            }

            if (largestChange <= 1e-5f * largestImpulse)
            {
                return;
            }
        }
    }

    /// <summary>One Gauss–Seidel sweep over every contact, bottom-up.</summary>
    private void Sweep(int count)
    {
        for (int k = 0; k < count; k++)
        {
            SolveContact(ref _constraints[_order[k]]);
        }
    }

    /// <summary>
    /// One contact's impulses given what all others did so far: friction (Coulomb, accumulated and clamped to
    /// the disc |P_t| ≤ μ P_n), then the normal impulse of eq. 16 that brings the relative normal velocity to the
    /// target (0, or for a speculative contact the speed that just closes its gap), accumulated and clamped to
    /// ≥ the committed impulse (≥ 0: a contact pushes, never pulls).
    /// </summary>
    private void SolveContact(ref Constraint c)
    {
        ref VelocityState a = ref _bodies[c.A];
        ref VelocityState b = ref _bodies[c.B];

        Vector3 relative = ImpulseMath.RelativeVelocity(a, b, c.RA, c.RB); // eq. 13–14
        float old1 = c.FrictionImpulse1, old2 = c.FrictionImpulse2;
        c.FrictionImpulse1 -= c.TangentMass1 * Vector3.Dot(relative, c.Tangent1);
        c.FrictionImpulse2 -= c.TangentMass2 * Vector3.Dot(relative, c.Tangent2);
        ClampFriction(ref c);
        Vector3 frictionDelta = (c.FrictionImpulse1 - old1) * c.Tangent1 + (c.FrictionImpulse2 - old2) * c.Tangent2;
        ImpulseMath.Apply(ref a, ref b, c.RA, c.RB, frictionDelta);

        relative = ImpulseMath.RelativeVelocity(a, b, c.RA, c.RB);
        float normalVelocity = Vector3.Dot(relative, c.Normal);
        float oldNormal = c.NormalImpulse;
        c.NormalImpulse = MathF.Max(oldNormal - c.NormalMass * (normalVelocity - c.TargetVelocity), c.CommittedImpulse);
        ImpulseMath.Apply(ref a, ref b, c.RA, c.RB, (c.NormalImpulse - oldNormal) * c.Normal);
    }

    /// <summary>
    /// Restitution (eq. 9) by Poisson's hypothesis, applied to all contacts at once. The sweeps before only kept
    /// contacts from approaching; a contact that pushed in them has collided. A speculative one was only slowed
    /// to close its gap within the substep, so first all colliding contacts are stopped completely, solved
    /// together (the bodies meet at most a substep's travel early); the energy balance below needs every
    /// colliding contact at rest before the bounce (a contact restituted while still closing its gap loses
    /// 2 P gap/h of energy). The normal impulse each contact added since
    /// the last round is then its compression impulse P_c, and restitution adds ε P_c to every contact
    /// simultaneously. For a lone pair this is exactly eq. 9 (the relative normal velocity becomes −ε times the
    /// approach); for several contacts at once, compression removes ½ Pᵀ A P of kinetic energy
    /// (A = J M⁻¹ Jᵀ) and restitution gives back ε² of it, so no round adds energy when ε ≤ 1. A contact whose
    /// impact speed P_c/m_eff is below <see cref="RestitutionThreshold"/> gets no bounce: a resting contact only
    /// absorbs what gravity adds in a substep. Impulses are committed: later sweeps may add, never take back.
    /// A bounce can throw a body against a third one; the caller's next sweeps find that compression and the
    /// next round bounces it. Returns whether any restitution impulse was applied.
    /// </summary>
    private bool Restitute(int count)
    {
        // Stop every colliding contact completely; stopping some can make others collide, hence the passes.
        for (int pass = 0; pass < MaxCollisionRounds && StopCollidingContacts(count); pass++)
        {
            SweepUntilConverged(count);
        }

        bool any = false;
        for (int k = 0; k < count; k++)
        {
            ref Constraint c = ref _constraints[_order[k]];
            float compression = c.NormalImpulse - c.StartImpulse;
            if (compression > 0 && c.NormalMass > 0 && c.Restitution > 0 && compression / c.NormalMass > _restitutionThreshold)
            {
                float bounce = c.Restitution * compression;
                ImpulseMath.Apply(ref _bodies[c.A], ref _bodies[c.B], c.RA, c.RB, bounce * c.Normal);
                c.NormalImpulse += bounce;
                any = true;
            }

            c.StartImpulse = c.NormalImpulse;
            c.CommittedImpulse = c.NormalImpulse;
            c.TargetVelocity = c.SpeculativeVelocity;
        }

        return any;
    }

    /// <summary>
    /// Sets the target of every speculative contact that pushed since the last round to 0 (a full stop);
    /// returns whether there was any.
    /// </summary>
    private bool StopCollidingContacts(int count)
    {
        bool any = false;
        for (int i = 0; i < count; i++)
        {
            ref Constraint c = ref _constraints[i];
            if (c.NormalImpulse > c.StartImpulse && c.TargetVelocity < 0)
            {
                c.TargetVelocity = 0;
                any = true;
            }
        }

        return any;
    }

    private void StoreImpulses(Span<Contact> contacts)
    {
        _cache.BeginStep(contacts.Length);
        for (int i = 0; i < contacts.Length; i++)
        {
            ref Constraint c = ref _constraints[i];
            Vector3 friction = c.FrictionImpulse1 * c.Tangent1 + c.FrictionImpulse2 * c.Tangent2;
            _cache.Store(contacts[i].Key, c.NormalImpulse, friction);
            contacts[i].NormalImpulse = c.NormalImpulse;
            contacts[i].TangentImpulse = friction.Length();
        }

        _cache.EndStep();
    }

    private void ScatterVelocities(ReadOnlySpan<RigidBody> bodies)
    {
        for (int i = 0; i < bodies.Length; i++)
        {
            _bodies[i + 1].StoreTo(bodies[i]);
        }
    }

    /// <summary>
    /// Listing 2 as a Gauss–Seidel position sweep: measure the contact at the current positions and push the
    /// bodies apart along the normal, split by inverse mass, by a bounded share of the depth beyond the slop.
    /// </summary>
    private void CorrectPosition(ref Constraint c, in Contact contact)
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
        if (contact.IsPlaneContact)
        {
            normal = contact.Normal;
            penetration = ContactGeometry.PlanePenetration(positionA, contact.BodyA.radius, normal, contact.PlaneOffset);
        }
        else
        {
            penetration = ContactGeometry.CirclePenetration(positionA, contact.BodyA.radius, positionB, contact.BodyB.radius, out normal);
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

    private static int SlotOf(RigidBody body) => body.index + 1; // the ground (index −1) maps to slot 0

    private static float InverseOrZero(float denominator) => denominator > 0 ? 1f / denominator : 0f;

    private struct Constraint
    {
        public int A, B;
        public Vector3 RA, RB;
        public Vector3 Normal, Tangent1, Tangent2;
        public float NormalMass, TangentMass1, TangentMass2;
        public float SpeculativeVelocity;
        public float TargetVelocity;
        public float Restitution;
        public float CommittedImpulse;
        public float StartImpulse;
        public float Friction;
        public float NormalImpulse, FrictionImpulse1, FrictionImpulse2;
    }
}
