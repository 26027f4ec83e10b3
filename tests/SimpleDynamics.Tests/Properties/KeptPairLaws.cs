using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using FsCheck.Fluent;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Properties;

/// <summary>
/// The spatial hash's kept pairs (a Verlet neighbour list, SpatialHashDetector.KeptPairs.cs): over generated runs of
/// calls on one detector, each call reports exactly the contacts that testing every pair reports
/// (<see cref="BruteForceDetector"/>), bit for bit, whether it built its grid or tested the pairs it kept. Between
/// calls the crowd drifts (not at all, by a hair, or by up to a third of a radius), bodies change speed or size, are
/// added, removed, swapped in the order, replaced by another body in the same place or thrown far away, one or two
/// bodies too large for the grid may be among them, and the margin and lookahead change; between some calls the
/// detector is trimmed, or serves a world of one body.
/// </summary>
public class KeptPairLaws(ITestOutputHelper output)
{
    private const int Calls = 8;

    private enum Change { None, NewVelocities, Grow, Remove, Add, Swap, Replace, Throw, NewMarginAndLookahead, Trim, Alone }

    private sealed record Run(int Count, int Giants, int Seed, float[] Drifts, Change[] Changes)
    {
        public override string ToString() =>
            $"{Count} bodies and {Giants} giants, seed {Seed}; drifts [{string.Join(", ", Drifts)}], changes [{string.Join(", ", Changes)}]";
    }

    private static readonly FsCheck.Gen<Run> Runs =
        from count in Gen.Choose(2, 60)
        from giants in Gen.Elements(0, 0, 0, 0, 1, 2)
        from seed in Gen.Choose(0, int.MaxValue)
        from drifts in Gen.Elements(0f, 0f, 1e-4f, 0.01f, 0.05f, 0.3f).ArrayOf(Calls)
        from changes in Gen.Elements(Enum.GetValues<Change>().Prepend(Change.None).Prepend(Change.None).ToArray()).ArrayOf(Calls)
        select new Run(count, giants, seed, drifts, changes);

    [Fact]
    public void Every_call_reports_exactly_the_contacts_of_every_pair_tested()
    {
        int kept = 0, built = 0, keptWithChangedPairs = 0;
        PropertyCheck.Run(Runs, run =>
        {
            var random = new Random(run.Seed);
            List<RigidBody> bodies = Enumerable.Range(0, run.Count).Select(_ => NewBody(random, run.Count)).ToList();
            for (int giant = 0; giant < run.Giants; giant++) // far more cells than MaxCellsPerBody: tested against every body
            {
                var centre = new Vector3(2f * giant, 0, 0);
                bodies.Insert(random.Next(bodies.Count + 1), giant == 0 ? RigidBody.CreateStatic(4f, centre) : new RigidBody(50f, 4f, centre));
            }

            var detector = new SpatialHashDetector();
            HashSet<(RigidBody, RigidBody)>? previousPairs = null;
            float margin = 0, lookahead = 0;
            for (int call = 0; call < Calls; call++)
            {
                if (call == 0 || run.Changes[call] == Change.NewMarginAndLookahead)
                {
                    margin = 0.02f * random.Next(3);
                    lookahead = random.Next(3) / 60f;
                }

                if (call > 0)
                {
                    Shake(bodies, random, run.Drifts[call], run.Changes[call], run.Count);
                }

                if (run.Changes[call] == Change.Trim)
                {
                    detector.TrimExcess(new World());
                }
                else if (run.Changes[call] == Change.Alone)
                {
                    detector.FindContacts(new[] { bodies[0] }, new CollisionData(capacity: 1));
                }

                RigidBody[] array = bodies.ToArray();
                var found = new CollisionData(capacity: 1);
                var expected = new CollisionData(capacity: 1);
                detector.FindContacts(array, found, margin, lookahead);
                new BruteForceDetector().FindContacts(array, expected, margin, lookahead);

                Dictionary<(RigidBody, RigidBody), Contact> foundByPair = ByPair(found, $"call {call}");
                Dictionary<(RigidBody, RigidBody), Contact> expectedByPair = ByPair(expected, $"call {call} (every pair)");
                string how = detector.LastCallKeptPairs ? "kept pairs" : "grid built";
                Law.Holds(foundByPair.Count == expectedByPair.Count && expectedByPair.Keys.All(foundByPair.ContainsKey),
                    $"call {call} ({how}): {foundByPair.Count} contacts, every pair tested gives {expectedByPair.Count}; " +
                    $"missing {Describe(array, expectedByPair.Keys.Except(foundByPair.Keys))}, extra {Describe(array, foundByPair.Keys.Except(expectedByPair.Keys))}");
                foreach (((RigidBody, RigidBody) pair, Contact contact) in expectedByPair)
                {
                    Contact other = foundByPair[pair];
                    Law.Holds(Same(contact, other), $"call {call} ({how}): pair {Describe(array, new[] { pair })} differs: {other.Point} {other.Normal} {other.Penetration} against {contact.Point} {contact.Normal} {contact.Penetration}");
                }

                var pairs = foundByPair.Keys.ToHashSet();
                if (detector.LastCallKeptPairs)
                {
                    kept++;
                    keptWithChangedPairs += previousPairs is not null && !pairs.SetEquals(previousPairs) ? 1 : 0;
                }
                else
                {
                    built++;
                }

                previousPairs = pairs;
            }
        }, seed: 1301, maxTest: 300);

        output.WriteLine($"{kept} calls kept their pairs ({keptWithChangedPairs} of them with other contacts than the call before), {built} built the grid");
        // Both ways must have been taken often, and the kept pairs must have been tested, not replayed: some calls that
        // kept them reported other pairs than the call before.
        Assert.True(kept >= 300 && built >= 300, $"{kept} calls kept their pairs, {built} built the grid");
        Assert.True(keptWithChangedPairs >= 30, $"only {keptWithChangedPairs} calls kept their pairs while contacts came or went");
    }

