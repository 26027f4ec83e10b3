using System;
using System.Numerics;

namespace SimpleDynamics.Response;

/// <summary>
/// Contact persistence for warm starting: the accumulated impulses of last step's contacts, keyed by pair.
/// A contact keeps its identity while its pair stays in touch. Two open-addressing tables are swapped each
/// step (last step's to read, this step's to write), so a warm cache allocates nothing.
/// </summary>
internal sealed class ContactCache
{
    private Table _previous = new(16);
    private Table _current = new(16);

    /// <summary>Looks up last step's impulses of a pair.</summary>
    public bool TryGet(ulong key, out float normalImpulse, out Vector3 frictionImpulse) =>
        _previous.TryGet(key, out normalImpulse, out frictionImpulse);

    /// <summary>Prepares the table this step writes, for up to <paramref name="count"/> contacts.</summary>
    public void BeginStep(int count) => _current.Reset(count);

    /// <summary>Records this step's impulses of a pair.</summary>
    public void Store(ulong key, float normalImpulse, Vector3 frictionImpulse) =>
        _current.Set(key, normalImpulse, frictionImpulse);

    /// <summary>Makes this step's table the one the next step reads.</summary>
    public void EndStep() => (_previous, _current) = (_current, _previous);

    /// <summary>Forgets everything.</summary>
    public void Clear()
    {
        _previous.Reset(0);
        _current.Reset(0);
    }

    private sealed class Table
    {
        private Entry[] _entries;
        private int _mask;

        // The slots Set filled since the last Reset, so that a table that once held a whole pit and now holds a
        // few awake contacts (the rest asleep) is emptied in proportion to what it holds, not to its size.
        private int[] _used = new int[16];
        private int _usedCount;

        public Table(int capacity)
        {
            _entries = new Entry[capacity];
            _mask = capacity - 1;
        }

        public void Reset(int count)
        {
            int capacity = 16;
            while (capacity < 2 * count)
            {
                capacity <<= 1;
            }

            if (_entries.Length < capacity)
            {
                _entries = new Entry[capacity];
            }
            else if (8 * _usedCount < _entries.Length)
            {
                for (int i = 0; i < _usedCount; i++)
                {
                    _entries[_used[i]] = default;
                }
            }
            else
            {
                Array.Clear(_entries, 0, _entries.Length);
            }

            _usedCount = 0;
            _mask = _entries.Length - 1;
        }

        public void Set(ulong key, float normal, Vector3 friction)
        {
            int slot = Slot(key);
            while (_entries[slot].Occupied && _entries[slot].Key != key)
            {
                slot = (slot + 1) & _mask;
            }

            if (!_entries[slot].Occupied)
            {
                Buffers.EnsureCapacity(ref _used, _usedCount + 1);
                _used[_usedCount++] = slot;
            }

            _entries[slot] = new Entry { Key = key, Occupied = true, Normal = normal, Friction = friction };
        }

        public bool TryGet(ulong key, out float normal, out Vector3 friction)
        {
            for (int slot = Slot(key); _entries[slot].Occupied; slot = (slot + 1) & _mask)
            {
                if (_entries[slot].Key == key)
                {
                    normal = _entries[slot].Normal;
                    friction = _entries[slot].Friction;
                    return true;
                }
            }

            normal = 0;
            friction = Vector3.Zero;
            return false;
        }

        private int Slot(ulong key)
        {
            ulong h = key * 0x9E3779B97F4A7C15UL; // Fibonacci hashing
            return (int)(h >> 32) & _mask;
        }

        private struct Entry
        {
            public ulong Key;
            public bool Occupied;
            public float Normal;
            public Vector3 Friction;
        }
    }
}
