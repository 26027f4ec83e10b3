using System;
using System.Numerics;
using System.Threading;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics;

// Contact and sensor events: what began, ended and struck in the last step, and each body's contacts now.
public sealed partial class World
{
    // Each event pass takes a number unique in the process, so a body's touchStamp says which world's pass (and
    // which step) its firstTouch belongs to, even after it moves to another world.
    private static long s_lastTouchStamp;

    private const int InitialTouchCapacity = 16;

    private readonly ContactEvents _contactEvents = new();
    private readonly PairOrder _previousTouch = new(); // the awake pairs touching after the step before, in order
    private ContactEvent[] _previousPairs = Array.Empty<ContactEvent>(); // by position in _previousTouch
    private bool[] _stillTouching = Array.Empty<bool>(); // by position in _previousTouch: found again this step
    private PairSet<SensorEvent> _previousSensor = new();

    // The touching contacts, in the order of ContactEvents.Touching: first the held pairs of sleeping bodies, then
    // the pairs of awake bodies found in the last step. Each body's touching contacts form a linked list through
    // _nextTouch (node 2k for body A of contact k, 2k + 1 for body B): an awake body's list, rebuilt every step,
    // starts at firstTouch; a sleeping body's, rebuilt when bodies fall asleep or wake, at firstSleepTouch.
    private Contact[] _touchContacts = new Contact[InitialTouchCapacity];
    private int _touchContactsUsed;
    private int[] _nextTouch = new int[2 * InitialTouchCapacity];
    private long _touchStamp;
    private long _sleepTouchStamp;
    private bool _touchesRegrouped = true;
    private bool _awakeTouchesLinked = true; // the awake bodies' lists match the touching pairs (LinkAwakeTouches)
    private readonly object _touchLinkGate = new();
    private int[] _touchOrder = new int[InitialTouchCapacity];
    private Contact[] _spareTouchContacts = new Contact[InitialTouchCapacity];
    private ShrinkPolicy _touchRoom;

    private float _touchTolerance = 1e-4f;
    private float _hitSpeedThreshold = 1f;

    /// <summary>Begin/end touch, hit and sensor events of the last step, and the pairs touching now.</summary>
    public ContactEvents ContactEvents => _contactEvents;

    /// <summary>
    /// A pair touches when its contact's <see cref="Contact.Penetration"/> at the end of the step is at least
    /// −TouchTolerance (m, ≥ 0, default 1e-4), or when the responder pushed it during the step
    /// (<see cref="Contact.NormalImpulse"/> &gt; 0). A resting pair overlaps slightly and touches; a ball that
    /// bounces within one step was pushed and touched; a speculative pair, merely close, does not touch.
    /// </summary>
    public float TouchTolerance
    {
        get => _touchTolerance;
        set
        {
            Guard.NonNegative(value, nameof(TouchTolerance));
            _touchTolerance = value;
        }
    }

    /// <summary>
    /// The least approach speed (m/s, ≥ 0, default 1) of a contact the responder pushed for it to be reported
    /// in <see cref="ContactEvents.Hits"/>. A body resting on another approaches at about g·dt (0.16 m/s at
    /// 60 Hz), so the default reports impacts, not resting.
    /// </summary>
    public float HitSpeedThreshold
    {
        get => _hitSpeedThreshold;
        set
        {
            Guard.NonNegative(value, nameof(HitSpeedThreshold));
            _hitSpeedThreshold = value;
        }
    }

