using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
using SimpleDynamics.Response;

namespace SimpleDynamics;

// How each contact's next impact is predicted: the depth limit a pair collides at, and the time its chords reach it.
internal sealed partial class ImpactStepper
{
    /// <summary>
    /// The depth at which a pair collides this substep: 0 (touching) if it is apart at the start of the substep, else
    /// its depth then plus <see cref="DepthTolerance"/> of the smaller radius (<see cref="HeldDepthTolerance"/> if a body is held by
    /// resting contacts), but not past the depth cap (the solver's slop without gravity) unless it started deeper.
    /// </summary>
    private float DepthLimit(int k)
    {
        ref Contact contact = ref _contacts[k];
        Ends(k, out int a, out int b);
        float penetration;
        float smaller = _motion[a].Radius;
        bool held = _held[a];
        Vector3D startA = _substepStart[a];
        if (b < 0)
        {
            penetration = _noGravity
                ? (float)ContactGeometry.Unchecked.PlanePenetration(startA, smaller, contact.Normal, contact.PlaneOffset)
                : ContactGeometry.Unchecked.PlanePenetration(startA.Rounded, smaller, contact.Normal, contact.PlaneOffset);
        }
        else
        {
            Vector3D startB = _substepStart[b];
            penetration = _noGravity
                ? (float)ContactGeometry.Unchecked.CirclePenetration(startA, smaller, startB, _motion[b].Radius, out _)
                : ContactGeometry.Unchecked.CirclePenetration(startA.Rounded, smaller, startB.Rounded, _motion[b].Radius, out _);
            smaller = MathF.Min(smaller, _motion[b].Radius);
            held |= _held[b];
        }

        if (penetration < 0)
        {
            return 0f;
        }

        // A held pair creeping slower than the tolerance per substep is the responder's; one closing faster collides now.
        // Never past the depth cap when nothing but their motion presses them: a pair at it collides as soon as it would sink further.
        float tolerance = (held ? HeldDepthTolerance : DepthTolerance) * smaller;
        if (_depthCap < float.PositiveInfinity && Unloaded(contact))
        {
            tolerance = MathF.Min(tolerance, MathF.Max(0f, _depthCap - penetration));
        }

        Vector3 chordB = b < 0 ? Vector3.Zero : _startChord[b];
        float closing = -Vectors.Dot(_startChord[a] - chordB, contact.Normal);
        return closing * _h > tolerance ? penetration : penetration + tolerance;
    }

    /// <summary>
    /// The depth a held pair pressed by nothing but its own motion may creep to within a substep before it collides:
    /// without gravity, the <see cref="SequentialImpulseSolver.Slop"/> of the solver answering it. A crowd struck hard
    /// (<see cref="Scenes.Smash"/>) creeps together by up to <see cref="HeldDepthTolerance"/> of a radius a substep,
    /// faster than the position pass can undo (measured without the cap: 1,000 discs ended steps 2 mm deep, 3,000
    /// discs 4 mm). A pair pressed by a load, gravity or an applied force, carries it beyond the slop until the
    /// solver's sweeps converge, and answering that creep as impacts jams a deep pile (measured under gravity: the
    /// 200-deep pour and the 2,000-disc pit did not fall asleep in time), so there is no cap under a load, nor for a
    /// responder that has no slop.
    /// </summary>
    private static float DepthCap(ICollisionResponder responder, bool noGravity) =>
        noGravity && responder is SequentialImpulseSolver solver ? solver.Slop : float.PositiveInfinity;

    /// <summary>Whether no applied force presses the contact's bodies (see DepthCap; gravity has no cap anyway).</summary>
    private static bool Unloaded(in Contact contact) =>
        contact.BodyA.force == Vector3.Zero && (contact.IsPlaneContact || contact.BodyB.force == Vector3.Zero);

