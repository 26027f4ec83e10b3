using System;
using System.Numerics;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>
/// After the last position sweep: the contacts it leaves deeper than the slop, swept again on their own.
/// </summary>
/// <remarks>
/// One Gauss–Seidel sweep, however ordered, can leave a contact deeper than it found it when a later contact pushes
/// one of its bodies back: a light disc lifted out of the disc below it by the shock sweep and then pushed down again
/// by a far heavier one leaning on it from the side, or a light disc squeezed in a row between heavy ones on the floor.
/// Each such correction pushes the body back by a fraction of the other (the cosine between the two normals), so
/// sweeping again converges, but a whole sweep more is far more work than the few contacts need, and a settled pile
/// has none. So the contacts still deeper than the slop (beyond what float rounding of where the bodies are accounts
/// for: see <see cref="StaysDeep"/>) are put on a queue, and each in turn is corrected, split by inverse mass (not as
/// the last sweep does it, the upper body alone when the contact carries weight); when a correction moves a body,
/// those of its touching contacts that it made deeper than the slop join the queue. A light body caged by heavier
/// ones (a 0.016 kg disc on a 4 kg one with 3 and 128 kg discs leaning on it, generated world 746 of 2,000, seed 801)
/// cannot get out on its own, and corrections split by inverse mass move its neighbours by a hundredth to a ten
/// thousandth of the depth each: so a body corrected <see cref="CorrectionsBeforeHeld"/> times is held where it is, and
/// its neighbours make room. Holding a body moves the centre of mass, which only something immovable can answer for, so
/// the queue runs only in a substep whose contacts touch a plane or an immovable body; the work is bounded (a few
/// corrections per queued contact, and a pile still landing, with many deep contacts, is left to the next substeps'
/// sweeps), and only substeps whose last sweep corrected something pay for the search.
/// </remarks>
public sealed partial class SequentialImpulseSolver
{
    /// <summary>
    /// The queue is for the few contacts a sweep leaves deep: with more than this many (plus one in 32 of the contacts),
    /// it is not started.
    /// </summary>
    private const int MostQueued = 16;

    /// <summary>
    /// Corrections allowed per contact that joins the queue before the queue is left as it stands. With 8, generated
    /// world 746 of 2,000 (seed 801), swept in strips (SweepStrips.cs), ended a step with its caged disc 0.12 mm deeper
    /// than the slop; 32 brings it within. Counted only for the contacts queued at the start, a cage that one deep
    /// contact set off ran out after 32 corrections with a 3.5 kg disc 0.5016 mm into the floor under a 0.014 kg one
    /// pressed by a 738 kg one (generated world 1,204 of 2,000, seed 801); so every contact that joins adds its share.
    /// Only substeps with deep contacts left spend any of it.
    /// </summary>
    private const int CorrectionsPerContact = 32;

    /// <summary>Corrections of one body in the queue after which it is held where it is and its neighbours move instead.</summary>
    private const int CorrectionsBeforeHeld = 4;

    private int[] _corrections = new int[InitialCapacity]; // per slot, in the queue
    private int[] _deepQueue = new int[InitialCapacity]; // a ring of contact indices
    private bool[] _queued = new bool[InitialCapacity];
    private bool[] _joined = new bool[InitialCapacity]; // queued at some time in this call: its share is in the budget

    /// <summary>Contacts the queue took up in the step begun last (each correction tried), for tests.</summary>
    internal int ResidualVisitsThisStep { get; private set; }

    private void SweepWhatStaysDeep(int count, int slots)
    {
        Buffers.EnsureCapacity(ref _deepQueue, count);
        Buffers.EnsureCapacity(ref _queued, count);
        Buffers.EnsureCapacity(ref _joined, count);
        int head = 0, queued = 0;
        for (int k = 0; k < count; k++)
        {
            ref ContactConstraint c = ref _constraints[k];
            _queued[k] = _joined[k] = !ClearlyWithinSlop(ref c) && StaysDeep(ref c);
            if (_queued[k])
            {
                _deepQueue[queued++] = k;
            }
        }

        if (queued == 0 || queued > MostQueued + count / 32)
        {
            return; // none, or a pile still landing, whose next substeps' sweeps take them
        }

        ListTouchingContacts(count, slots, everyContact: true);
        Buffers.EnsureCapacity(ref _corrections, slots);
        Array.Clear(_corrections, 0, slots);
        for (int budget = CorrectionsPerContact * queued; queued > 0 && budget > 0; budget--)
        {
            int k = _deepQueue[head];
            head = head + 1 == count ? 0 : head + 1;
            queued--;
            ResidualVisitsThisStep++;
            _queued[k] = false;
            ref ContactConstraint c = ref _constraints[k];
            if (CorrectCaged(ref c) <= 0)
            {
                continue;
            }

            budget += QueueDeepContactsOf(c.A, count, head, ref queued);
            budget += QueueDeepContactsOf(c.B, count, head, ref queued);
        }

    }

