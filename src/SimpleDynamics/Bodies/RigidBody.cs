using System;
using System.Numerics;
using System.Threading;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Bodies;

/// <summary>
/// A rigid body whose shape is a bounding circle (in 2-D, z = 0) or sphere (in 3-D) of <see cref="Radius"/>.
/// </summary>
/// <remarks>
/// <para><b>Units</b> are SI throughout: metres, kilograms, seconds, radians; velocities in m/s and rad/s,
/// impulses in N·s (tutorial eq. 3–4).</para>
/// <para><b>Frames.</b> <see cref="Position"/> is the centre of mass in world coordinates;
/// <see cref="Orientation"/> rotates body coordinates into world coordinates; <see cref="AngularVelocity"/> is
/// in world coordinates. <see cref="Inertia"/> is given in the body frame and rotated into the world frame as
/// <c>I_w⁻¹ = R I⁻¹ Rᵀ</c> for eq. 15–16 (<see cref="InverseInertiaWorld"/>).</para>
/// <para><b>Static</b> means infinite mass: <see cref="InverseMass"/> = 0 and <see cref="InverseInertiaWorld"/> = 0,
/// so no impulse or force moves it, and it never moves at all. A <b>kinematic</b> body also has infinite mass but
/// moves with the velocity you give it.</para>
/// <para><b>Legal ranges.</b> Mass and radius are any positive, finite floats whose derived quantities are
/// finite too: 1/m, the inertia tensor and its inverse (so a mass below about 3·10⁻³⁹ kg, or a tensor such as
/// <c>Matrix3.Diagonal(1, 1, 1e-39f)</c> whose inverse overflows, is rejected). Within masses of 10⁻⁶…10⁶ kg and
/// radii of 10⁻⁴…10⁴ m, in any combination, bodies step without NaN (tested in <c>Robustness/</c>); outside
/// it they are accepted, but float may run out of precision in contacts between very different bodies.
/// Forces, torques and impulses are rejected when the state they would produce (accumulated force or torque,
/// the acceleration they cause, or the new velocities) is not finite.</para>
/// <para>Every method and setter validates its arguments and throws an <see cref="ArgumentException"/> naming
/// the parameter (a setter names its property), leaving the body unchanged.</para>
/// </remarks>
public sealed partial class RigidBody
{
    private static int s_nextId;

    // Fields, not auto-properties: the world's hot path reads and writes them directly.
    internal Vector3 position;

    /// <summary>
    /// The centre in double precision as the impact pass left it (it moves bodies in double precision in a world
    /// without gravity); read it through <see cref="PreciseCentre"/>.
    /// </summary>
    internal Vector3D preciseCentre;
    internal Quaternion orientation = Quaternion.Identity;
    internal Vector3 linearVelocity;
    internal Vector3 angularVelocity;
    internal Vector3 force;
    internal Vector3 torque;
    internal float radius;
    internal float mass;
    internal float inverseMass;
    internal Matrix3 inertia;
    internal Matrix3 inverseInertia;
    internal Matrix3 inverseInertiaWorld;
    internal bool isotropic; // I⁻¹ = k·1 (a solid sphere): every rotation leaves it unchanged
    internal bool symmetricAboutZ; // I⁻¹ = diag(a, a, b) (a disc): a rotation about z leaves it unchanged
    internal float? restitution;
    internal float? friction;

    /// <summary>
    /// The body's slot among the awake bodies its world steps (<see cref="StepContext.Bodies"/>), or -1 when it
    /// sleeps or is in no world; the solver and the impact pass index their working arrays by it.
    /// </summary>
    internal int index = -1;

    /// <summary>
    /// Creates a dynamic body with the inertia of a solid sphere (2/5 m r²). For a 2-D disc pass
    /// <see cref="Bodies.Inertia.Disc"/>; any symmetric positive-definite tensor may be given.
    /// </summary>
    /// <param name="mass">Mass in kg; positive and finite.</param>
    /// <param name="radius">Radius of the bounding circle/sphere in m; positive and finite.</param>
    /// <param name="position">Centre of mass in world coordinates.</param>
    /// <exception cref="ArgumentException">An argument is out of range; the message names it.</exception>
    public RigidBody(float mass, float radius, Vector3 position)
        : this(mass, radius, position, default, useSphereInertia: true)
    {
    }

