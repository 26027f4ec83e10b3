using System;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Bodies;

/// <summary>
/// Body-frame inertia tensors of common shapes (kg·m²), about the centre of mass. Any symmetric positive-definite
/// <see cref="Matrix3"/> is accepted too, so a body can have a full, non-diagonal tensor.
/// </summary>
public static class Inertia
{
    /// <summary>Solid sphere: I = 2/5 m r² about every axis.</summary>
    public static Matrix3 SolidSphere(float mass, float radius)
    {
        Guard.Positive(mass, nameof(mass));
        Guard.Positive(radius, nameof(radius));
        float i = 0.4f * mass * radius * radius;
        return Matrix3.Diagonal(i, i, i);
    }

    /// <summary>Thin hollow sphere (a shell): I = 2/3 m r² about every axis.</summary>
    public static Matrix3 HollowSphere(float mass, float radius)
    {
        Guard.Positive(mass, nameof(mass));
        Guard.Positive(radius, nameof(radius));
        float i = 2f / 3f * mass * radius * radius;
        return Matrix3.Diagonal(i, i, i);
    }

    /// <summary>
    /// Uniform disc in the xy-plane: I = 1/2 m r² about z (its axis), 1/4 m r² about x and y. The shape for a
    /// 2-D game (z = 0).
    /// </summary>
    public static Matrix3 Disc(float mass, float radius)
    {
        Guard.Positive(mass, nameof(mass));
        Guard.Positive(radius, nameof(radius));
        float r2 = radius * radius;
        return Matrix3.Diagonal(0.25f * mass * r2, 0.25f * mass * r2, 0.5f * mass * r2);
    }

    /// <summary>Solid box with side lengths x, y, z: I_xx = m (y² + z²) / 12, and so on.</summary>
    public static Matrix3 Box(float mass, float sizeX, float sizeY, float sizeZ)
    {
        Guard.Positive(mass, nameof(mass));
        Guard.Positive(sizeX, nameof(sizeX));
        Guard.Positive(sizeY, nameof(sizeY));
        Guard.Positive(sizeZ, nameof(sizeZ));
        float k = mass / 12f;
        return Matrix3.Diagonal(
            k * (sizeY * sizeY + sizeZ * sizeZ),
            k * (sizeX * sizeX + sizeZ * sizeZ),
            k * (sizeX * sizeX + sizeY * sizeY));
    }

    /// <summary>
    /// Throws unless <paramref name="inertia"/> is a valid inertia tensor: finite, symmetric and positive definite.
    /// </summary>
    /// <exception cref="ArgumentException">The tensor is not finite, not symmetric, or singular / not positive definite.</exception>
    public static void Validate(Matrix3 inertia, string paramName)
    {
        if (!inertia.IsFinite())
        {
            throw new ArgumentException("The inertia tensor must have finite entries.", paramName);
        }

        if (!inertia.IsSymmetric())
        {
            throw new ArgumentException("The inertia tensor must be symmetric.", paramName);
        }

        if (!inertia.IsPositiveDefinite())
        {
            throw new ArgumentException("The inertia tensor must be positive definite (it is singular or has a non-positive moment).", paramName);
        }
    }
}
