using SimpleDynamics.Collision;

namespace SimpleDynamics.Bodies;

// What a game attaches to a body: its own data, a collision filter, and whether it is a sensor.
public sealed partial class RigidBody
{
    // Fields, as in RigidBody.cs: detection reads them for every candidate pair.
    internal CollisionFilter filter = CollisionFilter.Default;
    internal bool isSensor;

    // Where this body's touching contacts start in the world's event store, valid while touchStamp equals the
    // store's stamp (see World.ContactsOf); a stale stamp means the body touches nothing.
    internal long touchStamp;
    internal int firstTouch;

    /// <summary>
    /// Anything the game wants to find from the body (its game object, a score, a sound); the physics never
    /// reads it.
    /// </summary>
    public object? UserData { get; set; }

    /// <summary>
    /// Which bodies and planes this one collides with (default <see cref="CollisionFilter.Default"/>:
    /// everything). A pair the filter rejects never becomes a contact; see <see cref="CollisionFilter"/>.
    /// Takes effect at the next step.
    /// </summary>
    public CollisionFilter Filter
    {
        get => filter;
        set
        {
            filter = value;
            WakeIfAsleep();
        }
    }

    /// <summary>
    /// A sensor (a trigger area) takes and gives no impulses: nothing collides with it and none of its pairs is
    /// in <see cref="World.Collisions"/>. Instead the world reports which bodies overlap it, as
    /// <see cref="ContactEvents.SensorBegin"/> and <see cref="ContactEvents.SensorEnd"/> events.
    /// </summary>
    /// <remarks>
    /// A sensor moves as its type says: a static sensor stays put, a kinematic one moves with its velocity, and
    /// a dynamic one falls with gravity and takes forces but passes through every body and plane. Most sensors
    /// are static or kinematic. A sensor sees every body that is not a sensor and whose filter agrees with its
    /// own (<see cref="CollisionFilter.ShouldCollide"/>); it does not see planes or other sensors.
    /// </remarks>
    public bool IsSensor
    {
        get => isSensor;
        set
        {
            isSensor = value;
            WakeIfAsleep();
        }
    }
}
