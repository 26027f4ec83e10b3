using System;

namespace SimpleDynamics.Response;

/// <summary>
/// Orders items from the lowest to the highest: a counting sort into n equal slices between the lowest and the
/// highest height, then each slice put in order on its own. A pile spreads over its slices with about one item in
/// each, so the whole costs O(n); a small world with one body far above the rest puts most items in one slice, and the
/// slice's own sort keeps them in order (the solver's shock passes go bottom-up and need it: a body corrected out of
/// the ground after the contact above it was corrected is pushed back into that contact). Equal heights are ordered by
/// the items' tie keys when they are given (the solver's contacts: then the order, and so the solver's results, do not
/// depend on the order a detector reported them in), else kept in their order. Reuses its working arrays.
/// </summary>
internal sealed class HeightOrder
{
    private const int InitialCapacity = 17;

    /// <summary>Slices up to this size are put in order by insertion; larger ones by a comparison sort of keys.</summary>
    private const int InsertionSlice = 32;

    private int[] _cursor = new int[InitialCapacity];
    private long[] _keys = new long[InitialCapacity]; // a large slice's (height, index) keys while it is sorted
    private ulong[] _runTies = new ulong[InitialCapacity]; // the tie keys of a run of equal heights in a large slice
    private int[] _runItems = new int[InitialCapacity];
    private int[] _last = new int[InitialCapacity]; // the order the last sort gave, tried first by the next one
    private int _lastCount = -1; // its length; −1 when there is none to try
    private int _peak; // the most slices one sort used since the last ShrinkIfIdle

    /// <summary>Whether the last sort reused the order of the one before, for tests.</summary>
    internal bool ReusedLastOrder { get; private set; }
    private ShrinkPolicy _room;

    /// <summary>Applies the <see cref="ShrinkPolicy"/> once per step; the working array holds nothing between sorts.</summary>
    public void ShrinkIfIdle()
    {
        Buffers.ShrinkIfIdle(ref _cursor, _peak, ref _room, InitialCapacity);
        if (_last.Length > _cursor.Length)
        {
            Buffers.ShrinkTo(ref _last, _cursor.Length, 0);
            _lastCount = -1;
        }

        if (_keys.Length > _cursor.Length)
        {
            Buffers.ShrinkTo(ref _keys, _cursor.Length, 0);
            Buffers.ShrinkTo(ref _runTies, _cursor.Length, 0);
            Buffers.ShrinkTo(ref _runItems, _cursor.Length, 0);
        }

        _peak = 0;
    }

    /// <summary>Gives back all the spare room.</summary>
    public void TrimExcess()
    {
        Buffers.ShrinkTo(ref _cursor, InitialCapacity, 0);
        Buffers.ShrinkTo(ref _last, InitialCapacity, 0);
        _lastCount = -1;
        Buffers.ShrinkTo(ref _keys, InitialCapacity, 0);
        Buffers.ShrinkTo(ref _runTies, InitialCapacity, 0);
        Buffers.ShrinkTo(ref _runItems, InitialCapacity, 0);
    }

    /// <summary>
    /// Puts <paramref name="items"/> in the order Sort gave: item k becomes the item that was at
    /// <paramref name="order"/>[k]. In place, one cycle of the permutation at a time, so each item is copied once and
    /// no second array is needed; the order is used up (each entry is turned negative once its position is filled).
    /// </summary>
    public static void Apply<T>(Span<T> items, Span<int> order)
    {
        for (int start = 0; start < order.Length; start++)
        {
            if (order[start] < 0 || order[start] == start)
            {
                continue; // filled already, or in place
            }

            // Position j takes the item from order[j], until the cycle comes back to the start.
            T first = items[start];
            int j = start;
            while (order[j] != start)
            {
                int from = order[j];
                items[j] = items[from];
                order[j] = ~from;
                j = from;
            }

            items[j] = first;
            order[j] = ~start;
        }
    }

    /// <summary>Fills <paramref name="order"/> with the indices 0 … n − 1 of <paramref name="heights"/>, lowest first; equal heights keep their order.</summary>
    public void Sort(ReadOnlySpan<float> heights, Span<int> order) => Sort(heights, ReadOnlySpan<ulong>.Empty, order);

    /// <summary>
    /// Fills <paramref name="order"/> with the indices 0 … n − 1 of <paramref name="heights"/>, lowest first, and
    /// equal heights by their <paramref name="ties"/> (one distinct key per item), smallest first.
    /// </summary>
    public void Sort(ReadOnlySpan<float> heights, ReadOnlySpan<ulong> ties, Span<int> order)
    {
        int n = heights.Length;
        float lowest = float.PositiveInfinity, highest = float.NegativeInfinity;
        for (int i = 0; i < n; i++)
        {
            lowest = MathF.Min(lowest, heights[i]);
            highest = MathF.Max(highest, heights[i]);
        }

        Buffers.EnsureCapacity(ref _cursor, n + 1);
        _peak = Math.Max(_peak, n + 1); // the key arrays are kept no larger than this
        ReusedLastOrder = false;
        if (float.IsInfinity(highest - lowest))
        {
            for (int i = 0; i < n; i++)
            {
                order[i] = i; // heights beyond float's range apart: kept in their order
            }

            _lastCount = -1; // not an order by height: nothing to try next time
            return;
        }

        if (n == _lastCount && LastOrderHolds(heights, ties))
        {
            _last.AsSpan(0, n).CopyTo(order);
            ReusedLastOrder = true;
            return;
        }

        SortAnew(heights, ties, order, lowest, highest);
        Buffers.EnsureCapacity(ref _last, n);
        order.CopyTo(_last);
        _lastCount = n;
    }

