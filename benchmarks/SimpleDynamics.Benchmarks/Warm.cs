using System;
using System.Linq;
using SimpleDynamics.Bodies;
using SimpleDynamics.Response;

namespace SimpleDynamics.Benchmarks;

/// <summary>Brings a scene to the state a benchmark times.</summary>
internal static class Warm
{
    public const float Dt = 1f / 60f;

    /// <summary>
    /// A pit counts as settled when its balls' root-mean-square speed is below this (m/s), 1 cm/s. (Spheres with
    /// no rolling resistance may go on turning slowly in a 3-D pile; 1 mm/s is not always reached.)
    /// </summary>
    public const double SettledSpeed = 1e-2;

    /// <summary>At most this many steps (30 s) are spent settling.</summary>
    public const int MaxSteps = 1800;

    /// <summary>
    /// Steps a freshly poured ball pit until it has settled: at least long enough for the highest ball to fall
    /// to the floor (t = √(2h/g)) plus two seconds, then on until, over a whole simulated second, the balls'
    /// root-mean-square speed is below <see cref="SettledSpeed"/> and the solver has converged (see
    /// <see cref="Converged"/>), at most <see cref="MaxSteps"/> steps. The fall alone is not enough: the 16,000-ball
    /// 2-D pit starts about 28 m up, and its 126-layer pile is still moving at several centimetres per second seconds
    /// after the last ball has landed. Nor is the speed alone: that pile is under 1 cm/s at 7 s but spends 30–60
    /// sweeps a step until about 15 s, and a benchmark started at 7 s timed a pile still converging (its first
    /// iterations 93–183 ms a step, its last 53–71 ms). Returns the number of steps taken.
    /// </summary>
    public static int Pour(World world)
    {
        float top = world.Bodies.Max(b => b.Position.Y);
        float g = MathF.Max(world.Gravity.Length(), 1e-3f);
        int steps = (int)MathF.Ceiling((MathF.Sqrt(2 * top / g) + 2f) / Dt);
        var solver = world.Responder as SequentialImpulseSolver;
        int step = 0, sweeps = 0;
        while (step < MaxSteps)
        {
            world.Step(Dt);
            step++;
            sweeps += solver?.SweepsThisStep ?? 0;
            if (step % 60 != 0)
            {
                continue;
            }

            if (step >= steps && RmsSpeed(world) < SettledSpeed && Converged(solver, world.Substeps, sweeps / 60.0))
            {
                break;
            }

            sweeps = 0;
        }

        return step;
    }

    /// <summary>
    /// Whether the solver has converged, given the velocity sweeps it spent per step over the last second: no more
    /// than one extra sweep per substep on average beyond its fixed ones. (A 3-D pile of spheres without rolling
    /// resistance goes on spending one or two a step; a solver with no extra sweeps, or another responder, always
    /// counts as converged.)
    /// </summary>
    private static bool Converged(SequentialImpulseSolver? solver, int substeps, double sweepsPerStep) =>
        solver is null || sweepsPerStep <= (solver.VelocityIterations + 1) * substeps;

    /// <summary>√(2 KE / Σm): the root-mean-square speed of the bodies (translation and spin together).</summary>
    public static double RmsSpeed(World world) =>
        Math.Sqrt(2 * world.Diagnostics.KineticEnergy / world.Bodies.Sum(b => (double)b.Mass));
}
