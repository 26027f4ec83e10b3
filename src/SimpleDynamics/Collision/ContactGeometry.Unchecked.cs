using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using SimpleDynamics.Bodies;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Collision;

public static partial class ContactGeometry
{
    /// <summary>
    /// The same functions without argument checks, for the library's hot path: detection, the impact pass and the
    /// solver call them per pair or per contact and substep with values the world has already checked (finite
    /// positions, positive radii, unit plane normals), so checking them again there would only cost time. The public
    /// functions check their arguments and call these.
    /// </summary>
    internal static class Unchecked
    {
        /// <summary>
        /// Penetration of two circles along the line of centres, r_A + r_B − d, and the unit normal from B to A.
        /// Coincident centres (d below about 1e-6 of the radii) get the defined normal +y, never NaN.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] // per contact and substep in the solver's measuring loop
        public static float CirclePenetration(Vector3 centreA, float radiusA, Vector3 centreB, float radiusB, out Vector3 normal)
        {
            Vector3 delta = centreA - centreB;
            float distanceSquared = Vectors.LengthSquared(delta);
            float radii = radiusA + radiusB;
            if (distanceSquared <= 1e-12f * radii * radii)
            {
                normal = Vector3.UnitY;
                return radii;
            }

            float distance = MathF.Sqrt(distanceSquared);
            normal = delta / distance;
            return radii - distance;
        }

        /// <summary>Penetration of a circle into a plane: r − (signed distance of the centre).</summary>
        public static float PlanePenetration(Vector3 centre, float radius, Vector3 planeNormal, float planeOffset) =>
            radius - (Vectors.Dot(planeNormal, centre) - planeOffset);

        /// <summary>
        /// <see cref="CirclePenetration(Vector3, float, Vector3, float, out Vector3)"/> from centres in double precision
        /// (<see cref="RigidBody.PreciseCentre"/>), worked out in double: the depth of a grazing pair or a near-miss a
        /// kilometre from the origin is finer than float32 positions there can tell.
        /// </summary>
        public static double CirclePenetration(Vector3D centreA, double radiusA, Vector3D centreB, double radiusB, out Vector3D normal)
        {
            Vector3D delta = centreA - centreB;
            double distanceSquared = delta.LengthSquared, radii = radiusA + radiusB;
            if (distanceSquared <= 1e-12 * radii * radii)
            {
                normal = new Vector3D(0, 1, 0);
                return radii;
            }

            double distance = Math.Sqrt(distanceSquared);
            normal = delta / distance;
            return radii - distance;
        }

        /// <summary>
        /// <see cref="PlanePenetration(Vector3, float, Vector3, float)"/> from a centre in double precision, in double,
        /// with the float normal made exactly unit first: its length is 1 only to about 6e-8, which a kilometre out
        /// would move the plane by 60 µm.
        /// </summary>
        public static double PlanePenetration(Vector3D centre, double radius, Vector3 planeNormal, float planeOffset)
        {
            Vector3D normal = new(planeNormal);
            return radius - (Vector3D.Dot(normal, centre) / normal.Length - planeOffset);
        }

        /// <summary>
        /// True when the bounding circles of two bodies overlap (d &lt; r_A + r_B) and the pair can collide (at least
        /// one is dynamic). Fills a contact with A = <paramref name="a"/>, B = <paramref name="b"/>.
        /// </summary>
        public static bool TryCollide(RigidBody a, RigidBody b, out Contact contact) => TryCollide(a, b, 0f, 0f, out contact);

        /// <summary>The pair test of <see cref="ContactGeometry.TryCollide(RigidBody, RigidBody, float, float, out Contact)"/>, unchecked.</summary>
        public static bool TryCollide(RigidBody a, RigidBody b, float margin, float lookahead, out Contact contact) =>
            TryCollide(a, b, Vectors.Length(a.linearVelocity), Vectors.Length(b.linearVelocity), margin, lookahead, out contact);

