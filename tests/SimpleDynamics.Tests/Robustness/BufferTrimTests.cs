using System;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Robustness;

/// <summary>
/// The working arrays grow to the largest scene seen and are kept (a warm step allocates nothing); an explicit
/// <see cref="World.TrimExcess"/> gives the room back once the scene has shrunk, and so does a world that stays
/// small for long enough (<see cref="ShrinkPolicy"/>), without reallocating while its need is steady.
/// </summary>
/// <remarks>
/// The memory tests weigh the whole heap (<see cref="GC.GetTotalMemory"/>), so they run in a collection of their
/// own, with no other test allocating at the same time.
/// </remarks>
[Collection(nameof(MemoryMeasurements))]
public class BufferTrimTests
{
    private readonly ITestOutputHelper _output;

    public BufferTrimTests(ITestOutputHelper output) => _output = output;

    [Fact]
    public void The_issue_crowd_stepped_then_removed_holds_no_more_than_an_empty_world_after_TrimExcess()
    {
        long emptyWorld = Weigh(() => SteppedCrowd(0), out _);
        long baseline = Heap();
        World world = SteppedCrowd(300);
        long grown = Heap() - baseline;
        RemoveAll(world);
        // Two steps: the first reports the removed pairs' end events, which are readable until the next one.
        Step(world, 2);
        world.TrimExcess();
        long trimmed = Heap() - baseline;
        _output.WriteLine($"empty world {emptyWorld / 1024} KiB, crowd {grown / 1024} KiB, trimmed {trimmed / 1024} KiB");

        Assert.True(grown > 10 * 1024 * 1024, $"the crowd should grow the buffers by many MiB, not {grown / 1024} KiB");
        Assert.True(trimmed < emptyWorld + 64 * 1024, $"the trimmed world holds {trimmed / 1024} KiB, an empty one {emptyWorld / 1024} KiB");
        StepsAsBefore(world);
    }

    [Fact]
    public void A_world_that_stays_empty_after_the_crowd_gives_the_memory_back_without_being_asked()
    {
        long emptyWorld = Weigh(() => SteppedCrowd(0), out _);
        long baseline = Heap();
        World world = SteppedCrowd(300);
        long grown = Heap() - baseline;
        RemoveAll(world);

        // The policy's steps, and one to spare.
        Step(world, ShrinkPolicy.QuietSteps + 1);
        long shrunk = Heap() - baseline;
        _output.WriteLine($"empty world {emptyWorld / 1024} KiB, crowd {grown / 1024} KiB, after {ShrinkPolicy.QuietSteps + 1} empty steps {shrunk / 1024} KiB");

        // Automatic shrinking keeps up to ShrinkPolicy.MinimumCapacity items per array: well under 1 MiB in all.
        Assert.True(grown > 10 * 1024 * 1024, $"the crowd should grow the buffers by many MiB, not {grown / 1024} KiB");
        Assert.True(shrunk < emptyWorld + 1024 * 1024, $"the idle world holds {shrunk / 1024} KiB, an empty one {emptyWorld / 1024} KiB");
        StepsAsBefore(world);
    }

    /// <summary>
    /// The lattice of a 4,000-disc pit falling together at 10 m/s has most of its pairs left out of its contacts
    /// (ImpactStepper.Crowd.cs), and their lists grow by megabytes; a world that stays empty after it gives that room
    /// back without being asked, as it does everything else: it then holds little more than the same world that kept
    /// every pair (the lists keep room for <see cref="ShrinkPolicy.MinimumCapacity"/> pairs, about 110 KiB; measured
    /// 1,407 against 1,050 KiB and 1,150 against 1,313 KiB in two runs, and 2,676 against 1,050 KiB with the lists left
    /// at their room).
    /// </summary>
    [Fact]
    public void A_falling_crowd_leaves_its_pairs_out_and_a_world_that_stays_empty_after_it_gives_their_room_back()
    {
        long keptAll = HeldAfterFallingCrowd(leaveOut: false, out _, out _);
        long leftOut = HeldAfterFallingCrowd(leaveOut: true, out int pairs, out int contacts);
        _output.WriteLine($"{pairs} pairs left out beside {contacts} contacts; after {ShrinkPolicy.QuietSteps + 1} empty steps the world holds {leftOut / 1024} KiB, {keptAll / 1024} KiB had it kept every pair");

        Assert.True(pairs > 4 * contacts, $"{pairs} pairs left out beside {contacts} contacts");
        Assert.True(leftOut < keptAll + 512 * 1024, $"the idle world holds {leftOut / 1024} KiB, {keptAll / 1024} KiB had it kept every pair");
    }