    /// <summary>Predicts the next impact of contact <paramref name="k"/> and queues it if it falls within the substep.</summary>
    private void Predict(int k)
    {
        Ends(k, out int a, out int b);
        double time;
        if (b < 0)
        {
            ref Contact contact = ref _contacts[k];
            if (Vectors.Dot(contact.Normal, _motion[a].Chord) >= 0)
            {
                return; // moving away from the plane, or along it
            }

            time = PlaneImpactTime(contact, a, LimitOf(k));
        }
        else
        {
            // Along straight chords the squared distance |d + v s|² is convex in s, so a pair whose distance does not
            // fall now (d · v ≥ 0) does not fall during the rest of the substep: most contacts of a resting pile,
            // which therefore need no measuring.
            ref Motion motionA = ref _motion[a], motionB = ref _motion[b];
            double t0 = Math.Max(motionA.T, motionB.T);
            Vector3D d, relative;
            if (_noGravity)
            {
                // The same in double precision (see Precision in ImpactStepper.cs).
                Vector3D chordA = new(motionA.Chord), chordB = new(motionB.Chord);
                relative = chordA - chordB;
                d = _flight[a].PreciseX + (t0 - motionA.T) * chordA - (_flight[b].PreciseX + (t0 - motionB.T) * chordB);
                if (relative.LengthSquared == 0 || Vector3D.Dot(d, relative) >= 0)
                {
                    return;
                }
            }
            else
            {
                // A pair whose chords are alike (relative chord zero) has d · v = 0 and is let go by the first test.
                // The three tests are all taken, without short cuts (& rather than &&): in a resting pile each passes
                // about as often as it fails, which a branch per test would mispredict, and none costs much.
                Vector3 relativeF = motionA.Chord - motionB.Chord;
                Vector3 dF = motionA.X + motionA.Chord * (float)(t0 - motionA.T) - (motionB.X + motionB.Chord * (float)(t0 - motionB.T));
                bool approaches = Vectors.Dot(dF, relativeF) < 0;
                if (!(approaches
                    & !RestsThroughSubstep(motionA, motionB, _held[a] | _held[b], dF, relativeF)
                    & !OutOfReach(motionA, motionB, dF, relativeF)))
                {
                    return;
                }

                d = new Vector3D(dF);
                relative = new Vector3D(relativeF);
            }

            time = PairImpactTime(k, a, b, t0, d, relative);
        }

        if (time <= _h)
        {
            _queue.Push(time, k, _motion[a].Version, b >= 0 ? _motion[b].Version : 0);
        }
    }

    /// <summary>
    /// Whether a resting pair certainly stays short of its depth limit for the whole substep, decided without working
    /// the limit out: most contacts of a pile at rest that approach at all. It holds for a pair of which neither body has
    /// collided yet in the substep (so <paramref name="d"/>, the centres' offset now, is the one at the substep's start,
    /// and both move along their first chords), a body of which is held by resting contacts (<paramref name="held"/>),
    /// that is deeper than <see cref="HeldDepthTolerance"/> of the smaller radius, and whose relative chord
    /// <paramref name="relative"/> moves the centres by less than half that tolerance in the substep. Its limit is then
    /// its depth plus the tolerance (see DepthLimit), and its depth grows by no more than the centres move. Under gravity
    /// only: without it the pair is measured in double precision and its limit may be capped (see DepthCap).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // see Predict: taken without branches
    private bool RestsThroughSubstep(in Motion a, in Motion b, bool held, Vector3 d, Vector3 relative)
    {
        float tolerance = HeldDepthTolerance * MathF.Min(a.Radius, b.Radius);
        float travel = (float)_h * (float)_h * Vectors.LengthSquared(relative);
        float deepEnough = a.Radius + b.Radius - tolerance;
        return ((a.Version | b.Version) == 0) & held
            & (travel < 0.25f * tolerance * tolerance) & (deepEnough > 0) & (Vectors.LengthSquared(d) < deepEnough * deepEnough);
    }

    /// <summary>
    /// Whether a pair is so far apart that its relative chord <paramref name="relative"/> cannot bring it to touching
    /// in a whole substep: |d| &gt; r_A + r_B + |v| h. Every depth limit is at least touching (see DepthLimit), so
    /// such a pair has no impact this substep, and its limit need not be worked out: most of a settled pile's
    /// contacts that approach and are not deep (the speculative ones, a little apart), 4,900 of the 6,000 a step that
    /// reached the limit in the settled 4,000-disc pit. Under gravity only, as <see cref="RestsThroughSubstep"/>;
    /// the margin (1e-5 of the squared reach) keeps float rounding on the side of measuring.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // see Predict: taken without branches
    private bool OutOfReach(in Motion a, in Motion b, Vector3 d, Vector3 relative)
    {
        float reach = a.Radius + b.Radius + (float)_h * Vectors.Length(relative);
        return Vectors.LengthSquared(d) > reach * reach * (1f + 1e-5f);
    }

