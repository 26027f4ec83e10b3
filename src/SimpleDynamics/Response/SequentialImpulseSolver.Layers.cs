using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>
/// The layer correction of a deep pile: between its extra sweeps, each horizontal band of the pile scales all its
/// contacts' normal impulses by one factor, the factors chosen together so that the kinetic energy falls as far as
/// such a change can take it. Gauss–Seidel then smooths what the bands cannot express.
/// </summary>
/// <remarks>
/// <para><b>Why.</b> A Gauss–Seidel sweep carries a change of support only a few layers; what a deep pile lacks is
/// smooth across its height (every contact of a region pressing a little too little), and sweeps remove such an error
/// in of the order of depth² sweeps. Measured on the 16,000-disc 2-D pit (about 108 layers) loaded from a saved pour,
/// 480 substeps: 71 % ended unconverged after their whole budget (4 + 163 sweeps), leaving bodies moving a few cm/s,
/// whose gaps opened and closed (5.9 impacts a step), which kept the pile stirring (benchmarks/README.md, 2026-12-03,
/// sixth session). A correction on a coarse grid removes the smooth error at once: the two-level idea of multigrid
/// (W. L. Briggs, V. E. Henson, S. F. McCormick, <i>A Multigrid Tutorial</i>, 2nd ed., SIAM, 2000, ch. 3 and 5), with
/// the coarse unknowns built by scaling the current impulses, as aggregation methods do.</para>
/// <para><b>The coarse problem.</b> With the friction impulses held, the kinetic energy after the contact impulses λ
/// is E(λ) = E₀ + λ·(J v₀) + ½ λᵀ A λ, A = J M⁻¹ Jᵀ (J: each contact's normal, eq. 13–16; r × n = 0 for spheres,
/// so normal impulses turn nothing); a sweep's normal step minimises it one contact at a time (eq. 16, target
/// v_n = 0). (With a kinematic body moving, J v₀ holds its velocity too, and E is the energy less the work its pushes
/// do: the quantity the sweeps lower, which the correction lowers as well.) Band b scales its impulses by 1 + α_b:
/// λ' = λ + P α, where column b of P holds λ_i for the contacts of band b. The α that minimises E(λ + P α) solves the
/// Galerkin system (Pᵀ A P) α = −Pᵀ v_n, v_n the contacts' normal velocities now; a band's contacts touch only its
/// own and the neighbouring bands' (a band is taller than any body), so Pᵀ A P is tridiagonal, and it is built
/// exactly as Σ over bodies of (1/m) G_sᵀ G_s, G_s holding per band the sum of ±λ_i n_i over the body's contacts in
/// it; the right-hand side is Σ over bodies of −v_s · G_s (v_n,i = n_i · (v_A − v_B) for spheres; a moving kinematic
/// body's share is kept with the body it pushes), so one pass over the contacts gathers everything the system needs.
/// The sweep before the correction is that pass: it leaves each contact's λ_i final for the sweep, and adds it to its
/// bodies' sums there and then.</para>
/// <para><b>Laws.</b> Each factor is limited to ±½, so every impulse is scaled by at least ½ and stays ≥ 0; the step
/// along the limited factors d is t d with t = min(1, dᵀr / dᵀHd) (H = Pᵀ A P, r = −Pᵀ v_n), the exact minimum of the
/// convex E on that line, or none when dᵀr ≤ 0: so the correction never adds kinetic energy (to rounding). A contact's
/// impulse acts equally and oppositely on its two bodies, so momentum changes only through the ground and walls. A
/// sweep always follows (friction is clamped to the new cone there). The tests audit all three on generated deep
/// piles (LayerCorrectionTests).</para>
/// <para><b>When.</b> Only in a substep that has spent 2 × <see cref="ExtraIterations"/> extra sweeps without
/// converging, then after every second further sweep (<see cref="LayerCorrectionInterval"/>): a correction costs
/// about as much as a sweep, and a pile that is still landing converges, or not, by sweeps alone. After every extra
/// sweep from the first instead, 2,400 discs poured 60 deep into a box 40 wide took 5.7 s to fall asleep instead of
/// 3.3 s, with no fewer sweeps (3.7 s with the rule); on the 16,000-disc pit loaded from a saved pour, 180 steps took
/// 71 s instead of 63 s without (59 s with the rule; benchmarks/README.md, 2026-12-04). After each further sweep
/// instead of every second, four pours of that pit, spawn to asleep, took 156–194 s of wall time instead of
/// 123–156 s (mean 173 s against 140 s), and 60 steps of the saved pile 630 sweeps a step instead of 503 (every
/// third: 649, fourth: 566, eighth: 679; benchmarks/README.md, 2026-12-04, ninth session).</para>
/// </remarks>
public sealed partial class SequentialImpulseSolver
{
    /// <summary>A band's height, in mean diameters of the pile's bodies (see <see cref="LayerCorrection"/>).</summary>
    private const float BandDiameters = 3.5f;

