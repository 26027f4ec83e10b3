using System;
using System.Numerics;
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
        _motion[i].Chord = Vector3.Zero;
        _motion[i].A = Vector3.Zero;
        _motion[i].Impacts = ImpactsPerBody;
    }

    /// <summary>
    /// A body that used up its impacts was held where it stood, but kept its velocity: left so, it would drive into its
    /// neighbours again in the next substep, gain speed from gravity while it cannot move, and use up its impacts
    /// again (a pile stepped with one long substep did this, its balls reaching 1 m/s while standing still). So the
    /// touching contacts of such bodies are swept a few times (Gauss–Seidel), each pair's approach along its line of
    /// centres stopped by an inelastic push: the jammed cluster ends the substep moving as one, with linear and
    /// angular momentum kept and kinetic energy lost, as the inelastic collapse it is.
    /// </summary>
    private void SettleJams(ReadOnlySpan<StaticPlane> planes)
    {
        // Which contacts have a jammed end, marked through the jammed bodies' lists and kept up to date as bodies
        // join, so that a sweep reads one flag per contact.
        EnsureLinked();
        Array.Clear(_jamState, 0, _contactCount);
        for (int i = 0; i < _bodyCount; i++)
        {
            if (_motion[i].Impacts >= ImpactsPerBody)
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
                    Measure(ref contact, planes);
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
        }

        _jammed = false;
    }

    private void JoinJam(int i)
    {
        if (_motion[i].Impacts < ImpactsPerBody)
        {
            _motion[i].Impacts = ImpactsPerBody;
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
