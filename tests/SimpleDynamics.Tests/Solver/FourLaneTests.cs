using System;
using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Response;
using SimpleDynamics.Tests.Properties;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// Planar sweeps solve runs of four contacts that move eight different bodies in vector lanes
/// (SequentialImpulseSolver.Fours.cs). That is solving them one after the other, so a world must step exactly as with
/// every contact solved alone: every body, every step, every bit.
/// </summary>
public class FourLaneTests
{
    private const float Dt = 1f / 60f;
    private readonly ITestOutputHelper _output;

    public FourLaneTests(ITestOutputHelper output) => _output = output;

    /// <summary>A landing pour: mixed sizes and materials, a static post, a kinematic paddle, on one thread or in strips on two.</summary>
    private sealed record Pour(
        int Count, int Seed, float RadiusSpread, float Friction, float Restitution, bool Obstacles, int Threads, int Strips, int Steps)
    {
        public override string ToString() =>
            $"{Count} discs, seed {Seed}, radius spread {RadiusSpread:R}, μ {Friction:R}, ε {Restitution:R}, obstacles {Obstacles}, {Threads} thread(s), {Strips} strip(s), {Steps} steps";
    }

    private static Gen<Pour> Pours { get; } =
        from count in Gen.Choose(60, 400)
        from seed in Gen.Choose(0, 1_000_000)
        from spread in Gen.Elements(1f, 1.5f, 3f)
        from friction in Gen.OneOf(Gen.Elements(0f, 0.3f, 1f), Generators.UniformF(0, 1))
        from restitution in Gen.OneOf(Gen.Elements(0f, 0.5f, 1f), Generators.UniformF(0, 1))
        from obstacles in Gen.Elements(true, false)
        from threads in Gen.Elements(1, 2)
        from strips in threads == 1 ? Gen.Elements(1, 2) : Gen.Elements(2, 4)
        from steps in Gen.Choose(90, 150)
        select new Pour(count, seed, spread, friction, restitution, obstacles, threads, strips, steps);

    [Fact]
    public void Solving_four_contacts_at_once_steps_every_world_bit_for_bit_as_one_at_a_time()
    {
        long planned = 0, solved = 0;
        PropertyCheck.Run(Pours, pour =>
        {
            World inFours = Build(pour, fours: true), alone = Build(pour, fours: false);
            var solver = (SequentialImpulseSolver)inFours.Responder;
            long plannedHere = 0;
            try
            {
                for (int step = 1; step <= pour.Steps; step++)
                {
                    inFours.Step(Dt);
                    alone.Step(Dt);
                    plannedHere += solver.PlannedInFoursThisStep;
                    solved += solver.SweepsThisStep;
                    string? difference = WorldMeasure.FirstDifference(alone, inFours);
                    Law.Holds(difference is null, $"{pour}: step {step}: {difference}");
                }
            }
            finally
            {
                inFours.ThreadCount = alone.ThreadCount = 1;
            }

            Law.Holds(plannedHere > 0, $"{pour}: no four contacts were ever solved at once");
            planned += plannedHere;
        }, seed: 4404, maxTest: 12);

        _output.WriteLine($"{planned} contacts planned in fours over {solved} sweeps");
    }

    /// <summary>The switch the property compares against does switch: with it off, no four is planned.</summary>
    [Fact]
    public void With_fours_off_every_contact_is_solved_alone()
    {
        World world = Build(new Pour(300, 3, 1.5f, 0.3f, 0.5f, Obstacles: true, Threads: 1, Strips: 1, Steps: 120), fours: false);
        var solver = (SequentialImpulseSolver)world.Responder;
        for (int step = 0; step < 120; step++)
        {
            world.Step(Dt);
            Assert.Equal(0, solver.PlannedInFoursThisStep);
        }
    }

    private static World Build(Pour pour, bool fours)
    {
        var solver = new SequentialImpulseSolver(pour.Restitution, pour.Friction) { Strips = pour.Strips, SolvesInFours = fours };
        solver.Cut.ContactsPerStrip = 64; // so that a small pit is cut
        World world = Scenes.BallPit(pour.Count, planar: true, seed: pour.Seed, radiusSpread: pour.RadiusSpread, responder: solver);
        world.SleepingEnabled = false;
        if (pour.Obstacles)
        {
            PitObstacles.AddPostAndPaddle(world);
        }

        world.ThreadCount = pour.Threads;
        return world;
    }
}
