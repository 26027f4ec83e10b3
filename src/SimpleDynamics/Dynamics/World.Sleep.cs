using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics;

// Sleeping: islands of bodies at rest leave the step until something reaches them.
public sealed partial class World
{
    // The awake bodies, the ones each step works on; body.index is a body's slot here. While nothing sleeps this
    // holds the same bodies in the same order as _bodies, so a world that never sleeps steps exactly as before.
    private RigidBody[] _awake = new RigidBody[16];
    private int _awakeCount;
    private int _sleepingCount;

    private bool _sleepingEnabled = true;
    private float _sleepSpeed = 0.05f;
    private float _timeToSleep = 0.5f;

    private readonly Islands _islands = new();
    private float[] _islandSleepTime = new float[16];
    private bool[] _islandHeld = new bool[16];
    private bool[] _islandMoved = new bool[16];
    private int[] _sleepingIslandOf = new int[16];

    // The sleeping bodies in a grid, so that awake bodies find the ones they reach; rebuilt when the set changes.
    private readonly QueryGrid _sleepGrid = new();
    private RigidBody[] _sleepers = new RigidBody[16];
    private long _sleepVersion;

    // Wakes asked for while a step runs (from a responder, say), done before the next step's detection.
    private RigidBody[] _pendingWakes = new RigidBody[4];
    private int _pendingWakeCount;
    private bool _pendingWakeAll;

    /// <summary>
    /// Whether bodies at rest fall asleep (default true). An island — bodies joined by touching contacts — sleeps
    /// when every body in it has been slower than <see cref="SleepSpeed"/> for <see cref="TimeToSleep"/> and it rests
    /// on something that does not move (a plane, a static body or a kinematic body at rest, pushing on it against
    /// gravity; without gravity nothing sleeps). A sleeping body keeps
    /// its place, has zero velocity and costs nothing per step; an awake body that touches or closes on it, a
    /// force, torque or impulse, setting its position, orientation, velocity, mass, radius, filter or sensor flag,
    /// a moving kinematic body, <see cref="RigidBody.Wake"/> and removing a body it rests on wake its whole island.
    /// Setting false wakes every body.
    /// </summary>
    /// <remarks>
    /// <para><b>Why on by default.</b> Games expect it: Box2D, Bullet, PhysX, Unity and Godot all sleep bodies at rest
    /// unless told not to, and a pile or a floor of balls left awake costs a full step forever, while a sleeping one
    /// costs a constant: a settled pit of 1,000 discs stepped in 0.6 µs asleep against 6.4 ms awake (quick mode,
    /// benchmarks/README.md, "Sleeping"). Every existing test passes with it on: those that time or count an
    /// awake pile turn it off, because their pile would fall asleep.</para>
    /// <para><b>Why it keeps the laws.</b> Only an island resting on something that does not move may sleep, so
    /// bodies in free space never do: a slow cluster drifting through space keeps its momentum and angular momentum
    /// exactly, as the property tests of the laws demand (Box2D, by contrast, stops a slow drifter). Where an island
    /// rests on a support, momentum is not conserved anyway (the support pushes), and sleeping only takes away the
    /// little kinetic energy left, so energy still never rises. A sleeping body's position does not change at all.</para>
    /// </remarks>
    /// <exception cref="InvalidOperationException">Set while the world is stepping.</exception>
    public bool SleepingEnabled
    {
        get => _sleepingEnabled;
        set
        {
            ThrowIfStepping(nameof(SleepingEnabled));
            if (value && !_sleepingEnabled)
            {
                foreach (RigidBody body in AllBodies)
                {
                    body.sleepTime = 0; // rest is timed from now, not from before sleeping was turned off
                }
            }

            _sleepingEnabled = value;
            if (!value)
            {
                WakeAll();
            }
        }
    }

    /// <summary>
    /// The speed (m/s, ≥ 0, default 0.05 as Box2D's) below which a body counts as at rest: the fastest point of its
    /// surface, |v| + |ω| r, must stay at or below it. Box2D's default, for bodies about a metre across; scale it
    /// with the size of your bodies.
    /// </summary>
    public float SleepSpeed
    {
        get => _sleepSpeed;
        set
        {
            Guard.NonNegative(value, nameof(SleepSpeed));
            _sleepSpeed = value;
        }
    }

    /// <summary>
    /// How long (s, &gt; 0, default 0.5 as Box2D's <c>b2_timeToSleep</c>) every body of an island must stay at rest
    /// (see <see cref="SleepSpeed"/>) before the island falls asleep.
    /// </summary>
    public float TimeToSleep
    {
        get => _timeToSleep;
        set
        {
            Guard.Positive(value, nameof(TimeToSleep));
            _timeToSleep = value;
        }
    }

    /// <summary>How many bodies sleep now.</summary>
    public int SleepingBodyCount => _sleepingCount;

