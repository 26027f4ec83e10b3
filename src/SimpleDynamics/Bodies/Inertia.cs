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
        return InFloatRange(Matrix3.Diagonal(i, i, i), nameof(radius));
    }

    /// <summary>Thin hollow sphere (a shell): I = 2/3 m r² about every axis.</summary>
    public static Matrix3 HollowSphere(float mass, float radius)
    {
        Guard.Positive(mass, nameof(mass));
        Guard.Positive(radius, nameof(radius));
        float i = 2f / 3f * mass * radius * radius;
        return InFloatRange(Matrix3.Diagonal(i, i, i), nameof(radius));
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
        return InFloatRange(Matrix3.Diagonal(0.25f * mass * r2, 0.25f * mass * r2, 0.5f * mass * r2), nameof(radius));
    }

    /// <summary>Solid box with side lengths x, y, z: I_xx = m (y² + z²) / 12, and so on.</summary>
    public static Matrix3 Box(float mass, float sizeX, float sizeY, float sizeZ)
    {
        Guard.Positive(mass, nameof(mass));
        Guard.Positive(sizeX, nameof(sizeX));
        Guard.Positive(sizeY, nameof(sizeY));
        Guard.Positive(sizeZ, nameof(sizeZ));
        float k = mass / 12f;
        return InFloatRange(
            Matrix3.Diagonal(
                k * (sizeY * sizeY + sizeZ * sizeZ),
                k * (sizeX * sizeX + sizeZ * sizeZ),
                k * (sizeX * sizeX + sizeY * sizeY)),
            nameof(mass));
    }

    /// <summary>
    /// Returns a shape's tensor if its moments, m × size², and their inverses are finite, non-zero floats;
    /// otherwise the sizes are too extreme for float and the named argument is rejected.
    /// </summary>
    private static Matrix3 InFloatRange(Matrix3 tensor, string paramName)
    {
        if (!(tensor.M11 > 0 && tensor.M22 > 0 && tensor.M33 > 0) || !tensor.TryInvert(out _))
        {
            throw new ArgumentOutOfRangeException(paramName, $"mass × size² gives moments of inertia {tensor} that float cannot hold or invert.");
        }

        return tensor;
    }

    /// <summary>
    /// Throws unless <paramref name="inertia"/> is a valid inertia tensor: finite, symmetric and positive definite,
    /// with an inverse whose entries are finite floats (so <c>Diagonal(1, 1, 1e-39)</c> is rejected: 1/10⁻³⁹
    /// overflows float).
    /// </summary>
    /// <param name="inertia">The tensor to check (kg·m²).</param>
    /// <param name="paramName">The name the exception gives as its parameter.</param>
    /// <exception cref="ArgumentException">The tensor is not finite, not symmetric, singular, not positive definite,
    /// or has no inverse finite in float.</exception>
    /// <exception cref="ArgumentNullException"><paramref name="paramName"/> is null.</exception>
    public static void Validate(Matrix3 inertia, string paramName) => ValidateAndInvert(inertia, paramName);

    /// <summary>Validates as <see cref="Validate"/> does and returns the inverse it had to compute anyway.</summary>
    internal static Matrix3 ValidateAndInvert(Matrix3 inertia, string paramName)
    {
        Guard.NotNull(paramName, nameof(paramName));
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

        if (!inertia.TryInvert(out Matrix3 inverse))
        {
            throw new ArgumentException($"The inertia tensor {inertia} has no inverse that is finite in float.", paramName);
        }

        return inverse;
    }
}
