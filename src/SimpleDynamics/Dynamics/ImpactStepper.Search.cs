using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Mathematics;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics;

// Looking a body up again when a collision sends it beyond the sphere detection covered for it.
internal sealed partial class ImpactStepper
{
    /// <summary>Whether body i's path to the end of the substep leaves the sphere detection covered for it this step.</summary>
    private bool LeavesReach(int i)
    {
        Vector3 end = _motion[i].X + _motion[i].Chord * (float)(_h - _motion[i].T);
        return Vectors.DistanceSquared(end, _sphereCentre[i]) > _reach[i] * _reach[i];
    }

    /// <summary>
    /// Whether body i, whose velocity an impact has just changed, may now reach a sleeping body within the sphere
    /// detection covered for it: waking at the start of the step woke only the sleepers a body approached then, and an
    /// impact can turn it towards one (a light disc landing beside a sleeping 54 kg one, its spin turned by friction into
    /// 0.25 m/s towards it, ended the step 1.3 mm inside it: generated world 645 of seed 1,178). Asks the sleeping
    /// bodies' grid only while some sleep; the search that follows wakes them (see <see cref="Search"/>).
    /// </summary>
    private bool MayReachSleepers(StepContext step, int i)
    {
        World world = step.World;
        if (world.SleepingBodyCount == 0)
        {
            return false;
        }

        RigidBody body = step.Bodies[i];
        return body.IsDynamic && world.AnySleeperInPath(body, _sphereCentre[i], body.radius + _reach[i], 0.5f * _margin);
    }

    /// <summary>
    /// Grows body i's sphere to cover its path for the rest of the step and adds a contact for every body and plane
    /// it may now reach that has none yet (brute force over the world: this is rare). A sleeping body it may reach
    /// wakes with its island (<see cref="World.WakeSleepersInPath"/>): detection and waking at the start of the step
    /// looked only as far as each body's speed then, and a slow body knocked into a sleeping pile would otherwise pass
    /// into it. The woken bodies join the substep at rest and look up their own neighbours and planes the same way,
    /// since they had no contacts this step.
    /// </summary>
    private void Search(StepContext step, int i, float stepTimeLeft)
    {
        int firstWoken = _bodyCount;
        SearchFrom(step, i, stepTimeLeft);
        for (int j = firstWoken; j < _bodyCount; j++) // _bodyCount grows while searches wake more
        {
            SearchFrom(step, j, stepTimeLeft);
        }
    }

    private void SearchFrom(StepContext step, int i, float stepTimeLeft)
    {
        Searches++;
        RigidBody body = step.Bodies[i];
        Vector3 end = _motion[i].X + _motion[i].Chord * (float)(_h - _motion[i].T);
        float speed = MathF.Max(Vectors.Length(_motion[i].Chord), Vectors.Length(_flight[i].U + _flight[i].A * (float)(_h - _motion[i].T)));
        _reach[i] = MathF.Max(2 * _reach[i], Vectors.Distance(end, _sphereCentre[i]) + speed * stepTimeLeft);
        EnsureLinked();
        Vector3 start = _sphereCentre[i];
        float ownReach = body.radius + _reach[i];
        if (body.IsDynamic && step.World.WakeSleepersInPath(body, start, ownReach, 0.5f * _margin))
        {
            AdmitWokenBodies(step);
        }

        ReadOnlySpan<RigidBody> bodies = step.Bodies;
        CollisionData contacts = step.Contacts;
        for (int j = 0; j < bodies.Length; j++)
        {
            // The spheres first, from the pass's own arrays: most bodies are far, and are rejected without being read.
            float reach = ownReach + _motion[j].Radius + _reach[j];
            if (j == i || Vectors.DistanceSquared(start, _sphereCentre[j]) >= reach * reach)
            {
                continue;
            }

            RigidBody other = bodies[j];
            if (!body.IsDynamic && !other.IsDynamic)
            {
                continue;
            }

            RigidBody first = i < j ? body : other, second = i < j ? other : body;
            if (!PairFilter.Allows(first, second) || HasContactWith(i, j))
            {
                continue; // filtered or sensor pairs never become contacts; others may have one already
            }

            AddMeasuredContact(contacts, first, second);
        }

        if (!body.IsDynamic)
        {
            return;
        }

        ReadOnlySpan<StaticPlane> planes = step.Planes;
        for (int p = 0; p < planes.Length; p++)
        {
            if (planes[p].DistanceTo(_sphereCentre[i]) - body.radius < _reach[i] &&
                !HasContactWithPlane(i, p) &&
                ContactGeometry.Unchecked.TryCollide(body, planes[p], p, step.World.Ground, float.PositiveInfinity, 0f, out Contact contact))
            {
                AddContact(contacts, contact);
            }
        }
    }

    /// <summary>
    /// Gives the bodies just woken (at the end of the step's bodies) the sphere detection would have given a body at
    /// rest, and a motion at rest for the rest of the substep.
    /// </summary>
    private void AdmitWokenBodies(StepContext step)
    {
        ReadOnlySpan<RigidBody> bodies = step.Bodies;
        EnsureBodies(bodies.Length);
        for (int i = _bodyCount; i < bodies.Length; i++)
        {
            RigidBody body = bodies[i];
            _sphereCentre[i] = body.position;
            _reach[i] = 0.5f * _margin;
            _startVelocity[i] = _forcedVelocity[i] = body.linearVelocity; // zero: a sleeping body lies still
            StartMotion(body, i, (float)_h);
            _head[i] = -1; // no contacts yet (the lists are made by now: see SearchFrom)
        }

        _bodyCount = bodies.Length;
    }

    /// <summary>Adds the contact of two bodies, measured where they are now (the middle of their overlap, or of their gap).</summary>
    private void AddMeasuredContact(CollisionData contacts, RigidBody first, RigidBody second)
    {
        float penetration = ContactGeometry.Unchecked.CirclePenetration(first.position, first.radius, second.position, second.radius, out Vector3 normal);
        AddContact(contacts, Contact.Unchecked(first, second, first.position - normal * (first.radius - 0.5f * penetration), normal, penetration));
    }

    private void AddContact(CollisionData contacts, in Contact contact)
    {
        contacts.Add(contact);
        _contacts = contacts.Storage; // it may have grown
        int k = _contactCount++;
        EnsureContacts(_contactCount);
        ReadEnds();
        if (_linked)
        {
            Ends(k, out int a, out int b);
            Link(k, a, b);
            _linkedEnds = _endsVersion;
        }

        _limit[k] = float.NaN;
        Predict(k);
    }

    /// <summary>Whether body <paramref name="i"/> has a contact with body <paramref name="j"/> this step, read from its list.</summary>
    private bool HasContactWith(int i, int j)
    {
        for (int e = _head[i]; e >= 0; e = _next[e])
        {
            if (_ends[e ^ 1] == j)
            {
                return true; // the other end of the contact listed under end e
            }
        }

        return false;
    }

    /// <summary>Whether body <paramref name="i"/> has a contact with plane <paramref name="p"/> this step.</summary>
    private bool HasContactWithPlane(int i, int p)
    {
        for (int e = _head[i]; e >= 0; e = _next[e])
        {
            if (_ends[e ^ 1] < 0 && _contacts[e >> 1].PlaneIndex == p)
            {
                return true;
            }
        }

        return false;
    }
}