        /// <summary>The same, given the bodies' speeds |v_A| and |v_B| (detection works them out once per body, not per pair).</summary>
        public static bool TryCollide(RigidBody a, RigidBody b, float speedA, float speedB, float margin, float lookahead, out Contact contact)
        {
            // Most pairs a broad phase offers are rejected here, before the contact is built or even cleared.
            if ((!a.IsDynamic && !b.IsDynamic) || !MayMeet(a, b, speedA, speedB, margin, lookahead))
            {
                contact = default; // two infinite masses (nothing to resolve), or too far apart
                return false;
            }

            return TryMeasure(a, b, out contact);
        }

        /// <summary>Builds the contact of a pair that may meet, unless it is filtered out or a sensor (never a contact).</summary>
        private static bool TryMeasure(RigidBody a, RigidBody b, out Contact contact)
        {
            if (!PairFilter.Allows(a, b))
            {
                contact = default;
                return false;
            }

            float penetration = CirclePenetration(a.position, a.radius, b.position, b.radius, out Vector3 normal);

            Vector3 point = a.position - normal * (a.radius - 0.5f * penetration);
            contact = Contact.Unchecked(a, b, point, normal, penetration);
            return true;
        }

        /// <summary>
        /// The middle of a body's straight path over <paramref name="lookahead"/> seconds, x + v × lookahead / 2: the
        /// centre of the sphere detection gives it (see ContactGeometry.TryCollide).
        /// </summary>
        internal static Vector3 PathMiddle(RigidBody body, float lookahead) => body.position + body.linearVelocity * (0.5f * lookahead);

        /// <summary>Whether the spheres around the middles of both paths overlap (see ContactGeometry.TryCollide).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] // the broad phase's innermost test, most often false
        private static bool MayMeet(RigidBody a, RigidBody b, float speedA, float speedB, float margin, float lookahead)
        {
            float half = 0.5f * lookahead;
            float reach = a.radius + b.radius + margin + half * (speedA + speedB);
            Vector3 middles = PathMiddle(a, lookahead) - PathMiddle(b, lookahead);
            return Vectors.LengthSquared(middles) < reach * reach;
        }

        /// <summary>The plane test of <see cref="ContactGeometry.TryCollide(RigidBody, in StaticPlane, int, RigidBody, float, float, out Contact)"/>, unchecked.</summary>
        public static bool TryCollide(RigidBody body, in StaticPlane plane, int planeIndex, RigidBody ground, float margin, float lookahead, out Contact contact)
        {
            float penetration = PlanePenetration(body.position, body.radius, plane.Normal, plane.Offset);
            Vector3 middle = PathMiddle(body, lookahead); // its sphere's centre, as for a pair
            bool apartThroughout = penetration < 0 && -PlanePenetration(middle, body.radius, plane.Normal, plane.Offset) >= margin + 0.5f * lookahead * Vectors.Length(body.linearVelocity);
            if (!body.IsDynamic || apartThroughout ||
                !PairFilter.Allows(body, plane, planeIndex)) // filtered pairs and sensors never become contacts
            {
                contact = default;
                return false;
            }

            Vector3 point = body.position - plane.Normal * (body.radius - 0.5f * penetration);
            contact = Contact.Unchecked(body, ground, point, plane.Normal, penetration) with
            {
                Key = Contact.PlaneKey(body.Id, planeIndex),
                PlaneIndex = planeIndex,
                PlaneOffset = plane.Offset,
                PlaneRestitution = plane.Restitution,
                PlaneFriction = plane.Friction,
            };
            return true;
        }

        /// <summary>
        /// Measures a contact again at the bodies' current positions: penetration, normal and point. Used after
        /// positions have moved within a step.
        /// </summary>
        public static void Refresh(ref Contact contact)
        {
            RigidBody a = contact.BodyA;
            if (contact.PlaneIndex >= 0)
            {
                contact.Penetration = PlanePenetration(a.position, a.radius, contact.Normal, contact.PlaneOffset);
            }
            else
            {
                RigidBody b = contact.BodyB;
                contact.Penetration = CirclePenetration(a.position, a.radius, b.position, b.radius, out contact.Normal);
            }

            contact.Point = a.position - contact.Normal * (a.radius - 0.5f * contact.Penetration);
        }
    }
}
