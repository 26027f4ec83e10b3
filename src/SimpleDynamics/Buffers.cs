using System;

namespace SimpleDynamics;

/// <summary>The working arrays of the hot path grow, never shrink, so a warm world allocates nothing.</summary>
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
}
