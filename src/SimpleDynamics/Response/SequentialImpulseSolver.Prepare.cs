using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>The solver's working copies of the contacts: ordered along gravity, prepared for the step and measured each substep.</summary>
public sealed partial class SequentialImpulseSolver
{
    private readonly HeightOrder _heightOrder = new();
    private ContactConstraint[] _constraints = new ContactConstraint[InitialCapacity];
    private TangentFrame[] _frames = new TangentFrame[InitialCapacity]; // per constraint, in 3-D steps only (MeasureRange fills them)
    private ContactStepImpulses[] _stepImpulses = new ContactStepImpulses[InitialCapacity]; // per constraint
    private int[] _order = new int[InitialCapacity];
    private float[] _heights = new float[InitialCapacity];
    private ulong[] _ties = new ulong[InitialCapacity]; // per contact: its bodies' places in the world, for equal heights
    private int[] _active = new int[InitialCapacity]; // the active constraints of the substep, in sweep order (MeasureConstraints)
    private int _activeCount;
    private int _prepared;
    private bool _detectedPushed; // whether detection gave a contact a normal impulse this step (see MeasureRange)

    /// <summary>For tests: the measure reads every contact's impulse, pushed this step or not (see MeasureRange).</summary>
    internal bool ReadsEveryPush { get; set; }
    private int _extraSweeps; // this step's budget of extra sweeps per substep (see ExtraSweepsFor)
    private float _pileLayers; // this step's pile depth in bodies (PileMeasure), for the first sweep's test (SolvedTolerance)

    /// <summary>The extra sweeps per substep the last step began could spend (see <see cref="DeepPileLayers"/>), for tests.</summary>
    internal int ExtraSweepBudget => _extraSweeps;

    /// <summary>
    /// Visits contacts from the bottom of a pile upwards (along gravity), so that each Gauss–Seidel sweep carries
    /// support up through a stack instead of down through it; contacts at the same height (a floor's) by their bodies'
    /// places in the world. The order, and so every result, is the same whatever order the detector reported the
    /// contacts in. The contacts also give the pile's depth (<see cref="PileMeasure"/>), which sets the step's budget of
    /// extra sweeps (see <see cref="ExtraSweepsFor"/>).
    /// </summary>
    private void OrderAlongGravity(Span<Contact> contacts, Vector3 gravity)
    {
        Buffers.EnsureCapacity(ref _order, contacts.Length);
        Buffers.EnsureCapacity(ref _heights, contacts.Length);
        Buffers.EnsureCapacity(ref _ties, contacts.Length);
        var pile = new PileMeasure(gravity, _step!.TimeStep);
        for (int i = 0; i < contacts.Length; i++)
        {
            ref readonly Contact contact = ref contacts[i];
            _heights[i] = -Vectors.Dot(contact.Point, gravity);
            _ties[i] = contact.IsPlaneContact
                ? Contact.PlaneKey(contact.BodyA.index, contact.PlaneIndex)
                : Contact.PairKey(contact.BodyA.index, contact.BodyB.index);
            pile.Add(contact, _heights[i]);
        }

        _heightOrder.Sort(_heights.AsSpan(0, contacts.Length), _ties.AsSpan(0, contacts.Length), _order.AsSpan(0, contacts.Length));
        if (_strips.Count > 1)
        {
            // Strip after strip, each bottom-up, then the seam contacts (SweepStrips.cs).
            Buffers.EnsureCapacity(ref _contactScratch, contacts.Length);
            _strips.Group(_order.AsSpan(0, contacts.Length), bodies: false, _contactScratch, _contactStart);
        }

        _extraSweeps = ExtraSweepsFor(pile.Layers);
        _meanDiameter = pile.MeanDiameter;
        _pileLayers = pile.Layers;
    }

