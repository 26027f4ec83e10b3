using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>
/// The layer correction's coarse system (SequentialImpulseSolver.Layers.cs): the tridiagonal Galerkin system built
/// from the bodies' band sums, its solution, limited and line-searched, and the bodies moved by it.
/// </summary>
public sealed partial class SequentialImpulseSolver
{
    private double[] _bandDiagonal = new double[InitialCapacity], _bandUpper = new double[InitialCapacity];
    private double[] _bandResidual = new double[InitialCapacity], _bandFactor = new double[InitialCapacity];
    private double[] _bandEliminated = new double[InitialCapacity];
    private double[] _bandShares = new double[3 * InitialCapacity]; // per share of BuildBandSystem: its diagonal, upper and right-hand side
    private bool _bandCorrectionLimited; // the last solution was limited (some factor to ±½) or shortened by the line search

    /// <summary>
    /// The tridiagonal Pᵀ A P = Σ_s (1/m_s) G_sᵀ G_s (diagonal and upper neighbour; it is symmetric) and the
    /// right-hand side −Pᵀ v_n = −Σ_s v_s · G_s (plus what moving kinematic bodies add), in double precision: each
    /// strip's bodies give their share of it (on the step's threads, each where its strip's sweeps ran), then the
    /// bodies woken during the step theirs, and the shares are added in that order, so that the sums are the same on
    /// any number of threads.
    /// </summary>
    private void BuildBandSystem(int bands)
    {
        int shares = _strips.Count + 1;
        Buffers.EnsureCapacity(ref _bandShares, 3 * bands * shares);
        RunOverBodies(StripPass.BuildBands);

        Buffers.EnsureCapacity(ref _bandDiagonal, bands);
        Buffers.EnsureCapacity(ref _bandUpper, bands);
        Buffers.EnsureCapacity(ref _bandResidual, bands);
        for (int b = 0; b < bands; b++)
        {
            double diagonal = 0, upper = 0, residual = 0;
            for (int share = 0; share < shares; share++)
            {
                int at = 3 * bands * share + b;
                diagonal += _bandShares[at];
                upper += _bandShares[at + bands];
                residual += _bandShares[at + 2 * bands];
            }

            (_bandDiagonal[b], _bandUpper[b], _bandResidual[b]) = (diagonal, upper, residual);
        }
    }

    /// <summary>
    /// Share <paramref name="share"/> of the band system (see <see cref="BuildBandSystem"/>): that of strip
    /// <paramref name="share"/>'s bodies, or, for the last share, of the bodies woken during the step; in slot order.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // as SweepWithBandsRange
    private void BuildBandShare(int share)
    {
        int bands = _bandCount;
        (int first, int end) = SlotsOfShare(share);
        bool kinematicPushes = _kinematicPushes;
        Span<double> diagonal = _bandShares.AsSpan(3 * bands * share, bands);
        Span<double> upper = _bandShares.AsSpan(3 * bands * share + bands, bands);
        Span<double> residual = _bandShares.AsSpan(3 * bands * share + 2 * bands, bands);
        diagonal.Clear();
        upper.Clear();
        residual.Clear();
        for (int s = first; s < end; s++)
        {
            int even = _bandOfSum[2 * s] - 1, odd = _bandOfSum[2 * s + 1] - 1;
            if (even < 0 && odd < 0)
            {
                continue; // no pressed contact, or a body no impulse moves: nothing was summed here
            }

            double inverseMass = _bodies[s].InverseMass;
            var velocity = new Vector3D(_bodies[s].Linear);
            Vector3 sumEven = _bandSums[2 * s], sumOdd = _bandSums[2 * s + 1];
            if (even >= 0)
            {
                diagonal[even] += inverseMass * Vectors.LengthSquared(sumEven);
                residual[even] += (kinematicPushes ? _bandResidualSums[2 * s] : 0) - Vector3D.Dot(velocity, new Vector3D(sumEven));
            }

            if (odd >= 0)
            {
                diagonal[odd] += inverseMass * Vectors.LengthSquared(sumOdd);
                residual[odd] += (kinematicPushes ? _bandResidualSums[2 * s + 1] : 0) - Vector3D.Dot(velocity, new Vector3D(sumOdd));
            }

            if (even >= 0 && odd >= 0)
            {
                upper[Math.Min(even, odd)] += inverseMass * Vectors.Dot(sumEven, sumOdd);
            }
        }
    }