    /// <summary>
    /// Copies the contacts <paramref name="body"/> touches at the end of the last step into
    /// <paramref name="contacts"/> (as many as fit) and returns how many there are, so a caller can pass an
    /// empty span to count them, or a larger buffer when the count exceeds the one given. Allocates nothing.
    /// </summary>
    /// <remarks>
    /// The contacts are copies of those in <see cref="Collisions"/> (for a sleeping body, of the step it fell
    /// asleep in); the body may be either
    /// <see cref="Contact.BodyA"/> or <see cref="Contact.BodyB"/>, and the normal points from B to A, so flip
    /// it when the body is B. A body added since the last step, or not in this world, has none.
    /// </remarks>
    /// <exception cref="ArgumentNullException"><paramref name="body"/> is null.</exception>
    public int ContactsOf(RigidBody body, Span<Contact> contacts)
    {
        Guard.NotNull(body, nameof(body));
        if (body.World != this)
        {
            return 0;
        }

        LinkAwakeTouches();

        // A static body may touch both awake and sleeping bodies; any other body is on one list only.
        int count = 0;
        if (_touchStamp != 0 && body.touchStamp == _touchStamp)
        {
            count = CopyTouches(body.firstTouch, contacts, count);
        }

        if (_sleepTouchStamp != 0 && body.sleepTouchStamp == _sleepTouchStamp)
        {
            count = CopyTouches(body.firstSleepTouch, contacts, count);
        }

        return count;
    }

    private int CopyTouches(int first, Span<Contact> contacts, int count)
    {
        for (int node = first; node >= 0; node = _nextTouch[node])
        {
            if (count < contacts.Length)
            {
                contacts[count] = _touchContacts[node >> 1];
            }

            count++;
        }

        return count;
    }

    /// <summary>
    /// Called once at the end of <see cref="Step"/>: which pairs touch now, compared with last step's set
    /// (begin and end), which struck (hits), and which bodies overlap sensors.
    /// </summary>
    private void ReportContactEvents()
    {
        _queryVersion++; // the bodies have moved: the query grid must be rebuilt
        RegroupSleepingTouches(); // the touches of islands the impact pass woke during the step are no longer held
        ContactEvents events = _contactEvents;
        events.Clear();

        // This step's pairs are added after the held ones (the pairs of sleeping bodies, which stay as they are, unseen,
        // so a pile that sleeps costs nothing here and neither ends nor begins touching). Those that come in last
        // step's order, at last step's places, are kept where they are (only their items are renewed): each touched
        // last step too, and begins nothing. The first pair out of place lists last step's awake pairs as "previous"
        // (PairOrder; those found so far marked still touching), drops them from the set after the ones found, and from
        // there on pairs are added by key and looked up among the previous. A settled pile keeps every pair in place:
        // its step lists nothing, and its set's table is neither emptied nor filled again.
        PairSet<ContactEvent> touching = events.Touch;
        int held = touching.HeldCount, lastCount = touching.Count;
        PairOrder previous = _previousTouch;
        previous.Begin(lastCount - held); // every step, for its shrink policy; filled only when a pair is out of place
        previous.Fit(ref _previousPairs);
        previous.Fit(ref _stillTouching);
        ReadOnlySpan<ContactEvent> lastPairs = touching.Items; // read only while every pair is in place
        int inPlace = held; // this step's pairs so far, all at last step's places
        bool inOrder = true;
        foreach (ref readonly Contact contact in Collisions.Contacts)
        {
            bool isPlane = contact.IsPlaneContact;
            RigidBody? bodyB = isPlane ? null : contact.BodyB;
            int planeIndex = isPlane ? contact.PlaneIndex : -1;
            if (contact.NormalImpulse > 0 && -contact.ApproachVelocity >= _hitSpeedThreshold)
            {
                events.AddHit(new HitEvent(contact, bodyB, planeIndex));
            }

            // A pair touches if it overlaps at the end of the step, or if the responder pushed it during the
            // step: a ball that bounces within one step never ends a step overlapping, yet it touched.
            if (contact.Penetration < -_touchTolerance && !(contact.NormalImpulse > 0))
            {
                continue; // speculative: close, never touched
            }

            if (inOrder && inPlace < lastCount && lastPairs[inPlace].Is(contact.BodyA, bodyB, planeIndex))
            {
                _touchContacts[inPlace++].RenewFrom(contact); // stored last step with these bodies (as long as the pairs)
                continue;
            }

            ulong key = isPlane
                ? PairSet<ContactEvent>.PlanePairKey(contact.BodyA.Id, planeIndex)
                : PairSet<ContactEvent>.BodyPairKey(contact.BodyA.Id, bodyB!.Id);
            var pair = new ContactEvent(contact.BodyA, bodyB, planeIndex);
            if (inOrder && touching.TryRenew(inPlace, key, pair))
            {
                _touchContacts[inPlace++] = contact; // the bodies the other way round
                continue;
            }

            if (inOrder)
            {
                ListPreviousTouches(touching, inPlace, lastCount);
                touching.TruncateTo(inPlace);
                inOrder = false;
            }

            if (!touching.Add(key, pair))
            {
                continue;
            }

            int index = touching.Count - 1;
            Buffers.EnsureCapacity(ref _touchContacts, index + 1);
            _touchContacts[index] = contact;
            int before = previous.Find(index - held, key);
            if (before < 0)
            {
                events.AddBegin(pair);
            }
            else
            {
                _stillTouching[before] = true;
            }
        }

        if (inOrder)
        {
            // Last step's pairs after the last found in place touch no more.
            ReadOnlySpan<ContactEvent> ended = touching.Items;
            for (int i = inPlace; i < lastCount; i++)
            {
                events.AddEnd(ended[i]);
            }

            touching.TruncateTo(inPlace);
        }
        else
        {
            for (int i = 0; i < previous.Count; i++)
            {
                if (!_stillTouching[i])
                {
                    events.AddEnd(_previousPairs[i]);
                }
            }

            Array.Clear(_previousPairs, 0, previous.Count); // no references to bodies that may be removed
        }

        ForgetEarlierTouches(touching);
        ReportSensorOverlaps(events);

        // The scratch of RegroupSleepingTouches grows with the touching pairs, here, rather than in the step in
        // which a large island first falls asleep.
        Buffers.EnsureCapacity(ref _touchOrder, touching.Count);
        Buffers.EnsureCapacity(ref _spareTouchContacts, _touchContacts.Length);
        touching.ReserveSpare();
    }

