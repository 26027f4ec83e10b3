using System.Numerics;
using System.Runtime.InteropServices;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Response;

/// <summary>
/// One body as the sequential-impulse solver's sweeps read and write it: its velocities and inverse mass, 32 bytes,
/// two bodies to a 64-byte cache line. A sweep needs nothing else of a body (each contact carries the spins
/// I⁻¹ (r × t) its impulses cause, eq. 15), so the world inverse inertia is kept apart, for measuring the contacts.
/// </summary>
[StructLayout(LayoutKind.Sequential, Size = 32)]
internal struct SolverBody
{
    public Vector3 Linear;
    public Vector3 Angular;
    public float InverseMass;

    public static SolverBody Of(RigidBody body) => new()
    {
        Linear = body.linearVelocity,
        Angular = body.angularVelocity,
        InverseMass = body.inverseMass,
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
