using System;

namespace SimpleDynamics;

/// <summary>
/// When a working array gives memory back without being asked: once its use has stayed below a quarter of its
/// capacity for <see cref="QuietSteps"/> steps in a row, it is reallocated to twice the largest use of those steps,
/// never below its initial size nor <see cref="MinimumCapacity"/>. Arrays grow only past their capacity (<see cref="Buffers.EnsureCapacity"/>), so
/// a shrunk array has room for twice its recent use before it grows again, and an array whose use is steady never
/// shrinks at all: a world whose need is stable allocates nothing.
/// </summary>
/// <remarks>
/// The owner of the array calls <see cref="Observe"/> once per step with the step's use (the most items it held).
/// </remarks>
internal struct ShrinkPolicy
{
    /// <summary>
    /// 120 steps, 2 s at 60 Hz: a scene that empties for a moment (between rounds, a level reset) keeps its room and
    /// allocates nothing when it fills again, yet what a burst grew (2,000 bodies spawned in one place can take
    /// hundreds of MiB of contacts) comes back within seconds once the world stays small.
    /// </summary>
    public const int QuietSteps = 120;

    /// <summary>
    /// Arrays of up to this many items keep their size whatever their use. They hold tens of KiB at most, and as a scene
    /// comes to rest (ever fewer impacts and contact events) they would otherwise shrink again every few seconds, each
    /// time allocating, for nothing: the policy is for the bursts that grow arrays to MiB.
    /// <see cref="World.TrimExcess"/> gives back everything.
    /// </summary>
    public const int MinimumCapacity = 1024;

    private int _quietSteps;
    private int _peak;

    /// <summary>
    /// Records one step's use of an array of <paramref name="capacity"/> items whose initial size was
    /// <paramref name="initial"/>; returns the smaller capacity to reallocate it to now, or 0 to keep it.
    /// </summary>
    public int Observe(int used, int capacity, int initial)
    {
        int smallest = Math.Max(initial, MinimumCapacity);
        if (4L * used >= capacity || capacity <= smallest)
        {
            _quietSteps = 0; // in use (or as small as it gets): the count starts again
            _peak = 0;
            return 0;
        }

        _peak = Math.Max(_peak, used);
        if (++_quietSteps < QuietSteps)
        {
            return 0;
        }

        int target = Math.Max(smallest, 2 * _peak); // less than the capacity: _peak < capacity / 4
        _quietSteps = 0;
        _peak = 0;
        return target;
    }
}
