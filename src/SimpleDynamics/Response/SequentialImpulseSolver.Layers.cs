using System;
using System.Numerics;
using System.Runtime.CompilerServices;

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
/// it.</para>
/// <para><b>Laws.</b> Each factor is limited to ±½, so every impulse is scaled by at least ½ and stays ≥ 0; the step
/// along the limited factors d is t d with t = min(1, dᵀr / dᵀHd) (H = Pᵀ A P, r = −Pᵀ v_n), the exact minimum of the
/// convex E on that line, or none when dᵀr ≤ 0: so the correction never adds kinetic energy (to rounding). A contact's
/// impulse acts equally and oppositely on its two bodies, so momentum changes only through the ground and walls. A
/// sweep always follows (friction is clamped to the new cone there). The tests audit all three on generated deep
/// piles (LayerCorrectionTests).</para>
/// <para><b>When.</b> Only in a substep that has spent 2 × <see cref="ExtraIterations"/> extra sweeps without
/// converging, after each further sweep: a correction costs about one sweep, and a pile that is still landing
/// converges, or not, by sweeps alone. After every extra sweep instead, 2,400 discs poured 60 deep into a box 40 wide
/// took 5.7 s to fall asleep instead of 3.3 s, with no fewer sweeps (3.7 s with the rule); on the 16,000-disc pit
/// loaded from a saved pour, 180 steps took 71 s instead of 63 s without (59 s with the rule; 148 ms a step in the
/// last second against 237 ms without; benchmarks/README.md, 2026-12-04).</para>
/// </remarks>
public sealed partial class SequentialImpulseSolver
{
    /// <summary>A band's height, in mean diameters of the pile's bodies (see <see cref="LayerCorrection"/>).</summary>
    private const float BandDiameters = 3.5f;

    /// <summary>No correction is tried over more bands than this (a world thousands of bodies tall, or spread far).</summary>
    private const int MostBands = 4096;

    private int[] _bandOf = new int[InitialCapacity]; // per active contact (position in _active): its band
    private Vector3[] _bandSums = new Vector3[2 * InitialCapacity]; // per slot, per band parity: Σ ±λ_i n_i of its contacts
    private double[] _bandResidualSums = new double[2 * InitialCapacity]; // the same: Σ −λ_i v_n,i of the contacts kept there
    private int[] _bandOfSum = new int[2 * InitialCapacity]; // per slot, per band parity: the band summed there (−1: none)
    private double[] _bandDiagonal = new double[InitialCapacity], _bandUpper = new double[InitialCapacity];
    private double[] _bandResidual = new double[InitialCapacity], _bandFactor = new double[InitialCapacity];
    private double[] _bandEliminated = new double[InitialCapacity];
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

    /// <summary>Whether this step's pile is deep enough for the layer correction (see <see cref="LayerCorrection"/>).</summary>
    private bool CorrectsLayers => LayerCorrection && _extraSweeps > _extraIterations && _gravity != Vector3.Zero;

