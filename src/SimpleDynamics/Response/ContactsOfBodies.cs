using System;

namespace SimpleDynamics.Response;

/// <summary>
/// Each body's contacts: one list per body slot of the items (contact indices, or positions in a sweep) that touch it,
/// built by a counting sort in two passes over the contacts, the same test deciding in both which are listed: count
/// each listed contact under both of its bodies, then list it under both. The passes that follow a change through a
/// pile (the local sweeps, the walk from what cannot move, the queue of deep contacts) ask it which contacts a body's
/// change can reach.
/// </summary>
internal sealed class ContactsOfBodies
{
    private int[] _start = new int[16]; // per slot + 1: where its items begin in _items
    private int[] _fill = new int[16];
    private int[] _items = new int[32]; // every listed contact twice, once under each of its bodies
    private int _slots;

    /// <summary>Starts counting, for bodies in slots 0 to <paramref name="slots"/> − 1.</summary>
    public void BeginCounting(int slots)
    {
        Buffers.EnsureCapacity(ref _start, slots + 1);
        Buffers.EnsureCapacity(ref _fill, slots);
        Array.Clear(_start, 0, slots + 1);
        _slots = slots;
    }

    /// <summary>Counts a contact between the bodies in slots <paramref name="a"/> and <paramref name="b"/>.</summary>
    public void Count(int a, int b)
    {
        _start[a + 1]++;
        _start[b + 1]++;
    }

    /// <summary>Ends counting: each list's place follows from the counts; list the same contacts, in order, next.</summary>
    public void BeginListing()
    {
        for (int s = 0; s < _slots; s++)
        {
            _start[s + 1] += _start[s];
            _fill[s] = _start[s];
        }

        Buffers.EnsureCapacity(ref _items, _start[_slots]);
    }

    /// <summary>Lists <paramref name="item"/> under both of its bodies.</summary>
    public void List(int a, int b, int item)
    {
        _items[_fill[a]++] = item;
        _items[_fill[b]++] = item;
    }

    /// <summary>The items listed under the body in <paramref name="slot"/>, in the order they were listed.</summary>
    public ReadOnlySpan<int> Of(int slot) => new(_items, _start[slot], _start[slot + 1] - _start[slot]);

    /// <summary>Shrinks the room kept per body to <paramref name="slots"/> (see <see cref="Buffers.ShrinkTo{T}"/>); list again before asking.</summary>
    public void ShrinkBodies(int slots)
    {
        Buffers.ShrinkTo(ref _start, slots + 1, 0);
        Buffers.ShrinkTo(ref _fill, slots, 0);
        _slots = 0;
    }

    /// <summary>Shrinks the room kept for <paramref name="contacts"/> contacts (see <see cref="Buffers.ShrinkTo{T}"/>); list again before asking.</summary>
    public void ShrinkContacts(int contacts) => Buffers.ShrinkTo(ref _items, 2 * contacts, 0);
}
