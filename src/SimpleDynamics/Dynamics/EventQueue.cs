using System;

namespace SimpleDynamics;

/// <summary>
/// The collisions still to come in a substep, earliest first: a binary min-heap of (time, contact) with the
/// versions of both bodies when the time was computed. An entry whose body has collided since is stale and
/// skipped when it comes up, so a body's old predictions never need to be found and removed.
/// </summary>
internal sealed class EventQueue
{
    private const int InitialCapacity = 64;

    private Entry[] _heap = new Entry[InitialCapacity];
    private int _count;
    private int _peak; // the most entries held since the last ShrinkIfIdle: this step's use
    private ShrinkPolicy _room;

    public int Count => _count;

    public void Clear() => _count = 0;

    public void Push(double time, int contact, int versionA, int versionB)
    {
        Buffers.EnsureCapacity(ref _heap, _count + 1);
        int i = _count++;
        _peak = Math.Max(_peak, _count);
        var entry = new Entry(time, contact, versionA, versionB);
        while (i > 0)
        {
            int parent = (i - 1) >> 1;
            if (_heap[parent].Time <= time)
            {
                break;
            }

            _heap[i] = _heap[parent];
            i = parent;
        }

        _heap[i] = entry;
    }

    public Entry Pop()
    {
        Entry top = _heap[0];
        Entry last = _heap[--_count];
        int i = 0;
        while (true)
        {
            int child = 2 * i + 1;
            if (child >= _count)
            {
                break;
            }

            if (child + 1 < _count && _heap[child + 1].Time < _heap[child].Time)
            {
                child++;
            }

            if (last.Time <= _heap[child].Time)
            {
                break;
            }

            _heap[i] = _heap[child];
            i = child;
        }

        if (_count > 0)
        {
            _heap[i] = last;
        }

        return top;
    }

    /// <summary>
    /// Applies the <see cref="ShrinkPolicy"/> once per step, when the queue is empty. Its use is the step's
    /// <paramref name="contacts"/> (or more, if it held more): every contact may be queued at the start of a substep, so
    /// the queue stays ready for that even when a resting pile makes few impacts, and one knock does not grow it again.
    /// </summary>
    public void ShrinkIfIdle(int contacts)
    {
        Buffers.ShrinkIfIdle(ref _heap, Math.Max(_peak, contacts), ref _room, InitialCapacity);
        _peak = 0;
    }

    /// <summary>Gives back memory after a burst of events (between steps, when the queue is empty).</summary>
    public void TrimExcess() => Buffers.ShrinkTo(ref _heap, Math.Max(InitialCapacity, _count), _count);

    public readonly struct Entry
    {
        public readonly double Time;
        public readonly int Contact;
        public readonly int VersionA;
        public readonly int VersionB;

        public Entry(double time, int contact, int versionA, int versionB)
        {
            Time = time;
            Contact = contact;
            VersionA = versionA;
            VersionB = versionB;
        }
    }
}
