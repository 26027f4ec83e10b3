using System;
using System.Numerics;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// How deep a pile is, in bodies: the height along gravity that its contacts span, over the mean diameter of their
/// bodies. A contact belongs to the pile when both its bodies are slower than the speed gravity adds in one step,
/// g dt: bodies that rest on one another, or creep, or have just landed.
/// </summary>
/// <remarks>
/// Counting every contact measured a crowd that falls packed together, whose neighbours touch or come within the
/// detection margin but rest on nothing, as a pile as tall as the crowd, and a landing crowd as a pile as tall as what
/// has landed plus what still falls onto it. Measured on the 16,000-disc pour (benchmarks/README.md, 2026-12-02,
/// night): counting the resting contacts only, the budget grows as the pile does (8, 29, 110, then 165), seconds 3
/// and 4 of the pour spend 38 and 90 sweeps a step instead of 516 and 724, seconds 3 to 8 about a third fewer in all;
/// the pile settles about a second later, and at rest converges within its fixed sweeps.
/// </remarks>
internal struct PileMeasure
{
    private readonly float _g;
    private readonly float _restingSpeedSquared;
    private float _lowest, _highest;
    private double _diameters; // exact for up to a million diameters within a factor 256 of each other, so in any order alike
    private int _count;

    /// <summary>A measure with no contact yet, for a world with <paramref name="gravity"/> stepped by <paramref name="dt"/>.</summary>
    public PileMeasure(Vector3 gravity, float dt)
    {
        _g = gravity.Length();
        _restingSpeedSquared = _g * dt * (_g * dt);
        _lowest = float.PositiveInfinity;
        _highest = float.NegativeInfinity;
        _diameters = 0;
        _count = 0;
    }

    /// <summary>
    /// Counts <paramref name="contact"/> in the pile if both its bodies are slower than g dt. <paramref name="height"/>
    /// is its point's height times g, −p · g: the key the solver orders contacts by, so it is not worked out twice.
    /// </summary>
    public void Add(in Contact contact, float height)
    {
        if (contact.BodyA.linearVelocity.LengthSquared() < _restingSpeedSquared &&
            contact.BodyB.linearVelocity.LengthSquared() < _restingSpeedSquared)
        {
            _lowest = MathF.Min(_lowest, height);
            _highest = MathF.Max(_highest, height);
            _diameters += 2 * contact.BodyA.radius;
            _count++;
        }
    }

    /// <summary>The mean diameter of the bodies of the pile's contacts (0 when no contact rests).</summary>
    public readonly float MeanDiameter => _count == 0 ? 0 : (float)(_diameters / _count);

    /// <summary>The pile's depth in mean diameters (0 without gravity, or when no contact rests).</summary>
    public readonly float Layers => _count == 0 || _g == 0 ? 0 : (float)((_highest - _lowest) / (_g * _diameters / _count));
}
