using System;
using System.Collections;
using System.Collections.Generic;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics;

/// <summary>
/// Holds the bodies and static planes of a scene and steps them in time; <see cref="Step"/> is the pipeline
/// (World.Step.cs). Conventions are those of <see cref="RigidBody"/> (SI units, static = infinite mass) and
/// <see cref="Contact"/> (normal from B to A).
/// </summary>
/// <remarks>
/// <para><b>Mutation rule.</b> Bodies and planes may be added and removed between steps, never during one:
/// <see cref="Add"/>, <see cref="Remove"/>, <see cref="AddPlane"/>, <see cref="AddPlanes"/>,
/// <see cref="TrimExcess"/> and the <see cref="Substeps"/>, <see cref="Responder"/> and <see cref="Detector"/>
/// setters throw <see cref="InvalidOperationException"/> while <see cref="Step"/> runs (from a responder, say).
/// An enumerator of <see cref="Bodies"/> throws <see cref="InvalidOperationException"/> once a body has been
/// added or removed, as <see cref="List{T}"/>'s does: to remove bodies while looking at them, loop over a copy
/// or backwards by index. A removed body is gone from <see cref="Collisions"/> too: no contact names a body
/// that is not in the world.</para>
/// </remarks>
public sealed partial class World
{
    private RigidBody[] _bodies = new RigidBody[InitialBodyCapacity];
    private int _bodyCount;
    private StaticPlane[] _planes = new StaticPlane[8];
    private int _planeCount;
    private Vector3 _gravity;
    private int _substeps = 4;
    private bool _stepping;
    private int _bodiesVersion; // changed by every Add and Remove, so that enumerators of Bodies notice
    private float _contactMargin = 0.01f;
    private ICollisionResponder _responder;
    private ICollisionDetector _detector;

    /// <summary>
    /// Creates an empty world with no gravity, the iterative <see cref="SequentialImpulseSolver"/> as its
    /// responder and the <see cref="SpatialHashDetector"/> as its detector.
    /// </summary>
    public World()
    {
        _responder = new SequentialImpulseSolver();
        _detector = new SpatialHashDetector();
        Bodies = new BodyList(this);
        Collisions = new CollisionData { Owner = this };
    }

    /// <summary>Creates a world with the given gravity (m/s²) and responder (the default solver when null).</summary>
    /// <exception cref="ArgumentException"><paramref name="gravity"/> is not finite.</exception>
    public World(Vector3 gravity, ICollisionResponder? responder = null)
        : this()
    {
        Guard.Finite(gravity, nameof(gravity));
        Gravity = gravity;
        if (responder is not null)
        {
            Responder = responder;
        }
    }

    /// <summary>
    /// The fixed world frame: a static body at the origin that contacts with planes name as body B. It is not
    /// in <see cref="Bodies"/>.
    /// </summary>
    public RigidBody Ground { get; } = RigidBody.CreateGround();

    /// <summary>Gravitational acceleration (m/s²), e.g. (0, −9.81, 0).</summary>
    public Vector3 Gravity
    {
        get => _gravity;
        set
        {
            Guard.Finite(value, nameof(Gravity));
            if (value != _gravity)
            {
                WakeAll(); // a pile at rest under the old gravity is not at rest under the new one
            }

            _gravity = value;
        }
    }

    /// <summary>
    /// How many velocity-and-position substeps one <see cref="Step"/> takes (≥ 1, default 4). Detection runs
    /// once per step. More substeps: stiffer piles and less penetration, at more cost. With 1 the step is the
    /// tutorial's plain loop.
    /// </summary>
    public int Substeps
    {
        get => _substeps;
        set
        {
            Guard.AtLeast(value, 1, nameof(Substeps));
            ThrowIfStepping(nameof(Substeps));
            _substeps = value;
        }
    }

