using System;
using System.Numerics;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// The last position sweep for what gravity does not order: a body crushed against something immovable by a far heavier one.
/// </summary>
/// <remarks>
/// A position sweep splits each correction by inverse mass, so a light body between a wall and a body 10³ times heavier
/// is pushed into the wall and back out again, and the heavy body moves by a thousandth of the depth per sweep: a
/// 0.35 kg disc crushed by a 597 kg one at 60 m/s ended a step 3.9 mm deep (generated world 233 of 2,000, seed 801).
/// Under gravity the shock sweep answers the contacts that carry weight from the ground up; without gravity there is no
/// up, and across gravity (a contact whose normal is more than about 45° from vertical) the shock sweep has no order
/// either, but there is still what cannot move. So when the sweeps leave such a pair of bodies deeper than the slop,
/// each body is given its distance, in touching contacts that carry no weight, from anything immovable (a plane, a
/// static body), and a last sweep, nearest first, removes the depth of each of those contacts between two distances by
/// moving only the body farther from the immovable: the shock propagation of Guendelman, Bridson and Fedkiw
/// ("Nonconvex Rigid Bodies with Stacking", SIGGRAPH 2003, https://physbam.stanford.edu/~fedkiw/papers/stanford2003-01.pdf)
/// with distance from the walls for height. It moves positions only; momentum is not conserved by walls anyway, and
/// bodies that touch nothing immovable are left alone, so a free cluster keeps its momentum. The distances come from
/// one breadth-first walk over the touching contacts, listed per body by a counting sort: a few passes over the
/// contacts, and only in a substep whose last position sweep had to correct a sideways contact by more than 1 % of
/// the slop (a settled pile corrects next to nothing there) and then still leaves one deeper than the slop.
/// <para>Contacts that carry weight are left out of the walk, and that is what lets it run under gravity. Run over
/// every contact there, it fought the shock sweep in deep piles (4,000 discs poured 200 deep no longer fell asleep
/// within 12 s); over the sideways contacts alone the same pour sleeps after 458 steps (438 without the walk), and all
/// 2,000 generated worlds keep their bounds, world 991 among them (a 0.38 kg disc driven into a corner of its box by
/// discs up to 208 kg: 3.2 mm into the wall without the walk, 0.86 mm with it).</para>
/// </remarks>
public sealed partial class SequentialImpulseSolver
{
    /// <summary>Distances beyond this many contacts from anything immovable are not propagated (the work stays bounded).</summary>
    private const int AnchorLevels = 64;

    private int[] _anchorDistance = new int[InitialCapacity]; // per slot
    private readonly ContactsOfBodies _touching = new(); // each slot's touching contacts (ListTouchingContacts)
    private int[] _anchorQueue = new int[InitialCapacity];

    private void PropagateFromAnchors(int count, int slots)
    {
        if (!LeavesExcessDepth(count))
        {
            return;
        }

        ListTouchingContacts(count, slots, everyContact: false);

        // Breadth-first from everything immovable, so bodies come nearest first; each contact between distances d and
        // d + 1 is answered once, from its nearer end, by moving only the body at d + 1.
        Buffers.EnsureCapacity(ref _anchorDistance, slots);
        Buffers.EnsureCapacity(ref _anchorQueue, slots);
        int head = 0, tail = 0;
        for (int s = 0; s < slots; s++)
        {
            bool anchor = _bodies[s].InverseMass == 0 && !_touching.Of(s).IsEmpty;
            _anchorDistance[s] = anchor ? 0 : int.MaxValue;
            if (anchor)
            {
                _anchorQueue[tail++] = s;
            }
        }

        while (head < tail)
        {
            int u = _anchorQueue[head++];
            int next = _anchorDistance[u] + 1;
            if (next > AnchorLevels)
            {
                continue;
            }

            foreach (int k in _touching.Of(u))
            {
                ref ContactConstraint c = ref _constraints[k];
                int v = c.A == u ? c.B : c.A;
                if (_anchorDistance[v] == int.MaxValue)
                {
                    _anchorDistance[v] = next;
                    _anchorQueue[tail++] = v;
                }

                if (_anchorDistance[v] == next)
                {
                    MoveFarther(ref c, moveA: v == c.A);
                }
            }
        }
    }

    /// <summary>
    /// Lists each slot's touching contacts that carry no weight, or with <paramref name="everyContact"/> all those apart
    /// by no more than the slop, which a correction can bring into touch (a counting sort by slot: two passes over the contacts).
    /// </summary>
    private void ListTouchingContacts(int count, int slots, bool everyContact)
    {
        _touching.BeginCounting(slots);
        for (int k = 0; k < count; k++)
        {
            ref ContactConstraint c = ref _constraints[k];
            if (IsListed(ref c, everyContact))
            {
                _touching.Count(c.A, c.B);
            }
        }

        _touching.BeginListing();
        for (int k = 0; k < count; k++)
        {
            ref ContactConstraint c = ref _constraints[k];
            if (IsListed(ref c, everyContact))
            {
                _touching.List(c.A, c.B, k);
            }
        }
    }

    /// <summary>Whether <see cref="ListTouchingContacts"/> lists the contact (both of its passes ask the same).</summary>
    private bool IsListed(ref ContactConstraint c, bool everyContact) =>
        (everyContact || !c.CarriesWeight) && Depth(ref c, out _) >= (everyContact ? -_slop : 0f);

    /// <summary>
    /// Whether something immovable is touched (else there is nothing to propagate from: a free cluster, the smash) and
    /// a contact between two movable bodies is deeper than the slop after the sweeps.
    /// </summary>
    private bool LeavesExcessDepth(int count)
    {
        if (!TouchesAnythingImmovable(count))
        {
            return false;
        }

        for (int k = 0; k < count; k++)
        {
            ref ContactConstraint c = ref _constraints[k];
            if (!c.IsPlaneContact && !c.CarriesWeight && _bodies[c.A].InverseMass > 0 && _bodies[c.B].InverseMass > 0 && Depth(ref c, out _) > _slop)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Whether a contact has an immovable end (a plane, a static body): else no correction can start from one.</summary>
    private bool TouchesAnythingImmovable(int count)
    {
        for (int k = 0; k < count; k++)
        {
            ref ContactConstraint c = ref _constraints[k];
            if (_bodies[c.A].InverseMass == 0 || _bodies[c.B].InverseMass == 0)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>The contact's depth at the working positions (negative when apart), and its normal; every position sweep measures through it.</summary>
    private float Depth(ref ContactConstraint c, out Vector3 normal)
    {
        if (c.IsPlaneContact)
        {
            normal = c.Normal;
            return ContactGeometry.Unchecked.PlanePenetration(_positions[c.A], _radii[c.A], normal, c.PlaneOffset);
        }

        return ContactGeometry.Unchecked.CirclePenetration(_positions[c.A], _radii[c.A], _positions[c.B], _radii[c.B], out normal);
    }

    /// <summary>Removes the contact's depth beyond the slop by moving one body along the normal (n points from B to A).</summary>
    private void MoveFarther(ref ContactConstraint c, bool moveA)
    {
        float excess = Depth(ref c, out Vector3 normal) - _slop;
        if (excess <= 0)
        {
            return;
        }

        if (moveA)
        {
            _positions[c.A] += normal * excess;
        }
        else
        {
            _positions[c.B] -= normal * excess;
        }
    }
}
