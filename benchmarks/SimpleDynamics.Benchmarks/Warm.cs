using System;
using System.Linq;
using SimpleDynamics.Bodies;

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
    /// to the floor (t = √(2h/g)) plus two seconds, then on until the balls' root-mean-square speed is below
    /// <see cref="SettledSpeed"/> (checked once a simulated second), at most <see cref="MaxSteps"/> steps. The
    /// fall alone is not enough: the 16,000-ball 2-D pit starts about 28 m up, and its 126-layer pile is still
    /// moving at several centimetres per second seconds after the last ball has landed. Returns the number of steps taken.
    /// </summary>
    public static int Pour(World world)
    {
        float top = world.Bodies.Max(b => b.Position.Y);
        float g = MathF.Max(world.Gravity.Length(), 1e-3f);
        int steps = (int)MathF.Ceiling((MathF.Sqrt(2 * top / g) + 2f) / Dt);
        int step = 0;
        while (step < MaxSteps && (step < steps || (step % 60 != 0 || RmsSpeed(world) >= SettledSpeed)))
        {
            world.Step(Dt);
            step++;
        }

        return step;
    }

    /// <summary>√(2 KE / Σm): the root-mean-square speed of the bodies (translation and spin together).</summary>
    public static double RmsSpeed(World world) =>
        Math.Sqrt(2 * world.Diagnostics.KineticEnergy / world.Bodies.Sum(b => (double)b.Mass));
}