    /// <summary>No correction is tried over more bands than this (a world thousands of bodies tall, or spread far).</summary>
    private const int MostBands = 4096;

    private int[] _bandOf = new int[InitialCapacity]; // per active contact (position in _active): its band
    private Vector3[] _bandSums = new Vector3[2 * InitialCapacity]; // per slot, per band parity: Σ ±λ_i n_i of its contacts
    private double[] _bandResidualSums = new double[2 * InitialCapacity]; // the same: what the velocity of a body no impulse moves (a kinematic one) adds to −Pᵀ v_n
    private int[] _bandOfSum = new int[2 * InitialCapacity]; // per slot, per band parity: 1 + the band summed there (0: none)
    private bool _bandSumsEmpty = true; // the arrays above hold zeros everywhere (ApplyBandFactors empties them as it reads)
    private bool _kinematicPushes; // some body's _bandResidualSums are not zero (only a moving kinematic body writes them)
    private bool _gatheringBands; // the sweep running adds its contacts to the band sums
    private bool _bandScalePending; // a correction has moved the bodies; the next sweep scales its impulses, contact by contact
    private float _meanDiameter; // of the bodies of the pile's contacts, this step (PileMeasure)
    private bool _bandsAssigned; // in this substep (MeasureConstraints clears it)
    private int _bandCount;

    /// <summary>
    /// Whether a deep pile's extra sweeps (more than <see cref="DeepPileLayers"/> bodies deep, under gravity) are
    /// helped by a correction across its layers (default on): once a substep has spent 2 × <see cref="ExtraIterations"/>
    /// extra sweeps without converging, after each further one, every horizontal band of the pile scales its contacts'
    /// normal impulses by one factor, the factors chosen together to lower the kinetic energy as far as such factors
    /// can. It never adds energy and keeps every impulse pushing. Without it, most substeps of the 16,000-disc 2-D pit
    /// ended unconverged and the pile kept stirring after its pour.
    /// </summary>
    public bool LayerCorrection { get; set; } = true;

    /// <summary>Layer corrections applied in the step begun last, for tests.</summary>
    internal int LayerCorrectionsThisStep { get; private set; }

    /// <summary>For tests: check every layer correction against the laws it keeps (<see cref="Audit"/>), at two passes over the bodies.</summary>
    internal bool AuditLayerCorrections { get; set; }

    /// <summary>What the audited layer corrections did, for tests (see <see cref="LayerCorrectionAudit"/>).</summary>
    internal LayerCorrectionAudit Audit { get; } = new();

    /// <summary>
    /// Once a substep has spent 2 × <see cref="ExtraIterations"/> extra sweeps, a layer correction follows every this
    /// many further sweeps (see the file's remarks, "When"). Internal: measured, not a user's choice.
    /// </summary>
    internal int LayerCorrectionInterval { get; set; } = 2;

    /// <summary>Whether this step's pile is deep enough for the layer correction (see <see cref="LayerCorrection"/>).</summary>
    private bool CorrectsLayers => LayerCorrection && _extraSweeps > _extraIterations && _gravity != Vector3.Zero;

    /// <summary>
    /// Whether extra sweep number <paramref name="extra"/> (from 0) of this substep gathers and is followed by a layer
    /// correction: from sweep 2 × <see cref="ExtraIterations"/> on, every <see cref="LayerCorrectionInterval"/>th,
    /// never the last (a sweep must follow a correction: it scales the impulses, <see cref="ApplyBandFactors"/>).
    /// </summary>
    private bool CorrectsLayersAfter(int extra) =>
        extra >= 2 * _extraIterations && extra + 1 < _extraSweeps && CorrectsLayers
        && (extra - 2 * _extraIterations) % LayerCorrectionInterval == 0;

