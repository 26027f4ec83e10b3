using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>The position pass: the projection of listing 2 as non-linear Gauss–Seidel sweeps.</summary>
/// <remarks>
/// <para>In every substep but a step's last, only the first sweep visits every contact. A contact that a sweep leaves
/// within the slop, and whose bodies nothing moves after it, would be measured again by the next sweep at the very
/// same positions and corrected by nothing again. So the later sweeps visit, still in order, only the contacts that a
/// sweep left deeper than the slop by <see cref="PositionDrift"/> of it or more, and those of bodies that corrections
/// have moved by more than that since their contacts last saw them (<see cref="ContactMarks"/>; the body's position is
/// then "published" again, as the local velocity sweeps publish velocities). What a contact is left with beyond the
/// slop is then less than that drift, plus twice the drift for each of its bodies (each stays within the drift of where
/// it was published): 25 µm at most against the slop's 0.5 mm, and the next substep's sweeps take it. A settled pile corrects thousands of contacts per sweep by less than a
/// micrometre each (measured in the settled 1,000-disc 2-D pit: 16 % of the contacts visited are corrected, three
/// quarters of those by less than 0.5 µm, 2 % of the visits by more than 5 µm), and full sweeps would visit every
/// contact again for them. Measured there and at 4,000 discs, switching every 30 steps: the sweeps visit half as many
/// contacts, and a step takes 5 % (1,000) and 13 % (4,000) less time. With no drift allowed the marks saved no time:
/// too many contacts move by a little.</para>
/// <para>The first sweep marks only the contacts it leaves deep; the bodies it moved are looked at after it, and only
/// when no more than an eighth of them moved by more than the drift (and then at most a quarter of the contacts is to
/// be visited again) do the later sweeps keep track: a pile still landing moves most of its bodies, and full sweeps
/// serve it at less cost. The last substep sweeps every contact, so that a step ends within the slop exactly as full
/// sweeps end it (the world laws hold nobody deeper than the slop at the end of every step).</para>
/// <para>Each sweep runs in strips on the world's threads when the substep's velocity passes did, with the result of
/// one thread (SequentialImpulseSolver.PositionSweeps.cs); the walk from what cannot move and the residual sweeps that
/// follow run on the caller's thread.</para>
/// </remarks>
public sealed partial class SequentialImpulseSolver
{
    private readonly ContactsOfBodies _positionContactsOfBodies = new(); // contact indices, for the marked position sweeps
    private readonly ContactMarks _positionMarks = new();
    private int _positionListsCount = -1; // the contacts the lists above were made for this step (−1: none yet)

    private Vector3[] _publishedPositions = new Vector3[InitialCapacity]; // per slot: where its contacts last saw it

    /// <summary>For tests: position sweeps go over every contact, as without <see cref="ContactMarks"/>.</summary>
    internal bool FullPositionSweeps { get; set; }

    /// <summary>
    /// The depth, as a fraction of <see cref="Slop"/>, that the later position sweeps of a substep before a step's last
    /// may leave uncorrected (see the remarks above): 1 %. With 0 they do exactly what full sweeps would, bit for bit (tested).
    /// </summary>
    internal float PositionDrift { get; set; } = 0.01f;

    /// <summary>Contacts the position sweeps of the step begun last visited, for tests.</summary>
    internal long PositionVisitsThisStep { get; private set; }