    /// <summary>
    /// The slots of share <paramref name="share"/> of the bodies: strip <paramref name="share"/>'s, or, for the last
    /// share, the bodies woken during the step (slots follow the body order).
    /// </summary>
    private (int First, int End) SlotsOfShare(int share)
    {
        int strips = _strips.Count;
        return share < strips
            ? (_bodyStart[share + 1] + 1, _bodyStart[share + 2] + 1)
            : (_bodyStart[strips + 1] + 1, _step!.Bodies.Length + 1);
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

        _bandCorrectionLimited = false;
        for (int b = bands - 1; b >= 0; b--)
        {
            if (!double.IsNaN(_bandEliminated[b]) && b + 1 < bands)
            {
                _bandFactor[b] -= _bandEliminated[b] * _bandFactor[b + 1];
            }

            double factor = _bandFactor[b];
            _bandFactor[b] = Math.Clamp(factor, -0.5, 0.5); // NaN stays NaN, and fails the test below
            _bandCorrectionLimited |= _bandFactor[b] != factor;
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
        _bandCorrectionLimited |= step < 1 - 1e-6;
        for (int b = 0; b < bands; b++)
        {
            _bandFactor[b] *= step;
        }

        return true;
    }

    /// <summary>
    /// Applies the correction's band factors α to the bodies: each moves by Δv_s = (1/m_s) Σ α_b G_s,b over its bands,
    /// which is Σ ±α λ_i n_i / m_s over its pressed contacts (eq. 6), at one write per body; in strips on the step's
    /// threads, like the build. The contacts' impulses λ_i ← (1 + α) λ_i follow in the next sweep, each just before it
    /// is solved (<see cref="SweepWithBandsRange"/>), where the sweep reads the contact anyway; nothing reads them
    /// before. A pass over the contacts doing both costs about as much as building the system; this one, a write per
    /// body. Empties the band sums as it reads them.
    /// </summary>
    private void ApplyBandFactors()
    {
        RunOverBodies(StripPass.ApplyBands);
        EmptyKinematicPushes();
        _bandSumsEmpty = true;
        _bandScalePending = true;
    }

    /// <summary>Share <paramref name="share"/> of <see cref="ApplyBandFactors"/>: the same bodies as that share of <see cref="BuildBandShare"/>.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // as SweepWithBandsRange
    private void ApplyBandShare(int share)
    {
        (int first, int end) = SlotsOfShare(share);
        for (int s = first; s < end; s++)
        {
            int even = _bandOfSum[2 * s] - 1, odd = _bandOfSum[2 * s + 1] - 1;
            if (even < 0 && odd < 0)
            {
                continue; // nothing was summed here
            }

            Vector3 change = default;
            if (even >= 0)
            {
                change += (float)_bandFactor[even] * _bandSums[2 * s];
            }

            if (odd >= 0)
            {
                change += (float)_bandFactor[odd] * _bandSums[2 * s + 1];
            }

            _bodies[s].Linear += change * _bodies[s].InverseMass;
            _bandSums[2 * s] = _bandSums[2 * s + 1] = default;
            _bandOfSum[2 * s] = _bandOfSum[2 * s + 1] = 0;
        }
    }

    /// <summary>
    /// Contact <paramref name="i"/>'s (in <see cref="_active"/>) normal impulse scaled by 1 + α of its band, as the
    /// pending correction has already moved its bodies (never below zero: α ≥ −½).
    /// </summary>
    private float ScaledImpulse(ref ContactConstraint c, int i)
    {
        float change = (float)(_bandFactor[_bandOf[i]] * c.NormalImpulse);
        return MathF.Max(c.NormalImpulse + change, 0f);
    }
}