    // The most a deep pile's budget may grow: 28 × ExtraIterations (224 sweeps at the default) covers the
    // 16,000-disc pit, whose pile at rest is measured about 110 layers deep (a budget of 165–167); a deeper pile is
    // given no more, so that one pathological tower cannot make every step of a world cost thousands of sweeps.
    private const float MostDeepPileScale = 28f;

    /// <summary>
    /// The extra sweeps a substep may spend (see <see cref="ExtraIterations"/>): <see cref="ExtraIterations"/> for a
    /// pile up to <see cref="DeepPileLayers"/> bodies deep, more with the square of the depth for a deeper one, up to
    /// 28 times as many. <paramref name="layers"/> is the pile's depth in bodies (<see cref="PileMeasure"/>; 0 without
    /// gravity).
    /// </summary>
    private int ExtraSweepsFor(float layers)
    {
        float scale = layers > DeepPileLayers ? layers / DeepPileLayers * (layers / DeepPileLayers) : 1f;
        return scale < MostDeepPileScale // false for NaN too: any world gets a finite budget
            ? (int)MathF.Ceiling(_extraIterations * scale)
            : (int)MostDeepPileScale * _extraIterations;
    }

    /// <summary>
    /// Puts the contacts in the order they are solved (<see cref="OrderAlongGravity"/>), so that every pass over
    /// contacts and constraints walks both arrays front to back: constraint k is contact k. Contacts already in that
    /// order (always, without gravity) are not moved.
    /// </summary>
    private void ArrangeContacts(Span<Contact> contacts)
    {
        Span<int> order = _order.AsSpan(0, contacts.Length);
        if (!IsIdentity(order))
        {
            HeightOrder.Apply(contacts, order);
        }
    }

    /// <summary>
    /// What stays the same for a contact during the step: its bodies' slots, radii, friction and last step's impulses
    /// for the warm start. Prepares the contacts from <see cref="_prepared"/> on (the impact pass may add some).
    /// </summary>
    private void PrepareConstraints(Span<Contact> contacts)
    {
        Buffers.EnsureCapacity(ref _constraints, contacts.Length);
        Buffers.EnsureCapacity(ref _stepImpulses, contacts.Length);
        for (int k = _prepared; k < contacts.Length; k++)
        {
            ref Contact contact = ref contacts[k];
            ref ContactConstraint c = ref _constraints[k];
            c = default;
            _stepImpulses[k] = default;
            c.A = SlotOf(contact.BodyA);
            c.B = SlotOf(contact.BodyB);
            c.Friction = _mixing.Friction(contact, _friction);
            if (!ReferenceEquals(_mixing, MaterialMixing.Default))
            {
                // A rule of the user's that returns ε out of range throws now, before anything moves (the default, the
                // larger of two values in [0, 1], cannot).
                _ = _mixing.Restitution(contact, _restitution);
            }
            c.PlaneOffset = contact.IsPlaneContact ? contact.PlaneOffset : float.NaN;
            _detectedPushed |= contact.NormalImpulse > 0; // a detector of the user's may have set one
            if (WarmStarting && _cache.TryGet(k, contact.Key, out float normalImpulse, out Vector3 frictionImpulse))
            {
                c.NormalImpulse = normalImpulse * _warmStartScale;
                _stepImpulses[k].Friction = frictionImpulse * _warmStartScale;
            }
        }

        _prepared = contacts.Length;
    }

    /// <summary>
    /// A contact's depth and normal from the bodies' centres in double precision (<see cref="RigidBody.PreciseCentre"/>),
    /// as the impact pass measures them in a world without gravity: whether a slow pair grazing by, or passing within
    /// float rounding of touching, is a resting contact is decided from where it really is, not from its rounding.
    /// </summary>
    private float MeasureInDouble(ref ContactConstraint c, in Contact contact)
    {
        Vector3D centreA = contact.BodyA.PreciseCentre;
        if (c.IsPlaneContact)
        {
            c.Normal = contact.Normal;
            return (float)ContactGeometry.Unchecked.PlanePenetration(centreA, _radii[c.A], c.Normal, c.PlaneOffset);
        }

        double penetration = ContactGeometry.Unchecked.CirclePenetration(centreA, _radii[c.A], contact.BodyB.PreciseCentre, _radii[c.B], out Vector3D normal);
        c.Normal = normal.Rounded;
        return (float)penetration;
    }