    /// <summary>
    /// Lists last step's awake touching pairs (<paramref name="touching"/>'s items from its held ones up to
    /// <paramref name="lastCount"/>) as "previous", in their order: those before <paramref name="found"/> were found
    /// again at their places this step, and are still touching.
    /// </summary>
    private void ListPreviousTouches(PairSet<ContactEvent> touching, int found, int lastCount)
    {
        PairOrder previous = _previousTouch;
        ReadOnlySpan<ContactEvent> items = touching.Items;
        for (int i = touching.HeldCount; i < lastCount; i++)
        {
            int position = previous.Add(touching.KeyAt(i));
            _previousPairs[position] = items[i];
            _stillTouching[position] = i < found;
        }
    }

    /// <summary>
    /// After the touching pairs changed: drops references to bodies of earlier steps, so that removed bodies can be
    /// collected, and leaves the awake bodies' lists to be linked again when <see cref="ContactsOf"/> first needs them.
    /// </summary>
    private void ForgetEarlierTouches(PairSet<ContactEvent> touching)
    {
        if (_touchContactsUsed > touching.Count)
        {
            Array.Clear(_touchContacts, touching.Count, _touchContactsUsed - touching.Count);
        }

        _touchContactsUsed = touching.Count;
        Buffers.EnsureCapacity(ref _nextTouch, 2 * touching.Count); // here, so that ContactsOf allocates nothing
        Volatile.Write(ref _awakeTouchesLinked, false);
    }

