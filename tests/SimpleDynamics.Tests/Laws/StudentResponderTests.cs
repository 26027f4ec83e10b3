using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Laws;
using SimpleDynamics.Response;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Laws;

/// <summary>
/// A student's responder with a classic slip: eq. 16's impulse without the (1 + ε), so every collision is
/// perfectly inelastic along the normal. The kit catches it and shrinks the failure to a small collision.
/// </summary>
public class StudentResponderTests
{
    private readonly ITestOutputHelper _output;

    public StudentResponderTests(ITestOutputHelper output) => _output = output;

    /// <summary>The student's attempt: J = −v_n / (1/m_A + 1/m_B), where eq. 16 says −(1 + ε) v_n / (…).</summary>
    private sealed class ForgetfulResponder : PairwiseResponder
    {
        private readonly float _restitution;

        public ForgetfulResponder(float restitution) => _restitution = restitution;

        public float Restitution => _restitution; // unused: that is the bug

        public override void ResolveVelocity(ref Contact contact)
        {
            RigidBody a = contact.BodyA, b = contact.BodyB;
            Vector3 n = contact.Normal;
            float vn = Vector3.Dot(contact.RelativeVelocity, n);
            if (vn >= 0)
            {
                return;
            }

            float j = -vn / (a.InverseMass + b.InverseMass); // forgot (1 + ε)
            a.ApplyImpulse(j * n, contact.Point);
            b.ApplyImpulse(-j * n, contact.Point);
        }
    }

    [Fact]
    public void A_responder_that_forgets_one_plus_eps_fails_with_a_small_readable_collision()
    {
        var failure = Assert.Throws<ResponderLawException>(() => ResponderLaws.Check(e => new ForgetfulResponder(e)));

        string message = failure.Message;
        _output.WriteLine(message);
        // Momentum and angular momentum still hold (equal and opposite impulses at the contact point)...
        Assert.False(failure.Law.HasFlag(ResponderLaw.LinearMomentum), message);
        Assert.False(failure.Law.HasFlag(ResponderLaw.AngularMomentum), message);
        // ...but the bounce and the energy do not.
        Assert.True(failure.Law.HasFlag(ResponderLaw.Bounce), message);
        Assert.True(failure.Law.HasFlag(ResponderLaw.ElasticEnergy), message);
        Assert.Contains("Law Bounce: the relative normal velocity at the contact reverses and scales by eps: v_n' = -eps v_n (eq. 9)", message, StringComparison.Ordinal);
        // Shrunk to the simplest collision that still fails: unit masses, radii 0.5 m, along x, no spin.
        Assert.Contains("normal n (from B to A) = (1, 0, 0)", message, StringComparison.Ordinal);
        Assert.Contains("A: dynamic solid sphere, m = 1 kg, r = 0.5 m", message, StringComparison.Ordinal);
        Assert.Contains("w = (0, 0, 0) rad/s", message, StringComparison.Ordinal);
        Assert.Contains("approaching: v_n = (v_A - v_B).n = -1 m/s", message, StringComparison.Ordinal);
        Assert.Contains("eps = 0.5, mu = 0", message, StringComparison.Ordinal);
        Assert.Contains("relative normal velocity after, v_n' = -eps v_n (m/s): expected 0.5, got 0 ", message, StringComparison.Ordinal);
        Assert.Contains("Replay seed: 1,", message, StringComparison.Ordinal);
        Assert.Contains("FSCHECK_REPLAY=", message, StringComparison.Ordinal);
    }

    [Fact]
    public void A_correct_student_responder_passes_in_three_lines() =>
        ResponderLaws.Check(e => new ImpulseCollisionResponder(e, friction: 0.4f));
}
