using System;
using System.Linq;
using SimpleDynamics.Response;
using SimpleDynamics.Threading;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// <see cref="World.ThreadCount"/>: a pile cut into strips (SweepStrips.cs) steps bit for bit alike on any number of
/// threads, allocates nothing once warm, and a failure on a worker thread reaches the caller.
/// </summary>
public class ThreadTests
{
    private const float Dt = 1f / 60f;
    private const int Steps = 180; // 3 s: the pour falls, lands and its pile forms
    private readonly ITestOutputHelper _output;

    public ThreadTests(ITestOutputHelper output) => _output = output;

    /// <summary>
    /// A pour of mixed sizes with a static post and a kinematic paddle in it, cut into up to 8 strips (64 contacts a
    /// strip instead of 4,096, so that a small pit is cut), on 1, 2, 3 and 4 threads: every body, every step, every bit.
    /// (One thread and strips: the same order; threads without strips have nothing to share.) With
    /// <paramref name="everySubstep"/>, the pile counts as large enough to share every substep's passes, a settled
    /// one's too (SequentialImpulseSolver.SharedPileContacts).
    /// </summary>
    [Theory]
    [InlineData(true, 600, false)]
    [InlineData(false, 729, false)]
    [InlineData(true, 600, true)]
    public void A_pile_in_strips_steps_bit_for_bit_alike_on_one_to_four_threads(bool planar, int count, bool everySubstep)
    {
        World[] worlds = Enumerable.Range(1, 4).Select(threads => Pit(planar, count, threads, everySubstep)).ToArray();
        int cutSteps = 0, seams = 0, localSweeps = 0, positionSweeps = 0, settledInStrips = 0;
        try
        {
            for (int step = 1; step <= Steps; step++)
            {
                foreach (World world in worlds)
                {
                    world.Step(Dt);
                }

                var solver = (SequentialImpulseSolver)worlds[0].Responder;
                if (solver.Cut.Count > 1)
                {
                    cutSteps++;
                    seams += solver.SeamContacts;
                    localSweeps += solver.LocalSweepsThisStep; // shared by the threads in a cut step (SweepMarkedRange)
                    var onTwo = (SequentialImpulseSolver)worlds[1].Responder;
                    positionSweeps += onTwo.PositionSweepsInStripsThisStep; // on 2 threads (CorrectPositionRange)
                    bool settled = onTwo.SweepsThisStep == worlds[1].Substeps; // one velocity sweep a substep
                    settledInStrips += settled && onTwo.PositionSweepsInStripsThisStep > 0 ? 1 : 0;
                }

                for (int w = 1; w < worlds.Length; w++)
                {
                    Assert.True(WorldMeasure.FirstDifference(worlds[0], worlds[w]) is null,
                        $"step {step}, {w + 1} threads: {WorldMeasure.FirstDifference(worlds[0], worlds[w])}");
                }
            }
        }
        finally
        {
            foreach (World world in worlds)
            {
                world.ThreadCount = 1;
            }
        }

        _output.WriteLine($"{cutSteps} of {Steps} steps cut into strips, {seams / (double)Math.Max(cutSteps, 1):F0} seam contacts a step, {localSweeps} local sweeps and {positionSweeps} position sweeps in strips in them; {settledInStrips} settled steps in strips");
        // The lattice falls for over a second, its neighbours' pairs left out (ImpactStepper.Crowd.cs): too few contacts
        // then to cut. Once it has landed, every step is.
        Assert.True(cutSteps > Steps / 2, $"only {cutSteps} steps were cut into strips");
        Assert.True(seams > 0, "no contact lay across a cut");
        Assert.True(localSweeps > 0, "no local sweep ran in a cut step");
        Assert.True(positionSweeps > 0, "no position sweep ran in strips");
        Assert.True(everySubstep ? settledInStrips > 0 : settledInStrips == 0, $"{settledInStrips} steps of one sweep a substep ran their position sweeps in strips");
    }

