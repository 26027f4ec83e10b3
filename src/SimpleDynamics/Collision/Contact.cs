using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// One contact between two bodies: what the tutorial's §2.1 asks of collision detection — the contact point,
/// the contact normal and the penetration depth.
/// </summary>
/// <remarks>
/// <para><b>Normal convention.</b> <see cref="Normal"/> is a unit vector pointing from body B to body A, the
/// convention of eq. 5: a positive impulse J pushes A along +n and B along −n. The relative normal velocity is
/// <c>(v_pA − v_pB)·n</c> (eq. 13–14); it is negative while the bodies approach. A contact whose relative
/// normal velocity is ≥ 0 is separating or resting and gets no impulse. (Listing 3 of the tutorial writes the
/// separating test with the opposite sign because its normal points the other way.)</para>
/// <para><b>Penetration</b> is measured along the normal: for two circles r_A + r_B − d, for a circle and a
/// plane r − (signed distance of the centre from the plane). Positive means overlapping.</para>
/// <para>Contacts with a <see cref="StaticPlane"/> name <see cref="World.Ground"/> (the fixed world frame) as B.</para>
/// </remarks>
public struct Contact
{
    /// <summary>Body A; the normal points towards it.</summary>
    public RigidBody BodyA;

    /// <summary>Body B; the normal points away from it.</summary>
    public RigidBody BodyB;

    /// <summary>Contact point in world coordinates: the middle of the overlap along the normal.</summary>
    public Vector3 Point;

    /// <summary>Unit contact normal, from B to A.</summary>
    public Vector3 Normal;

    /// <summary>Penetration depth along the normal (m); positive when overlapping.</summary>
    public float Penetration;

    /// <summary>
    /// Relative normal velocity <c>(v_pA − v_pB)·n</c>: when the contact was detected, and at each collision the
    /// velocity with which the bodies meet at their time of impact (the one eq. 9 bounces). Negative: approaching.
    /// </summary>
    public float ApproachVelocity;

    /// <summary>Normal impulse (N·s) the responder applied in the last step, all substeps together; 0 if none.</summary>
    public float NormalImpulse;

    /// <summary>Size of the tangential (friction) impulses (N·s) applied in the last step, all substeps together.</summary>
    public float TangentImpulse;

    /// <summary>Identifies the pair across steps (by the bodies' <see cref="RigidBody.Id"/>, or a body and a plane index), e.g. to keep warm-start impulses.</summary>
    public ulong Key { readonly get; internal set; }

    /// <summary>Index into <see cref="World.Planes"/> when B is the ground of a plane, else −1.</summary>
    public int PlaneIndex { readonly get; internal set; }

    /// <summary>For a plane contact: the plane's offset along the normal.</summary>
    internal float PlaneOffset;

    /// <summary>For a plane contact: the plane's surface restitution, if it sets one.</summary>
    internal float? PlaneRestitution;

    /// <summary>For a plane contact: the plane's surface friction, if it sets one.</summary>
    internal float? PlaneFriction;

    /// <summary>
    /// Becomes a copy of <paramref name="other"/>, writing the bodies only when they differ: a copy of a struct that
    /// holds object references writes each through a GC write barrier, and the event store renews the same pairs'
    /// contacts every step (World.ReportContactEvents; 9 ns of the 15 a contact there took, in the settled 1,000-disc
    /// pit). Every other field is copied (tested by reflection, so that a field added later cannot be left out).
    /// </summary>
    internal void RenewFrom(in Contact other)
    {
        if (!ReferenceEquals(BodyA, other.BodyA) || !ReferenceEquals(BodyB, other.BodyB))
        {
            this = other;
            return;
        }

        Point = other.Point;
        Normal = other.Normal;
        Penetration = other.Penetration;
        ApproachVelocity = other.ApproachVelocity;
        NormalImpulse = other.NormalImpulse;
        TangentImpulse = other.TangentImpulse;
        Key = other.Key;
        PlaneIndex = other.PlaneIndex;
        PlaneOffset = other.PlaneOffset;
        PlaneRestitution = other.PlaneRestitution;
        PlaneFriction = other.PlaneFriction;
    }

    /// <summary>True when body B is the ground of a <see cref="StaticPlane"/>.</summary>
    public readonly bool IsPlaneContact => PlaneIndex >= 0;

    /// <summary>Creates a contact, as a test or a custom detector would.</summary>
    /// <exception cref="System.ArgumentNullException">A body is null.</exception>
    /// <exception cref="System.ArgumentException">The point or normal is not finite, or the penetration is not a finite number.</exception>
    public Contact(RigidBody bodyA, RigidBody bodyB, Vector3 point, Vector3 normal, float penetration)
    {
        Guard.NotNull(bodyA, nameof(bodyA));
        Guard.NotNull(bodyB, nameof(bodyB));
        Guard.Finite(point, nameof(point));
        Guard.Finite(normal, nameof(normal));
        Guard.Finite(penetration, nameof(penetration));
        this = Unchecked(bodyA, bodyB, point, normal, penetration);
    }

    /// <summary>
    /// The same contact without the argument checks, for detection's inner loop, whose values come from bodies the
    /// world has checked (finite positions, positive radii) through <see cref="ContactGeometry.Unchecked"/>.
    /// </summary>
    internal static Contact Unchecked(RigidBody bodyA, RigidBody bodyB, Vector3 point, Vector3 normal, float penetration) => new()
    {
        BodyA = bodyA,
        BodyB = bodyB,
        Point = point,
        Normal = normal,
        Penetration = penetration,
        ApproachVelocity = Vector3.Dot(bodyA.VelocityAt(point) - bodyB.VelocityAt(point), normal),
        Key = PairKey(bodyA.Id, bodyB.Id),
        PlaneIndex = -1,
    };

    /// <summary>Relative velocity of A with respect to B at the contact point, v_pA − v_pB (eq. 13–14).</summary>
    public readonly Vector3 RelativeVelocity => BodyA.VelocityAt(Point) - BodyB.VelocityAt(Point);

    /// <summary>The <see cref="Key"/> of the pair of bodies with these ids (in either order).</summary>
    public static ulong PairKey(int idA, int idB) =>
        idA < idB ? ((ulong)(uint)idA << 32) | (uint)idB : ((ulong)(uint)idB << 32) | (uint)idA;

    /// <summary>The <see cref="Key"/> of a body's contact with plane <paramref name="planeIndex"/>.</summary>
    public static ulong PlaneKey(int bodyId, int planeIndex) =>
        ((ulong)(uint)bodyId << 32) | 0x8000_0000u | (uint)planeIndex;
}
