using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics;

/// <summary>
/// What a student checks the laws with, measured over the dynamic bodies (static and kinematic bodies have
/// infinite mass and are left out). Energies are summed in double precision.
/// </summary>
/// <remarks>
/// The world measures these (<see cref="World.Diagnostics"/>); a student may build one to compare against. Every
/// value is checked when it is set: measured quantities are finite, the count and the energy are not negative.
/// </remarks>
public readonly struct WorldDiagnostics
{
    private readonly Vector3 _linearMomentum;
    private readonly Vector3 _angularMomentum;
    private readonly Vector3 _angularMomentumPoint;
    private readonly double _kineticEnergy;
    private readonly double _potentialEnergy;
    private readonly int _contactCount;
    private readonly float _maxPenetration;

    /// <summary>Σ m v (kg·m/s).</summary>
    /// <exception cref="ArgumentException">Set to a vector that is not finite.</exception>
    public Vector3 LinearMomentum
    {
        get => _linearMomentum;
        init
        {
            Guard.Finite(value, nameof(LinearMomentum));
            _linearMomentum = value;
        }
    }

    /// <summary>Σ (I_w ω + (c − point) × m v) about <see cref="AngularMomentumPoint"/> (kg·m²/s).</summary>
    /// <exception cref="ArgumentException">Set to a vector that is not finite.</exception>
    public Vector3 AngularMomentum
    {
        get => _angularMomentum;
        init
        {
            Guard.Finite(value, nameof(AngularMomentum));
            _angularMomentum = value;
        }
    }

    /// <summary>The fixed point the angular momentum is taken about.</summary>
    /// <exception cref="ArgumentException">Set to a point that is not finite.</exception>
    public Vector3 AngularMomentumPoint
    {
        get => _angularMomentumPoint;
        init
        {
            Guard.Finite(value, nameof(AngularMomentumPoint));
            _angularMomentumPoint = value;
        }
    }

    /// <summary>Σ (½ m v² + ½ ωᵀ I_w ω) (J).</summary>
    /// <exception cref="ArgumentOutOfRangeException">Set to a negative or non-finite value.</exception>
    public double KineticEnergy
    {
        get => _kineticEnergy;
        init
        {
            Guard.Finite(value, nameof(KineticEnergy));
            if (value < 0)
            {
                throw new ArgumentOutOfRangeException(nameof(KineticEnergy), value, "KineticEnergy cannot be negative.");
            }

            _kineticEnergy = value;
        }
    }

    /// <summary>Σ −m g·c, zero at the origin (J).</summary>
    /// <exception cref="ArgumentOutOfRangeException">Set to a value that is not finite.</exception>
    public double PotentialEnergy
    {
        get => _potentialEnergy;
        init
        {
            Guard.Finite(value, nameof(PotentialEnergy));
            _potentialEnergy = value;
        }
    }

    /// <summary>Kinetic plus potential energy (J).</summary>
    public double MechanicalEnergy => KineticEnergy + PotentialEnergy;

    /// <summary>Contacts in the last step.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Set to a negative count.</exception>
    public int ContactCount
    {
        get => _contactCount;
        init
        {
            Guard.AtLeast(value, 0, nameof(ContactCount));
            _contactCount = value;
        }
    }

    /// <summary>Largest penetration among the last step's contacts at the end of the step (m); 0 if none.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Set to a value that is not finite.</exception>
    public float MaxPenetration
    {
        get => _maxPenetration;
        init
        {
            Guard.Finite(value, nameof(MaxPenetration));
            _maxPenetration = value;
        }
    }
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