    /// <summary>The awake bodies, the ones a step works on.</summary>
    internal ReadOnlySpan<RigidBody> AwakeSpan => _awake.AsSpan(0, _awakeCount);

    /// <summary>
    /// Stage of <see cref="Step"/>, at its end: advances each awake body's sleep timer, and puts to sleep every
    /// island whose bodies have all been at rest for <see cref="TimeToSleep"/> and that rests on something fixed.
    /// </summary>
    /// <remarks>
    /// Islands are found only when some body's timer has run out, by a union-find over the step's contacts that
    /// link two dynamic bodies (<see cref="Links"/>). A contact with a plane, a static body or a kinematic body at
    /// rest marks its island as held; a contact with a moving kinematic body keeps its island awake.
    /// </remarks>
    private void UpdateSleep(float dt)
    {
        if (!_sleepingEnabled)
        {
            return;
        }

        bool anyReady = false;
        for (int i = 0; i < _awakeCount; i++)
        {
            RigidBody body = _awake[i];
            if (!body.IsDynamic)
            {
                continue; // static and kinematic bodies never sleep
            }

            float speed = Vectors.Length(body.linearVelocity) + Vectors.Length(body.angularVelocity) * body.radius;
            if (speed > _sleepSpeed || !body.AllowSleep || body.isSensor)
            {
                body.sleepTime = 0;
            }
            else
            {
                body.sleepTime += dt;
                anyReady |= body.sleepTime >= _timeToSleep;
            }
        }

        // Without gravity no island rests on anything (see Touches), so none can sleep: the search would find nothing.
        if (anyReady && Gravity != Vector3.Zero)
        {
            FindIslandsAndSleep(dt);
        }
    }

    private void FindIslandsAndSleep(float dt)
    {
        int n = _awakeCount;
        _islands.Reset(n);
        Buffers.EnsureCapacity(ref _islandSleepTime, n);
        Buffers.EnsureCapacity(ref _islandHeld, n);
        Buffers.EnsureCapacity(ref _islandMoved, n);
        Buffers.EnsureCapacity(ref _sleepingIslandOf, n);
        Array.Clear(_islandHeld, 0, n);
        Array.Clear(_islandMoved, 0, n);

        // Join the bodies that touch; note which bodies rest on something fixed and which touch something moving.
        foreach (ref readonly Contact contact in Collisions.Contacts)
        {
            if (!Links(contact, dt))
            {
                continue;
            }

            RigidBody a = contact.BodyA, b = contact.BodyB;
            if (a.IsDynamic && b.IsDynamic)
            {
                _islands.Union(a.index, b.index);
            }
            else if (a.IsDynamic)
            {
                Touches(a.index, b, contact.NormalImpulse > 0);
            }
            else if (b.IsDynamic)
            {
                Touches(b.index, a, contact.NormalImpulse > 0);
            }
        }

        // Gather each island's least sleep time and its flags at its root.
        for (int i = 0; i < n; i++)
        {
            _islandSleepTime[i] = float.PositiveInfinity;
            _sleepingIslandOf[i] = -1;
        }

        for (int i = 0; i < n; i++)
        {
            int root = _islands.Find(i);
            RigidBody body = _awake[i];
            float time = body.IsDynamic ? body.sleepTime : float.PositiveInfinity;
            _islandSleepTime[root] = MathF.Min(_islandSleepTime[root], time);
            _islandHeld[root] |= _islandHeld[i];
            _islandMoved[root] |= _islandMoved[i];
        }

        // Put the ready islands to sleep, one sleeping island per root.
        int asleepBefore = _sleepingCount;
        for (int i = 0; i < n; i++)
        {
            RigidBody body = _awake[i];
            int root = _islands.Find(i);
            if (!body.IsDynamic || !_islandHeld[root] || _islandMoved[root] || !(_islandSleepTime[root] >= _timeToSleep))
            {
                continue;
            }

            ref int id = ref _sleepingIslandOf[root];
            if (id < 0)
            {
                id = _islands.NewSleepingIsland(); // the first body of this island met
            }

            PutToSleep(body, id);
        }

        if (_sleepingCount != asleepBefore)
        {
            CompactAwake();
            _sleepVersion++;
            _touchesRegrouped = false;
            RegroupSleepingTouches();
        }
    }

    /// <summary>
    /// Notes that body i's island touches a static or kinematic body (or the ground of a plane): a moving kinematic
    /// body keeps the island awake; a fixed one holds it if it pushed on it in this step and gravity presses the island
    /// onto it. Without gravity nothing rests on anything: a slow ball that touches a wall keeps its motion.
    /// </summary>
    private void Touches(int i, RigidBody fixedOrKinematic, bool pushed)
    {
        bool moves = fixedOrKinematic.Type == BodyType.Kinematic
            && (fixedOrKinematic.linearVelocity != Vector3.Zero || fixedOrKinematic.angularVelocity != Vector3.Zero);
        if (moves)
        {
            _islandMoved[i] = true;
        }
        else if (pushed && Gravity != Vector3.Zero)
        {
            _islandHeld[i] = true; // the ground, a static body or a kinematic body at rest, holding the island up
        }
    }

