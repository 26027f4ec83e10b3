using System;

namespace SimpleDynamics;

/// <summary>
/// A set of pair keys (<see cref="Collision.Contact.Key"/>) by open addressing, reused from step to step so that a
/// warm world allocates nothing. Tells the impact pass which pairs already have a contact.
/// </summary>
internal sealed class PairKeySet
{
    private ulong[] _keys = new ulong[64];
    private bool[] _used = new bool[64];
    private int _count;

    /// <summary>Empties the set and makes room for <paramref name="expected"/> keys without growing.</summary>
    public void Reset(int expected)
    {
        int capacity = 64;
        while (capacity < 2 * expected)
        {
            capacity <<= 1;
        }

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
