using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Mathematics;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// Generated crowds: a lattice of bodies moving together (2 to 60 m/s in any direction, each a little off the common
/// velocity), struck by up to three bodies moving otherwise, in free space or a closed box, with or without gravity.
/// The world leaves the pairs of a crowd that moves together out of its contacts while both bodies keep to the crowd's
/// motion, and makes them contacts again when one does not (ImpactStepper.Crowd.cs). These properties check that this
/// changes nothing: until the first pair is restored, every body moves bit for bit as with every pair kept, and at
/// every step the laws of <see cref="WorldLaws"/> hold (momentum, angular momentum, energy, nothing passes through).
/// </summary>
public class CrowdLaws
{
    private const int Steps = 40;
    private readonly ITestOutputHelper _output;

    public CrowdLaws(ITestOutputHelper output) => _output = output;

    private static Gen<WorldCase> Crowds { get; } =
        from planar in Gen.Elements(true, false)
        from closedBox in Gen.Elements(true, false)
        from gravity in Gen.Elements(true, false)
        from restitution in Gen.OneOf(Gen.Elements(0f, 0.5f, 1f), Generators.UniformF(0, 1))
        from friction in Gen.Elements(0f, 0.3f)
        from threshold in Gen.Elements(0f, 0.5f)
        from dt in Gen.Elements(1f / 30, 1f / 60, 1f / 240)
        from substeps in Gen.Choose(1, 8)
        from side in planar ? Gen.Choose(3, 7) : Gen.Choose(2, 4)
        from radius in Generators.UniformF(0.05, 0.15)
        from spacing in Generators.UniformF(2.02, 3)
        from direction in Generators.UnitVector
        from speed in Generators.LogUniform(2, 60)
        from masses in Generators.Mass.ArrayOf(planar ? side * side : side * side * side)
        from offsets in Generators.Vector(0.02).ArrayOf(planar ? side * side : side * side * side)
        from strikers in (
            from position in Generators.UniformF(0, 1).Three()
            from mass in Generators.Mass
            from velocity in Generators.Vector(40)
            select (position, mass, velocity)).ArrayOf(3)
        from strikerCount in Gen.Choose(0, 3)
        select new WorldCase(planar, closedBox, gravity, restitution, friction, threshold, dt, substeps,
            Place(planar, side, radius, spacing, speed * direction, masses, offsets, strikers.Take(strikerCount).ToArray()));

    /// <summary>
    /// The lattice, centred in the box, each body at the common velocity times 1 + a few hundredths in each component;
    /// then the strikers where they overlap nothing (a striker that would is dropped).
    /// </summary>
    private static BodySpec[] Place(bool planar, int side, float radius, float spacing, Vector3 velocity, float[] masses, Vector3[] offsets,
        ((float, float, float) Position, float Mass, Vector3 Velocity)[] strikers)
    {
        if (planar)
        {
            velocity.Z = 0;
        }

        var placed = new List<BodySpec>();
        float pitch = spacing * radius, start = 0.5f * (WorldCase.BoxSize - (side - 1) * pitch);
        int count = masses.Length;
        for (int n = 0; n < count; n++)
        {
            int i = n % side, j = n / side % side, k = n / (side * side);
            var position = new Vector3(start + i * pitch, start + j * pitch, planar ? 0 : start + k * pitch);
            Vector3 off = planar ? offsets[n] with { Z = 0 } : offsets[n];
            Vector3 v = velocity * (Vector3.One + off);
            Matrix3 inertia = planar ? Inertia.Disc(masses[n], radius) : Inertia.SolidSphere(masses[n], radius);
            placed.Add(new BodySpec(BodyType.Dynamic, masses[n], radius, position, Quaternion.Identity, inertia, v, Vector3.Zero));
        }

        foreach (var s in strikers)
        {
            if (!WorldCase.TryPlace(placed, planar, s.Position, radius, out Vector3 position))
            {
                continue;
            }

            Vector3 sv = planar ? s.Velocity with { Z = 0 } : s.Velocity;
            Matrix3 inertia = planar ? Inertia.Disc(s.Mass, radius) : Inertia.SolidSphere(s.Mass, radius);
            placed.Add(new BodySpec(BodyType.Dynamic, s.Mass, radius, position, Quaternion.Identity, inertia, sv, Vector3.Zero));
        }

        return placed.ToArray();
    }

    /// <summary>
    /// Until some pair left out is made a contact again, the crowd's bodies move bit for bit as they do with every pair
    /// kept: a pair left out is one that cannot meet while both keep to the crowd's motion. Most generated crowds leave
    /// pairs out, and in many a striker, a wall or the crowd's own collisions make some contacts again.
    /// </summary>
    [Fact]
    public void A_crowd_moves_bit_for_bit_as_with_every_pair_kept_until_a_pair_left_out_is_restored()
    {
        int crowds = 0, leftOut = 0, restored = 0;
        PropertyCheck.Run(Crowds, c =>
        {
            crowds++;
            World world = c.Build(out _);
            World reference = c.Build(out _);
            reference.LeaveOutCrowdPairs = false;
            bool anyLeftOut = false, anyRestored = false;
            for (int step = 0; step < Steps; step++)
            {
                world.Step(c.Dt);
                reference.Step(c.Dt);
                anyLeftOut |= world.CrowdPairsLeftOut > 0;
                anyRestored |= world.CrowdPairsRestored > 0;
                Law.Holds(reference.CrowdPairsLeftOut == 0, "the reference world left pairs out");
                if (anyRestored)
                {
                    break; // from here on the contacts come in another order, and the two worlds may round otherwise
                }

                Law.Holds(Solver.WorldMeasure.FirstDifference(reference, world) is null,
                    $"step {step}: {world.CrowdPairsLeftOut} pairs left out, none restored, yet {Solver.WorldMeasure.FirstDifference(reference, world)}");
            }

            leftOut += anyLeftOut ? 1 : 0;
            restored += anyRestored ? 1 : 0;
        }, seed: 2106, maxTest: 300);

        _output.WriteLine($"{crowds} crowds: {leftOut} left pairs out, {restored} of them restored some");
        Assert.True(leftOut > crowds / 2, $"only {leftOut} of {crowds} crowds left pairs out");
        Assert.True(restored > crowds / 8, $"only {restored} of {crowds} crowds made a pair left out a contact again");
    }

    /// <summary>The laws of <see cref="WorldLaws"/>, at every step of every generated crowd, pairs left out and restored.</summary>
    [Fact]
    public void Every_step_of_a_generated_crowd_keeps_the_laws() =>
        PropertyCheck.Run(Crowds, c => WorldLaws.KeepsTheLaws(c, inStrips: false), seed: 2107, maxTest: 300);
}
