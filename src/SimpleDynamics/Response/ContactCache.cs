using System;
using System.Numerics;

namespace SimpleDynamics.Response;

/// <summary>
/// Contact persistence for warm starting: the accumulated impulses of last step's contacts, keyed by pair.
/// A contact keeps its identity while its pair stays in touch. Two open-addressing tables are swapped each
/// step (last step's to read, this step's to write), so a warm cache allocates nothing. The tables shrink once they
/// have long been far larger than the step's contacts (<see cref="ShrinkPolicy"/>), each when it is next written.
/// </summary>
internal sealed class ContactCache
{
    private Table _previous = new();
    private Table _current = new();
    private ShrinkPolicy _room;
    private int _shrinkTo;       // the room, in contacts, the policy chose last
    private int _tablesToShrink; // how many tables are still to be reallocated to it (each when next written)

    /// <summary>
    /// The substep length the stored impulses were accumulated over (0: none stored). An impulse that holds a
    /// resting contact for a substep is its force times the substep's length, so a warm start with another length
    /// scales them by the ratio (a pile stepped at dt = 1/30 after 1/60 needs twice the impulse per substep).
    /// </summary>
    public float SubstepLength { get; set; }

    /// <summary>Looks up last step's impulses of a pair.</summary>
    public bool TryGet(ulong key, out float normalImpulse, out Vector3 frictionImpulse) =>
        _previous.TryGet(key, out normalImpulse, out frictionImpulse);

    /// <summary>Prepares the table this step writes, for up to <paramref name="count"/> contacts.</summary>
    public void BeginStep(int count)
    {
        int room = _room.Observe(count, Math.Max(_current.Room, _previous.Room), Table.InitialRoom);
        if (room > 0)
        {
            _shrinkTo = room;
            _tablesToShrink = 2;
        }

        int shrinkTo = 0;
        if (_tablesToShrink > 0)
        {
            _tablesToShrink--;
            shrinkTo = _shrinkTo;
        }

        _current.Reset(count, shrinkTo);
    }

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

    /// <summary>
    /// Gives back the spare room: this step's table is rewritten before it is read, so it starts small again; last
    /// step's keeps its impulses for the next warm start, in a table just large enough for them.
    /// </summary>
    public void TrimExcess()
    {
        _current = new Table();
        _previous = _previous.Compacted();
    }

    private sealed class Table
    {
        private const int InitialSlots = 16;

        private Entry[] _entries = new Entry[InitialSlots];
        private int _mask = InitialSlots - 1;
        private int _count;

        // The slots Set filled since the last Reset, so that a table that once held a whole pit and now holds a
        // few awake contacts (the rest asleep) is emptied in proportion to what it holds, not to its size.
        private int[] _used = new int[InitialSlots];
        private int _usedCount;

        /// <summary>The contacts a new table holds (half its slots).</summary>
        public const int InitialRoom = InitialSlots / 2;

        /// <summary>The contacts it holds before it grows: half its slots.</summary>
        public int Room => _entries.Length / 2;

        /// <summary>
        /// Empties the table and makes room for <paramref name="count"/> contacts at most half full; given a
        /// <paramref name="shrinkTo"/> room (in contacts), reallocates it to that room if it is larger.
        /// </summary>
        public void Reset(int count, int shrinkTo = 0)
        {
            int needed = SlotsFor(count);
            int target = SlotsFor(Math.Max(count, shrinkTo));
            if (_entries.Length < needed)
            {
                _entries = new Entry[needed];
            }
            else if (shrinkTo > 0 && _entries.Length > target)
            {
                _entries = new Entry[target];
                Buffers.ShrinkTo(ref _used, target / 2, 0);
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
            _count = 0;
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
                _count++;
                Buffers.EnsureCapacity(ref _used, _usedCount + 1);
                _used[_usedCount++] = slot;
            }

            _entries[slot] = new Entry { Key = key, Occupied = true, Normal = normal, Friction = friction };
        }

        /// <summary>A copy of this table's entries in the smallest table that holds them at most half full.</summary>
        public Table Compacted()
        {
            var table = new Table();
            table.Reset(_count);
            foreach (Entry entry in _entries)
            {
                if (entry.Occupied)
                {
                    table.Set(entry.Key, entry.Normal, entry.Friction);
                }
            }

            return table;
        }

        private static int SlotsFor(int count)
        {
            int slots = InitialSlots;
            while (slots < 2 * count)
            {
                slots <<= 1;
            }

            return slots;
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
