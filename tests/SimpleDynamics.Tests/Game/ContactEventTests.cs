using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using System.Reflection;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Tests.Properties;
using Xunit;

namespace SimpleDynamics.Tests.Game;

/// <summary>Begin/end touch and hit events, and each body's contacts now.</summary>
public class ContactEventTests
{
    [Fact]
    public void A_ball_dropped_on_the_ground_begins_touching_once_and_hits_at_the_speed_of_its_fall()
    {
        const float radius = 0.5f, height = 3f, g = 9.81f;
        var world = new World(new Vector3(0, -g, 0));
        world.AddPlane(new StaticPlane(Vector3.UnitY, Vector3.Zero, restitution: 0f));
        RigidBody ball = world.Add(new RigidBody(1f, radius, new Vector3(0, height, 0)) { Restitution = 0f });
        var begins = new List<ContactEvent>();
        var hits = new List<HitEvent>();
        int ends = 0;
        for (int i = 0; i < 180; i++)
        {
            world.Step(1f / 60f);
            begins.AddRange(world.ContactEvents.BeginTouch.ToArray());
            hits.AddRange(world.ContactEvents.Hits.ToArray());
            ends += world.ContactEvents.EndTouch.Length;
        }

        ContactEvent begin = Assert.Single(begins);
        Assert.Equal(ball, begin.BodyA);
        Assert.Null(begin.BodyB);
        Assert.Equal(0, begin.PlaneIndex);
        Assert.Equal(0, ends);
        HitEvent hit = Assert.Single(hits);
        float expected = MathF.Sqrt(2 * g * (height - radius));
        Assert.InRange(hit.Speed, expected - 0.2f, expected + 0.2f);
        Assert.True(hit.NormalImpulse > 0.9f * expected, $"impulse {hit.NormalImpulse} N·s for a 1 kg ball at {hit.Speed} m/s");
        Assert.Equal(Vector3.UnitY, hit.Normal);
        Assert.InRange(hit.Point.Y, -0.01f, 0.01f);
        Assert.Single(world.ContactEvents.Touching.ToArray());
    }

