using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics;

// A body's motion within a substep: how it starts (free flight, or held by resting contacts), how it advances, and
// how a support it comes to rest on holds it up.
internal sealed partial class ImpactStepper
{
    /// <summary>Body <paramref name="i"/>'s motion at the start of the substep, from its velocity before and after gravity, forces and resting contacts.</summary>
    private void StartMotion(RigidBody body, int i, float h)
    {
        _motion[i].X = body.position;
        _motion[i].Radius = body.radius;
        _held[i] = HeldByContacts(body.linearVelocity, _forcedVelocity[i]);
        _flight[i].PreciseX = _noGravity ? body.PreciseCentre : new Vector3D(body.position);
        if (!_held[i])
        {
            // Free flight: from v₀ to v₁ at the uniform rate of gravity and forces, along a parabola.
            _flight[i].U = _startVelocity[i];
            _flight[i].A = (body.linearVelocity - _startVelocity[i]) / h;
            _motion[i].Chord = 0.5f * (_startVelocity[i] + body.linearVelocity);
        }
        else
        {
            // Held by resting contacts: it moves with the velocity the responder left (semi-implicit Euler),
            // which is what keeps a pile from sinking into itself.
            _flight[i].U = _motion[i].Chord = body.linearVelocity;
            _flight[i].A = Vector3.Zero;
        }

        _motion[i].T = 0;
        _motion[i].Version = 0;
        _flight[i].Impacts = 0;
        if (body.Type == BodyType.Static)
        {
            _flight[i].U = _flight[i].A = _motion[i].Chord = Vector3.Zero;
        }

        _substepStart[i] = _flight[i].PreciseX;
        _startChord[i] = _motion[i].Chord;
    }

    /// <summary>
    /// Whether the responder's resting contacts changed a body's velocity from <paramref name="forced"/> (after gravity
    /// and forces) to <paramref name="solved"/> by more than float rounding of the two: then it moves with the velocity
    /// they left, from the start of the substep (see <see cref="StartMotion"/>). A change within rounding is free
    /// flight. Held, a falling body that meets something within the substep arrives with gravity's gain for the whole
    /// substep, and a bounce with ε = 1 gives back the part not yet earned: a 690 kg disc that had just stopped
    /// against a wall, whose contact there only zeroed the 5e-23 m/s sideways that the stop left, bounced off the floor
    /// 0.12 m/s too fast and gained 639 J (generated world 1,146 of seed 884).
    /// </summary>
    private static bool HeldByContacts(Vector3 solved, Vector3 forced) =>
        Vectors.DistanceSquared(solved, forced) > 1e-12f * (Vectors.LengthSquared(solved) + Vectors.LengthSquared(forced)); // |Δv| ≳ 1e-6 |v|

    /// <summary>Body i's acceleration in free flight (gravity and forces); zero while resting contacts hold it.</summary>
    private void RestoreAcceleration(int i)
    {
        if (!_held[i])
        {
            _flight[i].A = ForcedAcceleration(i);
        }
    }

    /// <summary>The uniform acceleration that gravity and forces give body i over the substep, (v₁ − v₀) / h.</summary>
    private Vector3 ForcedAcceleration(int i) => (_forcedVelocity[i] - _startVelocity[i]) / (float)_h;

    /// <summary>
    /// A body that an impact leaves touching something immovable (a plane, a static or kinematic body), and not moving
    /// away from it, rests on it for the rest of the substep: the support cancels the part of its acceleration that
    /// presses into it, as the contact force on a resting body cancels its weight. Otherwise the pair is stopped along
    /// its chord (<see cref="StopApproach"/>), which keeps the body in touch by giving it now the speed away from the
    /// support that the acceleration takes back by the end of the substep, and it ends the substep at the support with
    /// that speed into it, ½ g (h − t) for a landing under gravity at time t: kinetic energy it never earned, since it
    /// fell no further (a 36 kg ball landing at 0.07 m/s early in a substep of 1/30 s ended it 0.15 m/s into the floor,
    /// 0.17 J more than it began with: generated world 1,089 of seed 916). A later impact gives the body its free flight
    /// back (<see cref="RestoreAcceleration"/>), and the support is found again if it still rests. The support's
    /// impulse over the rest of the substep is added to the contact's. Only with the default solver, whose resting
    /// contacts carry the weight, and its friction, from the next substep on: a pairwise responder carries a resting
    /// body's weight through its impacts alone, each substep's impact answering the speed into the floor that the last
    /// one left, and its friction comes from those (a ball set sliding reaches rolling only so).
    /// </summary>
    private void RestOnImmovable(ref Contact contact, int a, int b)
    {
        if (!_supports)
        {
            return;
        }

        Vector3 n = contact.Normal; // from B towards A
        int resting;
        Vector3 into; // from the resting body into its support
        if (contact.BodyB.inverseMass == 0 && contact.BodyA.inverseMass > 0)
        {
            (resting, into) = (a, -n);
        }
        else if (contact.BodyA.inverseMass == 0 && b >= 0 && contact.BodyB.inverseMass > 0)
        {
            (resting, into) = (b, n);
        }
        else
        {
            return;
        }

        Vector3 velocityB = b >= 0 ? _flight[b].U : Vector3.Zero;
        float separating = Vectors.Dot(_flight[a].U - velocityB, n);
        float pressing = Vectors.Dot(_flight[resting].A, into);
        if (pressing > 0 && separating <= (float)ClosingTolerance * (Vectors.Length(_flight[a].U) + Vectors.Length(velocityB)))
        {
            _flight[resting].A -= pressing * into;
            RigidBody body = resting == a ? contact.BodyA : contact.BodyB;
            contact.NormalImpulse += pressing * (float)(_h - _motion[resting].T) / body.inverseMass; // what the support gives
        }
    }

    /// <summary>Moves body <paramref name="i"/> along its chord to <paramref name="time"/>; its velocity follows the parabola.</summary>
    private void Advance(RigidBody body, int i, double time)
    {
        double span = time - _motion[i].T;
        if (span <= 0)
        {
            return;
        }

        float s = (float)span;
        if (_noGravity)
        {
            _flight[i].PreciseX += span * new Vector3D(_motion[i].Chord);
            _motion[i].X = _flight[i].PreciseX.Rounded;
        }
        else
        {
            _motion[i].X += _motion[i].Chord * s;
            _flight[i].PreciseX = new Vector3D(_motion[i].X);
        }

        _flight[i].U += _flight[i].A * s;
        _motion[i].T = time;
        Vector3 w = body.angularVelocity;
        if (w != Vector3.Zero)
        {
            // q += ½ (ω, 0) q s, renormalised (the orientation half of semi-implicit Euler).
            Quaternion q = body.orientation;
            Quaternion spin = new Quaternion(w, 0) * q;
            float half = 0.5f * s;
            body.orientation = Quaternion.Normalize(new Quaternion(q.X + half * spin.X, q.Y + half * spin.Y, q.Z + half * spin.Z, q.W + half * spin.W));
            body.UpdateInverseInertiaWorld();
        }
    }
}
