using System.Numerics;

namespace SimpleDynamics.Response;

/// <summary>
/// One contact as the sequential-impulse solver works on it. Bodies are slots in the solver's body arrays (slot 0 is
/// the fixed ground). The geometry (normal, tangents, lever arms and what a unit impulse does to each body's spin)
/// is measured again at the start of every substep from the bodies' positions, so that the equal and opposite
/// impulses act along the current line of contact and keep angular momentum.
/// </summary>
/// <remarks>
/// The velocity sweeps are most of a step's time, and in a large pile they wait on memory: what they read comes
/// first, a planar sweep's first of all (88 bytes), then what only 3-D sweeps read. The bodies' radii are the
/// solver's per slot, and the impulses kept between substeps and added up over the step are in
/// <see cref="ContactStepImpulses"/>, so that a sweep streams 136 bytes per contact.
/// </remarks>
internal struct ContactConstraint
{
    public int A, B;

    /// <summary>Whether A is the upper body along gravity (B lies below it, or is the ground), for shock propagation.</summary>
    public bool AIsUpper;

    /// <summary>Whether the normal lies within about 45° of vertical (|n·ĝ| &gt; 0.7): the contact carries weight.</summary>
    public bool CarriesWeight;

    // Accumulated impulses of the substep.
    public float NormalImpulse, FrictionImpulse1;

    // Geometry, measured each substep, then the material, fixed for the step.
    public float NormalMass, TangentMass1; // 1 / the denominator of eq. 16 along n, t1
    public float Friction;
    public float RhoA, RhoB; // lever arms along the normal: r_A = −ρ_A n, r_B = ρ_B n (the point is on the line of centres)
    public Vector3 Normal, Tangent1;
    public Vector3 SpinA1, SpinB1; // I⁻¹ (r × t) for each tangent (eq. 15); for spheres r × n = 0

    // The second tangent, zero in planar steps (from PrepareConstraints: a step never turns planar once begun).
    public float FrictionImpulse2, TangentMass2;
    public Vector3 Tangent2, SpinA2, SpinB2; // t₂ = n × t₁

    public float PlaneOffset; // NaN unless B is the ground of a plane

    public readonly bool IsPlaneContact => !float.IsNaN(PlaneOffset);
}

/// <summary>
/// What a contact keeps between the substeps of a step, apart from the constraint the sweeps stream through: its
/// friction impulse as a world vector (the tangents turn with the contact), and the step's totals that the contact
/// reports (<see cref="Collision.Contact.NormalImpulse"/>, <see cref="Collision.Contact.TangentImpulse"/>).
/// </summary>
internal struct ContactStepImpulses
{
    public Vector3 Friction;
    public float Normal, FrictionMagnitude;
}
