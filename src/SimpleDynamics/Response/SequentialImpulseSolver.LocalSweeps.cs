using System;
using System.Numerics;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>
/// The extra sweeps under gravity: Gauss–Seidel over the contacts that can still change, not over every contact.
/// </summary>
/// <remarks>
/// <para>A contact just solved has its own normal velocity at zero (or its impulse at zero), and solving it again
/// changes nothing as long as neither of its bodies has moved since. So once the fixed sweeps have left most of a pile
/// solved and some part of it not (a few contacts that press or let go in a deep pile keep a region stirring), a sweep
/// over every contact spends almost all its time confirming what is already solved. These sweeps visit, still
/// bottom-up, only the contacts of bodies whose velocity has changed by more than a quarter of the tolerance
/// (see <see cref="ConvergenceTolerance"/>) since their contacts were last told (the body's velocity is then
/// "published" again); the rest would each change by less than that on both sides, which the tolerance allows.</para>
/// <para>This is the Gauss–Seidel of the full sweeps with the contacts that cannot change left out: relaxing only
/// where the residual is large is the idea of Southwell's relaxation method (R. V. Southwell, <i>Relaxation Methods
/// in Engineering Science</i>, Oxford University Press, 1940). The largest change of the contacts visited decides
/// convergence, as <see cref="Sweep"/>'s does for all of them.</para>
/// <para><b>Only while few bodies change.</b> Keeping track costs more per contact than solving it, so these sweeps
/// begin only when the last fixed sweep changed at most an eighth of the bodies, and give way to full sweeps once a
/// quarter of the contacts is to be visited again. Without those limits an 8,000-disc pour spent 2–3 times as long
/// per step while it landed (every body moving). Measured in the settled 16,000-disc pit in a state where full sweeps
/// did not converge (98 sweeps a step): 99–100 ms a step with full sweeps, 57 ms with these, which visited 0.3 % of
/// the contacts full sweeps would (benchmarks/README.md, 2026-12-03, evening).</para>
/// <para><b>After a first sweep that nearly solved a 3-D pile.</b> Spheres resist no rolling, so a settled 3-D pile
/// goes on turning slowly, and its first sweep a substep often changes a contact by more than the quarter of the
/// tolerance that would end the substep, but by no more than half, the tolerance the later sweeps converge to. The
/// other fixed sweeps then visit only the contacts of the bodies the first one changed (see FinishesWhereChanging).
/// Measured on the settled 4,000-sphere pit: 9 sweeps a step instead of 13, and 7–13 % less time a step, at the same
/// overlap (benchmarks/README.md, twenty-fifth session).</para>
/// </remarks>
public sealed partial class SequentialImpulseSolver
{
    private readonly ContactsOfBodies _activeOfBodies = new(); // positions in _active, listed under both bodies
    private readonly ContactMarks _velocityMarks = new();
    private Vector3[] _publishedLinear = new Vector3[InitialCapacity]; // per slot: the velocity its contacts were last solved with
    private Vector3[] _publishedAngular = new Vector3[InitialCapacity];
    private float _localDrift2; // the squared drift allowed in the local sweep that threads share (SweepMarkedRange)

    /// <summary>Sweeps of the step begun last that visited only the contacts of changed bodies, for tests.</summary>
    internal int LocalSweepsThisStep { get; private set; }

    /// <summary>Contacts solved by those sweeps, for tests.</summary>
    internal long LocalSolvesThisStep { get; private set; }

    /// <summary>For tests: after local sweeps converge, measure what a full sweep would still change (costs a pass over the contacts).</summary>
    internal bool MeasureResidualAfterLocalSweeps { get; set; }

    /// <summary>
    /// The largest change of a contact's normal velocity that a full sweep would have made when local sweeps had last
    /// converged, on the tolerance's scale (see <see cref="Sweep"/>), if <see cref="MeasureResidualAfterLocalSweeps"/>.
    /// </summary>
    internal float LargestResidualAfterLocalSweeps { get; private set; }

    /// <summary>
    /// Keeps every body's velocity as the last fixed sweep begins (see <see cref="Sweeps"/>), so that the bodies that
    /// sweep changed can be found afterwards.
    /// </summary>
    private void RememberVelocities()
    {
        int slots = _step!.Bodies.Length + 1; // slot 0 is the ground
        Buffers.EnsureCapacity(ref _publishedLinear, slots);
        Buffers.EnsureCapacity(ref _publishedAngular, slots);
        for (int s = 0; s < slots; s++)
        {
            _publishedLinear[s] = _bodies[s].Linear;
            _publishedAngular[s] = _bodies[s].Angular;
        }
    }

