using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics;

public sealed partial class World
{
    /// <summary>
    /// Advances the world by <paramref name="dt"/> seconds.
    /// </summary>
    /// <remarks>
    /// The pipeline:
    /// <list type="number">
    /// <item>detect: bounding circles against each other and against the planes (§2.1), including pairs that
    ///   are about to touch within this step (speculative contacts, see <see cref="ContactMargin"/>);</item>
    /// <item>then <see cref="Substeps"/> times, with h = dt / substeps:
    ///   integrate velocities (gravity, forces, torques; semi-implicit Euler),
    ///   resolve velocities (the responder's impulses, eq. 2 or eq. 5–16),
    ///   integrate positions and orientations with the new velocities,
    ///   and measure the contacts again;</item>
    /// <item>resolve positions: the responder's projection / position correction (listing 2);</item>
    /// <item>measure the contacts again for <see cref="Collisions"/> and the diagnostics.</item>
    /// </list>
    /// Detection comes before the velocity update (positions are the same either way) so that each contact
    /// records its approach velocity from before this step's gravity: a bounce then returns the speed the
    /// body arrived with, not that plus g·dt, which would add energy at every bounce.
    /// Substeps make piles stiff: a body sinks into its support by about g·h² per substep before the solver
    /// catches it, so four substeps sink sixteen times less than one step ("Small Steps in Physics
    /// Simulation", Macklin et al., SCA 2019; Box2D v3 steps the same way).
    /// </remarks>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="dt"/> is not a positive, finite number; nothing changes.</exception>
    public void Step(float dt)
    {
        Guard.Positive(dt, nameof(dt));
        DetectCollisions(dt);
        float h = dt / _substeps;
        _stepping = true;
        for (Substep = 0; Substep < _substeps; Substep++)
        {
            IntegrateVelocities(h);
            Responder.ResolveVelocities(this, Collisions, h);
            IntegratePositions(h);
            MeasureContacts();
            Responder.ResolvePositions(this, Collisions, h);
            MeasureContacts();
        }

        Substep = 0;
        _stepping = false;
        ClearForces();
        ReportContactEvents();
        Time += dt;
    }

    /// <summary>The substep being run (0 to <see cref="Substeps"/> − 1), for responders; 0 between steps.</summary>
    public int Substep { get; private set; }

    /// <summary>
    /// Whether a responder is called on the first substep of a step, when contacts are new; outside
    /// <see cref="Step"/> (a responder called on its own) every call counts as a whole step.
    /// </summary>
    internal bool IsFirstSubstep => !_stepping || Substep == 0;

    /// <summary>Whether a responder is called on the last substep of a step (or outside <see cref="Step"/>).</summary>
    internal bool IsLastSubstep => !_stepping || Substep == _substeps - 1;

    private void DetectCollisions(float dt)
    {
        Collisions.Clear();
        Detector.FindContacts(BodySpan, Collisions, _contactMargin, dt);
        ReadOnlySpan<StaticPlane> planes = Planes;
        foreach (RigidBody body in BodySpan)
        {
            for (int p = 0; p < planes.Length; p++)
            {
                if (ContactGeometry.TryCollide(body, planes[p], p, Ground, _contactMargin, dt, out Contact contact))
                {
                    Collisions.Add(contact);
                }
            }
        }
    }

    /// <summary>Semi-implicit Euler, velocity half: v += (g + F/m) dt, ω += I_w⁻¹ τ dt.</summary>
    /// <remarks>
    /// The gyroscopic term ω × (I ω) is left out, as in most game engines; it is zero for spheres and discs,
    /// the shapes this library collides.
    /// </remarks>
    private void IntegrateVelocities(float dt)
    {
        foreach (RigidBody body in BodySpan)
        {
            if (body.IsDynamic)
            {
                body.linearVelocity += (Gravity + body.force * body.inverseMass) * dt;
                body.angularVelocity += body.inverseInertiaWorld.Transform(body.torque) * dt;
            }
        }
    }

    /// <summary>
    /// Semi-implicit Euler, position half, with the new velocities: x += v dt, q += ½ (ω, 0) q dt, renormalised.
    /// Static bodies never move; kinematic bodies move with their set velocity.
    /// </summary>
    private void IntegratePositions(float dt)
    {
        foreach (RigidBody body in BodySpan)
        {
            if (body.Type == BodyType.Static)
            {
                continue;
            }

            body.position += body.linearVelocity * dt;
            Vector3 w = body.angularVelocity;
            if (w != Vector3.Zero)
            {
                Quaternion q = body.orientation;
                Quaternion spin = new Quaternion(w, 0) * q;
                q = new Quaternion(q.X + 0.5f * dt * spin.X, q.Y + 0.5f * dt * spin.Y, q.Z + 0.5f * dt * spin.Z, q.W + 0.5f * dt * spin.W);
                body.orientation = Quaternion.Normalize(q);
                body.UpdateInverseInertiaWorld();
            }
        }
    }

    private void MeasureContacts()
    {
        foreach (ref Contact contact in Collisions.Contacts)
        {
            ContactGeometry.Refresh(ref contact);
        }
    }

    private void ClearForces()
    {
        foreach (RigidBody body in BodySpan)
        {
            body.ClearAccumulators();
        }
    }
}
