using System;
using System.Runtime.CompilerServices;
#if NET8_0_OR_GREATER
using System.Runtime.Intrinsics;
#endif

namespace SimpleDynamics.Response;

/// <summary>
/// Four contacts of a planar sweep at once, in the lanes of one vector, where four in a row move eight different
/// bodies. Gauss–Seidel solves each contact with what the ones before it did; a contact that shares no body with the
/// three before it reads nothing they wrote, so solving the four together is solving them one after the other: the
/// same order, the same arithmetic in each lane (no fused multiply–add, the clamps written as the scalar path's
/// comparisons), the same result bit for bit on every processor, with or without vectors (tested).
/// </summary>
/// <remarks>
/// <para>Why: in a landing pile a substep spends tens to hundreds of sweeps, and a sweep is bound by the instructions
/// each contact takes, not by contacts waiting for each other (a scratch copy of the planar solve over a landing
/// pile's contacts took as long, 9 ns a contact, with every contact given bodies of its own). Neighbours in the sweep
/// order share a body for only 2–3 % of the contacts (benchmarks/README.md, twenty-third session).</para>
/// <para>How: once a substep's first sweep has found the contacts unsolved, so that more sweeps follow, the active
/// contacts are cut into runs of four that move eight different bodies, and single contacts between them
/// (<see cref="PlanFours"/>). Each four's geometry, which no sweep changes, is written once in lanes
/// (PlanarFour); the sweeps then load it whole and gather only the impulses and the bodies' velocities.
/// The order stays the bottom-up one that carries a pile's weight down in few sweeps (see
/// <see cref="OrderAlongGravity"/>); Box2D v3 and BEPUphysics v2 solve in lanes too, but contacts they first sort
/// into colours, which changes the order of the solve. Planar steps only (a 3-D contact reads its tangent frame too);
/// on netstandard2.1, and where vectors are not accelerated, every contact is solved alone.</para>
/// </remarks>
public sealed partial class SequentialImpulseSolver
{
    private byte[] _fourStarts = new byte[InitialCapacity]; // per place in _active: 1 where a planned four begins

    /// <summary>Whether planar sweeps solve independent runs of four contacts in vector lanes (default on); tests compare both.</summary>
    internal bool SolvesInFours { get; set; } = true;

    /// <summary>Contacts that the plans of the step begun last put in fours, summed over its planned substeps, for tests.</summary>
    internal int PlannedInFoursThisStep { get; private set; }

    /// <summary>
    /// Cuts this substep's active contacts into fours that move eight different bodies and single contacts, and writes
    /// each four's geometry in lanes, if the step is planar and vectors are accelerated; the plan holds until the
    /// contacts are measured again. Runs in strips like the sweeps, so no four straddles two strips.
    /// </summary>
    private void PlanFours()
    {
#if NET8_0_OR_GREATER
        if (_planar && SolvesInFours && Vector128.IsHardwareAccelerated && _activeCount >= 4)
        {
            Buffers.EnsureCapacity(ref _fourStarts, _activeCount);
            Buffers.EnsureCapacity(ref _fours, _activeCount / 4 + 1);
            RunPass(StripPass.PlanFours);
            for (int slot = 0; slot < _resultSlots; slot++)
            {
                PlannedInFoursThisStep += _stripCounts[slot * Padding + 4];
            }

            _foursPlanned = true;
        }
#endif
    }

    /// <summary>
    /// How many contacts a sweep solves from place <paramref name="i"/> of <see cref="_active"/> on: four where this
    /// substep's plan has a four begin (<see cref="PlanFours"/>), else the one there.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // in the sweeps' loops
    private int ContactsSolvedFrom(int i) =>
#if NET8_0_OR_GREATER
        _foursPlanned && _fourStarts[i] != 0 ? 4 : 1;
#else
        1;
#endif

