using System.Numerics;

namespace SimpleDynamics.Response;

/// <summary>
/// One contact as the sequential-impulse solver works on it. Bodies are slots in the solver's body arrays (slot 0 is
/// the fixed ground). The geometry (normal, tangents, lever arms and what a unit impulse does to each body's spin)
/// is measured again at the start of every substep from the bodies' positions, so that the equal and opposite
/// impulses act along the current line of contact and keep angular momentum.
/// </summary>
/// <remarks>
/// The fields a velocity sweep reads come first, those of a planar sweep first of all, so that a sweep touches as few
/// cache lines per contact as it can (the sweeps are most of a step's time).
/// </remarks>
internal struct ContactConstraint
{
    public int A, B;

    /// <summary>Whether A is the upper body along gravity (B lies below it, or is the ground), for shock propagation.</summary>
    public bool AIsUpper;

    /// <summary>Whether the normal lies within about 45° of vertical (|n·ĝ| &gt; 0.7): the contact carries weight.</summary>
    public bool CarriesWeight;

    // Accumulated impulses of the substep.
    public float NormalImpulse, FrictionImpulse1, FrictionImpulse2;

    // Geometry, measured each substep, then the material, fixed for the step.
    public float NormalMass, TangentMass1, TangentMass2; // 1 / the denominator of eq. 16 along n, t1, t2
    public float Friction;
    public float RhoA, RhoB; // lever arms along the normal: r_A = −ρ_A n, r_B = ρ_B n (the point is on the line of centres)
    public Vector3 Normal, Tangent1;
    public Vector3 SpinA1, SpinB1; // I⁻¹ (r × t) for each tangent (eq. 15); for spheres r × n = 0
    public Vector3 Tangent2, SpinA2, SpinB2; // t₂ = n × t₁; zero in planar steps
    public float RadiusA, RadiusB;
    public float PlaneOffset; // NaN unless B is the ground of a plane

    // Friction as a world vector between substeps (the tangents turn), and the step's totals.
    public Vector3 FrictionImpulse;
    public float StepNormalImpulse, StepFrictionImpulse;

    public readonly bool IsPlaneContact => !float.IsNaN(PlaneOffset);
}