    /// <summary>
    /// Threads each awake body's touching contacts into a list that <see cref="ContactsOf"/> walks, once after each
    /// change of the touching pairs: a step of a game that never asks pays nothing for it (at 16,000 discs the links
    /// write to every body, 0.4 ms a step). Callers on several threads at once link once, under a lock.
    /// </summary>
    private void LinkAwakeTouches()
    {
        if (Volatile.Read(ref _awakeTouchesLinked))
        {
            return;
        }

        lock (_touchLinkGate)
        {
            if (_awakeTouchesLinked)
            {
                return;
            }

            PairSet<ContactEvent> touching = _contactEvents.Touch;
            _touchStamp = Interlocked.Increment(ref s_lastTouchStamp);
            ReadOnlySpan<ContactEvent> pairs = touching.Items;

            // Backwards, so that each list comes out in the order of the contacts.
            for (int k = pairs.Length - 1; k >= touching.HeldCount; k--)
            {
                Link(pairs[k].BodyA, 2 * k);
                if (pairs[k].BodyB is RigidBody bodyB)
                {
                    Link(bodyB, 2 * k + 1);
                }
            }

            Volatile.Write(ref _awakeTouchesLinked, true);
        }
    }

    private void Link(RigidBody body, int node)
    {
        if (body.touchStamp != _touchStamp)
        {
            body.touchStamp = _touchStamp;
            body.firstTouch = -1;
        }

        _nextTouch[node] = body.firstTouch;
        body.firstTouch = node;
    }

    /// <summary>
    /// After bodies fell asleep or woke: puts the touching pairs with a sleeping body first and holds them (they
    /// stay touching, unseen, while their bodies sleep), the rest after, and links both kinds to their bodies again.
    /// Costs one pass over the touching pairs, only when the set of sleeping bodies changed.
    /// </summary>
    private void RegroupSleepingTouches()
    {
        if (_touchesRegrouped)
        {
            return;
        }

        _touchesRegrouped = true;
        PairSet<ContactEvent> touching = _contactEvents.Touch;
        ReadOnlySpan<ContactEvent> pairs = touching.Items;
        int count = pairs.Length, held = 0;
        Buffers.EnsureCapacity(ref _touchOrder, count);
        for (int k = 0; k < count; k++)
        {
            if (!pairs[k].BodyA.IsAwake || pairs[k].BodyB is { IsAwake: false })
            {
                _touchOrder[held++] = k;
            }
        }

        int next = held;
        for (int k = 0; k < count; k++)
        {
            if (pairs[k].BodyA.IsAwake && pairs[k].BodyB is null or { IsAwake: true })
            {
                _touchOrder[next++] = k;
            }
        }

        touching.Permute(_touchOrder.AsSpan(0, count), held);
        Buffers.EnsureCapacity(ref _spareTouchContacts, _touchContacts.Length); // as long, so the swap never shrinks
        for (int k = 0; k < count; k++)
        {
            _spareTouchContacts[k] = _touchContacts[_touchOrder[k]];
        }

        (_touchContacts, _spareTouchContacts) = (_spareTouchContacts, _touchContacts);
        Array.Clear(_spareTouchContacts, 0, Math.Max(count, _touchContactsUsed));
        if (_touchContactsUsed > count)
        {
            Array.Clear(_touchContacts, count, _touchContactsUsed - count);
        }

        _touchContactsUsed = count;

        // The held pairs' lists, backwards so that each comes out in order; then the awake pairs' lists.
        _sleepTouchStamp = Interlocked.Increment(ref s_lastTouchStamp);
        Buffers.EnsureCapacity(ref _nextTouch, 2 * count);
        pairs = touching.Items;
        for (int k = held - 1; k >= 0; k--)
        {
            LinkAsleep(pairs[k].BodyA, 2 * k);
            if (pairs[k].BodyB is RigidBody bodyB)
            {
                LinkAsleep(bodyB, 2 * k + 1);
            }
        }

        ForgetEarlierTouches(touching);
    }

    private void LinkAsleep(RigidBody body, int node)
    {
        if (body.sleepTouchStamp != _sleepTouchStamp)
        {
            body.sleepTouchStamp = _sleepTouchStamp;
            body.firstSleepTouch = -1;
        }

        _nextTouch[node] = body.firstSleepTouch;
        body.firstSleepTouch = node;
    }