    /// <summary>
    /// The skins at their edge: two balls of 0.1 m whose grown spheres (0.125 m) just miss each other are not kept as a
    /// pair. Each may come 24.9 mm closer and the pairs still hold (they cannot touch yet: 0.2504 − 0.0498 &gt; 0.2);
    /// each coming 0.5 mm further than that leaves its grown sphere, the grid is built again, and their contact is found.
    /// </summary>
    [Fact]
    public void Balls_that_leave_their_skins_by_a_hair_are_found_when_they_touch()
    {
        foreach (float beyond in new[] { 0f, 0.0005f })
        {
            var a = new RigidBody(1f, 0.1f, new Vector3(3, 0, 0));
            var b = new RigidBody(1f, 0.1f, new Vector3(3.2504f, 0, 0));
            var far = new RigidBody(1f, 0.1f, new Vector3(8, 0, 0));
            RigidBody[] bodies = { a, b, far };
            var detector = new SpatialHashDetector();
            var collisions = new CollisionData();
            detector.FindContacts(bodies, collisions);
            Assert.Equal(0, collisions.Count);

            float step = 0.0249f + beyond;
            a.Position += new Vector3(step, 0, 0);
            b.Position -= new Vector3(step, 0, 0);
            collisions.Clear();
            detector.FindContacts(bodies, collisions);
            Assert.Equal(beyond == 0, detector.LastCallKeptPairs);
            Assert.Equal(beyond == 0 ? 0 : 1, collisions.Count);
        }
    }

    /// <summary>
    /// A game's collision filter that throws while the grid is being built leaves no half-kept pairs behind: the body
    /// that made it throw is taken out again, every other body lies where it was, and the next steps detect as a fresh
    /// detector does (a partial list trusted as whole would miss pairs, or read past the bodies).
    /// </summary>
    [Fact]
    public void A_build_cut_short_by_a_throwing_filter_leaves_no_kept_pairs_behind()
    {
        World world = SimpleDynamics.Scenes.BallPit(200, planar: true);
        world.SleepingEnabled = false;
        for (int i = 0; i < 240; i++)
        {
            world.Step(1f / 60f);
        }

        var detector = (SpatialHashDetector)world.Detector;
        Assert.True(detector.LastCallKeptPairs, "the settled pit keeps its pairs");
        RigidBody intruder = world.Add(new RigidBody(1f, 0.1f, world.Bodies[100].Position + new Vector3(0.05f, 0, 0)));
        world.ShouldCollide = (a, b) => a == intruder || b == intruder ? throw new InvalidOperationException("the game's filter failed") : true;
        Assert.Throws<InvalidOperationException>(() => world.Step(1f / 60f));
        world.ShouldCollide = null;
        world.Remove(intruder);
        for (int i = 0; i < 3; i++)
        {
            world.Step(1f / 60f); // would throw, or miss pairs, with the partial list kept
            var expected = new CollisionData();
            new SpatialHashDetector().FindContacts(world.Bodies.ToArray(), expected);
            var found = new CollisionData();
            detector.FindContacts(world.Bodies.ToArray(), found);
            Assert.Equal(expected.Count, found.Count);
        }
    }