    /// <summary>
    /// Solves the contact at place <paramref name="i"/> of <see cref="_active"/>, or the four planned from there
    /// (<see cref="PlanFours"/>); returns how many it solved.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // in the unmeasured sweep's loop
    private int SolveNext(int i)
    {
#if NET8_0_OR_GREATER
        if (ContactsSolvedFrom(i) == 4)
        {
            var unread = new FourMeasures();
            SolvePlanarFour(i, ref unread);
            return 4;
        }
#endif
        SolveContact(_active[i]);
        return 1;
    }

    /// <summary>Drops the plan of the last substep: its contacts are measured again (<see cref="MeasureConstraints"/>).</summary>
    private void ForgetFours()
    {
#if NET8_0_OR_GREATER
        _foursPlanned = false;
#endif
    }

#if NET8_0_OR_GREATER
    private bool _foursPlanned; // whether this substep's sweeps follow the plan (PlanFours)
    private PlanarFour[] _fours = new PlanarFour[InitialCapacity]; // per place in _active / 4: a planned four's geometry

    /// <summary>
    /// What a sweep reads of four contacts that no sweep changes, in lanes: the geometry measured at the start of the
    /// substep (<see cref="ContactConstraint"/>), and the bodies' inverse masses. 176 bytes, where the four constraints
    /// take 256.
    /// </summary>
    private struct PlanarFour
    {
        public Vector128<float> NormalX, NormalY, NormalMass, TangentMass, Friction, RhoA, RhoB, SpinA, SpinB;
        public Vector128<float> InverseMassA, InverseMassB;
    }

    /// <summary>
    /// The plan of <see cref="PlanFours"/> for <see cref="_active"/>[<paramref name="start"/>..<paramref name="end"/>);
    /// keeps in the counts of <paramref name="slot"/> how many contacts it put in fours.
    /// </summary>
    private void PlanFoursRange(int slot, int start, int end)
    {
        int inFours = 0;
        for (int i = start; i < end;)
        {
            if (i + 4 <= end && MoveDifferentBodies(i))
            {
                _fourStarts[i] = 1;
                WriteFour(i);
                i += 4;
                inFours += 4;
            }
            else
            {
                _fourStarts[i++] = 0;
            }
        }

        _stripCounts[slot * Padding + 4] = inFours;
    }

    /// <summary>Whether the four contacts from place <paramref name="i"/> of <see cref="_active"/> move eight different bodies.</summary>
    private bool MoveDifferentBodies(int i)
    {
        ref ContactConstraint c0 = ref _constraints[_active[i]];
        ref ContactConstraint c1 = ref _constraints[_active[i + 1]];
        ref ContactConstraint c2 = ref _constraints[_active[i + 2]];
        ref ContactConstraint c3 = ref _constraints[_active[i + 3]];
        var a = Vector128.Create(c0.A, c1.A, c2.A, c3.A);
        var b = Vector128.Create(c0.B, c1.B, c2.B, c3.B);

        // Each lane against the lanes one, two and three further on: every pair of the eight slots once at least.
        Vector128<int> a1 = Vector128.Shuffle(a, Vector128.Create(1, 2, 3, 0));
        Vector128<int> a2 = Vector128.Shuffle(a, Vector128.Create(2, 3, 0, 1));
        Vector128<int> b1 = Vector128.Shuffle(b, Vector128.Create(1, 2, 3, 0));
        Vector128<int> b2 = Vector128.Shuffle(b, Vector128.Create(2, 3, 0, 1));
        Vector128<int> b3 = Vector128.Shuffle(b, Vector128.Create(3, 0, 1, 2));
        Vector128<int> same = Vector128.Equals(a, a1) | Vector128.Equals(a, a2)
            | Vector128.Equals(b, b1) | Vector128.Equals(b, b2)
            | Vector128.Equals(a, b) | Vector128.Equals(a, b1) | Vector128.Equals(a, b2) | Vector128.Equals(a, b3);
        return same == Vector128<int>.Zero;
    }