    /// <summary>
    /// Detection also reports pairs not yet touching whose gap is smaller than this margin (m, ≥ 0, default
    /// 0.01) plus what they may close during the step at their present velocities (precisely: whose spheres around
    /// the middles of their paths overlap, see <see cref="ContactGeometry.TryCollide(RigidBody, RigidBody, float, float, out Contact)"/>): speculative contacts,
    /// with negative <see cref="Contact.Penetration"/>. The solver lets such bodies close the gap within a
    /// substep but not overlap, so a contact that begins during a step is caught in the substep where it
    /// begins, not a whole step late and deep. The margin covers what gravity adds during the step.
    /// </summary>
    public float ContactMargin
    {
        get => _contactMargin;
        set
        {
            Guard.NonNegative(value, nameof(ContactMargin));
            _contactMargin = value;
        }
    }

    /// <summary>Answers the contacts of each step.</summary>
    public ICollisionResponder Responder
    {
        get => _responder;
        set
        {
            Guard.NotNull(value, nameof(Responder));
            ThrowIfStepping(nameof(Responder));
            _responder = value;
        }
    }

    /// <summary>Finds overlapping pairs of bodies each step.</summary>
    public ICollisionDetector Detector
    {
        get => _detector;
        set
        {
            Guard.NotNull(value, nameof(Detector));
            ThrowIfStepping(nameof(Detector));
            _detector = value;
        }
    }

    /// <summary>
    /// The contacts of the last step, measured at the end of it, less those naming a body removed since. Sleeping
    /// bodies take no part in a step, so their contacts are not here; their touching pairs stay in
    /// <see cref="ContactEvents"/> (<see cref="Collision.ContactEvents.Touching"/>, <see cref="ContactsOf"/>). Nor are
    /// the pairs of a crowd moving together that never came near each other in the step (see <see cref="Step"/>).
    /// </summary>
    public CollisionData Collisions { get; }

    /// <summary>
    /// The bodies, in insertion order (a removal moves the last body into the gap). Its enumerators throw
    /// <see cref="InvalidOperationException"/> once a body has been added or removed.
    /// </summary>
    public IReadOnlyList<RigidBody> Bodies { get; }

    /// <summary>The static planes.</summary>
    public ReadOnlySpan<StaticPlane> Planes => _planes.AsSpan(0, _planeCount);

    /// <summary>Simulated time so far (s).</summary>
    public double Time { get; private set; }

    /// <summary>The bodies each step works on: the awake ones (all of them while none sleeps), in slots <c>index</c>.</summary>
    internal ReadOnlySpan<RigidBody> BodySpan => AwakeSpan;

    /// <summary>Every body, awake or asleep, in the order of <see cref="Bodies"/>.</summary>
    internal ReadOnlySpan<RigidBody> AllBodies => _bodies.AsSpan(0, _bodyCount);

    /// <summary>Adds a body and returns it.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="body"/> is null.</exception>
    /// <exception cref="ArgumentException">The body already belongs to a world.</exception>
    /// <exception cref="InvalidOperationException">Called during <see cref="Step"/>.</exception>
    public RigidBody Add(RigidBody body)
    {
        Guard.NotNull(body, nameof(body));
        if (body.World is not null)
        {
            throw new ArgumentException("The body already belongs to a world.", nameof(body));
        }

        ThrowIfStepping(nameof(Add));
        Buffers.EnsureCapacity(ref _bodies, _bodyCount + 1);
        body.worldSlot = _bodyCount;
        body.World = this;
        _bodies[_bodyCount++] = body;
        AddAwake(body);
        ReserveSleepBuffers(_bodies.Length);
        _bodiesVersion++;
        return body;
    }

    /// <summary>
    /// Removes a body, and with it every contact in <see cref="Collisions"/> that names it; returns false if it
    /// was not in this world. The last body moves into its slot.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="body"/> is null.</exception>
    /// <exception cref="InvalidOperationException">Called during <see cref="Step"/>.</exception>
    public bool Remove(RigidBody body)
    {
        Guard.NotNull(body, nameof(body));
        ThrowIfStepping(nameof(Remove));
        if (body.World != this)
        {
            return false;
        }

        WakeWhatRestsOn(body);
        RemoveAwake(body);
        int slot = body.worldSlot;
        RigidBody last = _bodies[--_bodyCount];
        _bodies[slot] = last;
        last.worldSlot = slot;
        _bodies[_bodyCount] = null!;
        body.worldSlot = -1;
        body.World = null;
        _bodiesVersion++;
        // The contacts are dropped when Collisions is next read: one pass for however many removals.
        Collisions.MarkBodiesRemoved();
        return true;
    }

