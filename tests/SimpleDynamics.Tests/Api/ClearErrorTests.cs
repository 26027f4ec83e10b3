using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
using Xunit;

namespace SimpleDynamics.Tests.Api;

/// <summary>
/// Input that would fail deep inside the library (a null in a span, a zero normal, a NaN handed on to a
/// constructor) is rejected at the door, by an <see cref="ArgumentException"/> naming the caller's parameter.
/// </summary>
public class ClearErrorTests
{
    private static void Names(string paramName, Action action)
    {
        Exception? caught = Record.Exception(action);
        ArgumentException e = Assert.IsAssignableFrom<ArgumentException>(caught);
        Assert.Equal(paramName, e.ParamName);
    }

    [Fact]
    public void A_null_body_in_the_span_given_to_a_detector_names_bodies_and_adds_nothing()
    {
        var a = new RigidBody(1f, 1f, Vector3.Zero);
        var b = new RigidBody(1f, 1f, new Vector3(0.5f, 0, 0));
        RigidBody[] bodies = { a, b, null! };
        foreach (ICollisionDetector detector in new ICollisionDetector[] { new BruteForceDetector(), new SpatialHashDetector() })
        {
            var collisions = new CollisionData();
            Names("bodies", () => detector.FindContacts(bodies, collisions));
            Assert.Equal(0, collisions.Count);
        }
    }

    [Fact]
    public void Tangents_of_a_zero_or_non_finite_normal_name_n_instead_of_returning_NaN()
    {
        Names("n", () => Vectors.Tangents(Vector3.Zero, out _, out _));
        Names("n", () => Vectors.Tangents(new Vector3(float.NaN, 0, 0), out _, out _));
        Names("n", () => Vectors.Tangents(new Vector3(0, float.PositiveInfinity, 0), out _, out _));
        Vectors.Tangents(Vector3.UnitX, out Vector3 t1, out Vector3 t2);
        Assert.Equal(0f, Vector3.Dot(t1, t2), 6);
    }

    [Fact]
    public void A_contact_without_bodies_cannot_enter_a_CollisionData()
    {
        var collisions = new CollisionData();
        Names("contact", () => collisions.Add(default));
        Assert.Equal(0, collisions.Count);
    }

    public static TheoryData<string, Func<World>> BadSceneArguments => new()
    {
        { "restitution", () => Scenes.DroppedBall(float.NaN) },
        { "restitution", () => Scenes.DroppedBall(1.5f) },
        { "height", () => Scenes.DroppedBall(0.5f, height: float.NaN) },
        { "height", () => Scenes.DroppedBall(0.5f, height: float.PositiveInfinity) },
        { "restitution", () => Scenes.OffCentreCollision(-0.1f, 0.3f) },
        { "friction", () => Scenes.OffCentreCollision(0.5f, float.NaN) },
        { "friction", () => Scenes.OffCentreCollision(0.5f, -1f) },
        { "count", () => Scenes.StruckRow(0, 1f) },
        { "speed", () => Scenes.StruckRow(3, float.NaN) },
        { "speed", () => Scenes.StruckRow(3, float.NegativeInfinity) },
        { "restitution", () => Scenes.StruckRow(3, 1f, restitution: float.NaN) },
        { "speed", () => Scenes.SlidingBall(float.NaN, 0.3f) },
        { "friction", () => Scenes.SlidingBall(1f, float.PositiveInfinity) },
        { "radius", () => Scenes.SlidingBall(1f, 0.3f, radius: float.NaN) },
        { "radius", () => Scenes.SlidingBall(1f, 0.3f, radius: 0f) },
        { "count", () => Scenes.BallPit(0, planar: true) },
        { "radius", () => Scenes.BallPit(5, planar: true, radius: float.NaN) },
        { "radiusSpread", () => Scenes.BallPit(5, planar: true, radiusSpread: float.PositiveInfinity) },
        { "radiusSpread", () => Scenes.BallPit(5, planar: true, radiusSpread: 0.5f) },
        { "count", () => Scenes.Smash(0) },
        { "radius", () => Scenes.Smash(4, radius: float.NaN) },
        { "radius", () => Scenes.Smash(4, radius: -1f) },
        { "count", () => Scenes.ElasticGas(-1, planar: false) },
        { "radius", () => Scenes.ElasticGas(4, planar: false, radius: float.PositiveInfinity) },
        { "speed", () => Scenes.ElasticGas(4, planar: false, speed: float.NaN) },
    };

    [Theory]
    [MemberData(nameof(BadSceneArguments))]
    public void Each_scene_names_its_own_bad_argument(string paramName, Func<World> scene)
    {
        Names(paramName, () => scene());
    }
}