    /// <summary>
    /// Removes the contact's depth beyond the slop, split by inverse mass, except that a body corrected
    /// <see cref="CorrectionsBeforeHeld"/> times already is held: it is caged by its neighbours (pushed back into one by
    /// each correction out of another), and only they can make room, however much heavier they are. When both bodies
    /// have been corrected that often, the one corrected more often is held: split by inverse mass, a light disc in a
    /// corner wedged by a heavy one took nearly all of each correction into the walls and back, and the heavy one's
    /// share was lost to float rounding, so the queue turned without progress (generated world 455 of 2,000, seed 802).
    /// </summary>
    private float CorrectCaged(ref ContactConstraint c)
    {
        float inverseMassA = _bodies[c.A].InverseMass, inverseMassB = _bodies[c.B].InverseMass;
        int correctionsA = _corrections[c.A], correctionsB = _corrections[c.B];
        bool heldA = correctionsA >= CorrectionsBeforeHeld && correctionsA > correctionsB;
        bool heldB = correctionsB >= CorrectionsBeforeHeld && correctionsB > correctionsA;
        if (heldA != heldB && inverseMassA > 0 && inverseMassB > 0)
        {
            inverseMassA = heldA ? 0f : 1f;
            inverseMassB = heldB ? 0f : 1f;
        }

        float inverseMassSum = inverseMassA + inverseMassB;
        float excess = Depth(ref c, out Vector3 normal) - _slop;
        if (inverseMassSum == 0 || excess <= 0)
        {
            return 0;
        }

        Vector3 startA = _positions[c.A], startB = _positions[c.B];
        Separate(ref c, normal, excess, inverseMassA, inverseMassB);
        if (_positions[c.A] == startA && _positions[c.B] == startB)
        {
            return 0; // rounding swallowed the correction: no body moved, none is counted, nothing is made deeper
        }

        _corrections[c.A] += inverseMassA > 0 ? 1 : 0;
        _corrections[c.B] += inverseMassB > 0 ? 1 : 0;
        return excess;
    }

    /// <summary>
    /// Whether a contact is deeper than the slop by more than a thousandth of it, and by more than float rounding of
    /// its bodies' centres accounts for: 2⁻²³ of their largest coordinate, at least one unit in its last place. That
    /// is the larger from 4.2 m away from the origin on (at the default slop): a centre 8 m away is placed to within
    /// 2⁻²⁰ m (0.95 µm), so what the last sweep leaves at the slop there can measure a little beyond it, and no
    /// correction can move it by so little. In the settled 16,000-disc pit about 1,000 contacts ended each step so,
    /// 95 % of them by less than one unit in the last place, and the queue corrected them again and again, moving
    /// nothing, until its budget ran out (27,600 corrections a step, a tenth of the step's time).
    /// </summary>
    private bool StaysDeep(ref ContactConstraint c)
    {
        float extent = MathF.Max(Vectors.LargestCoordinate(_positions[c.A]), Vectors.LargestCoordinate(_positions[c.B]));
        return Depth(ref c, out _) > _slop + MathF.Max(0.001f * _slop, extent * (1f / (1 << 23)));
    }

    /// <summary>
    /// Queues the touching contacts of <paramref name="slot"/> now deeper than the slop (<see cref="StaysDeep"/>; the
    /// ground, slot 0, has none listed that matter: it does not move); returns the corrections the contacts queued for
    /// the first time add to the budget.
    /// </summary>
    private int QueueDeepContactsOf(int slot, int count, int head, ref int queued)
    {
        if (_bodies[slot].InverseMass == 0)
        {
            return 0;
        }

        int share = 0;
        foreach (int k in _touching.Of(slot))
        {
            if (!_queued[k] && StaysDeep(ref _constraints[k]))
            {
                _queued[k] = true;
                share += _joined[k] ? 0 : CorrectionsPerContact;
                _joined[k] = true;
                int tail = head + queued;
                _deepQueue[tail >= count ? tail - count : tail] = k;
                queued++;
            }
        }

        return share;
    }
}