    /// <summary>
    /// Finds, through the query grid, the bodies overlapping each sensor (d &lt; r_sensor + r_body) and reports
    /// the changes since the last step.
    /// </summary>
    private void ReportSensorOverlaps(ContactEvents events)
    {
        PairSet<SensorEvent> previous = events.Sensor;
        PairSet<SensorEvent> overlapping = _previousSensor;
        overlapping.Clear();
        events.Sensor = overlapping;
        _previousSensor = previous;

        QueryGrid? grid = null;
        foreach (RigidBody sensor in BodySpan)
        {
            if (!sensor.isSensor)
            {
                continue;
            }

            grid ??= CurrentQueryGrid();
            float r = sensor.radius;
            grid.GatherBox(sensor.position - new Vector3(r), sensor.position + new Vector3(r));
            foreach (int slot in grid.Candidates)
            {
                RigidBody visitor = grid.BodyAt(slot);
                if (visitor == sensor || visitor.isSensor || visitor.World != this
                    || !CollisionFilter.ShouldCollide(sensor.filter, visitor.filter))
                {
                    continue;
                }

                float reach = r + visitor.radius;
                if (Vector3.DistanceSquared(sensor.position, visitor.position) >= reach * reach)
                {
                    continue;
                }

                ulong key = PairSet<SensorEvent>.BodyPairKey(sensor.Id, visitor.Id);
                var overlap = new SensorEvent(sensor, visitor);
                if (overlapping.Add(key, overlap) && !previous.Contains(key))
                {
                    events.AddSensorBegin(overlap);
                }
            }
        }

        ReadOnlySpan<SensorEvent> before = previous.Items;
        for (int i = 0; i < before.Length; i++)
        {
            if (!overlapping.Contains(previous.KeyAt(i)))
            {
                events.AddSensorEnd(before[i]);
            }
        }
    }

    /// <summary>
    /// Applies the <see cref="ShrinkPolicy"/> to the event buffers after each step, keeping what
    /// <see cref="ContactEvents"/> and <see cref="ContactsOf"/> read until the next step. Last step's sets
    /// (the previous touch and sensor sets) are emptied at the next step, but their size follows their use all the same.
    /// </summary>
    private void ShrinkIdleEventBuffers()
    {
        int touching = _contactEvents.Touch.Count;
        int room = _touchRoom.Observe(touching, _touchContacts.Length, InitialTouchCapacity);
        if (room > 0)
        {
            Buffers.ShrinkTo(ref _touchContacts, room, touching);
            Buffers.ShrinkTo(ref _nextTouch, 2 * room, 2 * touching);
            Buffers.ShrinkTo(ref _spareTouchContacts, room, 0);
            Buffers.ShrinkTo(ref _touchOrder, room, 0);
        }

        _contactEvents.ShrinkIfIdle();
        _previousSensor.ShrinkIfIdle();
    }

    /// <summary>Gives back the spare room of the event buffers (<see cref="TrimExcess"/>), keeping what is read until the next step.</summary>
    private void TrimEventBuffers()
    {
        int touching = _contactEvents.Touch.Count;
        Buffers.Shrink(ref _touchContacts, Math.Max(touching, InitialTouchCapacity));
        Buffers.Shrink(ref _nextTouch, 2 * Math.Max(touching, InitialTouchCapacity));
        Buffers.Shrink(ref _spareTouchContacts, Math.Max(touching, InitialTouchCapacity));
        Buffers.Shrink(ref _touchOrder, Math.Max(touching, InitialTouchCapacity));
        _contactEvents.TrimExcess();
        _previousTouch.Clear();
        _previousTouch.TrimExcess();
        _previousPairs = Array.Empty<ContactEvent>();
        _stillTouching = Array.Empty<bool>();
        _previousSensor.Clear();
        _previousSensor.TrimExcess();
    }
}