    /// <summary>
    /// Applies the layer correction once (see the file's remarks): bands, the tridiagonal Galerkin system, its solution
    /// and the scaled impulses. Leaves everything as it was when the system cannot be formed (too many bands, a body
    /// whose contacts span more than two bands) or its solution is not finite.
    /// </summary>
    private void CorrectLayers()
    {
        if (!_bandsAssigned)
        {
            _bandCount = AssignBands(); // the positions stay put through the substep's sweeps, and so do the bands
            _bandsAssigned = true;
        }

        if (_bandCount < 2 || !GatherBandSums())
        {
            return;
        }

        BuildBandSystem(_bandCount);
        if (!SolveBandSystem(_bandCount))
        {
            return;
        }

        if (AuditLayerCorrections)
        {
            Audit.Before(this);
        }

        ScaleBandImpulses();
        LayerCorrectionsThisStep++;
        if (AuditLayerCorrections)
        {
            Audit.After(this);
        }
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
            largestRadius = MathF.Max(largestRadius, MathF.Max(c.RadiusA, c.RadiusB));
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
        ? Vector3.Dot(_positions[c.A], up)
        : 0.5f * Vector3.Dot(_positions[c.A] + _positions[c.B], up);

    /// <summary>
    /// Sums, per body and band, ±λ_i n_i over the body's pressed contacts (+ for A, − for B: the direction the impulse
    /// pushes it), and each contact's share of the right-hand side, −λ_i v_n,i, under its body A (or B, if A does not
    /// move). Runs in strips on the step's threads: a strip's contacts move only its own bodies, and the seam contacts
    /// come after, so every sum is taken in storage order on any number of threads. Returns false if some movable
    /// body's contacts lie in two bands of the same parity, or in two that are not neighbours.
    /// </summary>
    private bool GatherBandSums()
    {
        int slots = _step!.Bodies.Length + 1;
        Buffers.EnsureCapacity(ref _bandSums, 2 * slots);
        Buffers.EnsureCapacity(ref _bandOfSum, 2 * slots);
        Buffers.EnsureCapacity(ref _bandResidualSums, 2 * slots);
        _bandSums.AsSpan(0, 2 * slots).Clear();
        _bandOfSum.AsSpan(0, 2 * slots).Fill(-1);
        _bandResidualSums.AsSpan(0, 2 * slots).Clear();
        RunPass(StripPass.GatherBands);
        return LargestOfPass(0) == 0;
    }

    /// <summary>The gathering of <see cref="GatherBandSums"/> over <see cref="_active"/>[<paramref name="start"/>..<paramref name="end"/>).</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // keeps RunRange, whose sweeps are the hot loop, as small as before
    private bool GatherBandRange(int start, int end)
    {
        bool formed = true;
        for (int i = start; i < end; i++)
        {
            ref ContactConstraint c = ref _constraints[_active[i]];
            if (c.NormalImpulse <= 0 || !formed)
            {
                continue;
            }

            int band = _bandOf[i];
            Vector3 push = c.NormalImpulse * c.Normal;
            formed = AddToBandSum(c.A, band, push) && AddToBandSum(c.B, band, -push);
            float normalVelocity = Vector3.Dot(_bodies[c.A].Linear - _bodies[c.B].Linear, c.Normal); // r × n = 0
            int keeper = _bodies[c.A].InverseMass > 0 ? c.A : c.B; // a body whose sums hold this band (if either moves)
            _bandResidualSums[2 * keeper + (band & 1)] -= c.NormalImpulse * (double)normalVelocity;
        }

        return formed;
    }

    private bool AddToBandSum(int slot, int band, Vector3 push)
    {
        if (_bodies[slot].InverseMass == 0)
        {
            return true; // the ground, or a body that no impulse moves, spans any number of bands and enters no sum
        }

        int place = 2 * slot + (band & 1);
        if (_bandOfSum[place] != band)
        {
            int other = _bandOfSum[place ^ 1];
            if (_bandOfSum[place] >= 0 || (other >= 0 && Math.Abs(other - band) != 1))
            {
                return false; // the body's contacts span more than two neighbouring bands
            }

            _bandOfSum[place] = band;
        }

        _bandSums[place] += push;
        return true;
    }

    /// <summary>
    /// The tridiagonal Pᵀ A P = Σ_s (1/m_s) G_sᵀ G_s (diagonal and upper neighbour; it is symmetric), in double
    /// precision and in slot order, and the right-hand side −Pᵀ v_n = −Σ λ_i v_n,i from the bodies' shares of it.
    /// </summary>
    private void BuildBandSystem(int bands)
    {
        Buffers.EnsureCapacity(ref _bandDiagonal, bands);
        Buffers.EnsureCapacity(ref _bandUpper, bands);
        Buffers.EnsureCapacity(ref _bandResidual, bands);
        _bandDiagonal.AsSpan(0, bands).Clear();
        _bandUpper.AsSpan(0, bands).Clear();
        _bandResidual.AsSpan(0, bands).Clear();
        int slots = _step!.Bodies.Length + 1;
        for (int s = 1; s < slots; s++)
        {
            float inverseMass = _bodies[s].InverseMass;
            int even = _bandOfSum[2 * s], odd = _bandOfSum[2 * s + 1];
            if (inverseMass == 0 || (even < 0 && odd < 0))
            {
                continue;
            }

            Vector3 sumEven = _bandSums[2 * s], sumOdd = _bandSums[2 * s + 1];
            if (even >= 0)
            {
                _bandDiagonal[even] += inverseMass * (double)sumEven.LengthSquared();
                _bandResidual[even] += _bandResidualSums[2 * s];
            }

            if (odd >= 0)
            {
                _bandDiagonal[odd] += inverseMass * (double)sumOdd.LengthSquared();
                _bandResidual[odd] += _bandResidualSums[2 * s + 1];
            }

            if (even >= 0 && odd >= 0)
            {
                _bandUpper[Math.Min(even, odd)] += inverseMass * (double)Vector3.Dot(sumEven, sumOdd);
            }
        }
    }

    /// <summary>
    /// Solves the tridiagonal system for the band factors (Thomas' algorithm; a band without pressed contacts keeps
    /// factor 0), limits each to ±½, and takes the step along the limited factors that lowers the energy most (an exact
    /// line search on the quadratic: t = min(1, dᵀr / dᵀHd) for the direction d, right-hand side r and matrix H).
    /// Returns false when no step lowers the energy, or the solution is not finite.
    /// </summary>
    private bool SolveBandSystem(int bands)
    {
        Buffers.EnsureCapacity(ref _bandFactor, bands);
        Buffers.EnsureCapacity(ref _bandEliminated, bands);
        double previousEliminated = 0, previousFactor = 0;
        for (int b = 0; b < bands; b++)
        {
            double lower = b > 0 ? _bandUpper[b - 1] : 0;
            double pivot = _bandDiagonal[b] - lower * previousEliminated;
            if (!(pivot > 1e-9 * _bandDiagonal[b]) || _bandDiagonal[b] == 0)
            {
                // No pressed contact, or nothing movable: the band keeps its impulses (factor 0) and decouples.
                _bandEliminated[b] = double.NaN;
                _bandFactor[b] = previousEliminated = previousFactor = 0;
                continue;
            }

            _bandEliminated[b] = previousEliminated = _bandUpper[b] / pivot;
            _bandFactor[b] = previousFactor = (_bandResidual[b] - lower * previousFactor) / pivot;
        }

        for (int b = bands - 1; b >= 0; b--)
        {
            if (!double.IsNaN(_bandEliminated[b]) && b + 1 < bands)
            {
                _bandFactor[b] -= _bandEliminated[b] * _bandFactor[b + 1];
            }

            _bandFactor[b] = Math.Clamp(_bandFactor[b], -0.5, 0.5); // NaN stays NaN, and fails the test below
        }

        double gain = 0, curvature = 0; // dᵀr and dᵀHd
        for (int b = 0; b < bands; b++)
        {
            double d = _bandFactor[b];
            double hd = _bandDiagonal[b] * d
                + (b > 0 ? _bandUpper[b - 1] * _bandFactor[b - 1] : 0)
                + (b + 1 < bands ? _bandUpper[b] * _bandFactor[b + 1] : 0);
            gain += d * _bandResidual[b];
            curvature += d * hd;
        }

        if (!(gain > 0) || !(curvature > 0) || !double.IsFinite(gain + curvature))
        {
            return false;
        }

        double step = Math.Min(1, gain / curvature);
        for (int b = 0; b < bands; b++)
        {
            _bandFactor[b] *= step;
        }

        return true;
    }

    /// <summary>
    /// Scales each pressed contact's normal impulse by 1 + α of its band, and its bodies' velocities with it (eq. 6);
    /// in strips on the step's threads, like the sweeps.
    /// </summary>
    private void ScaleBandImpulses() => RunPass(StripPass.ScaleBands);

    /// <summary>The scaling of <see cref="ScaleBandImpulses"/> over <see cref="_active"/>[<paramref name="start"/>..<paramref name="end"/>).</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // as GatherBandRange
    private void ScaleBandRange(int start, int end)
    {
        for (int i = start; i < end; i++)
        {
            ref ContactConstraint c = ref _constraints[_active[i]];
            float change = (float)(_bandFactor[_bandOf[i]] * c.NormalImpulse);
            if (change == 0)
            {
                continue;
            }

            c.NormalImpulse = MathF.Max(c.NormalImpulse + change, 0f);
            Vector3 push = change * c.Normal;
            _bodies[c.A].Linear += push * _bodies[c.A].InverseMass;
            _bodies[c.B].Linear -= push * _bodies[c.B].InverseMass;
        }
    }
}
