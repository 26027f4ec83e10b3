using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// A body that began or ended overlapping a sensor in the last step (<see cref="ContactEvents.SensorBegin"/>,
/// <see cref="ContactEvents.SensorEnd"/>), or overlaps it now (<see cref="ContactEvents.SensorOverlaps"/>).
/// </summary>
public readonly struct SensorEvent
{
    internal SensorEvent(RigidBody sensor, RigidBody visitor)
    {
        Sensor = sensor;
        Visitor = visitor;
    }

    /// <summary>The sensor body (<see cref="RigidBody.IsSensor"/>).</summary>
    public RigidBody Sensor { get; }

    /// <summary>The body that entered or left it.</summary>
    public RigidBody Visitor { get; }

    /// <inheritdoc />
    public override string ToString() => $"{Visitor} in sensor {Sensor}";
}
