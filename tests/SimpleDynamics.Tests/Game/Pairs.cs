using SimpleDynamics.Collision;

namespace SimpleDynamics.Tests.Game;

/// <summary>Pair keys for the tests' own bookkeeping: two body ids in order, or a body id and a plane.</summary>
internal static class Pairs
{
    public static (int, int) Key(ContactEvent e) => e.IsPlaneContact ? (e.BodyA.Id, -1 - e.PlaneIndex) : Ordered(e.BodyA.Id, e.BodyB!.Id);

    public static (int, int) Key(in Contact c) => c.IsPlaneContact ? (c.BodyA.Id, -1 - c.PlaneIndex) : Ordered(c.BodyA.Id, c.BodyB.Id);

    public static (int, int) Key(SensorEvent e) => (e.Sensor.Id, e.Visitor.Id);

    private static (int, int) Ordered(int a, int b) => a < b ? (a, b) : (b, a);
}
