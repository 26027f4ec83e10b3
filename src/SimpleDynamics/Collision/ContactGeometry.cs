using System;
using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// The narrow phase for bounding circles/spheres: the exact overlap test and the contact it produces. Every
/// detector, the position correction and the diagnostics measure penetration with these same functions.
/// </summary>
/// <remarks>
/// These public functions check their arguments (and change nothing when they throw); the library itself calls the
/// same code without the checks (ContactGeometry.Unchecked.cs), since it calls it per contact and substep.
/// </remarks>
public static partial class ContactGeometry
{
    /// <summary>
    /// Penetration of two circles along the line of centres, r_A + r_B − d, and the unit normal from B to A.
    /// Coincident centres (d below about 1e-6 of the radii) get the defined normal +y, never NaN.
    /// </summary>
    /// <exception cref="ArgumentException">A centre is not finite.</exception>
    /// <exception cref="ArgumentOutOfRangeException">A radius is negative or not finite.</exception>
    public static float CirclePenetration(Vector3 centreA, float radiusA, Vector3 centreB, float radiusB, out Vector3 normal)
    {
        Guard.Finite(centreA, nameof(centreA));
        Guard.NonNegative(radiusA, nameof(radiusA));
        Guard.Finite(centreB, nameof(centreB));
        Guard.NonNegative(radiusB, nameof(radiusB));
        return Unchecked.CirclePenetration(centreA, radiusA, centreB, radiusB, out normal);
    }

    /// <summary>Penetration of a circle into a plane: r − (signed distance of the centre).</summary>
    /// <exception cref="ArgumentException"><paramref name="centre"/> is not finite, or <paramref name="planeNormal"/> is not a unit vector.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="radius"/> is negative or not finite, or <paramref name="planeOffset"/> is not finite.</exception>
    public static float PlanePenetration(Vector3 centre, float radius, Vector3 planeNormal, float planeOffset)
    {
        Guard.Finite(centre, nameof(centre));
        Guard.NonNegative(radius, nameof(radius));
        Guard.UnitVector(planeNormal, nameof(planeNormal));
        Guard.Finite(planeOffset, nameof(planeOffset));
        return Unchecked.PlanePenetration(centre, radius, planeNormal, planeOffset);
    }

    /// <summary>
    /// True when the bounding circles of two bodies overlap (d &lt; r_A + r_B) and the pair can collide (at least
    /// one is dynamic). Fills a contact with A = <paramref name="a"/>, B = <paramref name="b"/>.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> or <paramref name="b"/> is null.</exception>
    public static bool TryCollide(RigidBody a, RigidBody b, out Contact contact) => TryCollide(a, b, 0f, 0f, out contact);

    /// <summary>
    /// True when the pair can collide (at least one body is dynamic) and may touch within
    /// <paramref name="lookahead"/> seconds. Each body's straight path over the lookahead, from x to x + v × lookahead,
    /// is wrapped in the smallest sphere that holds it and half the margin around it: centred at the middle of the
    /// path, x + v × lookahead / 2, of radius r + margin / 2 + |v| × lookahead / 2. The pair is accepted when the two
    /// spheres overlap; two bodies that stay in their spheres and whose spheres do not overlap cannot meet (the world
    /// looks a body up again if a collision sends it out of its sphere). Centring the sphere on the middle of the path
    /// rather than its start halves the part of its radius that grows with speed: a crowd falling together at 20 m/s
    /// no longer reports, as contacts, neighbours several diameters away that never approach it. With margin and
    /// lookahead 0 this is the overlap test d &lt; r_A + r_B. A reported pair with a gap has a negative
    /// <see cref="Contact.Penetration"/>, measured where the bodies are now.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> or <paramref name="b"/> is null.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="margin"/> or <paramref name="lookahead"/> is negative or not finite.</exception>
    public static bool TryCollide(RigidBody a, RigidBody b, float margin, float lookahead, out Contact contact)
    {
        Guard.NotNull(a, nameof(a));
        Guard.NotNull(b, nameof(b));
        Guard.NonNegative(margin, nameof(margin));
        Guard.NonNegative(lookahead, nameof(lookahead));
        return Unchecked.TryCollide(a, b, margin, lookahead, out contact);
    }

    /// <summary>
    /// True when a dynamic body's circle reaches into a plane, or its sphere (see the pair overload: centred at the
    /// middle of its path over <paramref name="lookahead"/> seconds) comes within <paramref name="margin"/> plus half
    /// its path's length of it; fills the contact (B = ground).
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="body"/> or <paramref name="ground"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="plane"/> is uninitialised (<c>default</c>).</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="planeIndex"/> is negative, or <paramref name="margin"/> or <paramref name="lookahead"/> is negative or not finite.</exception>
    public static bool TryCollide(RigidBody body, in StaticPlane plane, int planeIndex, RigidBody ground, float margin, float lookahead, out Contact contact)
    {
        Guard.NotNull(body, nameof(body));
        if (plane.Normal == Vector3.Zero)
        {
            throw new ArgumentException("The plane is uninitialised; create it with a unit normal.", nameof(plane));
        }

        Guard.AtLeast(planeIndex, 0, nameof(planeIndex));
        Guard.NotNull(ground, nameof(ground));
        Guard.NonNegative(margin, nameof(margin));
        Guard.NonNegative(lookahead, nameof(lookahead));
        return Unchecked.TryCollide(body, plane, planeIndex, ground, margin, lookahead, out contact);
    }

    /// <summary>
    /// Measures a contact again at the bodies' current positions: penetration, normal and point. Used after
    /// positions have moved within a step.
    /// </summary>
    /// <exception cref="ArgumentException">The contact names no bodies (it is <c>default</c>).</exception>
    public static void Refresh(ref Contact contact)
    {
        Guard.ContactBodies(contact, nameof(contact));
        Unchecked.Refresh(ref contact);
    }
}
