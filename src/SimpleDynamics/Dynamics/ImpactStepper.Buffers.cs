using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics;

// Per-body and per-contact working arrays, and the lists of each body's contacts.
internal sealed partial class ImpactStepper
{
    /// <summary>
    /// Lists each body's contacts (a linked list through the contacts' two ends), so an impact can re-predict its
    /// neighbours; done at the substep's first impact, so a resting pile with none does not pay for it.
    /// </summary>
    private void EnsureLinked()
    {
        if (_linked)
        {
            return;
        }

        for (int i = 0; i < _bodyCount; i++)
        {
            _head[i] = -1;
        }

        for (int k = 0; k < _contactCount; k++)
        {
            Ends(k, out int a, out int b);
            Link(k, a, b);
        }

        _linked = true;
        (_linkedEnds, _linkedBodies) = (_endsVersion, _bodyCount);
    }

    /// <summary>
    /// Reads the world indices of the bodies of the contacts not read yet this step (all of them at its first
    /// substep) into <see cref="_ends"/>, so that the passes over the contacts find them in one small array instead
    /// of in two body objects per contact. A plane contact's second end is ~p (−1 − p) for plane p. Whenever the ends
    /// differ from those read before (detection found other contacts, or the same in another order, or the step added
    /// one), <see cref="_endsVersion"/> moves on: what was worked out for the old ones (the body lists, the quiet
    /// substeps' sorting) no longer holds.
    /// </summary>
    private void ReadEnds()
    {
        int from = _endsCount;
        bool changed = _contactCount > _endsCount;
        if (_endsStep != _stepNumber)
        {
            _endsStep = _stepNumber;
            from = 0;
            changed = _contactCount != _endsCount;
        }

        for (int k = from; k < _contactCount; k++)
        {
            ref Contact contact = ref _contacts[k];
            int a = contact.BodyA.index, b = contact.IsPlaneContact ? ~contact.PlaneIndex : contact.BodyB.index;
            changed |= (_ends[2 * k] != a) | (_ends[2 * k + 1] != b);
            _ends[2 * k] = a;
            _ends[2 * k + 1] = b;
        }

        _endsCount = _contactCount;
        _endsVersion += changed ? 1 : 0;
    }

    /// <summary>The world indices of contact k's bodies (b = ~p, negative, for plane p).</summary>
    private void Ends(int k, out int a, out int b)
    {
        a = _ends[2 * k];
        b = _ends[2 * k + 1];
    }

    private void Link(int k, int a, int b)
    {
        _next[2 * k] = _head[a];
        _head[a] = 2 * k;
        if (b >= 0)
        {
            _next[2 * k + 1] = _head[b];
            _head[b] = 2 * k + 1;
        }
    }

    private const int InitialBodies = 16;
    private const int InitialContacts = 16;

    private ShrinkPolicy _bodyRoom;
    private ShrinkPolicy _contactRoom;
    private ShrinkPolicy _leftOutRoom;

    /// <summary>
    /// Applies the <see cref="ShrinkPolicy"/> after a step over <paramref name="bodies"/> bodies and
    /// <paramref name="contacts"/> contacts. The arrays hold nothing from one step to the next, so nothing is kept.
    /// </summary>
    public void ShrinkIfIdle(int bodies, int contacts)
    {
        int room = _bodyRoom.Observe(bodies, _sphereCentre.Length, InitialBodies);
        if (room > 0)
        {
            ShrinkBodies(room);
        }

        room = _contactRoom.Observe(contacts, _limit.Length, InitialContacts);
        if (room > 0)
        {
            ShrinkContacts(room);
        }

        room = _leftOutRoom.Observe(_leftOutCount, _leftOut.Length, InitialContacts);
        if (room > 0)
        {
            ShrinkLeftOut(room);
        }

        _queue.ShrinkIfIdle(contacts);
    }

    /// <summary>Gives back all the spare room (between steps, when the arrays hold nothing).</summary>
    public void TrimExcess()
    {
        ShrinkBodies(InitialBodies);
        ShrinkContacts(InitialContacts);
        ShrinkLeftOut(InitialContacts);
        _queue.TrimExcess();
    }

