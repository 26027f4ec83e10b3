using System;
using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Trajectories;

/// <summary>
/// What a whole run did, watched after every step (not only the printed ones): the energy at the start and
/// end, the largest mechanical energy and penetration seen, whether the motion left the z = 0 plane, and the
/// first step at which a body's state stopped being finite.
/// </summary>
public sealed class RunSummary
{
    /// <summary>Starts watching <paramref name="world"/> at its current state.</summary>
    public RunSummary(World world)
    {
        WorldDiagnostics d = world.Diagnostics;
        StartMechanicalEnergy = d.MechanicalEnergy;
        StartKineticEnergy = d.KineticEnergy;
        MaxMechanicalEnergy = d.MechanicalEnergy;
        MaxKineticEnergy = d.KineticEnergy;
        MaxPenetration = d.MaxPenetration;
        SmallestRadius = float.PositiveInfinity;
        foreach (RigidBody body in world.Bodies)
        {
            SmallestRadius = MathF.Min(SmallestRadius, body.Radius);
        }

        Observe(world, 0);
    }

    /// <summary>Mechanical energy (J) at the start.</summary>
    public double StartMechanicalEnergy { get; }

    /// <summary>Kinetic energy (J) at the start.</summary>
    public double StartKineticEnergy { get; }

    /// <summary>Mechanical energy (J) after the last step.</summary>
    public double EndMechanicalEnergy { get; private set; }

    /// <summary>Kinetic energy (J) after the last step.</summary>
    public double EndKineticEnergy { get; private set; }

    /// <summary>The largest mechanical energy (J) after any step.</summary>
    public double MaxMechanicalEnergy { get; private set; }

    /// <summary>The largest kinetic energy (J) after any step.</summary>
    public double MaxKineticEnergy { get; private set; }

    /// <summary>The largest penetration (m) after any step.</summary>
    public float MaxPenetration { get; private set; }

    /// <summary>The smallest body radius (m), to put the penetration in proportion.</summary>
    public float SmallestRadius { get; }

    /// <summary>Whether any body left the z = 0 plane or spun about an axis other than z.</summary>
    public bool LeftPlane { get; private set; }

    /// <summary>The first step after which some body's state was NaN or infinite, or null.</summary>
    public int? FirstNonFiniteStep { get; private set; }

    /// <summary>Records the state after <paramref name="step"/>.</summary>
    public void Observe(World world, int step)
    {
        WorldDiagnostics d = world.Diagnostics;
        EndMechanicalEnergy = d.MechanicalEnergy;
        EndKineticEnergy = d.KineticEnergy;
        MaxMechanicalEnergy = Math.Max(MaxMechanicalEnergy, d.MechanicalEnergy);
        MaxKineticEnergy = Math.Max(MaxKineticEnergy, d.KineticEnergy);
        MaxPenetration = MathF.Max(MaxPenetration, d.MaxPenetration);
        foreach (RigidBody body in world.Bodies)
        {
            if (FirstNonFiniteStep is null && !(IsFinite(body.Position) && IsFinite(body.LinearVelocity) && IsFinite(body.AngularVelocity)))
            {
                FirstNonFiniteStep = step;
            }

            if (body.Position.Z != 0f || body.LinearVelocity.Z != 0f || body.AngularVelocity.X != 0f || body.AngularVelocity.Y != 0f)
            {
                LeftPlane = true;
            }
        }
    }

    private static bool IsFinite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
}
