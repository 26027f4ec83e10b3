using System;

namespace SimpleDynamics.Collision;

/// <summary>
/// The contacts that detection found in one step (tutorial §2.1, <c>CollisionData.cs</c>): a reusable sink that
/// keeps its storage between steps, so a warm world allocates nothing here.
/// </summary>
public sealed class CollisionData
{
    private Contact[] _contacts;

    /// <summary>Creates an empty sink with room for <paramref name="capacity"/> contacts.</summary>
    public CollisionData(int capacity = 64)
    {
        Guard.AtLeast(capacity, 1, nameof(capacity));
        _contacts = new Contact[capacity];
    }

    /// <summary>The number of contacts.</summary>
    public int Count { get; private set; }

    /// <summary>The contacts, in detection order.</summary>
    public Span<Contact> Contacts => _contacts.AsSpan(0, Count);

    /// <summary>The contact at <paramref name="index"/>, by reference.</summary>
    public ref Contact this[int index]
    {
        get
        {
            if ((uint)index >= (uint)Count)
            {
                throw new ArgumentOutOfRangeException(nameof(index));
            }

            return ref _contacts[index];
        }
    }

    /// <summary>Appends a contact, growing the storage when full.</summary>
    public void Add(in Contact contact)
    {
        Buffers.EnsureCapacity(ref _contacts, Count + 1);
        _contacts[Count++] = contact;
    }

    /// <summary>Removes all contacts and keeps the storage.</summary>
    public void Clear()
    {
        // Drop body references so removed bodies can be collected.
        Array.Clear(_contacts, 0, Count);
        Count = 0;
    }
}