    /// <summary>A ball in a crowd about as wide as the balls' total width laid in a square (so most touch a few others).</summary>
    private static RigidBody NewBody(Random random, int count)
    {
        float radius = 0.05f + 0.25f * random.NextSingle();
        float side = 0.35f * MathF.Sqrt(count);
        var position = new Vector3(side * random.NextSingle(), side * random.NextSingle(), random.Next(2) == 0 ? 0 : 0.3f * random.NextSingle());
        Vector3 velocity = random.Next(3) == 0 ? Vector3.Zero : RandomVector(random, 2f);
        return random.Next(10) switch
        {
            0 => RigidBody.CreateStatic(radius, position),
            1 => RigidBody.CreateKinematic(radius, position, velocity),
            _ => new RigidBody(1f, radius, position) { LinearVelocity = velocity },
        };
    }

    private static void Shake(List<RigidBody> bodies, Random random, float drift, Change change, int count)
    {
        foreach (RigidBody body in bodies)
        {
            body.Position += RandomVector(random, drift * body.Radius);
        }

        int at = random.Next(bodies.Count);
        switch (change)
        {
            case Change.NewVelocities:
                foreach (RigidBody body in bodies.Where(b => b.IsDynamic))
                {
                    body.LinearVelocity = RandomVector(random, 3f);
                }

                break;
            case Change.Grow:
                bodies[at].Radius *= 0.5f + 1.5f * random.NextSingle();
                break;
            case Change.Remove when bodies.Count > 2:
                bodies.RemoveAt(at);
                break;
            case Change.Add:
                bodies.Insert(at, NewBody(random, count));
                break;
            case Change.Swap:
                int other = random.Next(bodies.Count);
                (bodies[at], bodies[other]) = (bodies[other], bodies[at]);
                break;
            case Change.Replace: // another body in the same place, with the same sphere
                RigidBody old = bodies[at];
                bodies[at] = old.IsDynamic
                    ? new RigidBody(2f, old.Radius, old.Position) { LinearVelocity = old.LinearVelocity }
                    : RigidBody.CreateKinematic(old.Radius, old.Position, old.LinearVelocity);
                break;
            case Change.Throw:
                bodies[at].Position = RandomVector(random, 1e3f);
                break;
        }
    }

    private static Vector3 RandomVector(Random random, float scale) =>
        scale * new Vector3(2 * random.NextSingle() - 1, 2 * random.NextSingle() - 1, 2 * random.NextSingle() - 1);

    private static Dictionary<(RigidBody, RigidBody), Contact> ByPair(CollisionData collisions, string what)
    {
        var byPair = new Dictionary<(RigidBody, RigidBody), Contact>();
        foreach (Contact contact in collisions.Contacts)
        {
            Law.Holds(byPair.TryAdd((contact.BodyA, contact.BodyB), contact), $"{what}: a pair reported twice");
        }

        return byPair;
    }

    private static bool Same(Contact a, Contact b) =>
        a.Point.Equals(b.Point) && a.Normal.Equals(b.Normal) && a.Penetration.Equals(b.Penetration) && a.Key == b.Key
        && a.PlaneIndex == b.PlaneIndex && a.NormalImpulse.Equals(b.NormalImpulse) && a.ApproachVelocity.Equals(b.ApproachVelocity);

    private static string Describe(RigidBody[] bodies, IEnumerable<(RigidBody, RigidBody)> pairs) =>
        "[" + string.Join(", ", pairs.Select(p => $"({Array.IndexOf(bodies, p.Item1)}, {Array.IndexOf(bodies, p.Item2)})")) + "]";
}
