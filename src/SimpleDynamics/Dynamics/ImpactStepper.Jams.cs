using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Mathematics;
using SimpleDynamics.Collision;

namespace SimpleDynamics;

// Jams: bodies that used up their impacts in a substep stand still, and the cluster they jam is settled at its end.
internal sealed partial class ImpactStepper
{
    /// <summary>
    /// Of the <see cref="ImpactsPerBody"/> impacts a body may take in a substep, those that only stop a creep (the pair
    /// would sink less than <see cref="HeldDepthTolerance"/> of the smaller radius in the substep): the chatter of a
    /// cluster pressed together, where each push passes on to a neighbour and comes back slower, the inelastic
    /// collapse itself. A body jams after this many of them. Measured on <see cref="Scenes.Smash"/> (1,000 discs):
    /// about 60 % of the impacts were such creeps, and with this limit the step took 2.4 ms instead of 3.4 ms, the
    /// cluster settled as one (see SettleJams) instead of through thousands of them.
    /// </summary>
    public const int CreepingImpactsPerBody = 4;

    /// <summary>Sweeps over the contacts of bodies that used up their impacts (see SettleJams).</summary>
    private const int JamSweeps = 8;

    private bool _jammed;
    private JamState[] _jamState = new JamState[InitialContacts]; // per contact, while settling
    private int[] _anchorDistance = new int[InitialBodies]; // per body, while a jam is stopped from what cannot move
    private int[] _anchorQueue = new int[InitialBodies];

    /// <summary>
    /// Where a contact stands in the settling of a jam. The bodies do not move while it is settled (only their
    /// velocities change), so a contact is measured once, when it first joins, and not again at every sweep.
    /// </summary>
    private enum JamState : byte
    {
        /// <summary>Neither end is jammed.</summary>
        Out,

        /// <summary>An end is jammed; not measured yet.</summary>
        Joined,

        /// <summary>Measured: touching, so swept.</summary>
        Touching,

        /// <summary>Measured: apart, so not part of the jam.</summary>
        Apart,
    }

    /// <summary>
    /// Whether an impact only stops a creep: its approach would sink the pair by less than
    /// <see cref="HeldDepthTolerance"/> of the smaller radius in a substep.
    /// </summary>
    private bool Creeping(in Contact contact, int a, int b)
    {
        return -contact.ApproachVelocity * (float)_h < HeldDepthTolerance * SmallerRadius(a, b);
    }

    /// <summary>The smaller radius of the pair's bodies (body a's alone against a plane, b &lt; 0).</summary>
    private float SmallerRadius(int a, int b) => b < 0 ? _motion[a].Radius : MathF.Min(_motion[a].Radius, _motion[b].Radius);

    /// <summary>A body that has used up its impacts stays where it is for the rest of the substep.</summary>
    private void HoldStill(int i)
    {
        _jammed = true;
        if (_held[i] && _motion[i].Chord != Vector3.Zero) // once: a body already held still has no chord left
        {
            ForgoGainWhileStill(i);
        }

        _motion[i].Chord = Vector3.Zero;
        _flight[i].A = Vector3.Zero;
        _flight[i].Impacts = ImpactsPerBody;
    }

    /// <summary>
    /// A body in free flight that is held still keeps the velocity it had when it stopped: gravity and forces give it
    /// nothing more for the rest of the substep (see <see cref="Advance"/>). A body held by resting contacts moves with
    /// the velocity the responder left it, which already has the whole substep's gain from gravity and forces in it; held
    /// still from time T on, it forgoes the gain of the rest of the substep, a (h − T) for its acceleration a, as the
    /// body in free flight does. Otherwise a heavy disc that jams at the start of every substep on a light one lying on
    /// the floor stands still while its speed grows by g h a substep, and the world gains energy: 79 J in a step in
    /// generated world 155 of 2,000 (seed 828), a 118 kg disc on a 0.09 kg one. Only as much of its velocity along a as it
    /// has is forgone, so that a body at rest is not thrown against the acceleration: its kinetic energy only falls.
    /// </summary>
    private void ForgoGainWhileStill(int i)
    {
        Vector3 acceleration = ForcedAcceleration(i);
        float squared = Vectors.LengthSquared(acceleration);
        if (squared == 0)
        {
            return;
        }

        float along = Vectors.Dot(_flight[i].U, acceleration) / squared; // the time a would take to give U its part along a
        float forgone = MathF.Min((float)(_h - _motion[i].T), along);
        if (forgone > 0)
        {
            _flight[i].U -= forgone * acceleration;
        }
    }