    /// <summary>The bytes a 4,000-disc lattice's world holds after falling 60 steps, its bodies removed and the policy's steps.</summary>
    private static long HeldAfterFallingCrowd(bool leaveOut, out int pairsLeftOut, out int contacts)
    {
        long baseline = Heap();
        World world = Scenes.BallPit(4000, planar: true);
        world.LeaveOutCrowdPairs = leaveOut;
        Step(world, 60);
        pairsLeftOut = world.CrowdPairsLeftOut;
        contacts = world.Collisions.Count;
        RemoveAll(world);
        Step(world, ShrinkPolicy.QuietSteps + 1);
        long held = Heap() - baseline;
        StepsAsBefore(world);
        return held;
    }

    [Fact]
    public void A_steady_pile_shrinks_once_after_a_burst_and_then_steps_without_allocating()
    {
        World world = Scenes.BallPit(300, planar: true, seed: 4);
        world.SleepingEnabled = false; // a pile that falls asleep steps no contacts: this one must keep using them
        Step(world, 200);
        int steadyCapacity = world.Collisions.Capacity;

        // A burst: 150 bodies within 1 mm of each other, far from the pile, for one step.
        var burst = new RigidBody[150];
        var random = new Random(7);
        for (int i = 0; i < burst.Length; i++)
        {
            var offset = new Vector3((float)random.NextDouble(), (float)random.NextDouble(), (float)random.NextDouble()) * 1e-3f;
            burst[i] = world.Add(new RigidBody(1f, 0.1f, new Vector3(50, 5, 0) + offset));
        }

        world.Step(1f / 60f);
        int burstCapacity = world.Collisions.Capacity;
        foreach (RigidBody body in burst)
        {
            world.Remove(body);
        }

        // Long enough for every buffer's policy, then steady.
        Step(world, ShrinkPolicy.QuietSteps + 10);
        int shrunkCapacity = world.Collisions.Capacity;
        long before = GC.GetAllocatedBytesForCurrentThread();
        Step(world, 3 * ShrinkPolicy.QuietSteps);
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        _output.WriteLine($"contact capacity: steady {steadyCapacity}, burst {burstCapacity}, shrunk {shrunkCapacity}, now {world.Collisions.Capacity} for {world.Collisions.Count} contacts; {allocated} bytes");

        Assert.True(burstCapacity >= 150 * 149 / 2, $"the burst should grow the contacts, capacity {burstCapacity}");
        Assert.True(shrunkCapacity <= 4 * world.Collisions.Count, $"capacity {shrunkCapacity} for {world.Collisions.Count} contacts");
        Assert.Equal(shrunkCapacity, world.Collisions.Capacity); // no shrink-then-grow while the need is steady
        Assert.Equal(0, allocated);
    }
    [Fact]
    public void A_crowd_of_2000_grows_the_contact_buffer_and_TrimExcess_gives_the_room_back()
    {
        World world = Crowd(2000);
        // Detection alone, into the world's own contact buffer, as the first stage of Step does: solving two
        // million contacts would take seconds and is not what this test is about.
        new BruteForceDetector().FindContacts(world.BodySpan, world.Collisions);
        AssertTrimmedAfterRemovingAllButTwo(world, 2000);
    }

    [Fact]
    public void A_crowd_stepped_by_the_world_grows_the_buffers_and_TrimExcess_gives_the_room_back()
    {
        World world = Crowd(300);
        // One substep and one cheap iteration: the buffers are the point, not the solution.
        world.Responder = new SequentialImpulseSolver { VelocityIterations = 1, PositionIterations = 0 };
        world.Substeps = 1;
        world.Step(1f / 60f);
        AssertTrimmedAfterRemovingAllButTwo(world, 300);

        // The trimmed world grows again as needed and steps as before.
        world.Add(new RigidBody(1f, 0.1f, new Vector3(1, 1, 1)));
        world.Step(1f / 60f);
        Assert.Equal(3, world.Bodies.Count);
        Assert.All(world.Bodies, b => Assert.True(float.IsFinite(b.Position.X)));
    }

    /// <summary>The issue's crowd, <paramref name="count"/> bodies within 1 mm, stepped once as cheaply as can be.</summary>
    private static World SteppedCrowd(int count)
    {
        World world = Crowd(count);
        // One substep and one cheap iteration: the buffers are the point, not the solution.
        world.Responder = new SequentialImpulseSolver { VelocityIterations = 1, PositionIterations = 0, ExtraIterations = 0 };
        world.Substeps = 1;
        world.Step(1f / 60f);
        return world;
    }

