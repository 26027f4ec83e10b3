using System;
using SimpleDynamics.Bodies;

namespace SimpleDynamics;

/// <summary>
/// The bookkeeping of sleeping: a union-find over the awake bodies, which groups them into islands (bodies joined
/// by touching contacts, directly or through others), and the record of each sleeping island, a linked list of its
/// bodies, so that waking one body wakes all of them.
/// </summary>
/// <remarks>
/// Union-find with union by size and path halving (Tarjan): each body starts as its own island and every touching
/// contact merges two; a find walks to the island's root. The arrays grow and are kept, so a warm world allocates
/// nothing here; <see cref="TrimExcess"/> gives their spare room back.
/// </remarks>
internal sealed class Islands
{
    private int[] _parent = new int[16];
    private int[] _size = new int[16];

    private RigidBody?[] _first = new RigidBody?[8];
    private int[] _freeIds = new int[8];
    private int _freeCount;
    private int _idCount;

    /// <summary>Grows every array to hold <paramref name="bodies"/> bodies (each in an island of its own at most).</summary>
    public void Reserve(int bodies)
    {
        Buffers.EnsureCapacity(ref _parent, bodies);
        Buffers.EnsureCapacity(ref _size, bodies);
        Buffers.EnsureCapacity(ref _first, bodies);
        Buffers.EnsureCapacity(ref _freeIds, bodies);
    }

    /// <summary>
    /// Gives back the room beyond <paramref name="bodies"/> bodies, keeping every sleeping island's record (ids up to
    /// the highest in use, and the free ones among them).
    /// </summary>
    public void TrimExcess(int bodies)
    {
        Buffers.Shrink(ref _parent, bodies);
        Buffers.Shrink(ref _size, bodies);
        Buffers.Shrink(ref _first, _idCount);
        Buffers.Shrink(ref _freeIds, _freeCount);
    }

    /// <summary>Makes each of the first <paramref name="n"/> slots an island of its own.</summary>
    public void Reset(int n)
    {
        Buffers.EnsureCapacity(ref _parent, n);
        Buffers.EnsureCapacity(ref _size, n);
        for (int i = 0; i < n; i++)
        {
            _parent[i] = i;
            _size[i] = 1;
        }
    }

    /// <summary>The root of slot <paramref name="i"/>'s island.</summary>
    public int Find(int i)
    {
        while (_parent[i] != i)
        {
            _parent[i] = _parent[_parent[i]]; // path halving: point every other node to its grandparent
            i = _parent[i];
        }

        return i;
    }

    /// <summary>Joins the islands of two slots; returns the root of the joined island.</summary>
    public int Union(int a, int b)
    {
        a = Find(a);
        b = Find(b);
        if (a == b)
        {
            return a;
        }

        if (_size[a] < _size[b])
        {
            (a, b) = (b, a);
        }

        _parent[b] = a;
        _size[a] += _size[b];
        return a;
    }

    /// <summary>A new, empty sleeping island; returns its id.</summary>
    public int NewSleepingIsland()
    {
        int id = _freeCount > 0 ? _freeIds[--_freeCount] : _idCount++;
        Buffers.EnsureCapacity(ref _first, _idCount);
        _first[id] = null;
        return id;
    }

    /// <summary>Puts a body into a sleeping island.</summary>
    public void Add(int id, RigidBody body)
    {
        body.island = id;
        body.nextInIsland = _first[id];
        _first[id] = body;
    }

    /// <summary>Empties a sleeping island and returns its first body (the rest follow through nextInIsland).</summary>
    public RigidBody? Release(int id)
    {
        RigidBody? first = _first[id];
        _first[id] = null;
        Buffers.EnsureCapacity(ref _freeIds, _freeCount + 1);
        _freeIds[_freeCount++] = id;
        return first;
    }
}
