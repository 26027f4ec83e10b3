using System;
using System.Threading;

namespace SimpleDynamics.Threading;

/// <summary>
/// Hands out the shares of one parallel pass (the strips of a pile) to the threads that run it, each share to exactly
/// one thread. Each thread first takes the shares of its own part (an equal, contiguous part, the same in every pass,
/// so that a thread finds its shares' data in its cache from the pass before), then, last first, any share of the
/// others' that no thread has taken yet: a thread that is done takes over from one that has more work.
/// </summary>
/// <remarks>
/// Only for shares that are independent, so that which thread runs a share, and when, changes nothing in the result.
/// <see cref="Reset"/> is called before the pass is posted to the workers; <see cref="WorkerThreads.Run"/> posts it with
/// a full fence, so the workers see the shares untaken.
/// </remarks>
internal sealed class ShareQueue
{
    private readonly int[] _taken; // per share: 1 once a thread has taken it
    private int _count;

    public ShareQueue(int most) => _taken = new int[most];

    /// <summary>Makes shares 0 to <paramref name="count"/> − 1 untaken, for the next pass.</summary>
    public void Reset(int count)
    {
        if ((uint)count > (uint)_taken.Length)
        {
            throw new ArgumentOutOfRangeException(nameof(count), count, $"A pass has at most {_taken.Length} shares.");
        }

        Array.Clear(_taken, 0, count);
        _count = count;
    }

    /// <summary>
    /// The next share for <paramref name="thread"/> of <paramref name="threads"/> that no thread has taken yet; false
    /// when none is left. <paramref name="cursor"/> starts at 0 and belongs to the calling thread.
    /// </summary>
    public bool TryTake(int thread, int threads, ref int cursor, out int share)
    {
        int count = _count;
        int first = thread * count / threads, end = (thread + 1) * count / threads;
        int own = end - first, above = count - end; // its own shares, and the others' after them
        while (cursor < count)
        {
            int place = cursor++;
            share = place < own ? first + place // its own part, in order
                : place - own < above ? count - 1 - (place - own) // then the others', from the last down
                : first - 1 - (place - own - above);
            if (Interlocked.Exchange(ref _taken[share], 1) == 0)
            {
                return true;
            }
        }

        share = -1;
        return false;
    }
}
