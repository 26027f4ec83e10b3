using System;
using System.Numerics;
using FsCheck.Fluent;
using SimpleDynamics.Mathematics;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// The contact tangents (<see cref="Vectors.Tangents"/>): for every unit normal n, unit vectors t1, t2 perpendicular to
/// n and to each other, with t2 = n × t1 (the right-handed basis the solver's lever arms rely on: r × t1 = ∓ρ t2).
/// Normals are drawn uniform on the sphere, and from the places where such bases lose precision: the poles, the
/// xy-plane, within 10⁻⁸–10⁻² of either pole, and about |z| = 0.9, where the axis n is crossed with changes.
/// </summary>
public class TangentLaws
{
    private static readonly FsCheck.Gen<Vector3> Normals = Gen.OneOf(
        Generators.UnitVector,
        Gen.Elements(Vector3.UnitZ, -Vector3.UnitZ, Vector3.UnitX, -Vector3.UnitY),
        from phi in Generators.Uniform(0, 2 * Math.PI)
        select new Vector3((float)Math.Cos(phi), (float)Math.Sin(phi), 0),
        from phi in Generators.Uniform(0, 2 * Math.PI)
        from tilt in Generators.LogUniform(1e-8, 1e-2)
        from pole in Gen.Elements(1f, -1f)
        select Vector3.Normalize(new Vector3(tilt * (float)Math.Cos(phi), tilt * (float)Math.Sin(phi), pole)),
        from phi in Generators.Uniform(0, 2 * Math.PI)
        from z in Generators.Uniform(0.899, 0.901)
        from pole in Gen.Elements(1.0, -1.0)
        let s = Math.Sqrt(1 - z * z)
        select Vector3.Normalize(new Vector3((float)(s * Math.Cos(phi)), (float)(s * Math.Sin(phi)), (float)(pole * z))));

    [Fact]
    public void Tangents_make_a_right_handed_orthonormal_basis_with_the_normal() =>
        PropertyCheck.Run(Normals, n =>
        {
            Vectors.Tangents(n, out Vector3 t1, out Vector3 t2);
            const double tolerance = 2e-6; // a few float roundings of unit-sized terms
            Law.Near(1, t1.Length(), tolerance, $"|t1| for n = {n}");
            Law.Near(1, t2.Length(), tolerance, $"|t2| for n = {n}");
            Law.Near(0, Vector3.Dot(n, t1), tolerance, $"n·t1 for n = {n}");
            Law.Near(0, Vector3.Dot(n, t2), tolerance, $"n·t2 for n = {n}");
            Law.Near(0, Vector3.Dot(t1, t2), tolerance, $"t1·t2 for n = {n}");
            Law.Holds(Vector3.Distance(Vector3.Cross(n, t1), t2) <= tolerance, $"n × t1 = {Vector3.Cross(n, t1)}, t2 = {t2}, for n = {n}");
        }, seed: 1301);

    [Fact]
    public void Tangents_of_a_normal_in_the_plane_stay_in_the_plane()
    {
        // A planar simulation's friction relies on it (on the general path too): t1 in the plane, t2 along z, exactly.
        PropertyCheck.Run(
            from phi in Generators.Uniform(0, 2 * Math.PI)
            select new Vector3((float)Math.Cos(phi), (float)Math.Sin(phi), 0),
            n =>
            {
                Vectors.Tangents(n, out Vector3 t1, out Vector3 t2);
                Law.Holds(t1.Z == 0 && t2.X == 0 && t2.Y == 0 && Math.Abs(Math.Abs(t2.Z) - 1) <= 2e-6, $"n = {n}: t1 = {t1}, t2 = {t2}");
            }, seed: 1303);
    }
}
