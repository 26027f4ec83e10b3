using System.Numerics;
using System.Runtime.InteropServices;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Response;

/// <summary>
/// One body as the sequential-impulse solver's sweeps read and write it: its velocities and inverse mass, 32 bytes,
/// two bodies to a 64-byte cache line. A sweep needs nothing else of a body (each contact carries the spins
/// I⁻¹ (r × t) its impulses cause, eq. 15), so the world inverse inertia is kept apart, for measuring the contacts in
/// 3-D; a planar step needs only its z–z entry, which fills the struct's last four bytes, so that measuring a contact
/// reads nothing more of its bodies than the sweeps do.
/// </summary>
[StructLayout(LayoutKind.Sequential, Size = 32)]
internal struct SolverBody
{
    public Vector3 Linear;
    public Vector3 Angular;
    public float InverseMass;

    /// <summary>(I⁻¹_world)_zz: in a planar step, the spin about z a unit torque about z gives (eq. 15).</summary>
    public float InverseInertiaZ;

    public static SolverBody Of(RigidBody body) => new()
    {
        Linear = body.linearVelocity,
        Angular = body.angularVelocity,
        InverseMass = body.inverseMass,
        InverseInertiaZ = body.inverseInertiaWorld.M33,
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