    /// <summary>
    /// One measured sweep (<see cref="Sweep"/>) that gathers the band sums as it leaves each contact, then, unless it
    /// converged, the layer correction (see the file's remarks): the tridiagonal Galerkin system, its solution, and the
    /// bodies moved by it (the impulses follow in the next sweep, <see cref="ApplyBandFactors"/>). Corrects nothing
    /// when the system cannot be formed (fewer than two bands or too many, a body whose contacts span more than two
    /// bands) or its solution is not finite. Returns whether the sweep converged.
    /// </summary>
    private bool SweepAndCorrectLayers()
    {
        if (!_bandsAssigned)
        {
            _bandCount = AssignBands(); // the positions stay put through the substep's sweeps, and so do the bands
            _bandsAssigned = true;
        }

        if (_bandCount < 2)
        {
            return Sweep() <= SettledTolerance;
        }

        PrepareBandSums();
        bool converged = Sweep(gatherBands: true) <= SettledTolerance;
        bool formed = LargestOfPass(3) == 0;
        if (converged || !formed)
        {
            EmptyBandSums();
            return converged;
        }

        BuildBandSystem(_bandCount);
        if (!SolveBandSystem(_bandCount))
        {
            EmptyBandSums();
            return false;
        }

        if (AuditLayerCorrections)
        {
            Audit.Before(this);
        }

        ApplyBandFactors();
        LayerCorrectionsThisStep++;
        if (AuditLayerCorrections)
        {
            Audit.After(this);
        }

        return false;
    }

    /// <summary>
    /// Gives each active contact its band from its height along −g (the mean of its bodies' centres', or its body's
    /// for a plane contact). A band is <see cref="BandDiameters"/> mean diameters tall, and never less than 2.5 of the
    /// largest radius, so that a body's contacts lie in at most two neighbouring bands. Returns the number of bands
    /// (0 if more than <see cref="MostBands"/>).
    /// </summary>
    private int AssignBands()
    {
        int n = _activeCount;
        Buffers.EnsureCapacity(ref _bandOf, n);
        Vector3 up = -Vector3.Normalize(_gravity);
        float lowest = float.PositiveInfinity, highest = float.NegativeInfinity, largestRadius = 0;
        for (int i = 0; i < n; i++)
        {
            ref ContactConstraint c = ref _constraints[_active[i]];
            float height = ContactHeight(ref c, up);
            lowest = MathF.Min(lowest, height);
            highest = MathF.Max(highest, height);
            largestRadius = MathF.Max(largestRadius, MathF.Max(_radii[c.A], _radii[c.B]));
        }

        float bandHeight = MathF.Max(BandDiameters * _meanDiameter, 2.5f * largestRadius);
        float span = (highest - lowest) / bandHeight;
        if (!(span < MostBands)) // false for NaN too
        {
            return 0;
        }

        for (int i = 0; i < n; i++)
        {
            _bandOf[i] = (int)((ContactHeight(ref _constraints[_active[i]], up) - lowest) / bandHeight);
        }

        return (int)span + 1;
    }

    private float ContactHeight(ref ContactConstraint c, Vector3 up) => c.IsPlaneContact
        ? Vectors.Dot(_positions[c.A], up)
        : 0.5f * Vectors.Dot(_positions[c.A] + _positions[c.B], up);

    /// <summary>
    /// Makes room for the band sums of every slot, and empties them if a gathering was left unfinished.
    /// </summary>
    private void PrepareBandSums()
    {
        int slots = _step!.Bodies.Length + 1;
        Buffers.EnsureCapacity(ref _bandSums, 2 * slots);
        Buffers.EnsureCapacity(ref _bandOfSum, 2 * slots);
        Buffers.EnsureCapacity(ref _bandResidualSums, 2 * slots);
        if (!_bandSumsEmpty)
        {
            EmptyBandSums();
        }

        _bandSumsEmpty = false; // until ApplyBandFactors or EmptyBandSums has emptied them again
    }

    private void EmptyBandSums()
    {
        Array.Clear(_bandSums, 0, _bandSums.Length);
        Array.Clear(_bandOfSum, 0, _bandOfSum.Length);
        EmptyKinematicPushes();
        _bandSumsEmpty = true;
    }

    private void EmptyKinematicPushes()
    {
        if (_kinematicPushes)
        {
            Array.Clear(_bandResidualSums, 0, _bandResidualSums.Length);
            _kinematicPushes = false;
        }
    }

