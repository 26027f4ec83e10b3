using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Behavior;

public class SmokeTests
{
    private readonly ITestOutputHelper _output;

    public SmokeTests(ITestOutputHelper output) => _output = output;

    [Fact]
    public void Dropped_ball_bounces_and_rests()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        world.AddPlane(StaticPlane.Ground());
        var ball = world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 3, 0)) { Restitution = 0.5f });
        for (int i = 0; i < 600; i++)
        {
            world.Step(1f / 60f);
            if (i % 20 == 0)
            {
                _output.WriteLine($"{world.Time:F2} y={ball.Position.Y:F4} vy={ball.LinearVelocity.Y:F4} pen={world.Diagnostics.MaxPenetration:F5} E={world.Diagnostics.MechanicalEnergy:F4}");
            }
        }

        Assert.True(ball.LinearVelocity.Length() < 1e-3f);
    }
}