    /// <summary>Writes the geometry of the four contacts from place <paramref name="i"/> in lanes (<see cref="PlanarFour"/>).</summary>
    private void WriteFour(int i)
    {
        ref ContactConstraint c0 = ref _constraints[_active[i]];
        ref ContactConstraint c1 = ref _constraints[_active[i + 1]];
        ref ContactConstraint c2 = ref _constraints[_active[i + 2]];
        ref ContactConstraint c3 = ref _constraints[_active[i + 3]];
        ref PlanarFour four = ref _fours[i >> 2]; // fours begin at least four places apart: one slot each
        four.NormalX = Vector128.Create(c0.Normal.X, c1.Normal.X, c2.Normal.X, c3.Normal.X);
        four.NormalY = Vector128.Create(c0.Normal.Y, c1.Normal.Y, c2.Normal.Y, c3.Normal.Y);
        four.NormalMass = Vector128.Create(c0.NormalMass, c1.NormalMass, c2.NormalMass, c3.NormalMass);
        four.TangentMass = Vector128.Create(c0.TangentMass1, c1.TangentMass1, c2.TangentMass1, c3.TangentMass1);
        four.Friction = Vector128.Create(c0.Friction, c1.Friction, c2.Friction, c3.Friction);
        four.RhoA = Vector128.Create(c0.RhoA, c1.RhoA, c2.RhoA, c3.RhoA);
        four.RhoB = Vector128.Create(c0.RhoB, c1.RhoB, c2.RhoB, c3.RhoB);
        four.SpinA = Vector128.Create(c0.PlanarSpinA, c1.PlanarSpinA, c2.PlanarSpinA, c3.PlanarSpinA);
        four.SpinB = Vector128.Create(c0.PlanarSpinB, c1.PlanarSpinB, c2.PlanarSpinB, c3.PlanarSpinB);
        four.InverseMassA = Vector128.Create(
            _bodies[c0.A].InverseMass, _bodies[c1.A].InverseMass, _bodies[c2.A].InverseMass, _bodies[c3.A].InverseMass);
        four.InverseMassB = Vector128.Create(
            _bodies[c0.B].InverseMass, _bodies[c1.B].InverseMass, _bodies[c2.B].InverseMass, _bodies[c3.B].InverseMass);
    }