    /// <summary>
    /// A body that used up its impacts was held where it stood, but kept its velocity: left so, it would drive into its
    /// neighbours again in the next substep, gain speed from gravity while it cannot move, and use up its impacts
    /// again (a pile stepped with one long substep did this, its balls reaching 1 m/s while standing still). So the
    /// touching contacts of such bodies are swept a few times (Gauss–Seidel), each pair's approach along its line of
    /// centres stopped by an inelastic push: the jammed cluster ends the substep moving as one, with linear and
    /// angular momentum kept and kinetic energy lost, as the inelastic collapse it is. When the sweeps do not settle it,
    /// it is stopped outward from what cannot move (<see cref="StopFromAnchors"/>), and what touches nothing immovable
    /// moves on as one lump (<see cref="MergeFreeJams"/>).
    /// </summary>
    private void SettleJams(ReadOnlySpan<RigidBody> bodies, ReadOnlySpan<StaticPlane> planes)
    {
        // Which contacts have a jammed end, marked through the jammed bodies' lists and kept up to date as bodies
        // join, so that a sweep reads one flag per contact.
        EnsureLinked();
        Array.Clear(_jamState, 0, _contactCount);
        for (int i = 0; i < _bodyCount; i++)
        {
            if (_flight[i].Impacts >= ImpactsPerBody)
            {
                MarkContacts(i);
            }
        }

        for (int sweep = 0; sweep < JamSweeps; sweep++)
        {
            bool pushed = false;
            for (int k = 0; k < _contactCount; k++)
            {
                JamState state = _jamState[k];
                if (state is JamState.Out or JamState.Apart)
                {
                    continue;
                }

                Ends(k, out int a, out int b);
                ref Contact contact = ref _contacts[k];
                if (state == JamState.Joined)
                {
                    Measure(ref contact, a, b, planes);
                    bool apart = contact.Penetration < -HeldDepthTolerance * SmallerRadius(a, b);
                    _jamState[k] = apart ? JamState.Apart : JamState.Touching;
                    if (apart)
                    {
                        continue; // not part of the jam
                    }
                }

                if (StopApproach(ref contact, a, b))
                {
                    // A body pushed by the jam joins it: its own contacts are swept too, down to the ground.
                    JoinJam(a);
                    if (b >= 0)
                    {
                        JoinJam(b);
                    }

                    pushed = true;
                }
            }

            if (!pushed)
            {
                break;
            }

            if (sweep == JamSweeps - 1)
            {
                StopFromAnchors();
                MergeFreeJams(bodies); // see ImpactStepper.Lumps.cs
            }
        }

        _jammed = false;
    }

