using System;
using SimpleDynamics.Threading;

namespace SimpleDynamics;

public sealed partial class World
{
    /// <summary>The most threads a world steps on.</summary>
    public const int MaxThreadCount = 64;

    private WorkerThreads? _workers;

    /// <summary>
    /// How many threads a step may use (1 to <see cref="MaxThreadCount"/>, default 1): the caller's and
    /// <c>ThreadCount − 1</c> worker threads of the world's own. Every result is the same, bit for bit, whatever the
    /// count. The default solver shares its velocity sweeps when it cuts a pile into strips
    /// (<see cref="Response.SequentialImpulseSolver.Strips"/>, off by default: set it to the thread count): it then
    /// sweeps a pile of at least 8,192 contacts strip after strip, then the contacts between strips (see SweepStrips.cs),
    /// and threads sweep the strips at once. Only the velocity and position passes of substeps that need more than one
    /// velocity sweep are shared (a landing or stirring pile), and the measuring of the contacts in the substep after
    /// such a one, or those of every substep in a pile of at least 32,768 contacts; a smaller pile, a smaller settled
    /// one, and every other stage of the step run on the caller's thread.
    /// </summary>
    /// <remarks>
    /// Setting a larger count starts the workers; setting 1 stops them, as does the world being collected. During a
    /// step the workers spin between passes (a sleeping thread takes too long to wake); between steps an idle worker
    /// spins for 100 µs, then sleeps.
    /// </remarks>
    public int ThreadCount
    {
        get => _workers?.Threads ?? 1;
        set
        {
            Guard.InRange(value, 1, MaxThreadCount, nameof(ThreadCount));
            ThrowIfStepping(nameof(ThreadCount));
            if (value == ThreadCount)
            {
                return;
            }

            _workers?.Stop();
            _workers = value > 1 ? new WorkerThreads(value) : null;
        }
    }

    /// <summary>The world's worker threads, for the stages that split their work; null on one thread.</summary>
    internal WorkerThreads? Workers => _workers;
}