    /// <summary>
    /// <see cref="SolvePlanarContact"/> for the four contacts planned from place <paramref name="i"/> of
    /// <see cref="_active"/>, one in each lane, and adds what it changed to <paramref name="measures"/>. Every line is the scalar
    /// path's, lane by lane; its early return (a contact that pushes nothing and has no friction) keeps the lane's
    /// bodies as they were.
    /// </summary>
    private void SolvePlanarFour(int i, ref FourMeasures measures)
    {
        ref PlanarFour four = ref _fours[i >> 2];
        ref ContactConstraint c0 = ref _constraints[_active[i]];
        ref ContactConstraint c1 = ref _constraints[_active[i + 1]];
        ref ContactConstraint c2 = ref _constraints[_active[i + 2]];
        ref ContactConstraint c3 = ref _constraints[_active[i + 3]];
        ref SolverBody a0 = ref _bodies[c0.A], a1 = ref _bodies[c1.A], a2 = ref _bodies[c2.A], a3 = ref _bodies[c3.A];
        ref SolverBody b0 = ref _bodies[c0.B], b1 = ref _bodies[c1.B], b2 = ref _bodies[c2.B], b3 = ref _bodies[c3.B];

        var velocityAX = Vector128.Create(a0.Linear.X, a1.Linear.X, a2.Linear.X, a3.Linear.X);
        var velocityAY = Vector128.Create(a0.Linear.Y, a1.Linear.Y, a2.Linear.Y, a3.Linear.Y);
        var spinA = Vector128.Create(a0.Angular.Z, a1.Angular.Z, a2.Angular.Z, a3.Angular.Z);
        var velocityBX = Vector128.Create(b0.Linear.X, b1.Linear.X, b2.Linear.X, b3.Linear.X);
        var velocityBY = Vector128.Create(b0.Linear.Y, b1.Linear.Y, b2.Linear.Y, b3.Linear.Y);
        var spinB = Vector128.Create(b0.Angular.Z, b1.Angular.Z, b2.Angular.Z, b3.Angular.Z);
        var oldNormal = Vector128.Create(c0.NormalImpulse, c1.NormalImpulse, c2.NormalImpulse, c3.NormalImpulse);
        var oldFriction = Vector128.Create(c0.FrictionImpulse1, c1.FrictionImpulse1, c2.FrictionImpulse1, c3.FrictionImpulse1);
        Vector128<float> nx = four.NormalX, ny = four.NormalY, zero = Vector128<float>.Zero;

        // The normal impulse of eq. 16, accumulated and clamped to ≥ 0 as MathF.Max(x, 0) does (NaN stays NaN).
        Vector128<float> vx = velocityAX - velocityBX, vy = velocityAY - velocityBY;
        Vector128<float> unclamped = oldNormal - four.NormalMass * (vx * nx + vy * ny);
        Vector128<float> normal = Vector128.ConditionalSelect(
            Vector128.GreaterThan(unclamped, zero) | ~Vector128.Equals(unclamped, unclamped), unclamped, zero);
        Vector128<float> pushed = normal - oldNormal;

        // Friction along t₁ = (n_y, −n_x), clamped to [−μ P_n, μ P_n] as Math.Clamp does, where the contact pushed or rubbed.
        Vector128<float> rubs = Vector128.GreaterThan(oldNormal, zero) | ~Vector128.Equals(oldFriction, zero);
        Vector128<float> limit = four.Friction * oldNormal, lowest = -limit;
        Vector128<float> sliding = vx * ny + vy * -nx + (four.RhoA * spinA + four.RhoB * spinB);
        Vector128<float> friction = oldFriction - four.TangentMass * sliding;
        friction = Vector128.ConditionalSelect(Vector128.LessThan(friction, lowest), lowest,
            Vector128.ConditionalSelect(Vector128.GreaterThan(friction, limit), limit, friction));
        Vector128<float> change = Vector128.ConditionalSelect(rubs, friction - oldFriction, zero);
        friction = Vector128.ConditionalSelect(rubs, friction, oldFriction);

        // ApplyPlanar: P = p_n n + p_1 t₁ to A, −P to B (eq. 6), and the spins about z (eq. 15).
        Vector128<float> moves = rubs | ~Vector128.Equals(normal, oldNormal);
        Vector128<float> px = pushed * nx + change * ny, py = pushed * ny + change * -nx;
        velocityAX = Vector128.ConditionalSelect(moves, velocityAX + px * four.InverseMassA, velocityAX);
        velocityAY = Vector128.ConditionalSelect(moves, velocityAY + py * four.InverseMassA, velocityAY);
        spinA = Vector128.ConditionalSelect(moves, spinA + change * four.SpinA, spinA);
        velocityBX = Vector128.ConditionalSelect(moves, velocityBX - px * four.InverseMassB, velocityBX);
        velocityBY = Vector128.ConditionalSelect(moves, velocityBY - py * four.InverseMassB, velocityBY);
        spinB = Vector128.ConditionalSelect(moves, spinB - change * four.SpinB, spinB);

        Store(ref c0, ref a0, ref b0, 0, normal, friction, velocityAX, velocityAY, spinA, velocityBX, velocityBY, spinB);
        Store(ref c1, ref a1, ref b1, 1, normal, friction, velocityAX, velocityAY, spinA, velocityBX, velocityBY, spinB);
        Store(ref c2, ref a2, ref b2, 2, normal, friction, velocityAX, velocityAY, spinA, velocityBX, velocityBY, spinB);
        Store(ref c3, ref a3, ref b3, 3, normal, friction, velocityAX, velocityAY, spinA, velocityBX, velocityBY, spinB);
        measures.Add(oldNormal, normal, four.NormalMass);
    }

