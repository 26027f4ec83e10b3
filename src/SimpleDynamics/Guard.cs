using System;
using System.Numerics;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics;

/// <summary>Argument checks that name the offending parameter. They throw before anything is changed.</summary>
internal static partial class Guard
{
    public static void Positive(float value, string paramName)
    {
        if (!(value > 0) || !float.IsFinite(value))
        {
            throw new ArgumentOutOfRangeException(paramName, value, $"{paramName} must be a positive, finite number.");
        }
    }

    public static void NonNegative(float value, string paramName)
    {
        if (!(value >= 0) || !float.IsFinite(value))
        {
            throw new ArgumentOutOfRangeException(paramName, value, $"{paramName} must be zero or a positive, finite number.");
        }
    }

    public static void UnitInterval(float value, string paramName)
    {
        if (!(value >= 0 && value <= 1))
        {
            throw new ArgumentOutOfRangeException(paramName, value, $"{paramName} must lie in [0, 1].");
        }
    }

    public static void AtLeast(int value, int minimum, string paramName)
    {
        if (value < minimum)
        {
            throw new ArgumentOutOfRangeException(paramName, value, $"{paramName} must be at least {minimum}.");
        }
    }

    public static void InRange(int value, int minimum, int maximum, string paramName)
    {
        if (value < minimum || value > maximum)
        {
            throw new ArgumentOutOfRangeException(paramName, value, $"{paramName} must lie in [{minimum}, {maximum}].");
        }
    }

    public static void Finite(Vector3 value, string paramName)
    {
        if (!Vectors.IsFinite(value))
        {
            throw new ArgumentException($"{paramName} must have finite components, but was {value}.", paramName);
        }
    }

    public static void UnitVector(Vector3 value, string paramName)
    {
        Finite(value, paramName);
        if (MathF.Abs(value.LengthSquared() - 1f) > 1e-3f)
        {
            throw new ArgumentException($"{paramName} must be a unit vector, but its length is {value.Length()}.", paramName);
        }
    }

    public static void NoNullElements<T>(ReadOnlySpan<T> items, string paramName)
        where T : class
    {
        for (int i = 0; i < items.Length; i++)
        {
            if (items[i] is null)
            {
                throw new ArgumentException($"{paramName}[{i}] is null.", paramName);
            }
        }
    }

    public static void Finite(float value, string paramName)
    {
        if (!float.IsFinite(value))
        {
            throw new ArgumentOutOfRangeException(paramName, value, $"{paramName} must be a finite number.");
        }
    }

    public static void Finite(double value, string paramName)
    {
        if (!double.IsFinite(value))
        {
            throw new ArgumentOutOfRangeException(paramName, value, $"{paramName} must be a finite number.");
        }
    }

    public static void NotNull(object? value, string paramName)
    {
        if (value is null)
        {
            throw new ArgumentNullException(paramName);
        }
    }
}