    /// <summary>Contact k's depth limit, worked out from the substep's start the first time the pair closes.</summary>
    private float LimitOf(int k)
    {
        if (float.IsNaN(_limit[k]))
        {
            _limit[k] = DepthLimit(k);
        }

        return _limit[k];
    }

    /// <summary>
    /// Re-predicts the contacts of <paramref name="body"/> after it collided, except <paramref name="skip"/> (the
    /// contact of the collision, when the other body's contacts have just predicted it).
    /// </summary>
    private void PredictAround(int body, int skip = -1)
    {
        EnsureLinked();
        for (int e = _head[body]; e >= 0; e = _next[e])
        {
            if (e >> 1 != skip)
            {
                Predict(e >> 1);
            }
        }
    }

    /// <summary>
    /// When the centres' distance, moving along their chords from <paramref name="d"/> at <paramref name="t0"/>, first
    /// reaches r_A + r_B − limit (contact <paramref name="k"/>'s depth limit) while they approach; +∞ if it does not.
    /// Solves |d + v s|² = D² for the smaller root s ≥ 0 in double precision.
    /// </summary>
    private double PairImpactTime(int k, int a, int b, double t0, Vector3D d, Vector3D relative)
    {
        double dx = d.X, dy = d.Y, dz = d.Z;
        double vx = relative.X, vy = relative.Y, vz = relative.Z;
        double dv = dx * vx + dy * vy + dz * vz;
        double dd = dx * dx + dy * dy + dz * dz;
        if (!Approaches(dv, dd, Vectors.LengthSquared(_motion[a].Chord), Vectors.LengthSquared(_motion[b].Chord)))
        {
            // Not approaching, or only by the rounding of a pair just answered: most contacts of a resting pile,
            // rejected before their depth limit is worked out.
            return double.PositiveInfinity;
        }

        double reach = (double)_motion[a].Radius + _motion[b].Radius - LimitOf(k);
        double excess = dd - reach * reach;
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

        // The root s = excess / (−dv + √disc) lies beyond the substep's end h − t0 exactly when
        // excess − (h − t0)(−dv) > (h − t0) √disc: decided without the square root for most pairs that do not meet in time.
        double left = _h - t0, beyond = excess + left * dv;
        if (beyond > 0 && beyond * beyond > left * left * discriminant)
        {
            return double.PositiveInfinity;
        }

        return t0 + excess / (-dv + Math.Sqrt(discriminant)); // the smaller root, written to avoid cancellation
    }

    /// <summary>
    /// Whether centres at squared distance <paramref name="dd"/>, whose distance changes at the rate given by
    /// <paramref name="dv"/> = d·v (v their relative chord), approach by more than the rounding of a pair just answered:
    /// −dv &gt; <see cref="ClosingTolerance"/> |d| (|v_A| + |v_B|). Squared, and the sum's square bounded by
    /// |v_A|² + |v_B|² ≤ (|v_A| + |v_B|)² ≤ 2 (|v_A|² + |v_B|²), it needs a square root only between those bounds.
    /// </summary>
    private static bool Approaches(double dv, double dd, double chordA2, double chordB2)
    {
        if (dv >= 0)
        {
            return false;
        }

        double scale = ClosingTolerance * ClosingTolerance * dd, dv2 = dv * dv, sum2 = chordA2 + chordB2;
        if (dv2 > 2 * scale * sum2)
        {
            return true;
        }

        if (dv2 <= scale * sum2)
        {
            return false;
        }

        return -dv > ClosingTolerance * Math.Sqrt(dd) * (Math.Sqrt(chordA2) + Math.Sqrt(chordB2));
    }

    /// <summary>When a body moving along its chord reaches the plane's depth limit; +∞ if it does not.</summary>
    private double PlaneImpactTime(in Contact contact, int a, float limit)
    {
        double closing = Vectors.Dot(contact.Normal, _motion[a].Chord);
        if (closing >= -ClosingTolerance * Vectors.Length(_motion[a].Chord))
        {
            return double.PositiveInfinity;
        }

        double gap = limit - (_noGravity
            ? ContactGeometry.Unchecked.PlanePenetration(_flight[a].PreciseX, contact.BodyA.radius, contact.Normal, contact.PlaneOffset)
            : contact.BodyA.radius - ((double)Vectors.Dot(contact.Normal, _motion[a].X) - contact.PlaneOffset));
        return gap <= 0 ? _motion[a].T : _motion[a].T + gap / -closing;
    }
}
