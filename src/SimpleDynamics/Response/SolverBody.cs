using System.Numerics;
using System.Runtime.InteropServices;

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
}