    /// <summary>Creates a dynamic body with a given body-frame inertia tensor (kg·m²).</summary>
    /// <exception cref="ArgumentException">An argument is out of range; the message names it.</exception>
    public RigidBody(float mass, float radius, Vector3 position, Matrix3 inertia)
        : this(mass, radius, position, inertia, useSphereInertia: false)
    {
    }

    private RigidBody(float mass, float radius, Vector3 position, Matrix3 inertia, bool useSphereInertia)
    {
        float inverse = InverseMassOf(mass);
        Guard.Positive(radius, nameof(radius));
        Guard.Finite(position, nameof(position));
        if (useSphereInertia)
        {
            inertia = Bodies.Inertia.SolidSphere(mass, radius);
        }

        Matrix3 inverseOfInertia = Bodies.Inertia.ValidateAndInvert(inertia, nameof(inertia));
        Id = Interlocked.Increment(ref s_nextId);
        Type = BodyType.Dynamic;
        this.radius = radius;
        this.position = position;
        SetMassValidated(mass, inverse, inertia, inverseOfInertia);
    }

    private RigidBody(BodyType type, float radius, Vector3 position, Vector3 velocity)
    {
        Id = Interlocked.Increment(ref s_nextId);
        Type = type;
        this.radius = radius;
        this.position = position;
        linearVelocity = velocity;
        mass = float.PositiveInfinity;
        inertia = Matrix3.Diagonal(float.PositiveInfinity, float.PositiveInfinity, float.PositiveInfinity);
        // inverseMass, inverseInertia and inverseInertiaWorld stay zero: infinite mass.
    }

    /// <summary>Creates a static body: infinite mass, never moves.</summary>
    /// <exception cref="ArgumentException">An argument is out of range; the message names it.</exception>
    public static RigidBody CreateStatic(float radius, Vector3 position)
    {
        Guard.Positive(radius, nameof(radius));
        Guard.Finite(position, nameof(position));
        return new RigidBody(BodyType.Static, radius, position, Vector3.Zero);
    }

    /// <summary>Creates a kinematic body: infinite mass, moves with <paramref name="velocity"/>.</summary>
    /// <exception cref="ArgumentException">An argument is out of range; the message names it.</exception>
    public static RigidBody CreateKinematic(float radius, Vector3 position, Vector3 velocity)
    {
        Guard.Positive(radius, nameof(radius));
        Guard.Finite(position, nameof(position));
        Guard.Finite(velocity, nameof(velocity));
        return new RigidBody(BodyType.Kinematic, radius, position, velocity);
    }

    /// <summary>The fixed world frame: the static body that contacts with planes name as body B.</summary>
    internal static RigidBody CreateGround() => new(BodyType.Static, 0f, Vector3.Zero, Vector3.Zero);

    /// <summary>A number unique to this body in the process; contact persistence keys pairs by it.</summary>
    public int Id { get; }

    /// <summary>Dynamic, static or kinematic.</summary>
    public BodyType Type { get; }

    /// <summary>True for a dynamic body (finite mass).</summary>
    public bool IsDynamic => Type == BodyType.Dynamic;

    /// <summary>Mass in kg; <see cref="float.PositiveInfinity"/> for static and kinematic bodies.</summary>
    public float Mass => mass;

    /// <summary>1 / mass; 0 for static and kinematic bodies.</summary>
    public float InverseMass => inverseMass;

    /// <summary>Body-frame inertia tensor about the centre of mass (kg·m²).</summary>
    public Matrix3 Inertia => inertia;

    /// <summary>World-frame inverse inertia tensor, R I⁻¹ Rᵀ (eq. 15–16); zero for static and kinematic bodies.</summary>
    public Matrix3 InverseInertiaWorld => inverseInertiaWorld;

    /// <summary>Radius of the bounding circle/sphere (m).</summary>
    public float Radius
    {
        get => radius;
        set
        {
            Guard.Positive(value, nameof(Radius));
            radius = value;
            WakeIfAsleep();
        }
    }

