using System;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// The contacts that detection found in one step (tutorial §2.1, <c>CollisionData.cs</c>): a reusable sink that
/// keeps its storage between steps, so a warm world allocates nothing here.
/// </summary>
public sealed class CollisionData
{
    private readonly int _initialCapacity;
    private Contact[] _contacts;
    private int _count;
    private bool _bodiesRemoved;
    private ShrinkPolicy _room;

    /// <summary>Creates an empty sink with room for <paramref name="capacity"/> contacts.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="capacity"/> is less than 1.</exception>
    public CollisionData(int capacity = 64)
    {
        Guard.AtLeast(capacity, 1, nameof(capacity));
        _initialCapacity = capacity;
        _contacts = new Contact[capacity];
    }

    /// <summary>The number of contacts.</summary>
    public int Count
    {
        get
        {
            DropContactsOfRemovedBodies();
            return _count;
        }
    }

    /// <summary>The contacts, in detection order.</summary>
    public Span<Contact> Contacts
    {
        get
        {
            DropContactsOfRemovedBodies();
            return _contacts.AsSpan(0, _count);
        }
    }

    /// <summary>The contact at <paramref name="index"/>, by reference.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="index"/> is not in [0, <see cref="Count"/>).</exception>
    public ref Contact this[int index]
    {
        get
        {
            DropContactsOfRemovedBodies();
            if ((uint)index >= (uint)_count)
            {
                throw new ArgumentOutOfRangeException(nameof(index));
            }

            return ref _contacts[index];
        }
    }

    /// <summary>
    /// The world whose <see cref="World.Collisions"/> this is, or null for a sink of one's own. Contacts of an
    /// owned sink must name bodies of its world (or its <see cref="World.Ground"/>).
    /// </summary>
    internal World? Owner { get; init; }

    /// <summary>
    /// The storage itself, the first <see cref="Count"/> entries being the contacts, for the step's inner loops (one
    /// read instead of a checked indexer per contact). It is replaced when <see cref="Add"/> grows it.
    /// </summary>
    internal Contact[] Storage
    {
        get
        {
            DropContactsOfRemovedBodies();
            return _contacts;
        }
    }

    /// <summary>The room in the storage, for tests of <see cref="TrimExcess"/>.</summary>
    internal int Capacity => _contacts.Length;

    /// <summary>Appends a contact, growing the storage when full.</summary>
    /// <exception cref="ArgumentException">The contact does not name two bodies (it is <c>default</c>, say).</exception>
    public void Add(in Contact contact)
    {
        if (contact.BodyA is null || contact.BodyB is null)
        {
            throw new ArgumentException("A contact must name two bodies; create it with the Contact constructor or ContactGeometry.TryCollide.", nameof(contact));
        }

        DropContactsOfRemovedBodies();
        Buffers.EnsureCapacity(ref _contacts, _count + 1);
        _contacts[_count++] = contact;
    }

    /// <summary>Removes all contacts and keeps the storage.</summary>
    public void Clear()
    {
        // Drop body references so removed bodies can be collected.
        Array.Clear(_contacts, 0, _count);
        _count = 0;
        _bodiesRemoved = false;
    }

    /// <summary>Keeps the first <paramref name="count"/> contacts and drops the rest (the world's detection, leaving pairs out).</summary>
    internal void TruncateTo(int count)
    {
        Array.Clear(_contacts, count, _count - count);
        _count = count;
    }

    /// <summary>
    /// Shrinks the storage to the contacts held (at least one), releasing what a crowded step grew it to.
    /// Allocates the smaller array: call it after the scene has shrunk, not every step.
    /// </summary>
    public void TrimExcess()
    {
        DropContactsOfRemovedBodies();
        Buffers.Shrink(ref _contacts, Math.Max(_count, 1));
    }

    /// <summary>
    /// Called by <see cref="Owner"/> at the end of each step: the storage shrinks once it has long been far larger
    /// than the steps need (<see cref="ShrinkPolicy"/>), keeping the contacts.
    /// </summary>
    internal void ShrinkIfIdle() => Buffers.ShrinkIfIdle(ref _contacts, Count, ref _room, _initialCapacity);

    /// <summary>
    /// Called by <see cref="Owner"/> when it removes a body: the contacts naming it are dropped before the
    /// contacts are next read, all removals since in one pass, so that removing many bodies costs one sweep
    /// of the contacts rather than one each.
    /// </summary>
    internal void MarkBodiesRemoved() => _bodiesRemoved = true;

    /// <summary>
    /// Stable compaction: keeps, in order, the contacts both of whose bodies are still in <see cref="Owner"/>.
    /// </summary>
    private void DropContactsOfRemovedBodies()
    {
        if (!_bodiesRemoved || Owner is not World world)
        {
            return;
        }

        _bodiesRemoved = false;
        int kept = 0;
        for (int i = 0; i < _count; i++)
        {
            ref Contact c = ref _contacts[i];
            if (IsIn(c.BodyA, world) && IsIn(c.BodyB, world))
            {
                if (kept != i)
                {
                    _contacts[kept] = c;
                }

                kept++;
            }
        }

        Array.Clear(_contacts, kept, _count - kept);
        _count = kept;
    }

    private static bool IsIn(RigidBody? body, World world) => body is not null && (body.World == world || body == world.Ground);
}