    /// <summary>
    /// Measures every contact at the start of a substep: the normal along the current line of centres (or the
    /// plane's), tangents, lever arms r = p − c (eq. 16), the spins I⁻¹ (r × t) a unit friction impulse causes (eq. 15)
    /// and the effective masses. A contact is solved here if it touches, or pushed (in the last substep or at an impact
    /// of this step) and is apart by
    /// no more than <see cref="Slop"/> (as the position pass leaves a pile), and approaches no faster than
    /// <see cref="RestitutionThreshold"/>. Any other is left to the impact pass, which answers it when it touches, not
    /// before (a slow ball that comes within the slop of the ground is not stopped in mid-air), and its accumulated
    /// impulses are dropped. The solved contacts are listed, in order, for the sweeps: in a scene of fast
    /// bodies most contacts are only speculative (the smash solves about one in ten), and the sweeps then visit only those solved.
    /// </summary>
    /// <remarks>
    /// Each contact is measured on its own, so a pile whose last substep ran in strips (it is stirring), or one large
    /// enough for every substep to (<see cref="SharedPileContacts"/>), is measured in strips on the world's threads
    /// (SequentialImpulseSolver.Strips.cs); the list comes out the same.
    /// </remarks>
    private void MeasureConstraints(ReadOnlySpan<Contact> contacts)
    {
        Buffers.EnsureCapacity(ref _active, contacts.Length);
        if (!_planar)
        {
            Buffers.EnsureCapacity(ref _frames, contacts.Length);
        }

        bool shared = SharesEverySubstep(contacts.Length);
        bool inStrips = shared || (_substepInStrips && _threads is not null && _strips.Count > 1); // or as the last substep was
        _substepInStrips = shared;
        _bandsAssigned = false;
        ForgetFours(); // the active contacts are new: plan them again if more sweeps follow
        if (inStrips)
        {
            MeasureInStrips(contacts);
            return;
        }

        _activeCount = MeasureRange(contacts, 0, contacts.Length);
        FindStripsInActive();
    }

    /// <summary>
    /// How many solved 3-D contacts the measure lists before it gives them their frames (see <see cref="MeasureFrames"/>):
    /// 64, so that a block's constraints are still in the nearest cache. Settable for tests, which check that any
    /// block steps a world alike.
    /// </summary>
    internal int FramesBlock { get; set; } = 64;