    /// <summary>
    /// The centre as the impact pass last left it, in double precision, while <see cref="Position"/> is still its
    /// rounding; otherwise (a responder or the position pass moved the body since) the float position. Whoever writes
    /// <see cref="position"/> thus replaces the precise centre without having to know of it; the setter of
    /// <see cref="Position"/> replaces it outright, so that setting a body where it already is puts it exactly there.
    /// </summary>
    internal Vector3D PreciseCentre => preciseCentre.Rounded == position ? preciseCentre : new Vector3D(position);

    /// <summary>Centre of mass, world coordinates (m).</summary>
    public Vector3 Position
    {
        get => position;
        set
        {
            Guard.Finite(value, nameof(Position));
            position = value;
            preciseCentre = new Vector3D(value);
            WakeIfAsleep();
        }
    }

    /// <summary>
    /// Rotation from body to world coordinates; normalised when set, so any finite, non-zero quaternion is
    /// accepted (however large or small its components).
    /// </summary>
    /// <exception cref="ArgumentException">The quaternion is zero or not finite; the body is unchanged.</exception>
    public Quaternion Orientation
    {
        get => orientation;
        set
        {
            if (!Vectors.TryNormalize(value, out Quaternion unit))
            {
                throw new ArgumentException($"Orientation must be a finite, non-zero quaternion, but was {value}.", nameof(Orientation));
            }

            orientation = unit;
            UpdateInverseInertiaWorld();
            WakeIfAsleep();
        }
    }

    /// <summary>Velocity of the centre of mass (m/s). A static body's is always zero.</summary>
    /// <exception cref="InvalidOperationException">Setting a non-zero velocity on a static body.</exception>
    public Vector3 LinearVelocity
    {
        get => linearVelocity;
        set
        {
            Guard.Finite(value, nameof(LinearVelocity));
            ThrowIfStaticAndMoving(value, nameof(LinearVelocity));
            linearVelocity = value;
            WakeIfAsleep();
        }
    }

    /// <summary>Angular velocity in world coordinates (rad/s). A static body's is always zero.</summary>
    /// <exception cref="InvalidOperationException">Setting a non-zero angular velocity on a static body.</exception>
    public Vector3 AngularVelocity
    {
        get => angularVelocity;
        set
        {
            Guard.Finite(value, nameof(AngularVelocity));
            ThrowIfStaticAndMoving(value, nameof(AngularVelocity));
            angularVelocity = value;
            WakeIfAsleep();
        }
    }

    /// <summary>
    /// Coefficient of restitution ε ∈ [0, 1] of this body's surface, or null to use the responder's setting.
    /// How two bodies' values combine is set by <see cref="Response.MaterialMixing"/>.
    /// </summary>
    public float? Restitution
    {
        get => restitution;
        set
        {
            if (value is float v)
            {
                Guard.UnitInterval(v, nameof(Restitution));
            }

            restitution = value;
        }
    }

    /// <summary>
    /// Coulomb friction coefficient μ ≥ 0 of this body's surface, or null to use the responder's setting.
    /// </summary>
    public float? Friction
    {
        get => friction;
        set
        {
            if (value is float v)
            {
                Guard.NonNegative(v, nameof(Friction));
            }

            friction = value;
        }
    }

    /// <summary>Force accumulated since the last step (N); cleared by each step.</summary>
    public Vector3 Force => force;

    /// <summary>Torque accumulated since the last step (N·m), world frame; cleared by each step.</summary>
    public Vector3 Torque => torque;

    /// <summary>The world the body belongs to, or null.</summary>
    public World? World { get; internal set; }

