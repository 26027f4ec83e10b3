using System;
using System.Linq;
using SimpleDynamics.Response;

namespace SimpleDynamics.Benchmarks;

/// <summary>
/// For benchmarks that time one window of steps, replayed every iteration: keeps the bodies' states at the window's
/// start and puts them back before each iteration, the solver forgetting its warm-start impulses.
/// </summary>
internal sealed class ReplayedWindow
{
    private BodyState[] _snapshot = Array.Empty<BodyState>();

    /// <summary>Keeps every body's state in <paramref name="world"/>, to put it back before each iteration.</summary>
    public void TakeSnapshot(World world) => _snapshot = world.Bodies.Select(BodyState.Of).ToArray();

    /// <summary>Puts every body of <paramref name="world"/> back to the snapshot; the solver forgets its warm-start impulses.</summary>
    public void Rewind(World world)
    {
        for (int i = 0; i < _snapshot.Length; i++)
        {
            _snapshot[i].Restore(world.Bodies[i]);
        }

        (world.Responder as SequentialImpulseSolver)?.ResetWarmStart();
    }
}
