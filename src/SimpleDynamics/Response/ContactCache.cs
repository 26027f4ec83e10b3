using System;
using System.Numerics;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// Contact persistence for warm starting: the accumulated impulses of last step's contacts, keyed by pair.
/// A contact keeps its identity while its pair stays in touch.
/// </summary>
/// <remarks>
/// The impulses are kept in the order the solver stored them, the order it solves its contacts in (bottom-up along
/// gravity), and a contact is looked for where that order puts it (<see cref="PairOrder"/>): a settled pile reads
/// them front to back, with no hashing. A pair stored twice in a step (a detector that reports it twice) warm-starts
/// from the entry found in order, else from the last one stored. Last step's impulses are all read before this step's
/// are stored (the solver stores them at the end of the step), so one list serves, and a warm cache allocates nothing.
/// </remarks>
internal sealed class ContactCache
{
    private readonly PairOrder _order = new();
    private Impulses[] _impulses = Array.Empty<Impulses>(); // by position in _order

    /// <summary>
    /// The substep length the stored impulses were accumulated over (0: none stored). An impulse that holds a
    /// resting contact for a substep is its force times the substep's length, so a warm start with another length
    /// scales them by the ratio (a pile stepped at dt = 1/30 after 1/60 needs twice the impulse per substep).
    /// </summary>
    public float SubstepLength { get; set; }

    /// <summary>
    /// Looks up last step's impulses of the pair <paramref name="key"/>, the contact at <paramref name="index"/> in
    /// this step's order.
    /// </summary>
    public bool TryGet(int index, ulong key, out float normalImpulse, out Vector3 frictionImpulse)
    {
        int position = _order.Find(index, key);
        if (position < 0)
        {
            normalImpulse = 0;
            frictionImpulse = Vector3.Zero;
            return false;
        }

        normalImpulse = _impulses[position].Normal;
        frictionImpulse = _impulses[position].Friction;
        return true;
    }

    /// <summary>Forgets last step's impulses, to store this step's <paramref name="count"/> contacts.</summary>
    public void BeginStep(int count)
    {
        _order.Begin(count);
        _order.Fit(ref _impulses);
    }

    /// <summary>Records this step's impulses of a pair, in the order the next step will most likely meet it.</summary>
    public void Store(ulong key, float normalImpulse, Vector3 frictionImpulse) =>
        _impulses[_order.Add(key)] = new Impulses { Normal = normalImpulse, Friction = frictionImpulse };

    /// <summary>Forgets everything.</summary>
    public void Clear() => _order.Clear();

    /// <summary>Gives back the spare room; the stored impulses are kept for the next warm start.</summary>
    public void TrimExcess()
    {
        _order.TrimExcess();
        Buffers.Shrink(ref _impulses, Math.Max(_order.Count, 1));
    }

    private struct Impulses
    {
        public float Normal;
        public Vector3 Friction;
    }
}