    /// <summary>
    /// Measures contacts [<paramref name="start"/>, <paramref name="end"/>) (see <see cref="MeasureConstraints"/>) and
    /// lists those solved, in order, in <see cref="_active"/> from place <paramref name="start"/> on; returns how many.
    /// </summary>
    private int MeasureRange(ReadOnlySpan<Contact> contacts, int start, int end)
    {
        float weight = 0.7f * _gravity.Length(); // see ContactConstraint.CarriesWeight (never, without gravity)
        bool noGravity = _gravity == Vector3.Zero;

        // A contact pushed by an impact of this step is solved while it is within the slop (see above). Until the impact
        // pass pushes one, no contact's impulse has changed since detection, and the contacts themselves, 88 bytes each,
        // are not read for it: in the settled 16,000-disc pit that stream was 40 % of this pass (bit for bit the same).
        bool readPushes = ReadsEveryPush || _detectedPushed || _step!.ContactsPushed;
        int listed = start, framed = start;
        for (int k = start; k < end; k++)
        {
            if (!_planar && listed - framed == FramesBlock)
            {
                MeasureFrames(framed, listed); // while the block's constraints are in the nearest cache
                framed = listed;
            }

            ref ContactConstraint c = ref _constraints[k];
            ref SolverBody a = ref _bodies[c.A];
            ref SolverBody b = ref _bodies[c.B];
            Vector3 positionA = _positions[c.A];
            float radiusA = _radii[c.A], radiusB = _radii[c.B];
            // What is measured is worked on in locals and stored once: each contact is a long chain of dependent steps,
            // and reading a value back from the constraint just written adds a store's round trip to it.
            float penetration;
            Vector3 normal;
            if (noGravity)
            {
                penetration = MeasureInDouble(ref c, contacts[k]);
                normal = c.Normal;
            }
            else if (c.IsPlaneContact)
            {
                normal = contacts[k].Normal;
                penetration = ContactGeometry.Unchecked.PlanePenetration(positionA, radiusA, normal, c.PlaneOffset);
            }
            else
            {
                penetration = ContactGeometry.Unchecked.CirclePenetration(positionA, radiusA, _positions[c.B], radiusB, out normal);
            }

            // Lever arms: the contact point lies on the line of centres, r_A = −ρ_A n and r_B = ρ_B n (eq. 16), with
            // ρ = r − d/2 for depth d (the point midway through the overlap). So r × n = 0: the normal impulse turns
            // nothing, and ω × r adds nothing along n.
            float rhoA = radiusA - 0.5f * penetration, rhoB = radiusB - 0.5f * penetration;
            c.Normal = normal;
            c.RhoA = rhoA;
            c.RhoB = rhoB;
            float normalVelocity = Vectors.Dot(a.Linear - b.Linear, normal); // eq. 13–14 along n
            bool pushed = c.NormalImpulse > 0 || (readPushes && contacts[k].NormalImpulse > 0); // in the last substep, or by an impact of this step
            bool solved = (penetration >= 0 || (penetration >= -_slop && pushed)) && normalVelocity >= -_restitutionThreshold;
            c.AIsUpper = c.B == 0 || Vectors.Dot(positionA - _positions[c.B], _gravity) <= 0;
            c.CarriesWeight = MathF.Abs(Vectors.Dot(normal, _gravity)) > weight;
            if (!solved)
            {
                c.NormalImpulse = 0;
                _stepImpulses[k].Friction = Vector3.Zero;
                c.FrictionImpulse1 = 0;
                if (!_planar)
                {
                    c.FrictionImpulse2 = 0;
                }

                continue;
            }

            _active[listed++] = k;

            float inverseMassSum = a.InverseMass + b.InverseMass;
            c.NormalMass = InverseOrZero(inverseMassSum); // eq. 16 along n: r × n = 0 for spheres, so J_α = 0
            if (_planar)
            {
                // In a planar step t₁ = n × ẑ lies in the plane and t₂ = −ẑ, along which nothing moves (IsPlanar): its
                // friction is exactly zero and is left out, and I⁻¹ ẑ = I⁻¹_zz ẑ (see MeasureFrames for the 3-D tangents).
                float spinA = rhoA * a.InverseInertiaZ, spinB = -rhoB * b.InverseInertiaZ;
                c.PlanarSpinA = spinA;
                c.PlanarSpinB = spinB;
                c.TangentMass1 = InverseOrZero(inverseMassSum + rhoA * spinA - rhoB * spinB);
                float friction = Vectors.Dot(_stepImpulses[k].Friction, ContactConstraint.PlanarTangentOf(normal)); // from the local normal, not read back
                float none = 0; // the disc's clamp with p₂ = 0 rounds as the 3-D path does (Math.Clamp may not)
                ClampFriction(ref friction, ref none, c.Friction * c.NormalImpulse);
                c.FrictionImpulse1 = friction;
            }
        }

        if (!_planar)
        {
            MeasureFrames(framed, listed);
        }

        return listed - start;
    }