    [Fact]
    public void A_pile_in_strips_on_two_threads_allocates_nothing_once_warm()
    {
        World world = Pit(planar: true, 600, threads: 2);
        try
        {
            for (int step = 0; step < 300; step++)
            {
                world.Step(Dt);
            }

            long before = GC.GetAllocatedBytesForCurrentThread(), workersBefore = world.Workers!.WorkerAllocatedBytes;
            for (int step = 0; step < 100; step++)
            {
                world.Step(Dt);
            }

            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            long workers = world.Workers.WorkerAllocatedBytes - workersBefore;
            Assert.True(((SequentialImpulseSolver)world.Responder).Cut.Count > 1, "the pile was not cut");
            Assert.True(allocated == 0 && workers == 0, $"{allocated} B allocated in 100 steps on the stepping thread, {workers} B on the worker");
        }
        finally
        {
            world.ThreadCount = 1;
        }
    }

    [Fact]
    public void A_worker_that_throws_fails_the_run_on_the_calling_thread_and_the_threads_go_on_working()
    {
        var workers = new WorkerThreads(3);
        try
        {
            var failing = new Job(throwOn: 2);
            var error = Assert.Throws<InvalidOperationException>(() => workers.Run(failing));
            Assert.Equal("thread 2", error.Message);

            var job = new Job(throwOn: -1);
            workers.Run(job);
            Assert.Equal(new[] { 1, 1, 1 }, job.Runs);
        }
        finally
        {
            workers.Stop();
        }
    }

    /// <summary>A job posted before the new threads have even started is still run by all of them (it once waited forever).</summary>
    [Fact]
    public async System.Threading.Tasks.Task A_job_posted_at_once_after_the_threads_are_made_runs_on_every_thread()
    {
        for (int round = 0; round < 200; round++)
        {
            var workers = new WorkerThreads(3);
            var job = new Job(throwOn: -1);
            var run = System.Threading.Tasks.Task.Run(() => workers.Run(job));
            bool finished = await System.Threading.Tasks.Task.WhenAny(run, System.Threading.Tasks.Task.Delay(TimeSpan.FromSeconds(10))) == run;
            workers.Stop();
            Assert.True(finished, $"round {round}: the job never finished");
            Assert.Equal(new[] { 1, 1, 1 }, job.Runs);
        }
    }

    [Fact]
    public void Setting_the_thread_count_back_to_one_stops_the_workers_and_the_world_steps_as_before()
    {
        World once = Pit(planar: true, 300, threads: 1), threaded = Pit(planar: true, 300, threads: 2);
        for (int step = 1; step <= 60; step++)
        {
            once.Step(Dt);
            threaded.Step(Dt);
            threaded.ThreadCount = step % 2 == 0 ? 1 : 2;
            Assert.True(WorldMeasure.FirstDifference(once, threaded) is null, $"step {step}: {WorldMeasure.FirstDifference(once, threaded)}");
        }

        threaded.ThreadCount = 1;
        Assert.Equal(1, threaded.ThreadCount);
    }

    private sealed class Job : ParallelJob
    {
        private readonly int _throwOn;

        public Job(int throwOn) => _throwOn = throwOn;

        public int[] Runs { get; } = new int[3];

        public override void Run(int thread, int threads)
        {
            Runs[thread]++;
            if (thread == _throwOn)
            {
                throw new InvalidOperationException($"thread {thread}");
            }
        }
    }

    private static World Pit(bool planar, int count, int threads, bool everySubstep = false)
    {
        var solver = new SequentialImpulseSolver { Strips = 8 };
        solver.Cut.ContactsPerStrip = 64;
        if (everySubstep)
        {
            solver.SharedPileContacts = 0;
        }

        World world = Scenes.BallPit(count, planar, seed: 7, radiusSpread: 1.5f, responder: solver);
        world.SleepingEnabled = false;
        PitObstacles.AddPostAndPaddle(world);
        world.ThreadCount = threads;
        return world;
    }
}
