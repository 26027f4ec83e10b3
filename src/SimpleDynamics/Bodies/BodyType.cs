namespace SimpleDynamics.Bodies;

/// <summary>How a body takes part in the simulation.</summary>
public enum BodyType
{
    /// <summary>Finite mass; moved by forces, gravity and collision impulses.</summary>
    Dynamic,

    /// <summary>
    /// Infinite mass (inverse mass 0, inverse inertia 0) and zero velocity: it never moves. Ground, walls and
    /// pegs are static.
    /// </summary>
    Static,

    /// <summary>
    /// Infinite mass, but moved by the velocity you set (a moving platform, a paddle). Impulses do not change it,
    /// and it pushes dynamic bodies out of its way.
    /// </summary>
    Kinematic,
}
