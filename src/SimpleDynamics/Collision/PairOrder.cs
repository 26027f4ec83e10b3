using System;

namespace SimpleDynamics.Collision;

/// <summary>
/// Last step's pairs (their <see cref="Contact.Key"/>s) in the order they were met, and where this step's pairs are
/// among them: the contact persistence behind warm starting and the contact events.
/// </summary>
/// <remarks>
/// <para>Detection and the solver meet a pile's pairs in nearly the same order from one step to the next, so a pair is
/// looked for first at its own index shifted as much as the pair before it was found shifted (so one pair more or
/// less early in the list costs one look-up, not all the rest). Only a pair not there is looked up by key, in a
/// table built from the list the first time a step needs it; a step that finds every pair in order builds no table
/// and reads the list front to back. Measured in the 1,000-disc 2-D pit, counting only the contacts the solver met at
/// their very own index: every one, once the pit has settled; 38–78 % while it lands.</para>
/// <para>The list and the table shrink once they have long been far larger than a step's pairs
/// (<see cref="ShrinkPolicy"/>); the owner calls <see cref="Begin"/> once a step.</para>
/// </remarks>
internal sealed class PairOrder
{
    private const int InitialCapacity = 16;

    private ulong[] _keys = new ulong[InitialCapacity];
    private ShrinkPolicy _keysRoom;
    private KeyTable _table = new();
    private ShrinkPolicy _tableRoom;
    private bool _tableBuilt;
    private int _offset; // where the last pair found was, relative to its own index

    /// <summary>The pairs listed.</summary>
    public int Count { get; private set; }

    /// <summary>
    /// Empties the list, to be filled with up to <paramref name="count"/> pairs (this step's use for the shrink policy).
    /// </summary>
    public void Begin(int count)
    {
        int room = _keysRoom.Observe(count, _keys.Length, InitialCapacity);
        if (room > 0)
        {
            _keys = new ulong[room];
        }

        Buffers.EnsureCapacity(ref _keys, count);
        room = _tableRoom.Observe(count, _table.Room, KeyTable.InitialRoom);
        if (room > 0)
        {
            _table = new KeyTable(room);
        }

        Count = 0;
        _tableBuilt = false;
        _offset = 0;
    }

    /// <summary>
    /// Gives an array of the owner's, kept by position beside the list, the list's room: it grows and shrinks with it
    /// (emptied; call it after <see cref="Begin"/>).
    /// </summary>
    public void Fit<T>(ref T[] byPosition)
    {
        if (byPosition.Length != _keys.Length)
        {
            byPosition = new T[_keys.Length];
        }
    }

    /// <summary>Appends a pair; returns its position.</summary>
    public int Add(ulong key)
    {
        _keys[Count] = key;
        return Count++;
    }

    /// <summary>
    /// Where pair <paramref name="key"/>, met at <paramref name="index"/> in this step's order, is in the list: first
    /// where order says (see the remarks above), then by key (the last position, if listed twice); −1 if it is not.
    /// </summary>
    public int Find(int index, ulong key)
    {
        int position = index + _offset;
        if ((uint)position < (uint)Count && _keys[position] == key)
        {
            return position;
        }

        if (!_tableBuilt)
        {
            _table.Build(_keys.AsSpan(0, Count));
            _tableBuilt = true;
        }

        position = _table.Find(key);
        if (position >= 0)
        {
            _offset = position - index;
        }

        return position;
    }

    /// <summary>Forgets every pair.</summary>
    public void Clear()
    {
        Count = 0;
        _tableBuilt = false;
        _offset = 0;
    }

    /// <summary>Reallocates the list to what it holds, and the table to nothing until it is next needed.</summary>
    public void TrimExcess()
    {
        Buffers.Shrink(ref _keys, Math.Max(Count, 1));
        _table = new KeyTable(0);
        _tableBuilt = false;
    }

    /// <summary>An open-addressing table from a pair's key to its position in the list.</summary>
    private sealed class KeyTable
    {
        private const int InitialSlots = 16;

        /// <summary>The pairs a new table holds (half its slots).</summary>
        public const int InitialRoom = InitialSlots / 2;

        private Entry[] _entries;
        private int _mask;

        // The slots filled since the table was last built, so that a table that once held a whole pit and now holds
        // a few awake pairs (the rest asleep) is emptied in proportion to what it holds, not to its size.
        private int[] _used = new int[InitialSlots];
        private int _usedCount;

        public KeyTable(int room = 0)
        {
            _entries = new Entry[SlotsFor(room)];
            _mask = _entries.Length - 1;
        }

        /// <summary>The pairs it holds before it grows: half its slots.</summary>
        public int Room => _entries.Length / 2;

        /// <summary>Empties the table and fills it with <paramref name="keys"/>, at most half full.</summary>
        public void Build(ReadOnlySpan<ulong> keys)
        {
            if (_entries.Length < SlotsFor(keys.Length))
            {
                _entries = new Entry[SlotsFor(keys.Length)];
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
            Buffers.EnsureCapacity(ref _used, keys.Length);
            for (int i = 0; i < keys.Length; i++)
            {
                Set(keys[i], i);
            }
        }

        /// <summary>The position stored for <paramref name="key"/>, or −1.</summary>
        public int Find(ulong key)
        {
            for (int slot = Slot(key); _entries[slot].PositionPlusOne > 0; slot = (slot + 1) & _mask)
            {
                if (_entries[slot].Key == key)
                {
                    return _entries[slot].PositionPlusOne - 1;
                }
            }

            return -1;
        }

        private void Set(ulong key, int position)
        {
            int slot = Slot(key);
            while (_entries[slot].PositionPlusOne > 0 && _entries[slot].Key != key)
            {
                slot = (slot + 1) & _mask;
            }

            if (_entries[slot].PositionPlusOne == 0)
            {
                _used[_usedCount++] = slot;
            }

            _entries[slot] = new Entry { Key = key, PositionPlusOne = position + 1 };
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

        private int Slot(ulong key)
        {
            ulong h = key * 0x9E3779B97F4A7C15UL; // Fibonacci hashing
            return (int)(h >> 32) & _mask;
        }

        private struct Entry
        {
            public ulong Key;
            public int PositionPlusOne; // 0: an empty slot
        }
    }
}