    /// <summary>Changes mass and body-frame inertia of a dynamic body.</summary>
    /// <param name="mass">Mass in kg; positive, finite, with a finite inverse.</param>
    /// <param name="inertia">Body-frame inertia tensor (kg·m²), symmetric positive definite with an inverse finite in float.</param>
    /// <exception cref="ArgumentException">An argument is out of range; the body is unchanged.</exception>
    /// <exception cref="InvalidOperationException">The body is not dynamic.</exception>
    public void SetMass(float mass, Matrix3 inertia)
    {
        // Everything that can throw runs before anything is stored.
        float inverse = InverseMassOf(mass);
        Matrix3 inverseOfInertia = Bodies.Inertia.ValidateAndInvert(inertia, nameof(inertia));
        if (!IsDynamic)
        {
            throw new InvalidOperationException($"A {Type} body has infinite mass; only a dynamic body's mass can be set.");
        }

        SetMassValidated(mass, inverse, inertia, inverseOfInertia);
        WakeIfAsleep();
    }

    /// <summary>Velocity of the material point at a world position: v + ω × (p − c) (eq. 12–13).</summary>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite.</exception>
    public Vector3 VelocityAt(Vector3 point)
    {
        Guard.Finite(point, nameof(point));
        return linearVelocity + Vector3.Cross(angularVelocity, point - position);
    }

    /// <summary>Linear momentum m v (kg·m/s); zero for infinite-mass bodies, which the diagnostics leave out.</summary>
    public Vector3 LinearMomentum => IsDynamic ? mass * linearVelocity : Vector3.Zero;

    /// <summary>
    /// Angular momentum about a fixed world point: I_w ω + (c − point) × m v (eq. 11 plus the orbital part);
    /// zero for infinite-mass bodies.
    /// </summary>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite.</exception>
    public Vector3 AngularMomentumAbout(Vector3 point)
    {
        Guard.Finite(point, nameof(point));
        if (!IsDynamic)
        {
            return Vector3.Zero;
        }

        Matrix3 inertiaWorld = inertia.RotatedBy(orientation);
        return inertiaWorld.Transform(angularVelocity) + Vector3.Cross(position - point, mass * linearVelocity);
    }

    /// <summary>Kinetic energy ½ m v² + ½ ωᵀ I_w ω (J); zero for infinite-mass bodies.</summary>
    public float KineticEnergy
    {
        get
        {
            if (!IsDynamic)
            {
                return 0f;
            }

            Matrix3 inertiaWorld = inertia.RotatedBy(orientation);
            return 0.5f * mass * linearVelocity.LengthSquared()
                + 0.5f * Vector3.Dot(angularVelocity, inertiaWorld.Transform(angularVelocity));
        }
    }

    /// <inheritdoc />
    public override string ToString() => $"{Type} body #{Id} at {position}";

    internal void UpdateInverseInertiaWorld()
    {
        if (!IsDynamic)
        {
            return;
        }

        // R I⁻¹ Rᵀ (eq. 15) is I⁻¹ itself when the rotation cannot change it: exactly so, without the rounding of
        // two matrix products, and the case of every sphere and of every disc turning in the plane.
        bool unchanged = isotropic || (symmetricAboutZ && orientation.X == 0 && orientation.Y == 0);
        inverseInertiaWorld = unchanged ? inverseInertia : inverseInertia.RotatedBy(orientation);
    }

    /// <summary>1/m, after checking that m is positive and finite and that 1/m is finite too.</summary>
    private static float InverseMassOf(float mass)
    {
        Guard.Positive(mass, nameof(mass));
        float inverse = 1f / mass;
        if (!float.IsFinite(inverse))
        {
            throw new ArgumentOutOfRangeException(nameof(mass), mass, "mass is so small that its inverse is not finite in float.");
        }

        return inverse;
    }

    private void SetMassValidated(float mass, float inverseMass, Matrix3 inertia, Matrix3 inverseInertia)
    {
        this.mass = mass;
        this.inverseMass = inverseMass;
        this.inertia = inertia;
        this.inverseInertia = inverseInertia;
        symmetricAboutZ = inverseInertia.IsSymmetricAboutZ();
        isotropic = symmetricAboutZ && inverseInertia.M11 == inverseInertia.M33;
        UpdateInverseInertiaWorld();
    }

    private void ThrowIfStaticAndMoving(Vector3 value, string property)
    {
        if (Type == BodyType.Static && value != Vector3.Zero)
        {
            throw new InvalidOperationException($"{property}: a static body never moves; use a kinematic body for one that moves.");
        }
    }
}