    /// <summary>Writes lane <paramref name="lane"/> back to its contact and bodies.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // the lane a constant
    private static void Store(
        ref ContactConstraint c, ref SolverBody a, ref SolverBody b, int lane, Vector128<float> normal,
        Vector128<float> friction, Vector128<float> velocityAX, Vector128<float> velocityAY, Vector128<float> spinA,
        Vector128<float> velocityBX, Vector128<float> velocityBY, Vector128<float> spinB)
    {
        c.NormalImpulse = normal.GetElement(lane);
        c.FrictionImpulse1 = friction.GetElement(lane);
        a.Linear.X = velocityAX.GetElement(lane);
        a.Linear.Y = velocityAY.GetElement(lane);
        a.Angular.Z = spinA.GetElement(lane);
        b.Linear.X = velocityBX.GetElement(lane);
        b.Linear.Y = velocityBY.GetElement(lane);
        b.Angular.Z = spinB.GetElement(lane);
    }

#endif

    /// <summary>
    /// Keeps in the results of <paramref name="slot"/> what a measured sweep over a range found: the largest change of
    /// a normal velocity, of a normal impulse, and the largest normal impulse, of the contacts it solved one at a time
    /// and of those it solved four at once (<paramref name="fours"/>).
    /// </summary>
    private void KeepSweepResults(int slot, float largestSpeedChange, float largestChange, float largestImpulse, in FourMeasures fours)
    {
#if NET8_0_OR_GREATER
        largestSpeedChange = FourMeasures.Largest(largestSpeedChange, fours.SpeedChange);
        largestChange = FourMeasures.Largest(largestChange, fours.Change);
        largestImpulse = FourMeasures.Largest(largestImpulse, fours.Impulse);
#endif
        _stripResults[slot * Padding] = largestSpeedChange;
        _stripResults[slot * Padding + 1] = largestChange;
        _stripResults[slot * Padding + 2] = largestImpulse;
    }

    /// <summary>
    /// What a measured sweep keeps of four contacts solved together (SolvePlanarFour), lane by lane as
    /// <see cref="SolveContactMeasured"/> does for one: the largest change of a normal velocity, of a normal impulse, and
    /// the largest normal impulse. Empty where nothing is solved in lanes (netstandard2.1).
    /// </summary>
    private struct FourMeasures
    {
#if NET8_0_OR_GREATER
        public Vector128<float> SpeedChange, Change, Impulse;

        [MethodImpl(MethodImplOptions.AggressiveInlining)] // at the end of SolvePlanarFour
        public void Add(Vector128<float> oldNormal, Vector128<float> normal, Vector128<float> normalMass)
        {
            Vector128<float> change = Vector128.Abs(normal - oldNormal);
            Vector128<float> speedChange = Vector128.ConditionalSelect(
                Vector128.GreaterThan(normalMass, Vector128<float>.Zero), change / normalMass, Vector128<float>.Zero);
            SpeedChange = Larger(SpeedChange, speedChange);
            Change = Larger(Change, change);
            Impulse = Larger(Impulse, normal);
        }

        /// <summary>MathF.Max lane by lane for what the sweeps measure (never −0): NaN wins.</summary>
        private static Vector128<float> Larger(Vector128<float> largest, Vector128<float> value) =>
            Vector128.ConditionalSelect(
                Vector128.GreaterThan(value, largest) | ~Vector128.Equals(value, value), value, largest);

        /// <summary>MathF.Max of <paramref name="largest"/> and the lanes of <paramref name="lanes"/>.</summary>
        public static float Largest(float largest, Vector128<float> lanes) =>
            MathF.Max(MathF.Max(MathF.Max(largest, lanes.GetElement(0)), MathF.Max(lanes.GetElement(1), lanes.GetElement(2))),
                lanes.GetElement(3));
#endif
    }
}
