using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Benchmarks;

/// <summary>A body's position, orientation and velocities, kept to put the body back (benchmarks that replay a window).</summary>
internal readonly struct BodyState
{
    private readonly Vector3 _position, _linearVelocity, _angularVelocity;
    private readonly Quaternion _orientation;

    private BodyState(Vector3 position, Quaternion orientation, Vector3 linearVelocity, Vector3 angularVelocity)
    {
        _position = position;
        _orientation = orientation;
        _linearVelocity = linearVelocity;
        _angularVelocity = angularVelocity;
    }

    public static BodyState Of(RigidBody body) =>
        new(body.Position, body.Orientation, body.LinearVelocity, body.AngularVelocity);

    public void Restore(RigidBody body)
    {
        body.Position = _position;
        body.Orientation = _orientation;
        body.LinearVelocity = _linearVelocity;
        body.AngularVelocity = _angularVelocity;
    }
}
