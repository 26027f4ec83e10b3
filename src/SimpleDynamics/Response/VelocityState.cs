using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>
/// What an impulse needs of one body: its velocities and its inverse mass and world inverse inertia. The
/// single-pair responders (and the solver's answer at an impact) load it from a <see cref="RigidBody"/>; the
/// solver's sweeps keep the smaller <see cref="SolverBody"/> for the whole world. Infinite-mass bodies have zero
/// inverses, so impulses leave them alone.
/// </summary>
internal struct VelocityState
{
    public Vector3 Linear;
    public Vector3 Angular;
    public float InverseMass;
    public Matrix3 InverseInertia;

    public static VelocityState Of(RigidBody body) => new()
    {
        Linear = body.linearVelocity,
        Angular = body.angularVelocity,
        InverseMass = body.inverseMass,
        InverseInertia = body.inverseInertiaWorld,
    };

    /// <summary>Writes the velocities back to a dynamic body; infinite-mass bodies keep theirs.</summary>
    public readonly void StoreTo(RigidBody body)
    {
        if (body.IsDynamic)
        {
            body.linearVelocity = Linear;
            body.angularVelocity = Angular;
        }
    }
}
