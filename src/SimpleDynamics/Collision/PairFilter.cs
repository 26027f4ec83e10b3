using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// The one place that decides whether a pair may become a contact, asked first by the narrow phase
/// (<see cref="ContactGeometry"/>) so that every detector obeys it: sensors never collide, then the two
/// <see cref="CollisionFilter"/>s, then the world's callbacks.
/// </summary>
internal static class PairFilter
{
    /// <summary>Whether two bodies may collide.</summary>
    public static bool Allows(RigidBody a, RigidBody b)
    {
        if (a.isSensor || b.isSensor || !CollisionFilter.ShouldCollide(a.filter, b.filter))
        {
            return false;
        }

        // The callback runs last, so a game's code sees only pairs the filters let through.
        World? world = a.World ?? b.World;
        return world?.ShouldCollide is not { } shouldCollide || shouldCollide(a, b);
    }

    /// <summary>Whether a body may collide with the plane at <paramref name="planeIndex"/>.</summary>
    public static bool Allows(RigidBody body, in StaticPlane plane, int planeIndex)
    {
        if (body.isSensor || !CollisionFilter.ShouldCollide(body.filter, plane.Filter))
        {
            return false;
        }

        return body.World?.ShouldCollideWithPlane is not { } shouldCollide || shouldCollide(body, planeIndex);
    }
}
