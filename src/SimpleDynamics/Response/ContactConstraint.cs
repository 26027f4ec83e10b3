using System.Numerics;
using System.Runtime.InteropServices;

namespace SimpleDynamics.Response;

/// <summary>
/// One contact as the sequential-impulse solver works on it. Bodies are slots in the solver's body arrays (slot 0 is
/// the fixed ground). The geometry (normal, lever arms and what a unit friction impulse does to each body's spin) is
/// measured again at the start of every substep from the bodies' positions, so that the equal and opposite impulses
/// act along the current line of contact and keep angular momentum.
/// </summary>
/// <remarks>
/// <para>The passes over the contacts (measure, warm start, sweeps, position sweeps) are most of a step's time, and in
/// a large pile they wait on memory. So this is what a planar step needs and no more, 64 bytes, one cache line: in the
/// plane the one tangent is t₁ = (n_y, −n_x, 0) (found from the normal, not stored), and a unit friction impulse turns
/// each body about z alone. A 3-D step puts the second tangent's impulse and mass where a planar one keeps the spins
/// about z, and reads the tangents and spins from the contact's <see cref="TangentFrame"/>, in a parallel array: 136
/// bytes a contact, as before the frame was split off, when a planar sweep too streamed 136 bytes a contact (and read
/// 88 of them). A step that turns general part-way (a body woken off the plane) measures its contacts again before any
/// sweep reads them, and the measure writes the second tangent's fields over the spins (tested). Measured with the same
/// results bit for bit: a settled 2-D pit steps 4–5 % (1,000 discs), 2–3 % (4,000)
/// and 7–8 % (16,000) faster, a 3-D one as fast as before (benchmarks/README.md, twenty-second session).</para>
/// <para>The bodies' radii are the solver's per slot, and the impulses kept between substeps and added up over the
/// step are in <see cref="ContactStepImpulses"/>.</para>
/// </remarks>
[StructLayout(LayoutKind.Explicit, Size = 64)]
internal struct ContactConstraint
{
    [FieldOffset(0)] public int A;
    [FieldOffset(4)] public int B;

    /// <summary>Whether A is the upper body along gravity (B lies below it, or is the ground), for shock propagation.</summary>
    [FieldOffset(8)] public bool AIsUpper;

    /// <summary>Whether the normal lies within about 45° of vertical (|n·ĝ| &gt; 0.7): the contact carries weight.</summary>
    [FieldOffset(9)] public bool CarriesWeight;

    // Accumulated impulses of the substep.
    [FieldOffset(12)] public float NormalImpulse;
    [FieldOffset(16)] public float FrictionImpulse1;

    // Geometry, measured each substep, then the material, fixed for the step.
    [FieldOffset(20)] public float NormalMass; // 1 / the denominator of eq. 16 along n
    [FieldOffset(24)] public float TangentMass1; // and along t₁
    [FieldOffset(28)] public float Friction;
    [FieldOffset(32)] public float RhoA; // lever arms along the normal: r_A = −ρ_A n, r_B = ρ_B n (the point is on the line of centres)
    [FieldOffset(36)] public float RhoB;
    [FieldOffset(40)] public Vector3 Normal;

    /// <summary>
    /// In a planar step: the z components of I⁻¹ (r × t₁) for A and B (eq. 15), the spin a unit friction impulse gives
    /// each body about z, ρ_A (I⁻¹_A)_zz and −ρ_B (I⁻¹_B)_zz.
    /// </summary>
    [FieldOffset(52)] public float PlanarSpinA;

    /// <inheritdoc cref="PlanarSpinA"/>
    [FieldOffset(56)] public float PlanarSpinB;

    /// <summary>In a 3-D step, in place of <see cref="PlanarSpinA"/>: the second tangent's accumulated impulse.</summary>
    [FieldOffset(52)] public float FrictionImpulse2;

    /// <summary>In a 3-D step, in place of <see cref="PlanarSpinB"/>: 1 / the denominator of eq. 16 along t₂.</summary>
    [FieldOffset(56)] public float TangentMass2;

    [FieldOffset(60)] public float PlaneOffset; // NaN unless B is the ground of a plane

    public readonly bool IsPlaneContact => !float.IsNaN(PlaneOffset);

    /// <summary>The one tangent of a planar step, t₁ = n × ẑ = (n_y, −n_x, 0).</summary>
    public readonly Vector3 PlanarTangent => PlanarTangentOf(Normal);

    /// <summary>The planar tangent of normal <paramref name="n"/> (see <see cref="PlanarTangent"/>).</summary>
    public static Vector3 PlanarTangentOf(Vector3 n) => new(n.Y, -n.X, 0);
}

/// <summary>
/// The 3-D part of a contact's friction, read only in 3-D steps: the tangents t₁ and t₂ = n × t₁, and the spins
/// I⁻¹ (r × t) a unit impulse along each gives the bodies (eq. 15; for spheres r × n = 0, so the normal needs none).
/// The tangents' impulses and masses are in <see cref="ContactConstraint"/>.
/// </summary>
internal struct TangentFrame
{
    public Vector3 Tangent1, Tangent2;
    public Vector3 SpinA1, SpinB1, SpinA2, SpinB2;
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
