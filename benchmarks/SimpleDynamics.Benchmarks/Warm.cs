using System;
using System.Linq;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Benchmarks;

/// <summary>Brings a scene to the state a benchmark times.</summary>
internal static class Warm
{
    public const float Dt = 1f / 60f;

    /// <summary>
    /// Steps a freshly poured ball pit until it has settled: long enough for the highest ball to fall to the
    /// floor (t = √(2h/g)) plus two seconds. A fixed 120 steps is not enough: the 16,000-ball 2-D pit starts
    /// about 28 m up and has made no ball–ball contact after 2 s. Returns the number of steps taken.
    /// </summary>
    public static int Pour(World world)
    {
        float top = world.Bodies.Max(b => b.Position.Y);
        float g = MathF.Max(world.Gravity.Length(), 1e-3f);
        int steps = (int)MathF.Ceiling((MathF.Sqrt(2 * top / g) + 2f) / Dt);
        for (int i = 0; i < steps; i++)
        {
            world.Step(Dt);
        }

        return steps;
    }
}
