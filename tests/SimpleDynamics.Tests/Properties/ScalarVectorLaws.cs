using System;
using System.Numerics;
using FsCheck.Fluent;
using SimpleDynamics.Mathematics;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// The solver's scalar dot products and lengths (<see cref="Vectors.Dot"/>, <see cref="Vectors.DistanceSquared"/>,
/// <see cref="Vectors.LengthSquared"/>, <see cref="Vectors.Length"/>, <see cref="Vectors.Distance"/>) replace
/// <see cref="Vector3"/>'s in the passes over every contact and body, and must not change a result: the same float as
/// <see cref="Vector3"/>'s, bit for bit, but for the sign of a zero dot product. Vectors are drawn from every scale a
/// world holds (10⁻⁶ to 10⁴), with components that are zero, of either sign, or cancel, and from the plane z = 0.
/// </summary>
public class ScalarVectorLaws
{
    private static readonly FsCheck.Gen<float> Component = Gen.OneOf(
        Generators.UniformF(-10, 10),
        from magnitude in Generators.LogUniform(1e-6, 1e4)
        from sign in Gen.Elements(1f, -1f)
        select sign * magnitude,
        Gen.Elements(0f, -0f, 1f, -1f, 0.1f, -0.3f));

    private static readonly FsCheck.Gen<Vector3> Vector = Gen.OneOf(
        from x in Component
        from y in Component
        from z in Component
        select new Vector3(x, y, z),
        from x in Component
        from y in Component
        select new Vector3(x, y, 0));

    [Fact]
    public void Scalar_dot_products_give_the_same_floats_as_Vector3() =>
        PropertyCheck.Run(
            from a in Vector
            from b in Gen.OneOf(Vector, Gen.Constant(Vector3.Zero))
            from mirrored in Gen.Elements(false, true)
            select (a, b: mirrored ? new Vector3(b.Y, -b.X, b.Z) : b),
            pair =>
            {
                (Vector3 a, Vector3 b) = pair;
                float dot = Vectors.Dot(a, b), expected = Vector3.Dot(a, b);
                Law.Holds(dot == expected && (dot == 0 || BitConverter.SingleToInt32Bits(dot) == BitConverter.SingleToInt32Bits(expected)),
                    $"a·b for a = {a:R}, b = {b:R}: {dot:R}, not {expected:R}");
                Law.Holds(BitConverter.SingleToInt32Bits(Vectors.DistanceSquared(a, b)) == BitConverter.SingleToInt32Bits(Vector3.DistanceSquared(a, b)),
                    $"|a − b|² for a = {a:R}, b = {b:R}");
                Law.Holds(BitConverter.SingleToInt32Bits(Vectors.LengthSquared(a)) == BitConverter.SingleToInt32Bits(a.LengthSquared()),
                    $"|a|² for a = {a:R}");
                Law.Holds(BitConverter.SingleToInt32Bits(Vectors.Length(a)) == BitConverter.SingleToInt32Bits(a.Length()),
                    $"|a| for a = {a:R}");
                Law.Holds(BitConverter.SingleToInt32Bits(Vectors.Distance(a, b)) == BitConverter.SingleToInt32Bits(Vector3.Distance(a, b)),
                    $"|a − b| for a = {a:R}, b = {b:R}");
            }, seed: 1401, maxTest: 2000);
}
