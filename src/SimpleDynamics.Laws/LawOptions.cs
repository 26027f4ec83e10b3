using System;

namespace SimpleDynamics.Laws;

/// <summary>
/// What <see cref="ResponderLaws.Check(Func{float, SimpleDynamics.Response.ICollisionResponder}, LawOptions)"/>
/// checks and on how many generated collisions. The defaults suit the tutorial's impulse responder.
/// </summary>
public sealed class LawOptions
{
    /// <summary>The laws to check; <see cref="ResponderLaws.ImpulseLaws"/> unless set.</summary>
    public ResponderLaw Laws { get; set; } = ResponderLaws.ImpulseLaws;

    /// <summary>Generated collisions per law (default 200).</summary>
    public int MaxTest { get; set; } = 200;

    /// <summary>
    /// The random seed (default 1, so a run is repeatable). The environment variable FSCHECK_REPLAY="seed,gamma",
    /// as printed on failure, overrides it.
    /// </summary>
    public ulong Seed { get; set; } = 1;

    /// <summary>
    /// Relative tolerance of every comparison (default 1e-4): the bodies are float, the measurements double, and
    /// a few float roundings per quantity stay far below it, while a wrong formula does not.
    /// </summary>
    public double Tolerance { get; set; } = 1e-4;

    /// <summary>
    /// Whether laws that hold with friction (momentum, angular momentum, bounce, separating, static, energy never
    /// rises) are also checked on contacts with friction μ ∈ (0, 1] (default true). The energy laws always use
    /// frictionless contacts (<see cref="SimpleDynamics.Bodies.RigidBody.Friction"/> = 0 on both bodies).
    /// </summary>
    public bool WithFriction { get; set; } = true;

    /// <summary>
    /// The slowest approach (m/s) generated (default 1): solvers stop bouncing below a restitution threshold
    /// (<see cref="SimpleDynamics.Response.SequentialImpulseSolver.RestitutionThreshold"/>, 0.5 m/s), so eq. 9 is
    /// checked above it.
    /// </summary>
    public double MinApproachSpeed { get; set; } = 1;

    /// <summary>The fastest approach (m/s) generated (default 10). Speeds are multiples of 0.01 m/s.</summary>
    public double MaxApproachSpeed { get; set; } = 10;

    /// <summary>The time step (s) of the one <see cref="World.Step"/> per collision (default 1/60).</summary>
    public float TimeStep { get; set; } = 1f / 60f;

    internal void Validate()
    {
        if (Laws == ResponderLaw.None)
        {
            throw new ArgumentException("No law selected.", nameof(Laws));
        }

        if (MaxTest < 1)
        {
            throw new ArgumentOutOfRangeException(nameof(MaxTest), MaxTest, "At least one test per law.");
        }

        if (!(Tolerance > 0 && Tolerance < 1))
        {
            throw new ArgumentOutOfRangeException(nameof(Tolerance), Tolerance, "A relative tolerance in (0, 1).");
        }

        // Generated numbers lie on a grid of 0.01, so the range must hold at least one grid point.
        if (!(MinApproachSpeed >= 0.01 && MaxApproachSpeed >= MinApproachSpeed && MaxApproachSpeed <= 1000
            && Math.Floor(MaxApproachSpeed * 100 + 1e-9) >= Math.Ceiling(MinApproachSpeed * 100 - 1e-9)))
        {
            throw new ArgumentOutOfRangeException(nameof(MinApproachSpeed), MinApproachSpeed,
                "Approach speeds need 0.01 <= MinApproachSpeed <= MaxApproachSpeed <= 1000 m/s, with a multiple of 0.01 m/s between them.");
        }

        if (!(TimeStep > 0 && TimeStep <= 1))
        {
            throw new ArgumentOutOfRangeException(nameof(TimeStep), TimeStep, "A time step in (0, 1] s.");
        }
    }
}
