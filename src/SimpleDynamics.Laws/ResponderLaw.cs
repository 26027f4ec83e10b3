using System;

namespace SimpleDynamics.Laws;

/// <summary>
/// The laws of the collision-response tutorial that <see cref="ResponderLaws"/> can check. Combine them with
/// <c>|</c>; <see cref="ResponderLaws.ImpulseLaws"/> and <see cref="ResponderLaws.PerfectlyInelasticLaws"/>
/// are the usual sets.
/// </summary>
[Flags]
public enum ResponderLaw
{
    /// <summary>No law.</summary>
    None = 0,

    /// <summary>Two dynamic bodies: m_A v_A + m_B v_B is the same after the collision (eq. 1, 3–6).</summary>
    LinearMomentum = 1 << 0,

    /// <summary>
    /// Two dynamic bodies: Σ (I ω + (c − O) × m v) about an arbitrary point O is the same after the collision
    /// (eq. 11, 15): the impulses act at the contact point, equal and opposite.
    /// </summary>
    AngularMomentum = 1 << 1,

    /// <summary>ε = 1 and no friction: kinetic energy is the same after the collision (eq. 1).</summary>
    ElasticEnergy = 1 << 2,

    /// <summary>
    /// ε &lt; 1 and no friction: kinetic energy falls by exactly ½ (1 − ε²) m_eff v_n², with
    /// m_eff = 1 / (1/m_A + 1/m_B) (1/m_B = 0 for a static body) and v_n the approach speed along the normal.
    /// </summary>
    EnergyLoss = 1 << 3,

    /// <summary>The relative normal velocity at the contact reverses and scales by ε: v_n' = −ε v_n (eq. 9, 14).</summary>
    Bounce = 1 << 4,

    /// <summary>A separating contact, v_n &gt; 0, gets no impulse: every velocity is unchanged.</summary>
    SeparatingUntouched = 1 << 5,

    /// <summary>A static body (infinite mass, eq. 2's limit) does not move: position, orientation, velocities unchanged.</summary>
    StaticUnmoved = 1 << 6,

    /// <summary>Kinetic energy never rises (ε ≤ 1; friction only takes energy away).</summary>
    EnergyNeverRises = 1 << 7,

    /// <summary>
    /// Perfectly inelastic (eq. 2, listing 1): both bodies leave with the common velocity
    /// (m_A v_A + m_B v_B) / (m_A + m_B); against a static body the dynamic one stops.
    /// </summary>
    CommonVelocity = 1 << 8,
}
