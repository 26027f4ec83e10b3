using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics;

// How each contact's next impact is predicted: the depth limit a pair collides at, and the time its chords reach it.
internal sealed partial class ImpactStepper
{
    /// <summary>
    /// The depth at which a pair collides this substep: 0 (touching) if it is apart at the start of the substep, else
    /// its depth then plus <see cref="DepthTolerance"/> of the smaller radius (<see cref="HeldDepthTolerance"/> if a body is held by
    /// resting contacts).
    /// </summary>
    private float DepthLimit(in Contact contact)
    {
        RigidBody a = contact.BodyA;
        float penetration;
        float smaller = a.radius;
        bool held = _held[a.index];
        if (contact.IsPlaneContact)
        {
            penetration = ContactGeometry.Unchecked.PlanePenetration(_substepStart[a.index], a.radius, contact.Normal, contact.PlaneOffset);
        }
        else
        {
            RigidBody b = contact.BodyB;
            penetration = ContactGeometry.Unchecked.CirclePenetration(_substepStart[a.index], a.radius, _substepStart[b.index], b.radius, out _);
            smaller = MathF.Min(smaller, b.radius);
            held |= _held[b.index];
        }

        if (penetration < 0)
        {
            return 0f;
        }

        // A held pair creeping slower than the tolerance per substep is the responder's; one closing faster collides now.
        float tolerance = (held ? HeldDepthTolerance : DepthTolerance) * smaller;
        Vector3 chordB = contact.IsPlaneContact ? Vector3.Zero : _startChord[contact.BodyB.index];
        float closing = -Vector3.Dot(_startChord[a.index] - chordB, contact.Normal);
        return closing * _h > tolerance ? penetration : penetration + tolerance;
    }

    /// <summary>Predicts the next impact of contact <paramref name="k"/> and queues it if it falls within the substep.</summary>
    private void Predict(int k)
    {
        ref Contact contact = ref _contacts[k];
        Ends(ref contact, out int a, out int b);
        if (Separating(contact, a, b))
        {
            return; // most contacts of a resting pile: no impact this substep, and no need to measure them
        }

        if (float.IsNaN(_limit[k]))
        {
            _limit[k] = DepthLimit(contact); // from the substep's start, worked out only for pairs that close
        }

        double time = b < 0 ? PlaneImpactTime(contact, a, _limit[k]) : PairImpactTime(contact, a, b, _limit[k]);
        if (time <= _h)
        {
            _queue.Push(time, k, _version[a], b >= 0 ? _version[b] : 0);
        }
    }

    /// <summary>
    /// Whether the pair's distance cannot fall during the rest of the substep: along straight chords the squared
    /// distance |d + v s|² is convex in s, so it never falls if it does not fall now (d · v ≥ 0).
    /// </summary>
    private bool Separating(in Contact contact, int a, int b)
    {
        if (b < 0)
        {
            return Vector3.Dot(contact.Normal, _chord[a]) >= 0;
        }

        Vector3 relative = _chord[a] - _chord[b];
        if (relative == Vector3.Zero)
        {
            return true;
        }

        double t0 = Math.Max(_t[a], _t[b]);
        Vector3 d = _x[a] + _chord[a] * (float)(t0 - _t[a]) - (_x[b] + _chord[b] * (float)(t0 - _t[b]));
        return Vector3.Dot(d, relative) >= 0;
    }

    private void PredictAround(int body)
    {
        EnsureLinked();
        for (int e = _head[body]; e >= 0; e = _next[e])
        {
            Predict(e >> 1);
        }
    }

    /// <summary>
    /// When the centres' distance, moving along their chords, first reaches r_A + r_B − limit while they approach;
    /// +∞ if it does not. Solves |d + v s|² = D² for the smaller root s ≥ 0 in double precision.
    /// </summary>
    private double PairImpactTime(in Contact contact, int a, int b, float limit)
    {
        double t0 = Math.Max(_t[a], _t[b]);
        Vector3 pa = _x[a] + _chord[a] * (float)(t0 - _t[a]);
        Vector3 pb = _x[b] + _chord[b] * (float)(t0 - _t[b]);
        double dx = pa.X - pb.X, dy = pa.Y - pb.Y, dz = pa.Z - pb.Z;
        Vector3 relative = _chord[a] - _chord[b];
        double vx = relative.X, vy = relative.Y, vz = relative.Z;
        double dv = dx * vx + dy * vy + dz * vz;
        double distance = Math.Sqrt(dx * dx + dy * dy + dz * dz);
        if (dv >= -ClosingTolerance * distance * (_chord[a].Length() + _chord[b].Length()))
        {
            return double.PositiveInfinity; // not approaching, or only by the rounding of a pair just answered
        }

        double reach = (double)contact.BodyA.radius + contact.BodyB.radius - limit;
        double excess = dx * dx + dy * dy + dz * dz - reach * reach;
        if (excess <= 0)
        {
            return t0; // at the limit already, and approaching
        }

        double vv = vx * vx + vy * vy + vz * vz;
        double discriminant = dv * dv - vv * excess;
        if (discriminant < 0)
        {
            return double.PositiveInfinity; // passing by
        }

        return t0 + excess / (-dv + Math.Sqrt(discriminant)); // the smaller root, written to avoid cancellation
    }

    /// <summary>When a body moving along its chord reaches the plane's depth limit; +∞ if it does not.</summary>
    private double PlaneImpactTime(in Contact contact, int a, float limit)
    {
        double closing = Vector3.Dot(contact.Normal, _chord[a]);
        if (closing >= -ClosingTolerance * _chord[a].Length())
        {
            return double.PositiveInfinity;
        }

        double gap = (double)Vector3.Dot(contact.Normal, _x[a]) - contact.PlaneOffset - contact.BodyA.radius + limit;
        return gap <= 0 ? _t[a] : _t[a] + gap / -closing;
    }
}
