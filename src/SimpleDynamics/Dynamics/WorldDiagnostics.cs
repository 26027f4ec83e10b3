using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics;

/// <summary>
/// What a student checks the laws with, measured over the dynamic bodies (static and kinematic bodies have
/// infinite mass and are left out). Energies are summed in double precision.
/// </summary>
public readonly struct WorldDiagnostics
{
    /// <summary>Σ m v (kg·m/s).</summary>
    public Vector3 LinearMomentum { get; init; }

    /// <summary>Σ (I_w ω + (c − point) × m v) about <see cref="AngularMomentumPoint"/> (kg·m²/s).</summary>
    public Vector3 AngularMomentum { get; init; }

    /// <summary>The fixed point the angular momentum is taken about.</summary>
    public Vector3 AngularMomentumPoint { get; init; }

    /// <summary>Σ (½ m v² + ½ ωᵀ I_w ω) (J).</summary>
    public double KineticEnergy { get; init; }

    /// <summary>Σ −m g·c, zero at the origin (J).</summary>
    public double PotentialEnergy { get; init; }

    /// <summary>Kinetic plus potential energy (J).</summary>
    public double MechanicalEnergy => KineticEnergy + PotentialEnergy;

    /// <summary>Contacts in the last step.</summary>
    public int ContactCount { get; init; }

    /// <summary>Largest penetration among the last step's contacts at the end of the step (m); 0 if none.</summary>
    public float MaxPenetration { get; init; }
}

public sealed partial class World
{
    /// <summary>The diagnostics of the current state, angular momentum about the origin.</summary>
    public WorldDiagnostics Diagnostics => MeasureDiagnostics(Vector3.Zero);

    /// <summary>The diagnostics of the current state, angular momentum about <paramref name="point"/>.</summary>
    public WorldDiagnostics MeasureDiagnostics(Vector3 point)
    {
        Guard.Finite(point, nameof(point));
        double kinetic = 0, potential = 0;
        Vector3 linear = Vector3.Zero, angular = Vector3.Zero;
        foreach (RigidBody body in AllBodies)
        {
            if (!body.IsDynamic)
            {
                continue;
            }

            kinetic += body.KineticEnergy;
            potential -= body.mass * (double)Vector3.Dot(Gravity, body.position);
            linear += body.LinearMomentum;
            angular += body.AngularMomentumAbout(point);
        }

        float maxPenetration = 0;
        foreach (ref readonly Contact contact in Collisions.Contacts)
        {
            maxPenetration = MathF.Max(maxPenetration, contact.Penetration);
        }

        return new WorldDiagnostics
        {
            LinearMomentum = linear,
            AngularMomentum = angular,
            AngularMomentumPoint = point,
            KineticEnergy = kinetic,
            PotentialEnergy = potential,
            ContactCount = Collisions.Count,
            MaxPenetration = maxPenetration,
        };
    }
}
