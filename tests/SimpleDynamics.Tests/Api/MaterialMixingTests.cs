using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Api;

/// <summary>The README's mixing rule: a surface that sets none takes the responder's value; ε = max, μ = √(μ_A μ_B).</summary>
public class MaterialMixingTests
{
    private static Contact Between(float? restitutionA, float? restitutionB, float? frictionA, float? frictionB)
    {
        var a = new RigidBody(1f, 0.5f, new Vector3(0, 1, 0)) { Restitution = restitutionA, Friction = frictionA };
        var b = new RigidBody(1f, 0.5f, Vector3.Zero) { Restitution = restitutionB, Friction = frictionB };
        return new Contact(a, b, new Vector3(0, 0.5f, 0), Vector3.UnitY, 0f);
    }

    [Fact]
    public void Default_restitution_is_the_larger_of_the_two()
    {
        Assert.Equal(0.7f, MaterialMixing.Default.Restitution(Between(0.2f, 0.7f, null, null), responderDefault: 0.5f));
    }

    [Fact]
    public void Default_friction_is_the_geometric_mean()
    {
        Assert.Equal(MathF.Sqrt(0.25f * 0.64f), MaterialMixing.Default.Friction(Between(null, null, 0.25f, 0.64f), responderDefault: 0.3f), 6);
    }

    [Fact]
    public void Surfaces_that_set_nothing_take_the_responder_s_values()
    {
        Contact contact = Between(null, null, null, null);

        Assert.Equal(0.5f, MaterialMixing.Default.Restitution(contact, responderDefault: 0.5f));
        Assert.Equal(0.3f, MaterialMixing.Default.Friction(contact, responderDefault: 0.3f));
    }

    [Fact]
    public void One_surface_that_sets_a_value_is_mixed_with_the_responder_s()
    {
        Assert.Equal(0.9f, MaterialMixing.Default.Restitution(Between(0.9f, null, null, null), responderDefault: 0.5f));
        Assert.Equal(MathF.Sqrt(0.8f * 0.2f), MaterialMixing.Default.Friction(Between(null, null, 0.8f, null), responderDefault: 0.2f), 6);
    }

    [Fact]
    public void A_rule_that_returns_restitution_out_of_range_stops_the_step_before_anything_moves()
    {
        // Two balls resting on each other on the ground: their contacts are solved as resting ones, never bounced,
        // yet a rule returning ε = 2 must be caught as the step begins, not left to surface at some later impact.
        var world = new World(new Vector3(0, -9.81f, 0), new SequentialImpulseSolver { Mixing = new MaterialMixing((a, b) => 2f, MathF.Max) });
        world.AddPlane(new StaticPlane(Vector3.UnitY, Vector3.Zero));
        RigidBody lower = world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 0.5f, 0)) { Restitution = 0.5f }); // the rule is asked only where a surface sets ε
        RigidBody upper = world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 1.5f, 0)));

        var error = Assert.Throws<InvalidOperationException>(() => world.Step(1f / 60f));

        Assert.Contains("restitution mixing rule", error.Message);
        Assert.Equal(new Vector3(0, 0.5f, 0), lower.Position);
        Assert.Equal(new Vector3(0, 1.5f, 0), upper.Position);
        Assert.Equal(Vector3.Zero, lower.LinearVelocity);
        Assert.Equal(Vector3.Zero, upper.LinearVelocity);
        Assert.Equal(0f, world.Time);
    }
}