    private void EnsureBodies(int n)
    {
        Buffers.EnsureCapacity(ref _sphereCentre, n);
        Buffers.EnsureCapacity(ref _reach, n);
        Buffers.EnsureCapacity(ref _startVelocity, n);
        Buffers.EnsureCapacity(ref _forcedVelocity, n);
        Buffers.EnsureCapacity(ref _substepStart, n);
        Buffers.EnsureCapacity(ref _startChord, n);
        Buffers.EnsureCapacity(ref _motion, n);
        Buffers.EnsureCapacity(ref _flight, n);
        Buffers.EnsureCapacity(ref _held, n);
        Buffers.EnsureCapacity(ref _head, n);
        Buffers.EnsureCapacity(ref _anchorDistance, n);
        Buffers.EnsureCapacity(ref _anchorQueue, n);
        Buffers.EnsureCapacity(ref _lumpOf, n);
        Buffers.EnsureCapacity(ref _lumps, n);
        Buffers.EnsureCapacity(ref _frameCentre, n);
        Buffers.EnsureCapacity(ref _frameReach, n);
        Buffers.EnsureCapacity(ref _keepsToFrame, n);
        Buffers.EnsureCapacity(ref _sortedAt, n);
        Buffers.EnsureCapacity(ref _restless, n);
        Buffers.EnsureCapacity(ref _drifted, n);
    }

    private void EnsureContacts(int count)
    {
        Buffers.EnsureCapacity(ref _next, 2 * count);
        Buffers.EnsureCapacity(ref _ends, 2 * count);
        Buffers.EnsureCapacity(ref _jamState, count);
        Buffers.EnsureCapacity(ref _limit, count);
        Buffers.EnsureCapacity(ref _sortedPairs, 2 * count);
        Buffers.EnsureCapacity(ref _nearBits, (count + 63) >> 6);
        Buffers.EnsureCapacity(ref _toPredict, (count + 63) >> 6);
    }

    private void ShrinkBodies(int capacity)
    {
        Buffers.ShrinkTo(ref _sphereCentre, capacity, 0);
        Buffers.ShrinkTo(ref _reach, capacity, 0);
        Buffers.ShrinkTo(ref _startVelocity, capacity, 0);
        Buffers.ShrinkTo(ref _forcedVelocity, capacity, 0);
        Buffers.ShrinkTo(ref _substepStart, capacity, 0);
        Buffers.ShrinkTo(ref _startChord, capacity, 0);
        Buffers.ShrinkTo(ref _motion, capacity, 0);
        Buffers.ShrinkTo(ref _flight, capacity, 0);
        Buffers.ShrinkTo(ref _held, capacity, 0);
        Buffers.ShrinkTo(ref _head, capacity, 0);
        Buffers.ShrinkTo(ref _anchorDistance, capacity, 0);
        Buffers.ShrinkTo(ref _anchorQueue, capacity, 0);
        Buffers.ShrinkTo(ref _lumpOf, capacity, 0);
        Buffers.ShrinkTo(ref _lumps, capacity, 0);
        Buffers.ShrinkTo(ref _frameCentre, capacity, 0);
        Buffers.ShrinkTo(ref _frameReach, capacity, 0);
        Buffers.ShrinkTo(ref _keepsToFrame, capacity, 0);
        Buffers.ShrinkTo(ref _sortedAt, capacity, 0);
        Buffers.ShrinkTo(ref _restless, capacity, 0);
        Buffers.ShrinkTo(ref _drifted, capacity, 0);
        _sortedEnds = _linkedEnds = -1; // nothing kept: sort and link again
        Buffers.ShrinkTo(ref _leftOutStart, capacity + 1, 0);
    }

    private void ShrinkContacts(int capacity)
    {
        Buffers.ShrinkTo(ref _next, 2 * capacity, 0);
        Buffers.ShrinkTo(ref _ends, 2 * capacity, 0);
        Buffers.ShrinkTo(ref _jamState, capacity, 0);
        (_endsStep, _endsCount) = (0, 0); // nothing kept: read them again
        Buffers.ShrinkTo(ref _limit, capacity, 0);
        Buffers.ShrinkTo(ref _sortedPairs, 2 * capacity, 0);
        Buffers.ShrinkTo(ref _nearBits, (capacity + 63) >> 6, 0);
        Buffers.ShrinkTo(ref _toPredict, (capacity + 63) >> 6, 0);
        _sortedEnds = _linkedEnds = -1;
    }

    /// <summary>Shrinks the lists of the pairs left out (ImpactStepper.Crowd.cs), which are not needed after their step.</summary>
    private void ShrinkLeftOut(int capacity)
    {
        Array.Clear(_leftOut, 0, _leftOutCount); // nothing kept: no body held from being collected
        _leftOutCount = 0;
        Buffers.ShrinkTo(ref _leftOut, capacity, 0);
        Buffers.ShrinkTo(ref _leftOutOf, 2 * capacity, 0);
    }
}
