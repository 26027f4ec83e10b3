using System;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>
/// One sweep of the position pass (SequentialImpulseSolver.Positions.cs), on one thread or in strips on several.
/// </summary>
/// <remarks>
/// The contacts are stored strip after strip, then the seam contacts (SweepStrips.cs), and a position sweep visits
/// them in that order. Two strips' contacts move no body in common, so when the substep's velocity passes ran in strips
/// (the pile needed more than one sweep: see <see cref="_substepInStrips"/>), each strip's part of a position sweep
/// runs on whichever thread takes it, and the seam contacts, with any the impact pass added, after all strips on this
/// thread: each body sees the same corrections in the same order as on one thread, bit for bit. Sweeps that visit only
/// marked contacts mark them atomically (<see cref="ContactMarks.MarkAroundShared"/>), as the local velocity sweeps do.
/// </remarks>
public sealed partial class SequentialImpulseSolver
{
    /// <summary>
    /// The sweeps of the position pass: the first visits every contact and marks those it leaves deep; the later ones
    /// visit the marked contacts (or all, untracked) and mark what they change; the last removes the whole depth
    /// beyond the slop (the shock under gravity) and marks what it changes for the rest of itself.
    /// </summary>
    private enum PositionSweep
    {
        First,
        Later,
        Last,
    }

    private PositionSweep _positionSweep; // the sweep the strips are running
    private bool _positionTracking;

    /// <summary>Position sweeps of the step begun last that ran in strips, for tests.</summary>
    internal int PositionSweepsInStripsThisStep { get; private set; }

    /// <summary>One sweep of the position pass over contacts [0, <paramref name="count"/>).</summary>
    private void SweepPositions(PositionSweep sweep, bool tracking, int count) =>
        SweepPositions(sweep, tracking, count, out _, out _);

    /// <summary>
    /// One sweep of the position pass over contacts [0, <paramref name="count"/>); tells whether it corrected a contact
    /// by more than 1 % of the slop, and whether such a contact was a sideways one (one that carries no weight).
    /// </summary>
    private void SweepPositions(PositionSweep sweep, bool tracking, int count, out bool sidewaysCorrected, out bool corrected)
    {
        _positionSweep = sweep;
        _positionTracking = tracking;
        int strips = _strips.Count;
        if (_substepInStrips && _threads is not null && strips > 1)
        {
            PositionSweepsInStripsThisStep++;
            RunStripsOnThreads(StripPass.Positions);
            CorrectPositionRange(strips, _contactStart[strips], count, shared: true); // the seams, then what the impact pass added
            _resultSlots = strips + 1;
        }
        else
        {
            CorrectPositionRange(0, 0, count, shared: false);
            _resultSlots = 1;
        }

        int markedForNext = 0, outcome = 0;
        for (int slot = 0; slot < _resultSlots; slot++)
        {
            markedForNext += _stripCounts[slot * Padding];
            PositionVisitsThisStep += _stripCounts[slot * Padding + 1];
            outcome |= _stripCounts[slot * Padding + 3];
        }

        _positionMarks.AddMarkedForNext(markedForNext);
        sidewaysCorrected = (outcome & 1) != 0;
        corrected = (outcome & 2) != 0;
    }

    /// <summary>
    /// The sweep of <see cref="_positionSweep"/> over contacts [<paramref name="start"/>, <paramref name="end"/>), its
    /// counts and outcome in the results of <paramref name="slot"/>. <paramref name="shared"/>: other threads sweep
    /// other ranges at the same time (see the remarks above).
    /// </summary>
    private void CorrectPositionRange(int slot, int start, int end, bool shared)
    {
        PositionSweep sweep = _positionSweep;
        bool tracking = _positionTracking;
        bool visitMarked = tracking && sweep != PositionSweep.First;
        bool markSelf = tracking && sweep != PositionSweep.Last, markBodies = visitMarked;
        float factor = sweep == PositionSweep.Last ? 1f : _correctionFactor;
        float drift = PositionDrift * _slop, counted = 0.01f * _slop;
        int word = start >> 6, k = start - 1, visits = 0, markedForNext = 0, outcome = 0;
        while (NextToCorrect(visitMarked, shared, ref word, start, end, ref k))
        {
            visits++;
            ref ContactConstraint c = ref _constraints[k];
            bool shock = sweep == PositionSweep.Last && c.CarriesWeight;
            float correction = CorrectPosition(ref c, shock, factor, out float excess);
            if (correction <= 0)
            {
                continue;
            }

            outcome |= correction > counted ? (shock ? 2 : 3) : 0; // 1: a sideways contact, 2: any contact
            if (markSelf && excess - correction >= drift)
            {
                MarkForNext(k, shared, ref markedForNext);
            }

            if (markBodies && (shock ? c.AIsUpper : _bodies[c.A].InverseMass > 0))
            {
                PublishPosition(c.A, k, drift, shared, ref markedForNext);
            }

            if (markBodies && (shock ? !c.AIsUpper : _bodies[c.B].InverseMass > 0))
            {
                PublishPosition(c.B, k, drift, shared, ref markedForNext);
            }
        }

        _stripCounts[slot * Padding] = markedForNext;
        _stripCounts[slot * Padding + 1] = visits;
        _stripCounts[slot * Padding + 3] = outcome;
    }

    /// <summary>
    /// Moves <paramref name="k"/> on to the next contact of [<paramref name="start"/>, <paramref name="end"/>) the sweep
    /// visits: the next one, or with <paramref name="marked"/> the next marked one; false when none is left.
    /// </summary>
    private bool NextToCorrect(bool marked, bool shared, ref int word, int start, int end, ref int k)
    {
        if (!marked)
        {
            return ++k < end;
        }

        return shared ? _positionMarks.TryTakeShared(ref word, start, end, out k) : _positionMarks.TryTake(out k);
    }

    /// <summary>Marks contact <paramref name="k"/> for the next sweep.</summary>
    private void MarkForNext(int k, bool shared, ref int markedForNext)
    {
        if (shared)
        {
            _positionMarks.MarkForNextShared(k, ref markedForNext);
        }
        else
        {
            _positionMarks.MarkForNext(k);
        }
    }

    /// <summary>
    /// If the body in <paramref name="slot"/> has moved by more than <paramref name="drift"/> since its contacts last
    /// saw it, publishes its position and marks its contacts around contact <paramref name="k"/>: those after it for
    /// this sweep, those before it for the next.
    /// </summary>
    private void PublishPosition(int slot, int k, float drift, bool shared, ref int markedForNext)
    {
        if (Vectors.DistanceSquared(_positions[slot], _publishedPositions[slot]) <= drift * drift)
        {
            return;
        }

        _publishedPositions[slot] = _positions[slot];
        if (shared)
        {
            _positionMarks.MarkAroundShared(_positionContactsOfBodies.Of(slot), k, ref markedForNext);
        }
        else
        {
            _positionMarks.MarkAround(_positionContactsOfBodies.Of(slot), k);
        }
    }
}