    /// <summary>
    /// When the sweeps have not settled a jam, its approach is stopped outward from what cannot move. A light body
    /// between a wall and a far heavier one is what keeps it from settling: each sweep takes away only about the mass
    /// ratio's inverse of the heavy body's approach, so the heavy one kept driving into it, substep after substep (a
    /// 548 kg disc on a 0.011 kg one on the floor kept 23 m/s while it stood still, generated world 787 of 2,000, seed
    /// 801). So each jammed body gets its distance, in touching contacts, from a plane or an immovable body, and nearest
    /// first each contact between distances d and d + 1 slows the body at d + 1 alone, as if the nearer one could not
    /// move: at most to rest along the normal, so kinetic energy only falls. This is shock propagation (Guendelman,
    /// Bridson and Fedkiw, "Nonconvex Rigid Bodies with Stacking", SIGGRAPH 2003,
    /// https://physbam.stanford.edu/~fedkiw/papers/stanford2003-01.pdf) with distance from the walls for height, as
    /// the solver's position pass does. A cluster that touches nothing immovable moves on as one lump instead, with its
    /// momentum and angular momentum (<see cref="MergeFreeJams"/>).
    /// </summary>
    private void StopFromAnchors()
    {
        int head = 0, tail = 0;
        for (int i = 0; i < _bodyCount; i++)
        {
            _anchorDistance[i] = int.MaxValue;
        }

        // Distance 1: the movable ends of touching contacts with a plane or an immovable body, stopped against it.
        for (int k = 0; k < _contactCount; k++)
        {
            if (_jamState[k] != JamState.Touching)
            {
                continue;
            }

            Ends(k, out int a, out int b);
            ref Contact contact = ref _contacts[k];
            bool immovableA = contact.BodyA.inverseMass == 0, immovableB = b < 0 || contact.BodyB.inverseMass == 0;
            if (immovableA == immovableB)
            {
                continue;
            }

            StopApproach(ref contact, a, b);
            int movable = immovableB ? a : b;
            if (_anchorDistance[movable] == int.MaxValue)
            {
                _anchorDistance[movable] = 1;
                _anchorQueue[tail++] = movable;
            }
        }

        // Breadth-first outward: each body is reached from its nearer neighbours only.
        while (head < tail)
        {
            int u = _anchorQueue[head++];
            int next = _anchorDistance[u] + 1;
            for (int e = _head[u]; e >= 0; e = _next[e])
            {
                int k = e >> 1;
                Ends(k, out int a, out int b);
                ref Contact contact = ref _contacts[k];
                if (_jamState[k] != JamState.Touching || b < 0 || contact.BodyA.inverseMass == 0 || contact.BodyB.inverseMass == 0)
                {
                    continue;
                }

                int v = a == u ? b : a;
                if (_anchorDistance[v] == int.MaxValue)
                {
                    _anchorDistance[v] = next;
                    _anchorQueue[tail++] = v;
                }

                if (_anchorDistance[v] == next)
                {
                    SlowFarther(ref contact, a, b, moveA: v == a);
                }
            }
        }
    }

    /// <summary>
    /// Slows one body of a touching pair, the farther from what cannot move, so that it no longer approaches the other
    /// along the normal, but at most to rest along it (n points from B to A). The velocities are the chords: the jam is
    /// settled at the end of the substep.
    /// </summary>
    private void SlowFarther(ref Contact contact, int a, int b, bool moveA)
    {
        Vector3 n = contact.Normal;
        float closing = Vectors.Dot(_flight[a].U - _flight[b].U, n);
        if (closing >= 0)
        {
            return;
        }

        if (moveA)
        {
            float slowing = MathF.Min(-closing, MathF.Max(-Vectors.Dot(_flight[a].U, n), 0f)); // A's speed into B, at most
            _flight[a].U += slowing * n;
            contact.BodyA.linearVelocity = _flight[a].U;
            contact.NormalImpulse += slowing / contact.BodyA.inverseMass;
        }
        else
        {
            float slowing = MathF.Min(-closing, MathF.Max(Vectors.Dot(_flight[b].U, n), 0f)); // B's speed into A, at most
            _flight[b].U -= slowing * n;
            contact.BodyB.linearVelocity = _flight[b].U;
            contact.NormalImpulse += slowing / contact.BodyB.inverseMass;
        }
    }

    private void JoinJam(int i)
    {
        if (_flight[i].Impacts < ImpactsPerBody)
        {
            _flight[i].Impacts = ImpactsPerBody;
            MarkContacts(i);
        }
    }

    private void MarkContacts(int i)
    {
        for (int e = _head[i]; e >= 0; e = _next[e])
        {
            ref JamState state = ref _jamState[e >> 1];
            if (state == JamState.Out)
            {
                state = JamState.Joined;
            }
        }
    }
}