    /// <summary>Adds a static plane (ground or wall).</summary>
    /// <exception cref="ArgumentException">The plane is uninitialised (<c>default</c>).</exception>
    /// <exception cref="InvalidOperationException">Called during <see cref="Step"/>.</exception>
    public void AddPlane(StaticPlane plane)
    {
        ValidatePlane(plane, nameof(plane));
        ThrowIfStepping(nameof(AddPlane));
        Buffers.EnsureCapacity(ref _planes, _planeCount + 1);
        _planes[_planeCount++] = plane;
        WakeAll(); // the plane may cut through sleeping bodies
    }

    /// <summary>
    /// Adds several static planes, e.g. the walls of <see cref="StaticPlane.Box"/>: all of them, or, if one is
    /// invalid, none.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="planes"/> is null.</exception>
    /// <exception cref="ArgumentException">A plane is uninitialised (<c>default</c>); none is added.</exception>
    /// <exception cref="InvalidOperationException">Called during <see cref="Step"/>.</exception>
    public void AddPlanes(IEnumerable<StaticPlane> planes)
    {
        Guard.NotNull(planes, nameof(planes));
        ThrowIfStepping(nameof(AddPlanes));
        // Read the sequence once (it may be lazy or single-use), check every plane, then add them all.
        var list = new List<StaticPlane>(planes);
        foreach (StaticPlane plane in list)
        {
            ValidatePlane(plane, nameof(planes));
        }

        Buffers.EnsureCapacity(ref _planes, _planeCount + list.Count);
        list.CopyTo(_planes, _planeCount);
        _planeCount += list.Count;
        WakeAll(); // the planes may cut through sleeping bodies
    }

    private static void ValidatePlane(in StaticPlane plane, string paramName)
    {
        if (plane.Normal == Vector3.Zero)
        {
            throw new ArgumentException("The plane is uninitialised; create it with a unit normal.", paramName);
        }
    }

    private void ThrowIfStepping(string member)
    {
        if (_stepping)
        {
            throw new InvalidOperationException(
                $"World.{member} cannot be used while the world is stepping (from a responder or detector); change the world between steps.");
        }
    }

    private sealed class BodyList : IReadOnlyList<RigidBody>
    {
        private readonly World _world;

        public BodyList(World world) => _world = world;

        public int Count => _world._bodyCount;

        public RigidBody this[int index] =>
            (uint)index < (uint)_world._bodyCount ? _world._bodies[index] : throw new ArgumentOutOfRangeException(nameof(index));

        public IEnumerator<RigidBody> GetEnumerator() => new Enumerator(_world);

        IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
    }

    /// <summary>
    /// Walks the body array, and throws once a body has been added or removed since it began: checked on every
    /// move, after the last item too, as <see cref="List{T}"/>'s enumerator does.
    /// </summary>
    private sealed class Enumerator : IEnumerator<RigidBody>
    {
        private readonly World _world;
        private readonly int _version;
        private int _next;

        public Enumerator(World world)
        {
            _world = world;
            _version = world._bodiesVersion;
        }

        public RigidBody Current { get; private set; } = null!;

        object IEnumerator.Current => Current;

        public bool MoveNext()
        {
            if (_version != _world._bodiesVersion)
            {
                throw new InvalidOperationException("The world's bodies changed (Add or Remove) while they were being enumerated.");
            }

            if (_next < _world._bodyCount)
            {
                Current = _world._bodies[_next++];
                return true;
            }

            Current = null!;
            return false;
        }

        public void Reset()
        {
            if (_version != _world._bodiesVersion)
            {
                throw new InvalidOperationException("The world's bodies changed (Add or Remove) while they were being enumerated.");
            }

            _next = 0;
            Current = null!;
        }

        public void Dispose()
        {
        }
    }

}
