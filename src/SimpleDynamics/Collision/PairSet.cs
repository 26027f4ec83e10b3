using System;

namespace SimpleDynamics.Collision;

/// <summary>
/// The pairs touching at the end of one step, keyed by a 64-bit pair key, in the order they were added:
/// an open-addressing hash set (linear probing) over a dense list. Both arrays are kept and only grow, so a
/// warm world allocates nothing here; comparing this step's set with last step's yields the begin and end events.
/// </summary>
/// <remarks>
/// The first <see cref="HeldCount"/> items are held: the pairs of sleeping bodies, which stay touching from step to
/// step without being found again. <see cref="TruncateTo"/> drops the rest in time proportional to what it drops, so
/// a step of a world that mostly sleeps costs nothing for the held pairs.
/// </remarks>
internal sealed class PairSet<T>
    where T : struct
{
    private const int InitialCapacity = 16;

    private ulong[] _keys = new ulong[InitialCapacity];
    private T[] _items = new T[InitialCapacity];

    // _slots[h] is 0 when empty, else (index into _keys/_items) + 1. Kept at most half full, so probes are short.
    private int[] _slots = new int[2 * InitialCapacity];
    private ShrinkPolicy _room;

    // Spare arrays Permute writes into, then swaps with the live ones.
    private ulong[] _spareKeys = new ulong[InitialCapacity];
    private T[] _spareItems = new T[InitialCapacity];

    public int Count { get; private set; }

    /// <summary>How many items at the front are held (kept by <see cref="TruncateTo"/>); set by <see cref="Permute"/>.</summary>
    public int HeldCount { get; private set; }

    /// <summary>The items in the order they were added.</summary>
    public ReadOnlySpan<T> Items => _items.AsSpan(0, Count);

    public ulong KeyAt(int index) => _keys[index];

    /// <summary>Adds the pair unless its key is already present; returns whether it was added.</summary>
    public bool Add(ulong key, in T item)
    {
        if (2 * (Count + 1) > _slots.Length)
        {
            Grow();
        }

        int mask = _slots.Length - 1;
        for (int h = Home(key, mask); ; h = (h + 1) & mask)
        {
            int slot = _slots[h];
            if (slot == 0)
            {
                Buffers.EnsureCapacity(ref _keys, Count + 1);
                Buffers.EnsureCapacity(ref _items, Count + 1);
                _keys[Count] = key;
                _items[Count] = item;
                _slots[h] = ++Count;
                return true;
            }

            if (_keys[slot - 1] == key)
            {
                return false;
            }
        }
    }

    /// <summary>
    /// If the pair at <paramref name="index"/> has key <paramref name="key"/>, replaces its item with
    /// <paramref name="item"/> and returns true: the pair stays where it is, and the table as it is.
    /// </summary>
    public bool TryRenew(int index, ulong key, in T item)
    {
        if ((uint)index >= (uint)Count || _keys[index] != key)
        {
            return false;
        }

        _items[index] = item;
        return true;
    }

    public bool Contains(ulong key)
    {
        int mask = _slots.Length - 1;
        for (int h = Home(key, mask); ; h = (h + 1) & mask)
        {
            int slot = _slots[h];
            if (slot == 0)
            {
                return false;
            }

            if (_keys[slot - 1] == key)
            {
                return true;
            }
        }
    }

    /// <summary>Empties the set and keeps its storage.</summary>
    public void Clear()
    {
        HeldCount = 0;
        if (8 * Count < _slots.Length)
        {
            TruncateTo(0); // a few items in a large table: remove them one by one rather than clear the table
            return;
        }

        Array.Clear(_items, 0, Count); // drop body references so removed bodies can be collected
        Array.Clear(_slots, 0, _slots.Length);
        Count = 0;
    }

    /// <summary>Applies the <see cref="ShrinkPolicy"/> once per step to the pairs held now, which are kept.</summary>
    public void ShrinkIfIdle()
    {
        int room = _room.Observe(Count, _items.Length, InitialCapacity);
        if (room > 0)
        {
            Reallocate(room);
        }
    }

    /// <summary>Gives back all the spare room, keeping the pairs.</summary>
    public void TrimExcess()
    {
        if (_items.Length > Math.Max(Count, InitialCapacity))
        {
            Reallocate(Math.Max(Count, InitialCapacity));
        }
    }

    /// <summary>Removes the items from <paramref name="count"/> on (not below <see cref="HeldCount"/>), last first.</summary>
    public void TruncateTo(int count)
    {
        int mask = _slots.Length - 1;
        for (int i = Count - 1; i >= count; i--)
        {
            int h = Home(_keys[i], mask);
            while (_slots[h] != i + 1)
            {
                h = (h + 1) & mask;
            }

            // Backward-shift deletion (Knuth 6.4, algorithm R): move up each later entry of the probe run whose home
            // does not lie cyclically in (h, j], so that no lookup meets a hole before finding its key.
            for (int j = (h + 1) & mask; _slots[j] != 0; j = (j + 1) & mask)
            {
                int home = Home(_keys[_slots[j] - 1], mask);
                bool stays = h <= j ? h < home && home <= j : h < home || home <= j;
                if (!stays)
                {
                    _slots[h] = _slots[j];
                    h = j;
                }
            }

            _slots[h] = 0;
            _items[i] = default;
        }

        Count = Math.Min(Count, count);
        HeldCount = Math.Min(HeldCount, Count);
    }

    /// <summary>Grows the spare arrays of <see cref="Permute"/> to the live ones' length.</summary>
    public void ReserveSpare()
    {
        Buffers.EnsureCapacity(ref _spareKeys, _keys.Length);
        Buffers.EnsureCapacity(ref _spareItems, _items.Length);
    }

    /// <summary>
    /// Puts the items in the order <paramref name="order"/> gives (item k becomes the old item order[k]) and holds the
    /// first <paramref name="heldCount"/> of them. Rebuilds the table: done only when pairs fall asleep or wake.
    /// </summary>
    public void Permute(ReadOnlySpan<int> order, int heldCount)
    {
        ReserveSpare(); // as long as the live arrays, so that swapping them never leaves a shorter array to grow
        for (int k = 0; k < Count; k++)
        {
            _spareKeys[k] = _keys[order[k]];
            _spareItems[k] = _items[order[k]];
        }

        (_keys, _spareKeys) = (_spareKeys, _keys);
        (_items, _spareItems) = (_spareItems, _items);
        Array.Clear(_spareItems, 0, Count);
        Array.Clear(_slots, 0, _slots.Length);
        Rehash();
        HeldCount = heldCount;
    }

    /// <summary>The key of a pair of bodies, whichever order they come in.</summary>
    public static ulong BodyPairKey(int idA, int idB) =>
        idA < idB ? ((ulong)(uint)idA << 32) | (uint)idB : ((ulong)(uint)idB << 32) | (uint)idA;

    /// <summary>The key of a body and a plane; body ids are positive, so the set high bit keeps it apart from body pairs.</summary>
    public static ulong PlanePairKey(int bodyId, int planeIndex) => ((ulong)(uint)bodyId << 32) | 0x8000_0000u | (uint)planeIndex;

    // Fibonacci hashing: multiply by 2^64/φ and keep the high bits, which mixes the two ids of a key.
    private static int Home(ulong key, int mask) => (int)((key * 0x9E3779B97F4A7C15UL) >> 32) & mask;

    /// <summary>Moves the pairs into arrays of <paramref name="capacity"/> items and a table that holds them half full.</summary>
    private void Reallocate(int capacity)
    {
        Buffers.ShrinkTo(ref _keys, capacity, Count);
        Buffers.ShrinkTo(ref _items, capacity, Count);
        Buffers.ShrinkTo(ref _spareKeys, capacity, 0);
        Buffers.ShrinkTo(ref _spareItems, capacity, 0);
        int slots = 2 * InitialCapacity;
        while (slots < 2 * capacity)
        {
            slots <<= 1;
        }

        _slots = new int[slots];
        Rehash();
    }

    private void Grow()
    {
        _slots = new int[_slots.Length * 2];
        Rehash();
    }

    private void Rehash()
    {
        int mask = _slots.Length - 1;
        for (int i = 0; i < Count; i++)
        {
            int h = Home(_keys[i], mask);
            while (_slots[h] != 0)
            {
                h = (h + 1) & mask;
            }

            _slots[h] = i + 1;
        }
    }
}