    private void CorrectPositions(ReadOnlySpan<RigidBody> bodies, int count)
    {
        if (_positionIterations == 0 || count == 0)
        {
            return;
        }

        for (int i = 0; i < bodies.Length; i++)
        {
            _positions[_slotOf[i]] = bodies[i].position;
        }

        count = Math.Min(count, _prepared);
        int slots = bodies.Length + 1;
        bool tracking = !FullPositionSweeps && !_step!.IsLastSubstep; // a step ends as full sweeps end it (see above)
        if (tracking)
        {
            _positionMarks.Begin(count);
            Buffers.EnsureCapacity(ref _publishedPositions, slots);
            Array.Copy(_positions, _publishedPositions, slots);
        }

        // The first sweep visits every contact, and marks only those it leaves deep; what it moved is looked at after
        // it, so that a pile still landing, which moves most of its bodies, pays for no tracking.
        SweepPositions(PositionSweep.First, tracking, count);
        tracking = tracking && MarkAfterFirstSweep(count, slots);
        for (int iteration = 1; iteration < _positionIterations; iteration++)
        {
            SweepPositions(PositionSweep.Later, tracking, count);
            if (tracking)
            {
                _positionMarks.NextSweep();
            }
        }

        // A last sweep removes the whole depth beyond the slop: under gravity, contacts that carry weight (normal
        // within about 45° of vertical) propagate the shock bottom-up; every other contact, and every contact without
        // gravity, is corrected in full, split by inverse mass.
        // A settled pile corrects next to nothing here; a jam against a wall corrects a sideways contact by much more,
        // and only then can the walk from what cannot move have anything to do.
        SweepPositions(PositionSweep.Last, tracking, count, out bool sidewaysCorrected, out bool corrected);
        if (sidewaysCorrected)
        {
            PropagateFromAnchors(count, slots); // see SequentialImpulseSolver.Anchoring.cs
        }

        // In a step's last substep always: corrections too small to count above can still leave a light body a few
        // micrometres beyond the slop, pushed into a wall by a heavier one (generated world 1,120 of seed 834: a 0.10 kg
        // disc in a corner under a 12 kg one ended a step 0.5035 mm into the wall), and the step must end within it.
        if ((corrected || _step!.IsLastSubstep) && TouchesAnythingImmovable(count))
        {
            SweepWhatStaysDeep(count, slots); // see SequentialImpulseSolver.Residual.cs
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
    /// After the first sweep: whether the later ones may visit only what can still change, and if so marks for the
    /// next sweep, besides the contacts the first left deep, every contact of each body it moved by more than the drift
    /// allowed (published). Not when more than an eighth of the bodies moved that much, or a quarter of the contacts
    /// would be visited again: a pile landing, which full sweeps serve at less cost.
    /// </summary>
    private bool MarkAfterFirstSweep(int count, int slots)
    {
        float drift = PositionDrift * _slop;
        int moved = 0;
        for (int s = 1; s < slots; s++)
        {
            moved += Vectors.DistanceSquared(_positions[s], _publishedPositions[s]) > drift * drift ? 1 : 0;
        }

        if (moved > slots / 8 || _positionMarks.MarkedForNext > count / 4)
        {
            return false;
        }

        ListContactsOfBodies(count, slots);
        int unused = 0;
        for (int s = 1; s < slots && _positionMarks.MarkedForNext <= count / 4; s++)
        {
            PublishPosition(s, int.MaxValue, drift, shared: false, ref unused); // before the contact at int.MaxValue: all of them, for the next sweep
        }

        _positionMarks.NextSweep();
        return _positionMarks.MarkedForNext <= count / 4;
    }

    /// <summary>Lists each body's contacts, once a step (and again if the impact pass has added contacts since).</summary>
    private void ListContactsOfBodies(int count, int slots)
    {
        if (_positionListsCount == count)
        {
            return;
        }

        _positionListsCount = count;
        _positionContactsOfBodies.BeginCounting(slots);
        for (int k = 0; k < count; k++)
        {
            _positionContactsOfBodies.Count(_constraints[k].A, _constraints[k].B);
        }

        _positionContactsOfBodies.BeginListing();
        for (int k = 0; k < count; k++)
        {
            _positionContactsOfBodies.List(_constraints[k].A, _constraints[k].B, k);
        }
    }

    /// <summary>
    /// Listing 2 as a Gauss–Seidel position sweep: measure the contact at the current positions and push the
    /// bodies apart along the normal, split by inverse mass, by a bounded share of the depth beyond the slop. With
    /// <paramref name="shock"/> (the last, bottom-up sweep under gravity) the whole depth beyond the slop is removed
    /// by moving the upper body alone. <paramref name="factor"/> is the share of the excess depth removed. Returns the
    /// depth removed (0 when none), and gives the depth beyond the slop it found (0 when it did not measure it).
    /// </summary>
    private float CorrectPosition(ref ContactConstraint c, bool shock, float factor, out float excess)
    {
        excess = 0;
        float inverseMassA = _bodies[c.A].InverseMass, inverseMassB = _bodies[c.B].InverseMass;
        if (shock)
        {
            if (c.AIsUpper ? inverseMassA == 0 : inverseMassB == 0)
            {
                return 0;
            }

            inverseMassA = c.AIsUpper ? 1f : 0f;
            inverseMassB = c.AIsUpper ? 0f : 1f;
        }

        float inverseMassSum = inverseMassA + inverseMassB;
        if (inverseMassSum == 0 || ClearlyWithinSlop(ref c))
        {
            return 0;
        }

        excess = Depth(ref c, out Vector3 normal) - _slop;
        float correction = shock ? excess : MathF.Min(factor * excess, _maxCorrection);
        if (correction <= 0)
        {
            return 0;
        }

        Separate(ref c, normal, correction, inverseMassA, inverseMassB);
        return correction;
    }

    /// <summary>
    /// Whether two bodies' centres are so far apart that their depth is certainly below the slop: the squared distance
    /// beyond (r_A + r_B − slop)² by more than float rounding could account for. Most contacts of a settled pile are
    /// shallower than the slop (84 % of the position pass's visits in the settled 4,000-disc 2-D pit), and this spares
    /// them the square root of measuring; the rest are measured as before, so the pass's result is the same.
    /// </summary>
    private bool ClearlyWithinSlop(ref ContactConstraint c)
    {
        if (c.IsPlaneContact)
        {
            return false;
        }

        float reach = _radii[c.A] + _radii[c.B] - _slop;
        return reach > 0 && Vectors.DistanceSquared(_positions[c.A], _positions[c.B]) > reach * reach * (1f + 1e-5f);
    }

    /// <summary>Pushes the contact's bodies apart along the normal by <paramref name="correction"/>, split by the inverse masses given.</summary>
    private void Separate(ref ContactConstraint c, Vector3 normal, float correction, float inverseMassA, float inverseMassB)
    {
        // A body that does not move is not written: threads sweeping strips at once share the ground and the walls.
        float share = correction / (inverseMassA + inverseMassB);
        if (inverseMassA > 0)
        {
            _positions[c.A] += normal * (share * inverseMassA);
        }

        if (inverseMassB > 0)
        {
            _positions[c.B] -= normal * (share * inverseMassB);
        }
    }
}
