namespace SimpleDynamics.Bodies;

// Sleeping: whether the body rests asleep in its world, and whether it may.
public sealed partial class RigidBody
{
    // The body's slot in its world's list of all bodies (World.Bodies), or -1; `index` is its slot among the
    // awake bodies the step works on.
    internal int worldSlot = -1;

    // The sleeping island the body belongs to, or -1 while it is awake (see World.Sleep.cs).
    internal int island = -1;

    // The next body of the same sleeping island (a singly linked list through the island's bodies).
    internal RigidBody? nextInIsland;

    // How long (s) the body has been slow without a break; an island sleeps when all its bodies have been slow
    // for World.TimeToSleep.
    internal float sleepTime;

    // Where this body's touching contacts start among the sleeping pairs of the world's event store, valid
    // while sleepTouchStamp equals the store's (see World.ContactsOf).
    internal long sleepTouchStamp;
    internal int firstSleepTouch;

    private bool _allowSleep = true;

    /// <summary>
    /// False while the body sleeps: it rests with zero velocity and costs its world nothing per step until
    /// something wakes it (see <see cref="SimpleDynamics.World.SleepingEnabled"/>). A body in no world is awake.
    /// </summary>
    public bool IsAwake => island < 0;

    /// <summary>
    /// Whether the body may fall asleep (default true). A body that may not keeps everything it touches awake;
    /// setting false wakes it.
    /// </summary>
    public bool AllowSleep
    {
        get => _allowSleep;
        set
        {
            _allowSleep = value;
            if (!value)
            {
                Wake();
            }
        }
    }

    /// <summary>
    /// Wakes the body and the sleeping island it belongs to (every body it rests on or that rests on it, directly
    /// or through others), and starts its sleep timer again. Does nothing to a body that is awake already.
    /// </summary>
    /// <remarks>
    /// Forces, torques, impulses and setting the position, orientation, velocities, mass, radius, filter or sensor
    /// flag wake a body by themselves; call this when you change something else the physics should answer.
    /// </remarks>
    public void Wake()
    {
        sleepTime = 0;
        WakeIfAsleep();
    }

    /// <summary>What every change the physics must answer calls: wakes the body's island if it sleeps.</summary>
    internal void WakeIfAsleep()
    {
        if (island >= 0)
        {
            World?.WakeIsland(this);
        }
    }
}
