using System;
using System.Collections.Generic;
using System.Threading;
using SimpleDynamics.Threading;
using Xunit;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// <see cref="ShareQueue"/>, which hands the strips of a pass to the threads: each share to exactly one thread, each
/// thread its own part first, and a thread that is done takes over the shares another has not begun.
/// </summary>
public class ShareQueueTests
{
    [Fact]
    public void One_thread_takes_every_share_in_order()
    {
        var queue = new ShareQueue(8);
        queue.Reset(8);
        Assert.Equal(new[] { 0, 1, 2, 3, 4, 5, 6, 7 }, TakeAll(queue, thread: 0, threads: 1));
    }

    /// <summary>Thread 1 of 3 over 8 shares owns 2, 3 and 4 (8/3 = 2 to 16/3 = 5); then it takes the others', last first.</summary>
    [Fact]
    public void A_thread_takes_its_own_part_first_then_the_others_last_first()
    {
        var queue = new ShareQueue(8);
        queue.Reset(8);
        Assert.Equal(new[] { 2, 3, 4, 7, 6, 5, 1, 0 }, TakeAll(queue, thread: 1, threads: 3));
    }

    /// <summary>One thread runs first, then another, as if the second had been held up: the second finds nothing left.</summary>
    [Fact]
    public void A_share_taken_by_one_thread_is_not_given_to_another()
    {
        var queue = new ShareQueue(8);
        queue.Reset(4);
        int cursor = 0;
        Assert.True(queue.TryTake(0, 2, ref cursor, out int first));
        Assert.Equal(0, first);

        Assert.Equal(new[] { 2, 3, 1 }, TakeAll(queue, thread: 1, threads: 2)); // its own, then thread 0's not yet taken
        Assert.False(queue.TryTake(0, 2, ref cursor, out _));

        queue.Reset(4); // the next pass: every share untaken again
        Assert.Equal(new[] { 0, 1, 3, 2 }, TakeAll(queue, thread: 0, threads: 2));
    }

    /// <summary>
    /// On four threads, over many passes whose shares take random times (one share far longer than the rest), every
    /// share runs exactly once a pass; and while one thread is held up, the others take over its part.
    /// </summary>
    [Fact]
    public void On_four_threads_every_share_runs_exactly_once_and_the_idle_take_over()
    {
        var workers = new WorkerThreads(4);
        try
        {
            var job = new CountingJob(shares: 8);
            for (int pass = 0; pass < 300; pass++)
            {
                job.Begin(seed: pass);
                workers.Run(job);
                Assert.Equal(8, job.Runs.Length);
                Assert.All(job.Runs, runs => Assert.Equal(1, runs));
            }

            job.Begin(seed: -1, holdUpThread: 3); // thread 3 starts only once the others have run out of shares
            workers.Run(job);
            Assert.All(job.Runs, runs => Assert.Equal(1, runs));
            Assert.Equal(0, job.SharesOf[3]);
            Assert.Equal(8, job.SharesOf[0] + job.SharesOf[1] + job.SharesOf[2]);
        }
        finally
        {
            workers.Stop();
        }
    }

    [Fact]
    public void More_shares_than_the_queue_holds_are_refused_by_name()
    {
        var queue = new ShareQueue(8);
        var error = Assert.Throws<ArgumentOutOfRangeException>(() => queue.Reset(9));
        Assert.Equal("count", error.ParamName);
    }

    private static List<int> TakeAll(ShareQueue queue, int thread, int threads)
    {
        var taken = new List<int>();
        int cursor = 0;
        while (queue.TryTake(thread, threads, ref cursor, out int share))
        {
            taken.Add(share);
        }

        return taken;
    }

    private sealed class CountingJob : ParallelJob
    {
        private readonly ShareQueue _queue;
        private readonly int[] _spins;
        private int _holdUpThread = -1;
        private int _othersDone;

        public CountingJob(int shares)
        {
            _queue = new ShareQueue(shares);
            Runs = new int[shares];
            _spins = new int[shares];
        }

        public int[] Runs { get; }

        public int[] SharesOf { get; } = new int[4];

        public void Begin(int seed, int holdUpThread = -1)
        {
            var random = new Random(seed);
            for (int s = 0; s < Runs.Length; s++)
            {
                Runs[s] = 0;
                _spins[s] = seed < 0 ? 0 : random.Next(0, 2_000) + (s == seed % Runs.Length ? 50_000 : 0);
            }

            Array.Clear(SharesOf);
            _holdUpThread = holdUpThread;
            _othersDone = 0;
            _queue.Reset(Runs.Length);
        }

        public override void Run(int thread, int threads)
        {
            if (thread == _holdUpThread)
            {
                SpinWait.SpinUntil(() => Volatile.Read(ref _othersDone) == threads - 1);
            }

            int cursor = 0;
            while (_queue.TryTake(thread, threads, ref cursor, out int share))
            {
                Thread.SpinWait(_spins[share]);
                Interlocked.Increment(ref Runs[share]);
                SharesOf[thread]++;
            }

            Interlocked.Increment(ref _othersDone);
        }
    }
}
