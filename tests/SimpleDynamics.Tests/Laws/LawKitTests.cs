using System;
using System.Numerics;
using SimpleDynamics;
using SimpleDynamics.Collision;
using SimpleDynamics.Laws;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Laws;

/// <summary>The kit itself: it catches each kind of broken responder, and reports rather than crashes.</summary>
public class LawKitTests
{
    /// <summary>Does nothing: bodies pass through each other.</summary>
    private sealed class IdleResponder : PairwiseResponder
    {
    }

    /// <summary>The impulse responder, plus a push on every separating contact.</summary>
    private sealed class PushesSeparatingContacts : ICollisionResponder
    {
        private readonly ImpulseCollisionResponder _inner;

        public PushesSeparatingContacts(float restitution) => _inner = new ImpulseCollisionResponder(restitution);

        public void BeginStep(StepContext step) => _inner.BeginStep(step);

        // The world answers only approaching pairs at their impact; a responder's resting stage sees every contact,
        // and this one wrongly pushes those that separate.
        public void SolveVelocities(StepContext step)
        {
            foreach (ref Contact contact in step.Contacts.Contacts)
            {
                if (Vector3.Dot(contact.RelativeVelocity, contact.Normal) >= 0)
                {
                    contact.BodyA.ApplyImpulse(0.1f * contact.Normal, contact.Point);
                    contact.BodyB.ApplyImpulse(-0.1f * contact.Normal, contact.Point);
                }
            }
        }

        public void Collide(StepContext step, ref Contact contact) => _inner.Collide(step, ref contact);

        public void SolvePositions(StepContext step) => _inner.SolvePositions(step);

        public void EndStep(StepContext step) => _inner.EndStep(step);
    }

    /// <summary>Applies the impulse to A only: momentum is not conserved.</summary>
    private sealed class OneSidedResponder : PairwiseResponder
    {
        public override void ResolveVelocity(ref Contact contact)
        {
            float vn = Vector3.Dot(contact.RelativeVelocity, contact.Normal);
            if (vn < 0)
            {
                contact.BodyA.ApplyImpulse(-2 * vn / (contact.BodyA.InverseMass + contact.BodyB.InverseMass) * contact.Normal, contact.Point);
            }
        }
    }

    private sealed class ThrowingResponder : PairwiseResponder
    {
        public override void ResolveVelocity(ref Contact contact) => throw new NotImplementedException("student forgot to write this");
    }

    [Fact]
    public void A_responder_that_does_nothing_breaks_the_bounce_but_keeps_momentum()
    {
        var failure = Assert.Throws<ResponderLawException>(() => ResponderLaws.Check(_ => new IdleResponder()));

        Assert.True(failure.Law.HasFlag(ResponderLaw.Bounce));
        Assert.True(failure.Law.HasFlag(ResponderLaw.EnergyLoss));
        Assert.False(failure.Law.HasFlag(ResponderLaw.LinearMomentum));
        Assert.False(failure.Law.HasFlag(ResponderLaw.SeparatingUntouched));
    }

    [Fact]
    public void Pushing_separating_contacts_is_caught()
    {
        var failure = Assert.Throws<ResponderLawException>(() =>
            ResponderLaws.Check(e => new PushesSeparatingContacts(e), new LawOptions { Laws = ResponderLaw.SeparatingUntouched }));

        Assert.Equal(ResponderLaw.SeparatingUntouched, failure.Law);
        Assert.Contains("separating: v_n = (v_A - v_B).n = +1 m/s", failure.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void A_one_sided_impulse_breaks_momentum()
    {
        var failure = Assert.Throws<ResponderLawException>(() =>
            ResponderLaws.Check(_ => new OneSidedResponder(), new LawOptions { Laws = ResponderLaw.LinearMomentum | ResponderLaw.AngularMomentum }));

        Assert.Equal(ResponderLaw.LinearMomentum | ResponderLaw.AngularMomentum, failure.Law);
        Assert.Contains("B: dynamic solid sphere, m = 1 kg, r = 0.5 m, centre (0, 0, 0), v = (0, 0, 0) m/s", failure.Message, StringComparison.Ordinal);
        // About a point on the line of action the one-sided impulse has no moment, so the shrunk pivot stays off it.
        Assert.Matches(@"angular momentum measured about O = \((?!0, 0, 0\))", failure.Message);
    }

    [Fact]
    public void A_responder_that_throws_is_reported_as_a_broken_law()
    {
        var failure = Assert.Throws<ResponderLawException>(() =>
            ResponderLaws.Check(_ => new ThrowingResponder(), new LawOptions { Laws = ResponderLaw.Bounce }));

        Assert.Contains("World.Step threw NotImplementedException: student forgot to write this", failure.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Bad_options_name_the_option()
    {
        var error = Assert.Throws<ArgumentOutOfRangeException>(() =>
            ResponderLaws.Check(e => new ImpulseCollisionResponder(e), new LawOptions { MaxTest = 0 }));

        Assert.Equal("MaxTest", error.ParamName);
        Assert.Throws<ArgumentException>(() => ResponderLaws.Check(e => new ImpulseCollisionResponder(e), new LawOptions { Laws = ResponderLaw.None }));
        Assert.Equal("MinApproachSpeed", Assert.Throws<ArgumentOutOfRangeException>(() =>
            ResponderLaws.Check(e => new ImpulseCollisionResponder(e), new LawOptions { MinApproachSpeed = 0.001, MaxApproachSpeed = 0.005 })).ParamName);
    }
}
