using System;

namespace SimpleDynamics.Response;

/// <summary>
/// The solver's memory: its working arrays (bodies and contacts of the step in progress, shared by every world it
/// serves) and each world's warm-start impulses grow to the largest step seen, and shrink when asked
/// (<see cref="TrimExcess"/>) or once steps have long needed far less (<see cref="ShrinkPolicy"/>).
/// </summary>
public sealed partial class SequentialImpulseSolver : ITrimmable
{
    private const int InitialCapacity = 16;

    private ShrinkPolicy _bodyRoom;
    private ShrinkPolicy _contactRoom;

    /// <summary>
    /// Releases the spare room of the warm-start impulses kept for <paramref name="world"/> (the impulses themselves
    /// are kept, so the next step starts as warm as it would have) and of the solver's working arrays, which hold
    /// nothing between steps. <see cref="World.TrimExcess"/> calls it; call it between steps.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="world"/> is null.</exception>
    public void TrimExcess(World world)
    {
        Guard.NotNull(world, nameof(world));
        if (_caches.TryGetValue(world, out ContactCache? cache))
        {
            cache.TrimExcess();
        }

        ShrinkBodies(InitialCapacity);
        ShrinkContacts(InitialCapacity);
        ShrinkBands(InitialCapacity);
        _heightOrder.TrimExcess();
    }

    /// <summary>Applies the <see cref="ShrinkPolicy"/> at the end of each step; the world's contact cache applies it itself.</summary>
    private void ShrinkIdleBuffers(int bodies, int contacts)
    {
        int room = _bodyRoom.Observe(bodies + 1, _bodies.Length, InitialCapacity); // slot 0 is the ground
        if (room > 0)
        {
            ShrinkBodies(room);
        }

        room = _contactRoom.Observe(contacts, _constraints.Length, InitialCapacity);
        if (room > 0)
        {
            ShrinkContacts(room);
        }

        _heightOrder.ShrinkIfIdle();
    }

    private void ShrinkBodies(int capacity)
    {
        Buffers.ShrinkTo(ref _bodies, capacity, 0);
        Buffers.ShrinkTo(ref _positions, capacity, 0);
        Buffers.ShrinkTo(ref _radii, capacity, 0);
        Buffers.ShrinkTo(ref _inertiaScalars, capacity, 0);
        Buffers.ShrinkTo(ref _inverseInertias, capacity, 0);
        Buffers.ShrinkTo(ref _bodyOrder, capacity, 0);
        Buffers.ShrinkTo(ref _publishedLinear, capacity, 0);
        Buffers.ShrinkTo(ref _publishedAngular, capacity, 0);
        Buffers.ShrinkTo(ref _publishedPositions, capacity, 0);
        Buffers.ShrinkTo(ref _slotOf, capacity, 0);
        Buffers.ShrinkTo(ref _bodyHeights, capacity, 0);
        Buffers.ShrinkTo(ref _anchorDistance, capacity, 0);
        Buffers.ShrinkTo(ref _anchorQueue, capacity, 0);
        Buffers.ShrinkTo(ref _corrections, capacity, 0);
        _activeOfBodies.ShrinkBodies(capacity);
        _touching.ShrinkBodies(capacity);
        _positionContactsOfBodies.ShrinkBodies(capacity);
        _strips.ShrinkBodies(capacity);
        Buffers.ShrinkTo(ref _bodyScratch, capacity, 0);
        Buffers.ShrinkTo(ref _bandSums, 2 * capacity, 0);
        Buffers.ShrinkTo(ref _bandOfSum, 2 * capacity, 0);
        Buffers.ShrinkTo(ref _bandResidualSums, 2 * capacity, 0);
    }

    /// <summary>The layer correction's arrays per band (SequentialImpulseSolver.Layers.cs): at most 4,096 bands, so only on request.</summary>
    private void ShrinkBands(int capacity)
    {
        Buffers.ShrinkTo(ref _bandDiagonal, capacity, 0);
        Buffers.ShrinkTo(ref _bandUpper, capacity, 0);
        Buffers.ShrinkTo(ref _bandResidual, capacity, 0);
        Buffers.ShrinkTo(ref _bandFactor, capacity, 0);
        Buffers.ShrinkTo(ref _bandEliminated, capacity, 0);
        Buffers.ShrinkTo(ref _bandShares, 3 * capacity, 0);
    }

    private void ShrinkContacts(int capacity)
    {
        Buffers.ShrinkTo(ref _constraints, capacity, 0);
        Buffers.ShrinkTo(ref _frames, capacity, 0);
        Buffers.ShrinkTo(ref _stepImpulses, capacity, 0);
        Buffers.ShrinkTo(ref _order, capacity, 0);
        Buffers.ShrinkTo(ref _heights, capacity, 0);
        Buffers.ShrinkTo(ref _ties, capacity, 0);
        Buffers.ShrinkTo(ref _active, capacity, 0);
        Buffers.ShrinkTo(ref _deepQueue, capacity, 0);
        Buffers.ShrinkTo(ref _queued, capacity, 0);
        Buffers.ShrinkTo(ref _joined, capacity, 0);
        _activeOfBodies.ShrinkContacts(capacity);
        _touching.ShrinkContacts(capacity);
        _positionContactsOfBodies.ShrinkContacts(capacity);
        _velocityMarks.Shrink(capacity);
        _positionMarks.Shrink(capacity);
        _strips.ShrinkContacts(capacity);
        Buffers.ShrinkTo(ref _contactScratch, capacity, 0);
        Buffers.ShrinkTo(ref _bandOf, capacity, 0);
        Buffers.ShrinkTo(ref _fourStarts, capacity, 0);
#if NET8_0_OR_GREATER
        Buffers.ShrinkTo(ref _fours, capacity / 4 + 1, 0);
#endif
    }
}