    [Fact]
    public void A_bouncing_ball_begins_and_ends_touching_with_each_bounce()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        world.AddPlane(new StaticPlane(Vector3.UnitY, Vector3.Zero, restitution: 0.8f));
        world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 3, 0)) { Restitution = 0.8f });
        int begins = 0, ends = 0, hits = 0;
        for (int i = 0; i < 240; i++)
        {
            world.Step(1f / 60f);
            begins += world.ContactEvents.BeginTouch.Length;
            ends += world.ContactEvents.EndTouch.Length;
            hits += world.ContactEvents.Hits.Length;
            Assert.Equal(begins - ends, world.ContactEvents.Touching.Length);
        }

        Assert.True(begins >= 3, $"{begins} begins in 4 s of bouncing");
        Assert.True(hits >= 3 && hits <= begins, $"{hits} hits, {begins} begins");
    }

    [Fact]
    public void Speculative_contacts_of_a_pile_in_free_fall_are_not_touching()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        for (int i = 0; i < 10; i++)
        for (int j = 0; j < 20; j++)
        {
            // 2 mm apart: within the contact margin, so detection reports them as speculative contacts.
            world.Add(new RigidBody(1f, 0.1f, new Vector3(i * 0.202f, j * 0.202f, 0)));
        }

        for (int step = 0; step < 30; step++)
        {
            world.Step(1f / 60f);
            Assert.True(world.Collisions.Count > 200, $"{world.Collisions.Count} speculative contacts expected");
            Assert.Equal(0, world.ContactEvents.Touching.Length);
            Assert.Equal(0, world.ContactEvents.BeginTouch.Length);
            Assert.Equal(0, world.ContactEvents.Hits.Length);
        }
    }

    [Fact]
    public void Contacts_of_a_body_are_listed_allocation_free_and_counted_beyond_the_buffer()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        world.AddPlane(StaticPlane.Ground());
        RigidBody bottom = world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 0.5f, 0)));
        RigidBody top = world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 1.5f, 0)));
        RigidBody aside = world.Add(RigidBody.CreateStatic(0.5f, new Vector3(5, 3f, 0)));
        for (int i = 0; i < 60; i++)
        {
            world.Step(1f / 60f);
        }

        Span<Contact> buffer = new Contact[4];
        long before = GC.GetAllocatedBytesForCurrentThread();
        int ofBottom = world.ContactsOf(bottom, buffer);
        int ofTop = world.ContactsOf(top, buffer[..1]);
        int ofTopCounted = world.ContactsOf(top, Span<Contact>.Empty);
        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
        Assert.Equal(2, ofBottom); // the ground and the top ball
        Assert.Equal(1, ofTop);
        Assert.Equal(1, ofTopCounted);
        Assert.Equal(0, world.ContactsOf(aside, buffer));
        Assert.True(buffer[0].BodyA == top || buffer[0].BodyB == top);

        Span<Contact> one = new Contact[1];
        Assert.Equal(2, world.ContactsOf(bottom, one)); // the count, though only one fits
        Assert.Equal(0, world.ContactsOf(new RigidBody(1, 1, Vector3.Zero), buffer));
        Assert.Throws<ArgumentNullException>("body", () => world.ContactsOf(null!, Span<Contact>.Empty));
        world.Remove(top);
        Assert.Equal(0, world.ContactsOf(top, buffer)); // removed: no contacts now, though the last step had one
    }

    /// <summary>
    /// The event store renews a pair's contact each step without writing its bodies again (Contact.RenewFrom): every
    /// other field must be copied, including any added to <see cref="Contact"/> later.
    /// </summary>
    [Fact]
    public void A_contact_renewed_from_the_same_pair_takes_every_field()
    {
        var a = new RigidBody(1f, 0.5f, Vector3.Zero);
        var b = new RigidBody(2f, 0.5f, Vector3.UnitX);
        object boxed = new Contact(a, b, Vector3.Zero, Vector3.UnitX, 0f);
        float value = 10f;
        FieldInfo[] fields = typeof(Contact).GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic);
        foreach (FieldInfo field in fields.Where(f => f.FieldType != typeof(RigidBody)))
        {
            object distinct = field.FieldType switch
            {
                Type t when t == typeof(float) => value++,
                Type t when t == typeof(float?) => (float?)value++,
                Type t when t == typeof(int) => (int)value++,
                Type t when t == typeof(ulong) => (ulong)value++,
                Type t when t == typeof(Vector3) => new Vector3(value++, value++, value++),
                _ => throw new Xunit.Sdk.XunitException($"Contact.{field.Name} is of a type this test does not fill: {field.FieldType}"),
            };
            field.SetValue(boxed, distinct);
        }

        var source = (Contact)boxed;
        var sameBodies = new Contact(a, b, Vector3.Zero, Vector3.UnitX, 0f);
        var otherBodies = new Contact(b, a, Vector3.Zero, Vector3.UnitX, 0f);
        sameBodies.RenewFrom(source);
        otherBodies.RenewFrom(source);
        foreach (FieldInfo field in fields)
        {
            Assert.Equal(field.GetValue(source), field.GetValue(sameBodies));
            Assert.Equal(field.GetValue(source), field.GetValue(otherBodies));
        }
    }

    [Fact]
    public void Settings_reject_bad_values_and_keep_the_old_ones()
    {
        var world = new World();
        Assert.Throws<ArgumentOutOfRangeException>("TouchTolerance", () => world.TouchTolerance = -1);
        Assert.Throws<ArgumentOutOfRangeException>("TouchTolerance", () => world.TouchTolerance = float.NaN);
        Assert.Throws<ArgumentOutOfRangeException>("HitSpeedThreshold", () => world.HitSpeedThreshold = -0.5f);
        Assert.Throws<ArgumentOutOfRangeException>("HitSpeedThreshold", () => world.HitSpeedThreshold = float.PositiveInfinity);
        Assert.Equal(1e-4f, world.TouchTolerance);
        Assert.Equal(1f, world.HitSpeedThreshold);
    }

    /// <summary>
    /// Over generated runs (filters, sensors, statics and kinematics in a box, bodies removed midway): every end
    /// has an earlier begin, no pair begins twice without ending, the touching set is exactly the begins minus
    /// the ends, and it is exactly the contacts with penetration ≥ −tolerance or a push, each body's listed as this
    /// step measured them.
    /// </summary>
    [Fact]
    public void Begin_and_end_events_balance_and_match_the_touching_contacts()
    {
        int begins = 0, ends = 0;
        PropertyCheck.Run(GameGenerators.Scene(), scene =>
        {
            World world = scene.Build(out RigidBody[] bodies);
            var touching = new HashSet<(int, int)>();
            for (int step = 0; step < 60; step++)
            {
                if (step == 30 && bodies.Length > 2)
                {
                    world.Remove(bodies[0]); // its touches end in the next step's events
                    world.Remove(bodies[^1]);
                }

                world.Step(1f / 60f);
                ContactEvents events = world.ContactEvents;
                begins += events.BeginTouch.Length;
                ends += events.EndTouch.Length;
                foreach (ContactEvent end in events.EndTouch)
                {
                    Law.Holds(touching.Remove(Pairs.Key(end)), $"step {step}: end without begin: {end}");
                }

                foreach (ContactEvent begin in events.BeginTouch)
                {
                    Law.Holds(touching.Add(Pairs.Key(begin)), $"step {step}: begins twice: {begin}");
                }

                var now = new HashSet<(int, int)>();
                foreach (ContactEvent e in events.Touching)
                {
                    now.Add(Pairs.Key(e));
                }

                var expected = new HashSet<(int, int)>();
                foreach (ref readonly Contact c in world.Collisions.Contacts)
                {
                    if (c.Penetration >= -world.TouchTolerance || c.NormalImpulse > 0)
                    {
                        expected.Add(Pairs.Key(c));
                    }
                }

                Law.Holds(touching.SetEquals(now), $"step {step}: begins − ends = {touching.Count} pairs, touching {now.Count}");
                Law.Holds(expected.SetEquals(now), $"step {step}: {expected.Count} contacts touch, {now.Count} reported touching");
                Law.Holds(now.Count == events.Touching.Length, $"step {step}: a pair listed twice");

                // Each body's contacts are the touching pairs that name it, as this step measured them (a pair that
                // touched last step too is listed with this step's contact, every field of it, not last step's).
                var measured = new Dictionary<(int, int), Contact>();
                foreach (ref readonly Contact c in world.Collisions.Contacts)
                {
                    measured.TryAdd(Pairs.Key(c), c);
                }

                foreach (RigidBody body in world.Bodies)
                {
                    int count = world.ContactsOf(body, Span<Contact>.Empty);
                    int listed = events.Touching.ToArray().Count(e => e.Involves(body));
                    Law.Holds(count == listed, $"step {step}: ContactsOf({body}) = {count}, touching pairs naming it {listed}");
                    var contacts = new Contact[count];
                    world.ContactsOf(body, contacts);
                    foreach (Contact c in contacts)
                    {
                        Law.Holds(measured.TryGetValue(Pairs.Key(c), out Contact thisStep) && thisStep.Equals(c),
                            $"step {step}: ContactsOf({body}) lists {Pairs.Key(c)} at depth {c.Penetration}, not as this step measured it");
                    }
                }
            }
        }, seed: 1102, maxTest: 60);
        Assert.True(begins > 200 && ends > 50, $"only {begins} begins and {ends} ends in all: the scenes test too little");
    }
}
