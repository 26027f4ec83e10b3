using FsCheck;
using FsCheck.Fluent;
using SimpleDynamics.Response;
using SimpleDynamics.Tests.Behavior;
using SimpleDynamics.Tests.Properties;
using Xunit;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// The solver measures a 3-D contact in two loops: depth, normal and whether it is solved, then, a block of solved
/// contacts at a time, its tangent frame and friction (SequentialImpulseSolver.Prepare.cs). Where the blocks end must
/// not matter: a world must step exactly as when every contact is framed right after it is listed, or all of them after
/// the whole measure, every body, every step, every bit.
/// </summary>
public class FramesBlockTests
{
    private const float Dt = 1f / 60f;

    private sealed record Pour(int Count, int Seed, float RadiusSpread, float Friction, int Threads, int Block)
    {
        public override string ToString() =>
            $"{Count} spheres, seed {Seed}, radius spread {RadiusSpread:R}, μ {Friction:R}, {Threads} thread(s), frames in blocks of {Block}";
    }

    private static Gen<Pour> Pours { get; } =
        from count in Gen.Choose(80, 240)
        from seed in Gen.Choose(0, 1_000_000)
        from spread in Gen.Elements(1f, 1.5f, 3f)
        from friction in Gen.OneOf(Gen.Elements(0f, 0.3f, 1f), Generators.UniformF(0, 1))
        from threads in Gen.Elements(1, 2)
        from block in Gen.Elements(1, 2, 7, 64)
        select new Pour(count, seed, spread, friction, threads, block);

    [Fact]
    public void Any_block_of_frames_steps_every_world_bit_for_bit_alike()
    {
        PropertyCheck.Run(Pours, pour =>
        {
            World world = Build(pour, pour.Block), reference = Build(pour, int.MaxValue);
            try
            {
                for (int step = 1; step <= 150; step++)
                {
                    world.Step(Dt);
                    reference.Step(Dt);
                    string? difference = WorldMeasure.FirstDifference(reference, world);
                    Law.Holds(difference is null, $"{pour}: step {step}: {difference}");
                }
            }
            finally
            {
                world.ThreadCount = reference.ThreadCount = 1;
            }
        }, seed: 3101, maxTest: 8);
    }

    private static World Build(Pour pour, int block)
    {
        var solver = new SequentialImpulseSolver(0.3f, pour.Friction) { Strips = pour.Threads, FramesBlock = block };
        solver.Cut.ContactsPerStrip = 64; // so that a small pit is cut
        World world = Scenes.BallPit(pour.Count, planar: false, seed: pour.Seed, radiusSpread: pour.RadiusSpread, responder: solver);
        world.SleepingEnabled = false;
        world.ThreadCount = pour.Threads;
        return world;
    }
}
