using System;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// How the surface settings of two bodies combine into one ε and one μ for their contact.
/// </summary>
/// <remarks>
/// A surface that sets no value (<c>null</c>) takes the responder's setting. When neither sets a value the
/// responder's setting is used as it is. Otherwise the two values are combined; by default, as Box2D does,
/// restitution by the maximum (a bouncy ball bounces off mud) and friction by the geometric mean √(μ_A μ_B)
/// (ice on anything is slippery). Pass other functions to override; their results must stay in range.
/// </remarks>
public sealed class MaterialMixing
{
    private readonly Func<float, float, float> _restitution;
    private readonly Func<float, float, float> _friction;

    /// <summary>Creates a rule from two combining functions.</summary>
    public MaterialMixing(Func<float, float, float> restitution, Func<float, float, float> friction)
    {
        Guard.NotNull(restitution, nameof(restitution));
        Guard.NotNull(friction, nameof(friction));
        _restitution = restitution;
        _friction = friction;
    }

    /// <summary>ε = max(ε_A, ε_B), μ = √(μ_A μ_B).</summary>
    public static MaterialMixing Default { get; } = new(MathF.Max, (a, b) => MathF.Sqrt(a * b));

    /// <summary>The combined restitution of a contact, given the responder's default.</summary>
    public float Restitution(in Contact contact, float responderDefault)
    {
        Guard.ContactBodies(contact, nameof(contact));
        Guard.UnitInterval(responderDefault, nameof(responderDefault));
        float? b = contact.IsPlaneContact ? contact.PlaneRestitution : contact.BodyB.restitution;
        float value = Combine(contact.BodyA.restitution, b, responderDefault, _restitution);
        if (!(value >= 0 && value <= 1))
        {
            throw new InvalidOperationException($"The restitution mixing rule returned {value}, outside [0, 1].");
        }

        return value;
    }

    /// <summary>The combined friction coefficient of a contact, given the responder's default.</summary>
    public float Friction(in Contact contact, float responderDefault)
    {
        Guard.ContactBodies(contact, nameof(contact));
        Guard.NonNegative(responderDefault, nameof(responderDefault));
        float? b = contact.IsPlaneContact ? contact.PlaneFriction : contact.BodyB.friction;
        float value = Combine(contact.BodyA.friction, b, responderDefault, _friction);
        if (!(value >= 0) || !float.IsFinite(value))
        {
            throw new InvalidOperationException($"The friction mixing rule returned {value}; it must be finite and ≥ 0.");
        }

        return value;
    }

    private static float Combine(float? a, float? b, float fallback, Func<float, float, float> combine) =>
        a is null && b is null ? fallback : combine(a ?? fallback, b ?? fallback);
}
