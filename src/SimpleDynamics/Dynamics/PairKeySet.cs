using System;

namespace SimpleDynamics;

/// <summary>
/// A set of pair keys (<see cref="Collision.Contact.Key"/>) by open addressing, reused from step to step so that a
/// warm world allocates nothing. Tells the impact pass which pairs already have a contact.
/// </summary>
internal sealed class PairKeySet
{
    private const int InitialSlots = 64;

    private ulong[] _keys = new ulong[InitialSlots];
    private bool[] _used = new bool[InitialSlots];
    private int _count;
    private bool _resetSinceShrink; // whether the set was filled since the last ShrinkIfIdle, i.e. in this step
    private ShrinkPolicy _room;

    /// <summary>Empties the set and makes room for <paramref name="expected"/> keys without growing.</summary>
    public void Reset(int expected)
    {
        int capacity = SlotsFor(expected);
        if (_keys.Length < capacity)
        {
            _keys = new ulong[capacity];
            _used = new bool[capacity];
        }
        else
        {
            Array.Clear(_used, 0, _used.Length);
        }

        _count = 0;
        _resetSinceShrink = true;
    }

    /// <summary>
    /// Applies the <see cref="ShrinkPolicy"/> once per step. Its use is the step's <paramref name="contacts"/> (or the
    /// keys it held, if more): it is filled with every contact whenever a body is looked up again, which is rare, so it
    /// stays ready for that between look-ups. It is filled afresh (<see cref="Reset"/>) before every use: nothing is kept.
    /// </summary>
    public void ShrinkIfIdle(int contacts)
    {
        // Measured in keys: the table holds up to half its slots.
        int used = Math.Max(contacts, _resetSinceShrink ? _count : 0);
        int room = _room.Observe(used, _keys.Length / 2, InitialSlots / 2);
        _resetSinceShrink = false;
        if (room > 0)
        {
            Reallocate(SlotsFor(room));
        }
    }

    /// <summary>Gives back all the spare room; the set is empty afterwards.</summary>
    public void TrimExcess()
    {
        if (_keys.Length > InitialSlots)
        {
            Reallocate(InitialSlots);
        }
    }

    private void Reallocate(int slots)
    {
        _keys = new ulong[slots];
        _used = new bool[slots];
        _count = 0;
    }

    /// <summary>The power of two of at least 64 slots that holds <paramref name="keys"/> at most half full.</summary>
    private static int SlotsFor(int keys)
    {
        int slots = InitialSlots;
        while (slots < 2 * keys)
        {
            slots <<= 1;
        }

        return slots;
    }

    /// <summary>Adds a key; returns false if it was there already.</summary>
    public bool Add(ulong key)
    {
        if (2 * (_count + 1) > _keys.Length)
        {
            Grow();
        }

        int mask = _keys.Length - 1;
        for (int slot = Slot(key, mask); ; slot = (slot + 1) & mask)
        {
            if (!_used[slot])
            {
                _used[slot] = true;
                _keys[slot] = key;
                _count++;
                return true;
            }

            if (_keys[slot] == key)
            {
                return false;
            }
        }
    }

    /// <summary>Whether the key is in the set.</summary>
    public bool Contains(ulong key)
    {
        int mask = _keys.Length - 1;
        for (int slot = Slot(key, mask); _used[slot]; slot = (slot + 1) & mask)
        {
            if (_keys[slot] == key)
            {
                return true;
            }
        }

        return false;
    }

    private void Grow()
    {
        ulong[] keys = _keys;
        bool[] used = _used;
        _keys = new ulong[keys.Length * 2];
        _used = new bool[keys.Length * 2];
        _count = 0;
        for (int i = 0; i < keys.Length; i++)
        {
            if (used[i])
            {
                Add(keys[i]);
            }
        }
    }

    private static int Slot(ulong key, int mask) => (int)((key * 0x9E3779B97F4A7C15UL) >> 32) & mask; // Fibonacci hashing
}