    private void PutToSleep(RigidBody body, int id)
    {
        _islands.Add(id, body);
        body.linearVelocity = Vector3.Zero;
        body.angularVelocity = Vector3.Zero;
        body.ClearAccumulators();
        _sleepingCount++;
    }

    /// <summary>
    /// Whether a contact joins its bodies into one island: they touch (the contact pushed during the step, or its gap
    /// is within <see cref="TouchTolerance"/>), or they may touch within the next step. The same test decides when an
    /// awake body wakes a sleeping one, so an island never sleeps beside a body that would wake it at once.
    /// </summary>
    private bool Links(in Contact contact, float dt)
    {
        if (contact.NormalImpulse > 0)
        {
            return true;
        }

        float closing = -Vector3.Dot(contact.BodyA.linearVelocity - contact.BodyB.linearVelocity, contact.Normal);
        return MayTouch(contact.Penetration, closing, dt);
    }

    /// <summary>
    /// Whether two spheres with this penetration (negative: a gap) may touch within a step of dt: the gap is no
    /// more than the touch tolerance, plus what they close at <paramref name="closingSpeed"/> (m/s, positive when
    /// approaching), plus the ½ g dt² gravity may add. For spheres only the centres' velocities change the gap.
    /// </summary>
    private bool MayTouch(float penetration, float closingSpeed, float dt) =>
        -penetration <= _touchTolerance + dt * MathF.Max(closingSpeed, 0f) + 0.5f * Gravity.Length() * dt * dt;

    /// <summary>
    /// Grows the per-body arrays of sleeping with the world, when a body is added, so that the step in which a large
    /// island first falls asleep allocates as little as possible.
    /// </summary>
    private void ReserveSleepBuffers(int bodies)
    {
        _islands.Reserve(bodies);
        Buffers.EnsureCapacity(ref _islandSleepTime, bodies);
        Buffers.EnsureCapacity(ref _islandHeld, bodies);
        Buffers.EnsureCapacity(ref _islandMoved, bodies);
        Buffers.EnsureCapacity(ref _sleepingIslandOf, bodies);
        Buffers.EnsureCapacity(ref _sleepers, bodies);
    }

    /// <summary>
    /// Gives back the room of the sleeping arrays beyond <paramref name="bodies"/> bodies (at least the world's):
    /// on <see cref="TrimExcess"/>, and when the body array has shrunk on its own. The island arrays are refilled at
    /// every search for islands, the sleepers' list at every rebuild of their grid; only the record of the sleeping
    /// islands is kept.
    /// </summary>
    private void TrimSleepBuffers(int bodies)
    {
        _islands.TrimExcess(bodies);
        Buffers.Shrink(ref _islandSleepTime, bodies);
        Buffers.Shrink(ref _islandHeld, bodies);
        Buffers.Shrink(ref _islandMoved, bodies);
        Buffers.Shrink(ref _sleepingIslandOf, bodies);
        Buffers.ShrinkTo(ref _sleepers, _sleepingCount, 0);
        Buffers.ShrinkTo(ref _pendingWakes, Math.Max(_pendingWakeCount, 4), _pendingWakeCount);
        _sleepGrid.TrimExcess(); // rebuilt from the sleeping bodies at its next use
    }

    private void AddAwake(RigidBody body)
    {
        Buffers.EnsureCapacity(ref _awake, _awakeCount + 1);
        body.index = _awakeCount;
        _awake[_awakeCount++] = body;
    }

    /// <summary>Takes an awake body out of the step's list; the last awake body moves into its slot, as in <see cref="Remove"/>.</summary>
    private void RemoveAwake(RigidBody body)
    {
        int slot = body.index;
        if (slot < 0)
        {
            return;
        }

        RigidBody last = _awake[--_awakeCount];
        _awake[slot] = last;
        last.index = slot;
        _awake[_awakeCount] = null!;
        body.index = -1;
    }

    /// <summary>Drops the bodies that fell asleep from the awake list, keeping the order of the rest.</summary>
    private void CompactAwake()
    {
        int kept = 0;
        for (int i = 0; i < _awakeCount; i++)
        {
            RigidBody body = _awake[i];
            if (body.IsAwake)
            {
                body.index = kept;
                _awake[kept++] = body;
            }
            else
            {
                body.index = -1;
            }
        }

        Array.Clear(_awake, kept, _awakeCount - kept);
        _awakeCount = kept;
    }
}