    /// <summary>
    /// Whether the last order still puts these heights (and ties) in order: each item strictly after the one before
    /// by height, then by tie key (or by index without ties). NaN heights fail, and are sorted anew.
    /// </summary>
    private bool LastOrderHolds(ReadOnlySpan<float> heights, ReadOnlySpan<ulong> ties)
    {
        ReadOnlySpan<int> last = _last.AsSpan(0, _lastCount);
        for (int k = 1; k < last.Length; k++)
        {
            int below = last[k - 1], item = last[k];
            float lower = heights[below], height = heights[item];
            if (!(lower < height || (lower == height && (ties.IsEmpty ? below < item : ties[below] < ties[item]))))
            {
                return false;
            }
        }

        return true;
    }

    private void SortAnew(ReadOnlySpan<float> heights, ReadOnlySpan<ulong> ties, Span<int> order, float lowest, float highest)
    {
        int n = heights.Length;
        if (!(highest > lowest))
        {
            for (int i = 0; i < n; i++)
            {
                order[i] = i;
            }

            if (!ties.IsEmpty && n > 1)
            {
                SortByKeys(heights, ties, order); // all at one height: by their ties alone
            }

            return;
        }

        Array.Clear(_cursor, 0, n + 1);
        float scale = (n - 1) / (highest - lowest);
        for (int i = 0; i < n; i++)
        {
            _cursor[Slice(heights[i]) + 1]++;
        }

        for (int s = 1; s <= n; s++)
        {
            _cursor[s] += _cursor[s - 1]; // now the first position of each slice
        }

        for (int i = 0; i < n; i++)
        {
            order[_cursor[Slice(heights[i])]++] = i;
        }

        // _cursor[s] is now where slice s + 1 begins.
        for (int s = 0, start = 0; s < n; start = _cursor[s], s++)
        {
            int count = _cursor[s] - start;
            if (count > InsertionSlice)
            {
                SortByKeys(heights, ties, order.Slice(start, count));
            }
            else if (count > 1)
            {
                SortByInsertion(heights, ties, order.Slice(start, count));
            }
        }

        int Slice(float height) => Math.Min((int)((height - lowest) * scale), n - 1);
    }

    /// <summary>Stable insertion sort of a few indices by their heights, then their ties if given.</summary>
    private static void SortByInsertion(ReadOnlySpan<float> heights, ReadOnlySpan<ulong> ties, Span<int> slice)
    {
        for (int k = 1; k < slice.Length; k++)
        {
            int item = slice[k];
            float height = heights[item];
            int j = k - 1;
            for (; j >= 0 && (heights[slice[j]] > height || (heights[slice[j]] == height && !ties.IsEmpty && ties[slice[j]] > ties[item])); j--)
            {
                slice[j + 1] = slice[j];
            }

            slice[j + 1] = item;
        }
    }

    /// <summary>
    /// Sorts many indices by (height, index), packed into one 64-bit key each so that an unstable comparison sort of
    /// the keys is stable in the items: the height's bits made to order as integers do, then the index.
    /// </summary>
    private void SortByKeys(ReadOnlySpan<float> heights, ReadOnlySpan<ulong> ties, Span<int> slice)
    {
        Buffers.EnsureCapacity(ref _keys, slice.Length);
        for (int k = 0; k < slice.Length; k++)
        {
            _keys[k] = ((long)OrderedBits(heights[slice[k]]) << 32) | (uint)slice[k];
        }

        Array.Sort(_keys, 0, slice.Length); // the keys are distinct (their indices are), so any sort orders them the same
        for (int k = 0; k < slice.Length; k++)
        {
            slice[k] = (int)(_keys[k] & 0xFFFFFFFF);
        }

        if (ties.IsEmpty)
        {
            return;
        }

        // Each run of equal heights, now in index order, by its ties instead.
        for (int start = 0, end; start < slice.Length; start = end)
        {
            int height = (int)(_keys[start] >> 32);
            for (end = start + 1; end < slice.Length && (int)(_keys[end] >> 32) == height; end++)
            {
            }

            if (end - start > 1)
            {
                SortRunByTies(ties, slice.Slice(start, end - start));
            }
        }
    }

    private void SortRunByTies(ReadOnlySpan<ulong> ties, Span<int> run)
    {
        Buffers.EnsureCapacity(ref _runTies, run.Length);
        Buffers.EnsureCapacity(ref _runItems, run.Length);
        for (int k = 0; k < run.Length; k++)
        {
            _runItems[k] = run[k];
            _runTies[k] = ties[run[k]];
        }

        Array.Sort(_runTies, _runItems, 0, run.Length); // distinct ties: any sort orders them the same
        _runItems.AsSpan(0, run.Length).CopyTo(run);
    }

    /// <summary>The bits of a finite float as an int that orders as the float does (negative floats' bits reversed).</summary>
    private static int OrderedBits(float height)
    {
        int bits = BitConverter.SingleToInt32Bits(height + 0f); // + 0: −0 becomes +0, equal to it
        return bits >= 0 ? bits : bits ^ int.MaxValue;
    }
}
