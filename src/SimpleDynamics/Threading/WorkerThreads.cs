using System;
using System.Diagnostics;
using System.Runtime.ExceptionServices;
using System.Threading;

namespace SimpleDynamics.Threading;

/// <summary>One piece of parallel work: <see cref="Run"/> is called once on each thread, with that thread's number.</summary>
internal abstract class ParallelJob
{
    /// <summary>Does thread <paramref name="thread"/>'s share (0 is the thread that called <see cref="WorkerThreads.Run"/>).</summary>
    public abstract void Run(int thread, int threads);
}

/// <summary>
/// A world's own worker threads, so that a step can fork and join many times (once per velocity sweep) without
/// allocating and without waiting for the .NET thread pool to wake up. The caller's thread takes part: with
/// <see cref="Threads"/> = 2 there is one worker.
/// </summary>
/// <remarks>
/// While the owner is <see cref="Busy"/> (a world in its step) the workers spin between jobs (yielding their core after
/// <see cref="SpinTicks"/>, in case there are more threads than cores), because a thread woken from sleep takes tens
/// to hundreds of microseconds to run again (measured on a 2-core VM: a settled 4,000-disc pit
/// stepped 20 % slower on two threads than on one when the worker slept between substeps). Otherwise a worker spins
/// for <see cref="SpinTicks"/> after its last job, then blocks, so an idle world costs no CPU. The threads are background threads
/// and hold only the <see cref="Crew"/>, not this object: when the world that owns this object is collected, the
/// finalizer stops them.
/// </remarks>
internal sealed class WorkerThreads
{
    private readonly Crew _crew;

    public WorkerThreads(int threads)
    {
        Threads = threads;
        _crew = new Crew(threads - 1);
        for (int w = 0; w < threads - 1; w++)
        {
            int worker = w;
            var thread = new Thread(() => _crew.Work(worker)) { IsBackground = true, Name = $"SimpleDynamics worker {w + 1}" };
            thread.Start();
        }
    }

    ~WorkerThreads() => _crew.Stop();

    /// <summary>Whether the workers keep spinning between jobs (set for the length of a step).</summary>
    public bool Busy
    {
        get => _crew.Busy;
        set => _crew.Busy = value;
    }

    /// <summary>The threads a job runs on, the caller's included.</summary>
    public int Threads { get; }

    /// <summary>The bytes the worker threads have allocated since they started, as of their last job (for tests).</summary>
    public long WorkerAllocatedBytes => _crew.AllocatedBytes();

    /// <summary>How long a worker spins for the next job before it blocks: 100 µs.</summary>
    private static readonly long SpinTicks = Stopwatch.Frequency / 10_000;

    /// <summary>Runs <paramref name="job"/> on every thread and returns when all are done; rethrows the first failure.</summary>
    public void Run(ParallelJob job)
    {
        Crew crew = _crew;
        crew.Job = job;
        crew.Failure = null;
        crew.Remaining = Threads - 1;
        Interlocked.Increment(ref crew.Generation);
        crew.WakeSleepers();
        try
        {
            job.Run(0, Threads);
        }
        catch (Exception e)
        {
            Interlocked.CompareExchange(ref crew.Failure, e, null);
        }

        for (int spins = 0; Volatile.Read(ref crew.Remaining) > 0; spins++)
        {
            Pause(spins);
        }

        crew.Job = null;
        if (crew.Failure is Exception failure)
        {
            crew.Failure = null;
            ExceptionDispatchInfo.Capture(failure).Throw();
        }
    }

    /// <summary>Stops the workers now (they also stop when this object is collected).</summary>
    public void Stop()
    {
        _crew.Stop();
        GC.SuppressFinalize(this);
    }

    /// <summary>One wait of a spin loop: a short busy wait; after many, a yield, and after very many a sleep, in case the awaited thread has no core.</summary>
    private static void Pause(int spins)
    {
        if (spins < 1_000)
        {
            Thread.SpinWait(8);
        }
        else if (spins < 20_000)
        {
            Thread.Yield();
        }
        else
        {
            Thread.Sleep(1);
        }
    }

    /// <summary>What the worker threads share with the caller.</summary>
    private sealed class Crew
    {
        private readonly SemaphoreSlim[] _wake;
        private readonly int[] _sleeping; // 1 while worker w is about to block or blocked on _wake[w]
        private readonly long[] _allocated; // per worker: its allocated bytes after its last job
        private volatile bool _stopping;
        public volatile bool Busy;
        public ParallelJob? Job;
        public int Generation; // one more for each job
        public int Remaining; // workers still running the job
        public Exception? Failure;

        public Crew(int workers)
        {
            _wake = new SemaphoreSlim[workers];
            _sleeping = new int[workers];
            _allocated = new long[workers];
            for (int w = 0; w < workers; w++)
            {
                _wake[w] = new SemaphoreSlim(0);
            }
        }

        public long AllocatedBytes()
        {
            long sum = 0;
            for (int w = 0; w < _allocated.Length; w++)
            {
                sum += Volatile.Read(ref _allocated[w]);
            }

            return sum;
        }

        public void WakeSleepers()
        {
            for (int w = 0; w < _wake.Length; w++)
            {
                if (Interlocked.Exchange(ref _sleeping[w], 0) == 1)
                {
                    _wake[w].Release();
                }
            }
        }

        public void Stop()
        {
            _stopping = true;
            Interlocked.Increment(ref Generation);
            WakeSleepers();
        }

        public void Work(int worker)
        {
            int seen = 0; // not Generation as the thread finds it: a job posted before the thread started would be missed
            while (true)
            {
                WaitForJob(worker, seen);
                seen = Volatile.Read(ref Generation);
                if (_stopping)
                {
                    return;
                }

                try
                {
                    Job!.Run(worker + 1, _wake.Length + 1);
                }
                catch (Exception e)
                {
                    Interlocked.CompareExchange(ref Failure, e, null);
                }

                Volatile.Write(ref _allocated[worker], GC.GetAllocatedBytesForCurrentThread());
                Interlocked.Decrement(ref Remaining);
            }
        }

        /// <summary>Spins until the generation moves on past <paramref name="seen"/>, or blocks once the spinning has gone on too long.</summary>
        private void WaitForJob(int worker, int seen)
        {
            long start = Stopwatch.GetTimestamp();
            int spins = 0;
            while (Volatile.Read(ref Generation) == seen)
            {
                if (++spins % 64 != 0 || Stopwatch.GetTimestamp() - start < SpinTicks)
                {
                    Thread.SpinWait(8);
                    continue;
                }

                if (Busy)
                {
                    // In a step: stay awake, but let a thread that has no core run (more threads than cores).
                    Thread.Yield();
                    continue;
                }

                // Announce the sleep, then look once more: a job posted in between either sees the announcement (and
                // releases the semaphore) or is seen here (and the announcement is taken back, if it still can be).
                Interlocked.Exchange(ref _sleeping[worker], 1); // a full fence: the look below comes after it
                if (Volatile.Read(ref Generation) != seen && Interlocked.Exchange(ref _sleeping[worker], 0) == 1)
                {
                    return;
                }

                _wake[worker].Wait();
                start = Stopwatch.GetTimestamp();
            }
        }
    }
}
