using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics;

// Waking: what reaches a sleeping island wakes it whole, before the step's detection sees it.
public sealed partial class World
{
    /// <summary>
    /// Stage of <see cref="Step"/>, before detection: every awake body that touches a sleeping one, or closes on it
    /// fast enough to touch it within the step, wakes that body's island, so detection and the solver see the
    /// whole island. Costs nothing while no body sleeps.
    /// </summary>
    private void WakeWhatAwakeBodiesReach(float dt)
    {
        DoPendingWakes();
        if (_sleepingCount > 0)
        {
            QueryGrid sleepers = CurrentSleepGrid();
            float fall = 0.5f * Gravity.Length() * dt * dt;
            for (int i = 0; i < _awakeCount; i++)
            {
                RigidBody body = _awake[i];
                bool moves = body.linearVelocity != Vector3.Zero || body.angularVelocity != Vector3.Zero;
                if (body.isSensor || body.Type == BodyType.Static || (body.Type == BodyType.Kinematic && !moves))
                {
                    continue; // sensors, static bodies and kinematic bodies at rest wake nothing
                }

                float reach = body.radius + _touchTolerance + fall + dt * Vectors.Length(body.linearVelocity);
                sleepers.GatherBox(body.position - new Vector3(reach), body.position + new Vector3(reach));
                foreach (int slot in sleepers.Candidates)
                {
                    RigidBody sleeper = sleepers.BodyAt(slot);
                    if (sleeper.IsAwake || sleeper.World != this || !PairFilter.Allows(body, sleeper))
                    {
                        continue;
                    }

                    float penetration = ContactGeometry.CirclePenetration(body.position, body.radius, sleeper.position, sleeper.radius, out Vector3 normal);
                    if (MayTouch(penetration, -Vector3.Dot(body.linearVelocity, normal), dt))
                    {
                        WakeIslandNow(sleeper);
                    }
                }
            }
        }

        RegroupSleepingTouches();
    }

    /// <summary>
    /// During the impact pass: wakes the island of every sleeping body that a body's path may now reach, because a
    /// collision has sent it further within the step than waking and detection looked at its start (the impact pass's
    /// search, ImpactStepper.Search.cs). A sleeper is reached when its sphere, grown by <paramref name="margin"/>, meets
    /// the sphere of radius <paramref name="reach"/> around <paramref name="centre"/>. The woken bodies join the step's
    /// bodies at the end (<see cref="BodySpan"/>), at rest, so the bodies already stepping keep their places. Returns
    /// whether any woke.
    /// </summary>
    internal bool WakeSleepersInPath(RigidBody body, Vector3 centre, float reach, float margin) =>
        SleepersInPath(body, centre, reach, margin, wake: true);

    /// <summary>Whether <see cref="WakeSleepersInPath"/> would wake any sleeping body; wakes none.</summary>
    internal bool AnySleeperInPath(RigidBody body, Vector3 centre, float reach, float margin) =>
        SleepersInPath(body, centre, reach, margin, wake: false);

    private bool SleepersInPath(RigidBody body, Vector3 centre, float reach, float margin, bool wake)
    {
        if (_sleepingCount == 0 || body.isSensor)
        {
            return false;
        }

        QueryGrid sleepers = CurrentSleepGrid();
        sleepers.GatherBox(centre - new Vector3(reach), centre + new Vector3(reach));
        bool found = false;
        foreach (int slot in sleepers.Candidates)
        {
            RigidBody sleeper = sleepers.BodyAt(slot);
            float meet = reach + sleeper.radius + margin;
            if (!sleeper.IsAwake && sleeper.World == this && PairFilter.Allows(body, sleeper) &&
                Vector3.DistanceSquared(centre, sleeper.position) < meet * meet)
            {
                if (!wake)
                {
                    return true;
                }

                WakeIslandNow(sleeper); // the grid is only read again after this loop, and rebuilt then
                found = true;
            }
        }

        return found;
    }

    /// <summary>Wakes the island of a sleeping body; during a step, before the next step's detection.</summary>
    internal void WakeIsland(RigidBody body)
    {
        if (_stepping)
        {
            Buffers.EnsureCapacity(ref _pendingWakes, _pendingWakeCount + 1);
            _pendingWakes[_pendingWakeCount++] = body;
            return;
        }

        WakeIslandNow(body);
    }

    /// <summary>Wakes every sleeping body.</summary>
    private void WakeAll()
    {
        if (_sleepingCount == 0)
        {
            return;
        }

        if (_stepping)
        {
            _pendingWakeAll = true;
            return;
        }

        foreach (RigidBody body in AllBodies)
        {
            if (!body.IsAwake)
            {
                WakeIslandNow(body);
            }
        }
    }

    private void DoPendingWakes()
    {
        if (_pendingWakeAll)
        {
            _pendingWakeAll = false;
            WakeAll();
        }

        for (int k = 0; k < _pendingWakeCount; k++)
        {
            RigidBody body = _pendingWakes[k];
            _pendingWakes[k] = null!;
            if (!body.IsAwake && body.World == this)
            {
                WakeIslandNow(body);
            }
        }

        _pendingWakeCount = 0;
    }

    /// <summary>Moves every body of a sleeping body's island back among the awake bodies, with its timer reset.</summary>
    private void WakeIslandNow(RigidBody body)
    {
        if (body.island < 0)
        {
            return;
        }

        RigidBody? next;
        for (RigidBody? member = _islands.Release(body.island); member is not null; member = next)
        {
            next = member.nextInIsland;
            member.nextInIsland = null;
            member.island = -1;
            member.sleepTime = 0;
            AddAwake(member);
            _sleepingCount--;
        }

        _sleepVersion++;
        _touchesRegrouped = false;
    }

    /// <summary>
    /// Before a body leaves the world: wakes its own island if it sleeps, and, if it is a static or kinematic body,
    /// every sleeping island that rests on it.
    /// </summary>
    private void WakeWhatRestsOn(RigidBody body)
    {
        if (_sleepingCount == 0)
        {
            return;
        }

        body.WakeIfAsleep();
        if (!body.IsDynamic)
        {
            foreach (ContactEvent pair in _contactEvents.Touch.Items)
            {
                if (pair.BodyA == body)
                {
                    pair.BodyB?.WakeIfAsleep();
                }
                else if (pair.BodyB == body)
                {
                    pair.BodyA.WakeIfAsleep();
                }
            }
        }
    }

    /// <summary>The grid of the sleeping bodies, rebuilt when bodies fell asleep or woke since it was built.</summary>
    private QueryGrid CurrentSleepGrid()
    {
        if (_sleepGrid.Version != _sleepVersion)
        {
            Buffers.EnsureCapacity(ref _sleepers, _sleepingCount);
            int count = 0;
            foreach (RigidBody body in AllBodies)
            {
                if (!body.IsAwake)
                {
                    _sleepers[count++] = body;
                }
            }

            _sleepGrid.Build(_sleepers.AsSpan(0, count), _sleepVersion);
            Array.Clear(_sleepers, 0, count);
        }

        return _sleepGrid;
    }
}