    /// <summary>
    /// The 3-D friction of the contacts measured solved, <see cref="_active"/>[<paramref name="start"/>,
    /// <paramref name="end"/>): tangents, the spins a unit friction impulse along each causes, the tangents' masses,
    /// and last substep's friction on the new tangents.
    /// </summary>
    /// <remarks>
    /// A loop of its own, run on every <see cref="FramesBlock"/> contacts listed: each contact's measure is one long chain
    /// of dependent steps (the normal's square root and division, then the tangent's), and a shorter loop lets the
    /// processor work on several contacts' chains at once, while a block's constraints are still in the nearest cache.
    /// Bit for bit what measuring each contact in one go gives.
    /// </remarks>
    private void MeasureFrames(int start, int end)
    {
        for (int i = start; i < end; i++)
        {
            int k = _active[i];
            ref ContactConstraint c = ref _constraints[k];
            float inverseMassSum = _bodies[c.A].InverseMass + _bodies[c.B].InverseMass;

            // Tangents with t₂ = n × t₁, so that r_A × t₁ = −ρ_A t₂, r_A × t₂ = ρ_A t₁ (and for B with +ρ_B): the spins
            // I⁻¹ (r × t) a unit friction impulse causes (eq. 15) and the denominators of eq. 16 along t need no cross
            // product.
            ref TangentFrame f = ref _frames[k];
            Vectors.UncheckedTangents(c.Normal, out Vector3 t1, out Vector3 t2); // a unit normal: measured, or a plane's
            f.Tangent1 = t1;
            f.Tangent2 = t2;
            float rhoA = c.RhoA, rhoB = c.RhoB;
            float kA = _inertiaScalars[c.A], kB = _inertiaScalars[c.B];
            if (!float.IsNaN(kA) && !float.IsNaN(kB))
            {
                // Spheres (I⁻¹ = k·1, or 0 for the ground): both tangents see 1/m_A + 1/m_B + k_A ρ_A² + k_B ρ_B².
                f.SpinA1 = -rhoA * kA * t2;
                f.SpinB1 = rhoB * kB * t2;
                f.SpinA2 = rhoA * kA * t1;
                f.SpinB2 = -rhoB * kB * t1;
                c.TangentMass1 = c.TangentMass2 = InverseOrZero(inverseMassSum + kA * rhoA * rhoA + kB * rhoB * rhoB);
            }
            else
            {
                Vector3 spinA1 = -rhoA * _inverseInertias[c.A].Transform(t2), spinB1 = rhoB * _inverseInertias[c.B].Transform(t2);
                Vector3 spinA2 = rhoA * _inverseInertias[c.A].Transform(t1), spinB2 = -rhoB * _inverseInertias[c.B].Transform(t1);
                f.SpinA1 = spinA1;
                f.SpinB1 = spinB1;
                f.SpinA2 = spinA2;
                f.SpinB2 = spinB2;
                c.TangentMass1 = InverseOrZero(inverseMassSum + Vectors.Dot(rhoB * spinB1 - rhoA * spinA1, t2));
                c.TangentMass2 = InverseOrZero(inverseMassSum + Vectors.Dot(rhoA * spinA2 - rhoB * spinB2, t1));
            }

            Vector3 friction = _stepImpulses[k].Friction;
            float friction2 = Vectors.Dot(friction, t2), friction1 = Vectors.Dot(friction, t1);
            ClampFriction(ref friction1, ref friction2, c.Friction * c.NormalImpulse);
            c.FrictionImpulse1 = friction1;
            c.FrictionImpulse2 = friction2;
        }
    }

    private static bool IsIdentity(ReadOnlySpan<int> order)
    {
        for (int k = 0; k < order.Length; k++)
        {
            if (order[k] != k)
            {
                return false;
            }
        }

        return true;
    }

    private int SlotOf(RigidBody body) => body.index < 0 ? 0 : _slotOf[body.index]; // the ground (index −1) is slot 0

    private static float InverseOrZero(float denominator) => denominator > 0 ? 1f / denominator : 0f;
}