    /// <summary>For tests: whether a first sweep within the settling tolerance may be followed by local sweeps (default true; see <see cref="FinishesWhereChanging"/>).</summary>
    internal bool FinishesFirstSweepLocally { get; set; } = true;

    /// <summary>
    /// Whether this substep's fixed sweeps may be finished where bodies change (<see cref="FinishesWhereChanging"/>):
    /// under gravity, with extra sweeps allowed, in a 3-D step, in a pile no deeper than SolvedDepth. In a deeper one
    /// what the local sweeps leave unvisited adds up over the depth, as the first sweep's does (see SolvedTolerance).
    /// Not in a planar step: there it kept the 16,000-disc pour stirring (seed 1: 660 sweeps a step at step 480,
    /// which without it is asleep by step 400; benchmarks/README.md, twenty-fifth session).
    /// </summary>
    private bool MayFinishWhereChanging(bool local) => local && !_planar && FinishesFirstSweepLocally && _pileLayers <= SolvedDepth;

    /// <summary>
    /// After a first sweep that changed no contact by more than the tolerance the later sweeps converge to, but by
    /// more than the fraction that ends the substep at once (SolvedTolerance): spends the other fixed sweeps only on the
    /// contacts of the bodies that sweep changed, and returns whether they converged. If they did not (too many bodies
    /// changed, or the change spread), the fixed sweeps over every contact follow as usual.
    /// </summary>
    private bool FinishesWhereChanging()
    {
        SweepWhereChanging(_velocityIterations - 1, out bool converged);
        SubstepsFinishedLocallyThisStep += converged ? 1 : 0;
        return converged;
    }

    /// <summary>Substeps of the step begun last whose fixed sweeps were finished where bodies change (<see cref="FinishesWhereChanging"/>), for tests.</summary>
    internal int SubstepsFinishedLocallyThisStep { get; private set; }

    /// <summary>
    /// Sweeps, up to <paramref name="budget"/> of them, only the contacts of the bodies that changed since the
    /// velocities were remembered, while those are few: at most an eighth of the bodies to begin with, a quarter of
    /// the contacts after that. Returns the sweeps spent; <paramref name="converged"/> tells whether the last converged.
    /// </summary>
    private int SweepWhereChanging(int budget, out bool converged)
    {
        converged = false;
        int slots = _step!.Bodies.Length + 1;
        float speedScale = _gravity.Length() * _step.SubstepLength;
        float drift = 0.25f * SettledTolerance * speedScale;
        int changed = 0;
        for (int s = 1; s < slots; s++)
        {
            changed += Drifted(s, drift * drift) ? 1 : 0;
        }

        if (changed > slots / 8)
        {
            return 0; // moving all over: sweeping everything is cheaper than keeping track
        }

        ListActiveContactsOfSlots(slots);
        _velocityMarks.Begin(_activeCount);
        for (int s = 1; s < slots; s++)
        {
            Publish(s, position: -1, drift * drift); // every contact of a changed body, in the first sweep
        }

        for (int sweep = 1; sweep <= budget; sweep++)
        {
            if (SweepMarked(drift * drift) <= SettledTolerance * speedScale)
            {
                converged = true;
                if (MeasureResidualAfterLocalSweeps)
                {
                    LargestResidualAfterLocalSweeps = MathF.Max(LargestResidualAfterLocalSweeps, LargestNormalResidual() / speedScale);
                }

                return sweep;
            }

            if (_velocityMarks.MarkedForNext > _activeCount / 4)
            {
                return sweep; // the change has spread: the remaining sweeps go over every contact
            }

            _velocityMarks.NextSweep();
        }

        return budget;
    }

    /// <summary>Whether the body in <paramref name="slot"/> has changed by more than the drift allowed since its velocity was last published.</summary>
    private bool Drifted(int slot, float drift2)
    {
        ref SolverBody body = ref _bodies[slot];
        float radius = _radii[slot];
        return Vectors.DistanceSquared(body.Linear, _publishedLinear[slot]) +
            radius * radius * Vectors.DistanceSquared(body.Angular, _publishedAngular[slot]) > drift2;
    }