    /// <summary>
    /// The measured sweep of <see cref="Sweep"/> over <see cref="_active"/>[<paramref name="start"/>..<paramref name="end"/>),
    /// which first scales each contact's impulse by the correction just applied to its bodies, if one is pending
    /// (<see cref="ScaledImpulse"/>), and adds each pressed contact, as the sweep leaves it, to its bodies' band sums if
    /// a correction is being gathered (<see cref="GatherBand"/>); keeps in result 3 whether some body's contacts spanned
    /// too many bands. Runs in strips like every sweep: a strip's contacts move only its own bodies, and the seam
    /// contacts come after, so every sum is taken in storage order on any number of threads.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // keeps RunRange, whose sweeps are the hot loop, as small as before
    private void SweepWithBandsRange(int slot, int start, int end)
    {
        float largestChange = 0, largestImpulse = 0, largestSpeedChange = 0;
        bool formed = true, scale = _bandScalePending, gather = _gatheringBands;
        var fours = new FourMeasures();
        for (int i = start; i < end;)
        {
            int count = ContactsSolvedFrom(i);
            for (int p = i; scale && p < i + count; p++)
            {
                ref ContactConstraint scaled = ref _constraints[_active[p]];
                scaled.NormalImpulse = ScaledImpulse(ref scaled, p);
            }

#if NET8_0_OR_GREATER
            if (count == 4)
            {
                SolvePlanarFour(i, ref fours);
            }
            else
#endif
            {
                int k = _active[i];
                largestSpeedChange = MathF.Max(largestSpeedChange, SolveContactMeasured(k, out float change));
                largestChange = MathF.Max(largestChange, change);
                largestImpulse = MathF.Max(largestImpulse, _constraints[k].NormalImpulse);
            }

            for (int end4 = i + count; i < end4; i++)
            {
                ref ContactConstraint c = ref _constraints[_active[i]];
                if (gather && c.NormalImpulse > 0 && formed)
                {
                    formed = GatherBand(ref c, _bandOf[i]);
                }
            }
        }

        KeepSweepResults(slot, largestSpeedChange, largestChange, largestImpulse, fours);
        _stripResults[slot * Padding + 3] = formed ? 0f : 1f;
    }

    /// <summary>
    /// Adds a pressed contact of band <paramref name="band"/> to its bodies' band sums: +λ n to A's, −λ n to B's (the
    /// directions it pushes them). Where one body cannot move, the other also keeps the term of −λ v_n that the
    /// immovable body's velocity gives (zero for the ground and walls; a kinematic body may move). Returns false if a
    /// movable body's contacts lie in two bands of the same parity, or in two that are not neighbours.
    /// </summary>
    private bool GatherBand(ref ContactConstraint c, int band)
    {
        Vector3 push = c.NormalImpulse * c.Normal;
        if (!AddToBandSum(c.A, band, push) || !AddToBandSum(c.B, band, -push))
        {
            return false;
        }

        bool movesA = _bodies[c.A].InverseMass > 0, movesB = _bodies[c.B].InverseMass > 0;
        if (movesA != movesB)
        {
            // −λ v_n = −λ n · v_A + λ n · v_B: the movable body's own term comes from its sums (BuildBandSystem).
            int mover = movesA ? c.A : c.B;
            double other = c.NormalImpulse * (double)Vectors.Dot(c.Normal, _bodies[movesA ? c.B : c.A].Linear);
            if (other != 0) // zero against the ground and walls
            {
                _bandResidualSums[2 * mover + (band & 1)] += movesA ? other : -other;
                _kinematicPushes = true; // the same value from any thread
            }
        }

        return true;
    }

    private bool AddToBandSum(int slot, int band, Vector3 push)
    {
        if (_bodies[slot].InverseMass == 0)
        {
            return true; // the ground, or a body that no impulse moves, spans any number of bands and enters no sum
        }

        int place = 2 * slot + (band & 1), tag = band + 1;
        if (_bandOfSum[place] != tag)
        {
            int other = _bandOfSum[place ^ 1];
            if (_bandOfSum[place] != 0 || (other != 0 && Math.Abs(other - tag) != 1))
            {
                return false; // the body's contacts span more than two neighbouring bands
            }

            _bandOfSum[place] = tag;
        }

        _bandSums[place] += push;
        return true;
    }
}
