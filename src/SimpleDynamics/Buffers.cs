using System;

namespace SimpleDynamics;

/// <summary>
/// The working arrays of the hot path grow and are kept, so a warm world allocates nothing. They shrink when asked
/// to (<see cref="World.TrimExcess"/>) and, on their own, when their use has long been far below their size
/// (<see cref="ShrinkPolicy"/>).
/// </summary>
internal static class Buffers
{
    /// <summary>Makes <paramref name="array"/> hold at least <paramref name="needed"/> items, at least doubling it.</summary>
    public static void EnsureCapacity<T>(ref T[] array, int needed)
    {
        if (array.Length < needed)
        {
            Array.Resize(ref array, Math.Max(needed, array.Length * 2));
        }
    }

    /// <summary>
    /// Shrinks <paramref name="array"/> to <paramref name="needed"/> items, keeping the first
    /// <paramref name="needed"/>; does nothing (and allocates nothing) when it is no larger.
    /// </summary>
    public static void Shrink<T>(ref T[] array, int needed) => ShrinkTo(ref array, needed, needed);

    /// <summary>
    /// Reallocates <paramref name="array"/> to <paramref name="capacity"/> items if it is larger, keeping the first
    /// <paramref name="keep"/> (at most <paramref name="capacity"/>); 0 for an array that holds nothing between steps.
    /// </summary>
    public static void ShrinkTo<T>(ref T[] array, int capacity, int keep)
    {
        if (array.Length > capacity)
        {
            var smaller = new T[capacity];
            Array.Copy(array, smaller, keep);
            array = smaller;
        }
    }

    /// <summary>
    /// Applies the <see cref="ShrinkPolicy"/> to one array after a step that used <paramref name="used"/> of its
    /// items (which are kept), its initial size being <paramref name="initial"/>.
    /// </summary>
    public static void ShrinkIfIdle<T>(ref T[] array, int used, ref ShrinkPolicy policy, int initial)
    {
        int capacity = policy.Observe(used, array.Length, initial);
        if (capacity > 0)
        {
            ShrinkTo(ref array, capacity, used);
        }
    }
}