    /// <summary>
    /// One bottom-up sweep over the marked contacts; a body that changes by more than the drift allowed marks its
    /// contacts, the later ones for this sweep and the earlier ones for the next. Returns the largest change of a
    /// contact's normal velocity.
    /// </summary>
    private float SweepMarked(float drift2)
    {
        SweepsThisStep++;
        LocalSweepsThisStep++;
        if (_substepInStrips)
        {
            _localDrift2 = drift2;
            RunPass(StripPass.LocalSweep);
            for (int slot = 0; slot < _resultSlots; slot++)
            {
                _velocityMarks.AddMarkedForNext(_stripCounts[slot * Padding]);
                LocalSolvesThisStep += _stripCounts[slot * Padding + 1];
            }

            return LargestOfPass(0);
        }

        float largestSpeedChange = 0;
        while (_velocityMarks.TryTake(out int p))
        {
            LocalSolvesThisStep++;
            int k = _active[p];
            ref ContactConstraint c = ref _constraints[k];
            largestSpeedChange = MathF.Max(largestSpeedChange, SolveContactMeasured(k, out _));
            Publish(c.A, p, drift2);
            Publish(c.B, p, drift2);
        }

        return largestSpeedChange;
    }

    /// <summary>
    /// <see cref="SweepMarked"/> over positions [<paramref name="start"/>, <paramref name="end"/>) of the active
    /// contacts only, by one of the threads that share the sweep (<paramref name="slot"/>: its results). A strip's
    /// bodies touch only its own contacts and the seams (SweepStrips.cs), so each thread visits and marks its own range
    /// in the order one thread would, and marks seam contacts, which come after every strip, for this sweep, to be
    /// visited once the strips are done: the same marks and the same order as one thread's sweep, bit for bit.
    /// </summary>
    private void SweepMarkedRange(int slot, int start, int end)
    {
        float drift2 = _localDrift2, largestSpeedChange = 0;
        int word = start >> 6, markedForNext = 0, solves = 0;
        while (_velocityMarks.TryTakeShared(ref word, start, end, out int p))
        {
            solves++;
            int k = _active[p];
            ref ContactConstraint c = ref _constraints[k];
            largestSpeedChange = MathF.Max(largestSpeedChange, SolveContactMeasured(k, out _));
            PublishShared(c.A, p, drift2, ref markedForNext);
            PublishShared(c.B, p, drift2, ref markedForNext);
        }

        _stripResults[slot * Padding] = largestSpeedChange;
        _stripCounts[slot * Padding] = markedForNext;
        _stripCounts[slot * Padding + 1] = solves;
    }

    /// <summary><see cref="Publish"/> in a sweep that threads share (<see cref="ContactMarks.MarkAroundShared"/>).</summary>
    private void PublishShared(int slot, int position, float drift2, ref int markedForNext)
    {
        if (!Drifted(slot, drift2))
        {
            return;
        }

        _publishedLinear[slot] = _bodies[slot].Linear;
        _publishedAngular[slot] = _bodies[slot].Angular;
        _velocityMarks.MarkAroundShared(_activeOfBodies.Of(slot), position, ref markedForNext);
    }

    /// <summary>
    /// If the body in <paramref name="slot"/> has drifted from what its contacts last saw, publishes its velocity and
    /// marks its contacts to be solved again: those after <paramref name="position"/> in this sweep, the others in the next.
    /// </summary>
    private void Publish(int slot, int position, float drift2)
    {
        if (!Drifted(slot, drift2))
        {
            return;
        }

        _publishedLinear[slot] = _bodies[slot].Linear;
        _publishedAngular[slot] = _bodies[slot].Angular;
        _velocityMarks.MarkAround(_activeOfBodies.Of(slot), position);
    }

    /// <summary>The largest change of a contact's normal velocity a full sweep would make now (the normal part of SolveContact), m/s.</summary>
    private float LargestNormalResidual()
    {
        float largest = 0;
        foreach (int k in _active.AsSpan(0, _activeCount))
        {
            ref ContactConstraint c = ref _constraints[k];
            if (c.NormalMass > 0)
            {
                float normalVelocity = Vector3.Dot(_bodies[c.A].Linear - _bodies[c.B].Linear, c.Normal);
                float impulse = MathF.Max(c.NormalImpulse - c.NormalMass * normalVelocity, 0f);
                largest = MathF.Max(largest, MathF.Abs(impulse - c.NormalImpulse) / c.NormalMass);
            }
        }

        return largest;
    }

    /// <summary>Lists each slot's active contacts by their positions in the sweep.</summary>
    private void ListActiveContactsOfSlots(int slots)
    {
        _activeOfBodies.BeginCounting(slots);
        for (int p = 0; p < _activeCount; p++)
        {
            ref ContactConstraint c = ref _constraints[_active[p]];
            _activeOfBodies.Count(c.A, c.B);
        }

        _activeOfBodies.BeginListing();
        for (int p = 0; p < _activeCount; p++)
        {
            ref ContactConstraint c = ref _constraints[_active[p]];
            _activeOfBodies.List(c.A, c.B, p);
        }
    }
}
