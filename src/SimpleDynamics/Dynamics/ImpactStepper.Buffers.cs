using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics;

// Per-body and per-contact working arrays, and the lists of each body's contacts.
internal sealed partial class ImpactStepper
{
    /// <summary>Lists each body's contacts (a linked list through the contacts' two ends), so an impact can re-predict its neighbours.</summary>
    private void LinkContacts(CollisionData contacts, int n)
    {
        EnsureContacts(contacts.Count);
        for (int i = 0; i < n; i++)
        {
            _head[i] = -1;
        }

        for (int k = 0; k < contacts.Count; k++)
        {
            ref Contact contact = ref contacts[k];
            Link(k, contact.BodyA.index, contact.BodyB.index);
        }

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

    private void EnsureBodies(int n)
    {
        Buffers.EnsureCapacity(ref _stepStart, n);
        Buffers.EnsureCapacity(ref _reach, n);
        Buffers.EnsureCapacity(ref _startVelocity, n);
        Buffers.EnsureCapacity(ref _forcedVelocity, n);
        Buffers.EnsureCapacity(ref _x, n);
        Buffers.EnsureCapacity(ref _u, n);
        Buffers.EnsureCapacity(ref _a, n);
        Buffers.EnsureCapacity(ref _chord, n);
        Buffers.EnsureCapacity(ref _substepStart, n);
        Buffers.EnsureCapacity(ref _startChord, n);
        Buffers.EnsureCapacity(ref _t, n);
        Buffers.EnsureCapacity(ref _version, n);
        Buffers.EnsureCapacity(ref _impacts, n);
        Buffers.EnsureCapacity(ref _held, n);
        Buffers.EnsureCapacity(ref _head, n);
    }

    private void EnsureContacts(int count)
    {
        Buffers.EnsureCapacity(ref _next, 2 * count);
        Buffers.EnsureCapacity(ref _limit, count);
    }
}
