using System;
using System.Numerics;
using System.Threading;

namespace SimpleDynamics.Response;

/// <summary>
/// Which contacts a Gauss–Seidel sweep that visits only what can still change has left to visit, by their positions
/// in the sweep: one bit each for this sweep and one for the next. A contact whose body has just been changed by the
/// contact at position p is marked for this sweep if it comes after p (it has not seen the change yet and its turn
/// is still to come), else for the next.
/// </summary>
internal sealed class ContactMarks
{
    private ulong[] _now = new ulong[1];
    private ulong[] _next = new ulong[1];
    private int _words;
    private int _word; // the sweep's cursor: no bit before this word is set

    /// <summary>Contacts marked for the next sweep since this one began.</summary>
    public int MarkedForNext { get; private set; }

    /// <summary>Starts with nothing marked, for a sweep over <paramref name="count"/> positions.</summary>
    public void Begin(int count)
    {
        _words = (count + 63) >> 6;
        Buffers.EnsureCapacity(ref _now, _words);
        Buffers.EnsureCapacity(ref _next, _words);
        Array.Clear(_now, 0, _words);
        Array.Clear(_next, 0, _words);
        _word = 0;
        MarkedForNext = 0;
    }

    /// <summary>
    /// Marks the contacts at <paramref name="positions"/> (the contacts of a body just changed by the contact at
    /// <paramref name="position"/>, −1 before the sweep begins): those after it for this sweep, those before it for the next.
    /// </summary>
    public void MarkAround(ReadOnlySpan<int> positions, int position)
    {
        foreach (int q in positions)
        {
            if (q > position)
            {
                _now[q >> 6] |= 1UL << (q & 63);
            }
            else if (q < position)
            {
                MarkForNext(q);
            }
        }
    }

    /// <summary>Marks the contact at <paramref name="position"/> for the next sweep.</summary>
    public void MarkForNext(int position)
    {
        ulong bit = 1UL << (position & 63);
        if ((_next[position >> 6] & bit) == 0)
        {
            _next[position >> 6] |= bit;
            MarkedForNext++;
        }
    }

    /// <summary>Takes the next position marked for this sweep, in order; false when none is left.</summary>
    public bool TryTake(out int position)
    {
        for (; _word < _words; _word++)
        {
            ulong bits = _now[_word];
            if (bits != 0)
            {
                position = (_word << 6) | TrailingZeros(bits);
                _now[_word] = bits & (bits - 1);
                return true;
            }
        }

        position = -1;
        return false;
    }

    /// <summary>
    /// <see cref="MarkAround"/> for a sweep that threads share, each over its own range of positions: a word at the
    /// edge of a range holds bits of the next range too, and the positions after every range (the seams) are marked
    /// by all of them, so bits are set atomically. Counts the contacts newly marked for the next sweep in
    /// <paramref name="markedForNext"/> (the caller's own count, added up after the sweep: see <see cref="AddMarkedForNext"/>).
    /// </summary>
    public void MarkAroundShared(ReadOnlySpan<int> positions, int position, ref int markedForNext)
    {
        foreach (int q in positions)
        {
            ulong bit = 1UL << (q & 63);
            if (q > position)
            {
                if ((Volatile.Read(ref _now[q >> 6]) & bit) == 0)
                {
                    Or(ref _now[q >> 6], bit);
                }
            }
            else if (q < position && (Or(ref _next[q >> 6], bit) & bit) == 0)
            {
                markedForNext++;
            }
        }
    }

    /// <summary>
    /// <see cref="MarkForNext"/> for a sweep that threads share (see <see cref="MarkAroundShared"/>): sets the bit
    /// atomically and counts it in <paramref name="markedForNext"/> if it was not set.
    /// </summary>
    public void MarkForNextShared(int position, ref int markedForNext)
    {
        ulong bit = 1UL << (position & 63);
        if ((Or(ref _next[position >> 6], bit) & bit) == 0)
        {
            markedForNext++;
        }
    }

    /// <summary>
    /// <see cref="TryTake"/> within positions [<paramref name="start"/>, <paramref name="end"/>) for a sweep that
    /// threads share, from the thread's own cursor <paramref name="word"/> (begin it at start / 64).
    /// </summary>
    public bool TryTakeShared(ref int word, int start, int end, out int position)
    {
        int lastWord = (end - 1) >> 6;
        for (; word <= lastWord; word++)
        {
            ulong mine = ulong.MaxValue;
            if (word == start >> 6)
            {
                mine &= ulong.MaxValue << (start & 63);
            }

            if (word == lastWord && (end & 63) != 0)
            {
                mine &= (1UL << (end & 63)) - 1;
            }

            ulong bits = Volatile.Read(ref _now[word]) & mine;
            if (bits != 0)
            {
                int bitIndex = TrailingZeros(bits);
                And(ref _now[word], ~(1UL << bitIndex));
                position = (word << 6) | bitIndex;
                return true;
            }
        }

        position = -1;
        return false;
    }

    /// <summary>Adds the contacts that threads marked for the next sweep (<see cref="MarkAroundShared"/>) to <see cref="MarkedForNext"/>.</summary>
    public void AddMarkedForNext(int count) => MarkedForNext += count;

    /// <summary>Begins the next sweep: what was marked for it is now to visit.</summary>
    public void NextSweep()
    {
        (_now, _next) = (_next, _now);
        Array.Clear(_next, 0, _words);
        _word = 0;
        MarkedForNext = 0;
    }

    /// <summary>Shrinks the room kept to <paramref name="contacts"/> positions (see <see cref="Buffers.ShrinkTo{T}"/>).</summary>
    public void Shrink(int contacts)
    {
        Buffers.ShrinkTo(ref _now, (contacts + 63) >> 6, 0);
        Buffers.ShrinkTo(ref _next, (contacts + 63) >> 6, 0);
        _words = 0;
    }

    /// <summary>Sets <paramref name="bits"/> in <paramref name="word"/> atomically; returns the word before.</summary>
    private static ulong Or(ref ulong word, ulong bits)
    {
#if NETSTANDARD2_1
        ref long signed = ref System.Runtime.InteropServices.MemoryMarshal.Cast<ulong, long>(System.Runtime.InteropServices.MemoryMarshal.CreateSpan(ref word, 1))[0];
        long before = Volatile.Read(ref signed);
        while (true)
        {
            long seen = Interlocked.CompareExchange(ref signed, before | (long)bits, before);
            if (seen == before)
            {
                return (ulong)before;
            }

            before = seen;
        }
#else
        return Interlocked.Or(ref word, bits);
#endif
    }

    /// <summary>Keeps only <paramref name="bits"/> of <paramref name="word"/>, atomically.</summary>
    private static void And(ref ulong word, ulong bits)
    {
#if NETSTANDARD2_1
        ref long signed = ref System.Runtime.InteropServices.MemoryMarshal.Cast<ulong, long>(System.Runtime.InteropServices.MemoryMarshal.CreateSpan(ref word, 1))[0];
        long before = Volatile.Read(ref signed);
        while (true)
        {
            long seen = Interlocked.CompareExchange(ref signed, before & (long)bits, before);
            if (seen == before)
            {
                return;
            }

            before = seen;
        }
#else
        Interlocked.And(ref word, bits);
#endif
    }

    internal static int TrailingZeros(ulong bits)
    {
#if NETSTANDARD2_1
        int count = 0;
        while ((bits & 1) == 0)
        {
            bits >>= 1;
            count++;
        }

        return count;
#else
        return BitOperations.TrailingZeroCount(bits);
#endif
    }
}
