using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics;

// Memory: the working arrays of the world and of its stages grow to the largest scene seen (so a warm step allocates
// nothing) and shrink on TrimExcess, or on their own once the world has long needed far less (ShrinkPolicy).
public sealed partial class World
{
    private const int InitialBodyCapacity = 16;

    private ShrinkPolicy _bodyRoom;
    private ShrinkPolicy _awakeRoom;

    /// <summary>
    /// Releases the spare room of the world's working arrays (bodies, planes, <see cref="Collisions"/>, the contact
    /// events, sleeping, the queries' grid and the impact pass) and asks the <see cref="Responder"/> and the
    /// <see cref="Detector"/> to release what they keep for this world, if they implement <see cref="ITrimmable"/>.
    /// </summary>
    /// <remarks>
    /// The arrays grow to the largest scene seen and are kept. They also shrink on their own once a step has used
    /// less than a quarter of them for 120 steps in a row (about 2 s at 60 Hz), to twice that use; call this to give
    /// the memory back at once, after removing many bodies, say. Not every step: it allocates the smaller arrays.
    /// Nothing a reader can see changes: bodies, planes, contacts, contact events and warm-start impulses are kept.
    /// </remarks>
    /// <exception cref="System.InvalidOperationException">Called during <see cref="Step"/>.</exception>
    public void TrimExcess()
    {
        ThrowIfStepping(nameof(TrimExcess));
        Buffers.Shrink(ref _bodies, _bodyCount);
        Buffers.Shrink(ref _awake, _awakeCount);
        Buffers.Shrink(ref _planes, _planeCount);
        Collisions.TrimExcess();
        TrimEventBuffers();
        TrimSleepBuffers(_bodyCount);
        _queryGrid.TrimExcess();
        _impacts.TrimExcess();
        (Responder as ITrimmable)?.TrimExcess(this);
        (Detector as ITrimmable)?.TrimExcess(this);
    }

    /// <summary>
    /// Applies the <see cref="ShrinkPolicy"/> to the world's own arrays, once at the end of every step. The library's
    /// responder and detector apply it to theirs in their own stages; the queries' grid when it is rebuilt.
    /// </summary>
    private void ShrinkIdleBuffers()
    {
        int bodyRoom = _bodies.Length;
        Buffers.ShrinkIfIdle(ref _bodies, _bodyCount, ref _bodyRoom, InitialBodyCapacity);
        if (_bodies.Length < bodyRoom)
        {
            TrimSleepBuffers(_bodies.Length); // sized by the bodies, they follow the body array
        }

        Buffers.ShrinkIfIdle(ref _awake, _awakeCount, ref _awakeRoom, InitialBodyCapacity);
        Collisions.ShrinkIfIdle();
        _impacts.ShrinkIfIdle(_bodyCount, Collisions.Count);
        ShrinkIdleEventBuffers();
    }

    /// <summary>Room in the body array, for tests of <see cref="TrimExcess"/>.</summary>
    internal int BodyCapacity => _bodies.Length;

    /// <summary>Room in the plane array, for tests of <see cref="TrimExcess"/>.</summary>
    internal int PlaneCapacity => _planes.Length;
}