    /// <summary>The bytes the world made by <paramref name="make"/> holds (with its responder and detector).</summary>
    private static long Weigh(Func<World> make, out World world)
    {
        long before = Heap();
        world = make();
        long after = Heap();
        GC.KeepAlive(world);
        return after - before;
    }

    /// <summary>
    /// The live heap, as the least of three full-collection readings: what another thread (the test runner's
    /// message bus) holds for a moment can only add to a reading, and the least one is the closest to what stays.
    /// </summary>
    private static long Heap()
    {
        long least = long.MaxValue;
        for (int i = 0; i < 3; i++)
        {
            least = Math.Min(least, GC.GetTotalMemory(forceFullCollection: true));
        }

        return least;
    }

    private static void RemoveAll(World world)
    {
        foreach (RigidBody body in world.Bodies.ToArray())
        {
            world.Remove(body);
        }
    }

    /// <summary>A trimmed or shrunk world grows again as needed and steps as before.</summary>
    private static void StepsAsBefore(World world)
    {
        world.Add(new RigidBody(1f, 0.1f, new Vector3(1, 1, 1)));
        world.Add(new RigidBody(1f, 0.1f, new Vector3(1.15f, 1, 1)));
        world.Step(1f / 60f);
        Assert.Equal(2, world.Bodies.Count);
        Assert.Equal(1, world.Collisions.Count);
        Assert.All(world.Bodies, b => Assert.True(float.IsFinite(b.Position.X)));
    }

    private static void Step(World world, int steps)
    {
        for (int i = 0; i < steps; i++)
        {
            world.Step(1f / 60f);
        }
    }

    /// <summary>Bodies of radius 0.1 m all within 1 mm of each other, so every pair overlaps, in a closed box.</summary>
    private static World Crowd(int count)
    {
        var world = new World(Vector3.Zero);
        world.AddPlanes(StaticPlane.Box(new Vector3(-5, -5, -5), new Vector3(5, 5, 5)));
        var random = new Random(7);
        for (int i = 0; i < count; i++)
        {
            var p = new Vector3((float)random.NextDouble(), (float)random.NextDouble(), (float)random.NextDouble()) * 1e-3f;
            world.Add(new RigidBody(1f, 0.1f, p));
        }

        return world;
    }

    private static void AssertTrimmedAfterRemovingAllButTwo(World world, int count)
    {
        int crowdedCapacity = world.Collisions.Capacity;
        Assert.True(crowdedCapacity >= count * (count - 1) / 2, $"capacity {crowdedCapacity}");
        Assert.True(world.BodyCapacity >= count);

        RigidBody[] keep = world.Bodies.Take(2).ToArray();
        foreach (RigidBody body in world.Bodies.Skip(2).ToArray())
        {
            world.Remove(body);
        }

        Assert.Equal(crowdedCapacity, world.Collisions.Capacity); // kept until asked for
        Assert.True(world.Collisions.Count <= 1);
        world.TrimExcess();

        Assert.True(world.Collisions.Capacity <= 1, $"capacity {world.Collisions.Capacity}");
        Assert.Equal(2, world.BodyCapacity);
        Assert.Equal(6, world.PlaneCapacity);
        Assert.Equal(keep, world.Bodies.ToArray());
        Assert.Equal(6, world.Planes.Length);
    }

    [Fact]
    public void CollisionData_TrimExcess_keeps_its_contacts()
    {
        var a = new RigidBody(1f, 1f, Vector3.Zero);
        var b = new RigidBody(1f, 1f, new Vector3(1, 0, 0));
        var collisions = new CollisionData(1000);
        Assert.True(ContactGeometry.TryCollide(a, b, out Contact contact));
        collisions.Add(contact);
        collisions.Add(contact);
        collisions.TrimExcess();
        Assert.Equal(2, collisions.Capacity);
        Assert.Equal(2, collisions.Count);
        Assert.Same(a, collisions[1].BodyA);
        collisions.Clear();
        collisions.TrimExcess();
        Assert.Equal(1, collisions.Capacity);
        collisions.Add(contact);
        collisions.Add(contact);
        Assert.Equal(2, collisions.Count);
    }
}

/// <summary>Tests that weigh the heap: run alone, after the parallel tests.</summary>
[CollectionDefinition(nameof(MemoryMeasurements), DisableParallelization = true)]
public class MemoryMeasurements
{
}
