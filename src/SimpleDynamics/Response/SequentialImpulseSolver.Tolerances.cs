using System.Numerics;

namespace SimpleDynamics.Response;

/// <summary>
/// When the velocity sweeps have converged: how far within <see cref="ConvergenceTolerance"/> a substep's first sweep
/// must stay to end the substep, and the sweeps after it, given the pile's depth.
/// </summary>
public sealed partial class SequentialImpulseSolver
{
    /// <summary>
    /// How far within the convergence tolerance the first sweep must stay for the pile to count as already solved by
    /// the warm start (see <see cref="Sweeps"/>). Measured on settled 2-D pits (two pours each of 8,000 discs, one of
    /// 1,000 and 4,000): with a quarter, the settled steps took 15 % (1,000 discs), 8 % (4,000) and 5–8 % (8,000)
    /// less time at the same overlap (0.50 mm); with the tolerance itself, the 8,000-disc pile that had settled
    /// began to stir again (90 sweeps a step, root-mean-square speed up from 3e-6 to 2e-4 m/s), because a substep
    /// ended after one sweep each time left what it had not solved to accumulate.
    /// </summary>
    private const float SolvedFraction = 0.25f;

    /// <summary>
    /// The depth, in bodies, up to which a pile's first sweep counts it solved within <see cref="SolvedFraction"/> of
    /// the tolerance; in a deeper pile the allowance falls with the depth (see <see cref="SolvedTolerance"/>), and the
    /// later sweeps' with its cube (see <see cref="DepthFactor"/>).
    /// </summary>
    /// <remarks>
    /// What the first sweep leaves, each contact up a pile's column may leave, and the upper bodies sink by the sum; so
    /// the allowance per contact falls in proportion to the depth beyond this one, keeping the sum that of a pile this
    /// deep. Measured on 2-D pits, sleeping off, with <see cref="SettlingFraction"/>: the 4,000-disc pile, 56 deep
    /// (<see cref="PileMeasure"/>), lies still at 4 sweeps a step with a quarter, and spends 26 a step with an eighth;
    /// the 16,000-disc pile, 110 deep, came to rest in none of three pours with a quarter; with an eighth in all
    /// three, and with this rule (about an eighth there) in two, the third lying still at 60–240 sweeps a step
    /// (benchmarks/README.md, twentieth session).
    /// </remarks>
    private const float SolvedDepth = 56f;

    /// <summary>
    /// The largest change (on the scale of <see cref="Sweep"/>'s result) with which a substep's first sweep finds the
    /// contacts already solved, so that no other follows: <see cref="SolvedFraction"/> of the tolerance, and under
    /// gravity, in a pile deeper than <see cref="SolvedDepth"/> bodies, that times <see cref="SolvedDepth"/> / depth.
    /// </summary>
    private float SolvedTolerance => SolvedFraction * _convergenceTolerance * DepthRatio;

    /// <summary>
    /// Under gravity, in a pile deeper than <see cref="SolvedDepth"/> bodies, <see cref="SolvedDepth"/> / depth; 1
    /// otherwise (no gravity, no pile, or one no deeper).
    /// </summary>
    private float DepthRatio => _gravity != Vector3.Zero && _pileLayers > SolvedDepth ? SolvedDepth / _pileLayers : 1f;

    /// <summary>
    /// Under gravity, in a pile deeper than <see cref="SolvedDepth"/> bodies, the factor (<see cref="SolvedDepth"/> /
    /// depth)³ by which the sweeps after a substep's first must converge more tightly (see
    /// <see cref="SettledTolerance"/>); 1 otherwise.
    /// </summary>
    /// <remarks>
    /// Why the cube. A sweep is stopped by the change it made, not by the error it leaves, and in a column of L bodies
    /// Gauss–Seidel removes the smooth part of the error only at a rate of about 1/L² a sweep (the slowest mode of the
    /// column's tridiagonal system), so the error left is about L² times the last change; the top of the column sinks by
    /// the sum over its L contacts. Holding that sum to what it is in a pile <see cref="SolvedDepth"/> deep asks the
    /// change to fall as 1/L³. Measured on the 16,000-disc 2-D pit (110–126 deep, sleeping off): with the tolerance
    /// fixed, pours with seeds 4 and 5 never came to rest (seed 4 in steps 600–1,500: 0.1–9 mm/s root-mean-square,
    /// slumps that moved up to 14,700 discs at once, 88–700 sweeps a step); with this factor both lay still from about
    /// step 480 (under 1 µm per 30 steps), as did seeds 1 and 3, and came down to 11–14 sweeps a step (seed 3 still
    /// spent 60–300, mostly local, at step 900). Eight times the extra sweeps instead did not stop the creep
    /// (benchmarks/README.md, twenty-seventh session).
    /// </remarks>
    private float DepthFactor
    {
        get
        {
            float ratio = DepthRatio;
            return ratio * ratio * ratio;
        }
    }

    /// <summary>
    /// Under gravity, the fraction of the convergence tolerance that the sweeps after a substep's first, and the shock
    /// pass, must meet (see <see cref="SettledTolerance"/>).
    /// </summary>
    /// <remarks>
    /// A contact left approaching at the tolerance lets its upper body sink that much more each substep, and in a pile
    /// those sinkings add up from the floor to the top. Held to the tolerance itself, the 16,000-disc 2-D pit (110
    /// deep, sleeping off) never came to rest: its packing crept and slumped, each slump unsettled thousands of
    /// contacts, and steps 701–1,200 of three pours (seeds 1–3) spent 150–570 sweeps a step. Held to half, with the
    /// first sweep's test falling with the depth (<see cref="SolvedDepth"/>), two of the pours came to rest (10–18
    /// sweeps a step) and the third lay still at 60–240, all at the same largest overlap, 0.50 mm (benchmarks/README.md,
    /// twentieth session). Each part alone was not enough: half for the sweeps after the first, or an eighth for the
    /// first sweep, left two pours of two stirring, and half for those and the shock pass, one. A quarter of the
    /// tolerance throughout was too strict for the budget: the seed-1 pour still stirred at step 650, spending all its
    /// sweeps. The price is paid while a pile lands, when the substeps spend their whole budget either way: the
    /// 16,000-disc pour with sleeping on took 131.5 s of wall time to fall asleep, against 96.1 s.
    /// </remarks>
    private const float SettlingFraction = 0.5f;

    /// <summary>
    /// The tolerance, on the scale of <see cref="Sweep"/>'s result, at which the sweeps after a substep's first have
    /// converged: under gravity <see cref="SettlingFraction"/> of <see cref="ConvergenceTolerance"/>, times
    /// <see cref="DepthFactor"/> in a pile deeper than <see cref="SolvedDepth"/>; without gravity the tolerance itself.
    /// </summary>
    private float SettledTolerance => _gravity != Vector3.Zero ? SettlingFraction * _convergenceTolerance * DepthFactor : _convergenceTolerance;
}
