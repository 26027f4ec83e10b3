using System;

namespace SimpleDynamics;

/// <summary>
/// The working arrays of the hot path grow and are kept, so a warm world allocates nothing; they shrink only when
/// asked to (<see cref="World.TrimExcess"/>).
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
    public static void Shrink<T>(ref T[] array, int needed)
    {
        if (array.Length > needed)
        {
            var smaller = new T[needed];
            Array.Copy(array, smaller, needed);
            array = smaller;
        }
    }
}
