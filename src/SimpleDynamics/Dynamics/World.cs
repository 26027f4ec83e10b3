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
public sealed partial class World
{
    private RigidBody[] _bodies = new RigidBody[16];
    private int _bodyCount;
    private StaticPlane[] _planes = new StaticPlane[8];
    private int _planeCount;
    private Vector3 _gravity;
    private int _substeps = 4;
    private bool _stepping;
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
    }

    /// <summary>Creates a world with the given gravity and responder.</summary>
    public World(Vector3 gravity, ICollisionResponder? responder = null)
        : this()
    {
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
            _substeps = value;
        }
    }

    /// <summary>
    /// Detection also reports pairs not yet touching whose gap is smaller than this margin (m, ≥ 0, default
    /// 0.01) plus the distance they can travel during the step at their present speeds: speculative contacts,
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
            _detector = value;
        }
    }

    /// <summary>The contacts of the last step, measured at the end of it.</summary>
    public CollisionData Collisions { get; } = new();

    /// <summary>The bodies, in insertion order (a removal moves the last body into the gap).</summary>
    public IReadOnlyList<RigidBody> Bodies { get; }

    /// <summary>The static planes.</summary>
    public ReadOnlySpan<StaticPlane> Planes => _planes.AsSpan(0, _planeCount);

    /// <summary>Simulated time so far (s).</summary>
    public double Time { get; private set; }

    internal ReadOnlySpan<RigidBody> BodySpan => _bodies.AsSpan(0, _bodyCount);

    /// <summary>Adds a body and returns it.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="body"/> is null.</exception>
    /// <exception cref="ArgumentException">The body already belongs to a world.</exception>
    public RigidBody Add(RigidBody body)
    {
        Guard.NotNull(body, nameof(body));
        if (body.World is not null)
        {
            throw new ArgumentException("The body already belongs to a world.", nameof(body));
        }

        if (_bodyCount == _bodies.Length)
        {
            Array.Resize(ref _bodies, _bodies.Length * 2);
        }

        body.index = _bodyCount;
        body.World = this;
        _bodies[_bodyCount++] = body;
        return body;
    }

    /// <summary>Removes a body; returns false if it was not in this world.</summary>
    public bool Remove(RigidBody body)
    {
        Guard.NotNull(body, nameof(body));
        if (body.World != this)
        {
            return false;
        }

        int slot = body.index;
        RigidBody last = _bodies[--_bodyCount];
        _bodies[slot] = last;
        last.index = slot;
        _bodies[_bodyCount] = null!;
        body.index = -1;
        body.World = null;
        return true;
    }

    /// <summary>Adds a static plane (ground or wall).</summary>
    public void AddPlane(StaticPlane plane)
    {
        if (plane.Normal == Vector3.Zero)
        {
            throw new ArgumentException("The plane is uninitialised; create it with a unit normal.", nameof(plane));
        }

        if (_planeCount == _planes.Length)
        {
            Array.Resize(ref _planes, _planes.Length * 2);
        }

        _planes[_planeCount++] = plane;
    }

    /// <summary>Adds several static planes, e.g. the walls of <see cref="StaticPlane.Box"/>.</summary>
    public void AddPlanes(IEnumerable<StaticPlane> planes)
    {
        Guard.NotNull(planes, nameof(planes));
        foreach (StaticPlane plane in planes)
        {
            AddPlane(plane);
        }
    }

    private sealed class BodyList : IReadOnlyList<RigidBody>
    {
        private readonly World _world;

        public BodyList(World world) => _world = world;

        public int Count => _world._bodyCount;

        public RigidBody this[int index] =>
            (uint)index < (uint)_world._bodyCount ? _world._bodies[index] : throw new ArgumentOutOfRangeException(nameof(index));

        public IEnumerator<RigidBody> GetEnumerator()
        {
            for (int i = 0; i < _world._bodyCount; i++)
            {
                yield return _world._bodies[i];
            }
        }

        IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
    }
}
