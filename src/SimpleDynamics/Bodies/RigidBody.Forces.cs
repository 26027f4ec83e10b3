using System;
using System.Numerics;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Bodies;

// Forces, torques and impulses: what a game applies to a body, each checked so that the state it leads to stays finite.
public sealed partial class RigidBody
{
    /// <summary>Adds a force (N) through the centre of mass, applied during the next step.</summary>
    /// <exception cref="ArgumentException">The force, the accumulated force or the acceleration it causes is not
    /// finite; the body is unchanged.</exception>
    public void ApplyForce(Vector3 force)
    {
        Guard.Finite(force, nameof(force));
        this.force = AccumulatedForce(force);
        WakeIfAsleep();
    }

    /// <summary>Adds a force (N) at a world point; it also adds the torque (point − c) × F.</summary>
    /// <exception cref="ArgumentException">An argument, or the force, torque or acceleration it results in, is not
    /// finite; the body is unchanged.</exception>
    public void ApplyForce(Vector3 force, Vector3 point)
    {
        Guard.Finite(force, nameof(force));
        Guard.Finite(point, nameof(point));
        Vector3 newForce = AccumulatedForce(force);
        Vector3 arm = LeverArm(point);
        Vector3 newTorque = AccumulatedTorque(Vector3.Cross(arm, force), nameof(force));
        this.force = newForce;
        torque = newTorque;
        WakeIfAsleep();
    }

    /// <summary>Adds a torque (N·m, world frame), applied during the next step.</summary>
    /// <exception cref="ArgumentException">The torque, the accumulated torque or the angular acceleration it causes
    /// is not finite; the body is unchanged.</exception>
    public void ApplyTorque(Vector3 torque)
    {
        Guard.Finite(torque, nameof(torque));
        this.torque = AccumulatedTorque(torque, nameof(torque));
        WakeIfAsleep();
    }

    /// <summary>
    /// Applies an impulse (N·s) at a world point at once: Δv = J/m (eq. 6), Δω = I_w⁻¹ (r × J) (eq. 15).
    /// Does nothing to a static or kinematic body.
    /// </summary>
    /// <exception cref="ArgumentException">An argument or a resulting velocity is not finite; the body is unchanged.</exception>
    public void ApplyImpulse(Vector3 impulse, Vector3 point)
    {
        Guard.Finite(impulse, nameof(impulse));
        Guard.Finite(point, nameof(point));
        Vector3 newLinear = linearVelocity + impulse * inverseMass;
        if (!Vectors.IsFinite(newLinear))
        {
            throw new ArgumentException($"The impulse {impulse} would give body #{Id} a velocity that is not finite.", nameof(impulse));
        }

        Vector3 newAngular = angularVelocity + inverseInertiaWorld.Transform(Vector3.Cross(LeverArm(point), impulse));
        if (!Vectors.IsFinite(newAngular))
        {
            throw new ArgumentException($"The impulse {impulse} at {point} would give body #{Id} an angular velocity that is not finite.", nameof(impulse));
        }

        linearVelocity = newLinear;
        angularVelocity = newAngular;
        WakeIfAsleep();
    }

    internal void ClearAccumulators()
    {
        force = Vector3.Zero;
        torque = Vector3.Zero;
    }

    /// <summary>point − c, checked: two finite points can still be more than float's range apart.</summary>
    private Vector3 LeverArm(Vector3 point)
    {
        Vector3 arm = point - position;
        if (!Vectors.IsFinite(arm))
        {
            throw new ArgumentException($"point {point} is too far from body #{Id} at {position} for float.", nameof(point));
        }

        return arm;
    }

    /// <summary>
    /// The force after adding <paramref name="added"/>, checked so that it, and the acceleration F/m the next step
    /// will integrate, stay finite.
    /// </summary>
    private Vector3 AccumulatedForce(Vector3 added)
    {
        Vector3 sum = force + added;
        if (!Vectors.IsFinite(sum) || !Vectors.IsFinite(sum * inverseMass))
        {
            throw new ArgumentException($"Adding force {added} would make body #{Id}'s force or acceleration not finite.", "force");
        }

        return sum;
    }

    /// <summary>
    /// The torque after adding <paramref name="added"/>, checked so that it, and the angular acceleration
    /// I_w⁻¹ τ the next step will integrate, stay finite.
    /// </summary>
    private Vector3 AccumulatedTorque(Vector3 added, string paramName)
    {
        Vector3 sum = torque + added;
        if (!Vectors.IsFinite(sum) || !Vectors.IsFinite(inverseInertiaWorld.Transform(sum)))
        {
            throw new ArgumentException($"Adding torque {added} would make body #{Id}'s torque or angular acceleration not finite.", paramName);
        }

        return sum;
    }
}
