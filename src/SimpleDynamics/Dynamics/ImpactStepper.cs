using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics;

/// <summary>
/// Moves the bodies through one substep and answers every collision at its time of impact: the bodies travel to
/// contact, the responder exchanges the collision impulse there (<see cref="ICollisionResponder.Collide"/>), and
/// they travel the rest of the substep with their new velocities. Event-driven within the substep: the earliest
/// impact first, then the next one given what changed.
/// </summary>
/// <remarks>
/// <para><b>Motion within a substep.</b> A body's velocity goes from v₀ (start of the substep) to v₁ (after gravity,
/// forces and the responder's resting contacts) at the uniform rate a = (v₁ − v₀)/h, as free flight under gravity
/// does exactly. Its centre therefore moves along a parabola, and reaches x + h (v₀ + v₁)/2 at the end, the exact
/// free-flight position. Impacts are found on the chord of that parabola (a straight line, so the time of impact of
/// two spheres is a quadratic's root), which lies within ⅛ |a| h² of the parabola. At an impact the responder sees
/// the true velocity v₀ + a t, not the end-of-substep velocity: a ball that meets the ground bounces with the speed
/// it arrives with, so a bounce with ε = 1 keeps the ball's mechanical energy and its apex.</para>
/// <para><b>Depth limit.</b> Two bodies apart at the start of the substep collide when they touch. Two bodies
/// already touching collide as soon as they approach, unless a body is held by resting contacts and the pair only
/// creeps (it would sink less than <see cref="HeldDepthTolerance"/> of the smaller radius in the substep): then they
/// collide only if they sink that far, so that the slow creep of a resting pile is left to the responder instead of
/// becoming thousands of tiny impacts.</para>
/// <para><b>Nothing passes through anything.</b> After the responder has answered an impact, a pair whose centres
/// still approach is stopped along the normal (an inelastic push through both centres), whatever the responder did.
/// A body whose path leaves the sphere that detection covered for it (it was knocked into motion faster than it
/// moved at the start of the step) is looked up again against every body and plane, so it is caught by what lies in
/// its path in the same step. If a substep needs more than a generous number of impacts (an inelastic collapse,
/// where impacts come ever faster), the remaining motion of that substep is dropped: bodies stay where they are,
/// with their velocities, rather than pass through each other.</para>
/// <para><b>Conservation.</b> The normal of an impact is the current line of centres and both impulses act at one
/// point, so every impact conserves linear and angular momentum about any point, to float rounding.</para>
/// </remarks>
internal sealed class ImpactStepper
{
    /// <summary>A touching pair of free bodies collides when it would sink deeper than it is by this fraction of the smaller radius.</summary>
    public const float DepthTolerance = 0f;

    /// <summary>
    /// The same for a pair with a body held by resting contacts (a pile): the responder's sweeps leave such contacts
    /// creeping by far less than this per substep, and they are the responder's to hold, not impacts.
    /// </summary>
    public const float HeldDepthTolerance = 1e-3f;

    /// <summary>
    /// Impacts one body may take part in during one substep with the responder's answer. A dense cluster hit hard can
    /// otherwise need ever more impacts, ever closer together (inelastic collapse). Past them, an impact only stops
    /// the pair's approach (ε = 0, which conserves momentum and angular momentum and loses energy) and both bodies
    /// stand still for the rest of the substep, keeping their velocities for the next one: nothing passes through
    /// anything, and the work per substep is bounded.
    /// </summary>
    public const int ImpactsPerBody = 32;

    /// <summary>
    /// A pair closes only if its closing speed exceeds this fraction of its speeds: a pair just answered is left
    /// exactly non-approaching, up to float rounding, which must not count as a new impact.
    /// </summary>
    private const double ClosingTolerance = 1e-5;

    private Vector3[] _stepStart = new Vector3[16];
    private float[] _reach = new float[16];
    private Vector3[] _startVelocity = new Vector3[16];
    private Vector3[] _forcedVelocity = new Vector3[16];
    private Vector3[] _x = new Vector3[16];
    private Vector3[] _u = new Vector3[16];
    private Vector3[] _a = new Vector3[16];
    private Vector3[] _chord = new Vector3[16];
    private double[] _t = new double[16];
    private int[] _version = new int[16];
    private int[] _impacts = new int[16];
    private bool[] _held = new bool[16];
    private int[] _head = new int[16];
    private int[] _next = new int[32];
    private float[] _limit = new float[16];
    private readonly EventQueue _queue = new();
    private readonly PairKeySet _pairs = new();
    private bool _pairsReady;
    private double _h;

    /// <summary>Impacts answered in the last step.</summary>
    public int ImpactCount { get; private set; }

    /// <summary>Substeps of the last step whose impacts hit the limit (see remarks).</summary>
    public int SaturatedSubsteps { get; private set; }

    /// <summary>Bodies looked up again in the last step because their path left the sphere detection covered.</summary>
    public int Searches { get; private set; }

    /// <summary>
    /// Remembers where each body starts the step and how far detection looked around it: a sphere of radius
    /// <c>margin / 2 + lookahead · |v|</c> beyond its own radius (the detector's pair test is that two such spheres overlap).
    /// </summary>
    public void BeginStep(ReadOnlySpan<RigidBody> bodies, float margin, float lookahead)
    {
        int n = bodies.Length;
        EnsureBodies(n);
        for (int i = 0; i < n; i++)
        {
            RigidBody body = bodies[i];
            _stepStart[i] = body.position;
            _reach[i] = 0.5f * margin + lookahead * body.linearVelocity.Length();
        }

        _pairsReady = false;
        ImpactCount = 0;
        SaturatedSubsteps = 0;
        Searches = 0;
    }

    /// <summary>Keeps each body's velocity from before this substep's gravity and forces: v₀ of the motion.</summary>
    public void BeginSubstep(ReadOnlySpan<RigidBody> bodies)
    {
        for (int i = 0; i < bodies.Length; i++)
        {
            _startVelocity[i] = bodies[i].linearVelocity;
        }
    }

    /// <summary>Keeps each body's velocity after gravity and forces, before the responder's resting contacts.</summary>
    public void AfterForces(ReadOnlySpan<RigidBody> bodies)
    {
        for (int i = 0; i < bodies.Length; i++)
        {
            _forcedVelocity[i] = bodies[i].linearVelocity;
        }
    }

    /// <summary>Moves every body through the substep of length <paramref name="h"/>, answering impacts on the way.</summary>
    public void Move(StepContext step, ICollisionResponder responder, float h, float stepTimeLeft)
    {
        World world = step.World;
        ReadOnlySpan<RigidBody> bodies = step.Bodies;
        CollisionData contacts = step.Contacts;
        _h = h;
        int n = bodies.Length;
        for (int i = 0; i < n; i++)
        {
            RigidBody body = bodies[i];
            _x[i] = body.position;
            _held[i] = body.linearVelocity != _forcedVelocity[i];
            if (!_held[i])
            {
                // Free flight: from v₀ to v₁ at the uniform rate of gravity and forces, along a parabola.
                _u[i] = _startVelocity[i];
                _a[i] = (body.linearVelocity - _startVelocity[i]) / h;
                _chord[i] = 0.5f * (_startVelocity[i] + body.linearVelocity);
            }
            else
            {
                // Held by resting contacts: it moves with the velocity the responder left (semi-implicit Euler),
                // which is what keeps a pile from sinking into itself.
                _u[i] = _chord[i] = body.linearVelocity;
                _a[i] = Vector3.Zero;
            }

            _t[i] = 0;
            _version[i] = 0;
            _impacts[i] = 0;
            if (body.Type == BodyType.Static)
            {
                _u[i] = _a[i] = _chord[i] = Vector3.Zero;
            }
        }

        LinkContacts(contacts, n);
        _queue.Clear();
        for (int k = 0; k < contacts.Count; k++)
        {
            _limit[k] = DepthLimit(contacts[k]);
            Predict(contacts, k);
        }

        for (int i = 0; i < n; i++)
        {
            if (LeavesReach(i))
            {
                Search(step, i, stepTimeLeft);
            }
        }

        int impacts = 0, limit = 8 * (contacts.Count + n) + 256;
        while (_queue.Count > 0)
        {
            EventQueue.Entry next = _queue.Pop();
            ref Contact contact = ref contacts[next.Contact];
            int a = contact.BodyA.index, b = contact.BodyB.index;
            if (_version[a] != next.VersionA || (b >= 0 && _version[b] != next.VersionB))
            {
                continue; // a body of this pair has collided since: its prediction is stale
            }

            if (++impacts > limit)
            {
                StopAll(n);
                SaturatedSubsteps++;
                break;
            }

            Impact(step, responder, ref contact, next.Time);
            ImpactCount++;
            _version[a]++;
            if (b >= 0)
            {
                _version[b]++;
            }

            if (LeavesReach(a))
            {
                Search(step, a, stepTimeLeft);
            }

            if (b >= 0 && LeavesReach(b))
            {
                Search(step, b, stepTimeLeft);
            }

            PredictAround(contacts, a);
            if (b >= 0)
            {
                PredictAround(contacts, b);
            }
        }

        for (int i = 0; i < n; i++)
        {
            Advance(bodies[i], i, h);
            if (bodies[i].Type != BodyType.Static)
            {
                bodies[i].position = _x[i];
                bodies[i].linearVelocity = _u[i];
            }
        }
    }

    /// <summary>
    /// One impact at time <paramref name="time"/>: both bodies travel to it, the contact is measured there, the
    /// responder answers it, and a pair that still approaches is stopped along the normal.
    /// </summary>
    private void Impact(StepContext step, ICollisionResponder responder, ref Contact contact, double time)
    {
        RigidBody bodyA = contact.BodyA, bodyB = contact.BodyB;
        int a = bodyA.index, b = bodyB.index;
        Advance(bodyA, a, time);
        bodyA.position = _x[a];
        bodyA.linearVelocity = _u[a];
        if (b >= 0)
        {
            Advance(bodyB, b, time);
            bodyB.position = _x[b];
            bodyB.linearVelocity = _u[b];
        }

        Measure(ref contact, step.Planes);
        contact.ApproachVelocity = Vector3.Dot(bodyA.VelocityAt(contact.Point) - bodyB.VelocityAt(contact.Point), contact.Normal);
        bool exhausted = _impacts[a] >= ImpactsPerBody || (b >= 0 && _impacts[b] >= ImpactsPerBody);
        _impacts[a]++;
        if (b >= 0)
        {
            _impacts[b]++;
        }

        if (exhausted)
        {
            StopApproach(contact, a, b);
            HoldStill(a);
            if (b >= 0)
            {
                HoldStill(b);
            }

            return;
        }

        if (contact.ApproachVelocity < 0)
        {
            step.Enter(StepStage.Collide);
            responder.Collide(step, ref contact);
            step.Enter(StepStage.None);
        }

        _u[a] = bodyA.linearVelocity;
        if (b >= 0)
        {
            _u[b] = bodyB.linearVelocity;
        }

        StopApproach(contact, a, b);
        _chord[a] = _u[a] + 0.5f * (float)(_h - _t[a]) * _a[a];
        if (b >= 0)
        {
            _chord[b] = _u[b] + 0.5f * (float)(_h - _t[b]) * _a[b];
        }
    }

    /// <summary>A body that has used up its impacts stays where it is for the rest of the substep.</summary>
    private void HoldStill(int i)
    {
        _chord[i] = Vector3.Zero;
        _a[i] = Vector3.Zero;
        _impacts[i] = ImpactsPerBody;
    }

    /// <summary>
    /// If the centres still approach along the normal for the rest of the substep, push them apart just enough that
    /// they do not (an inelastic impulse through both centres: it conserves momentum and angular momentum and
    /// removes kinetic energy). The responder's answer stands whenever it already separates the pair.
    /// </summary>
    private void StopApproach(in Contact contact, int a, int b)
    {
        float inverseMassA = contact.BodyA.inverseMass, inverseMassB = contact.BodyB.inverseMass;
        float inverseMassSum = inverseMassA + inverseMassB;
        Vector3 n = contact.Normal;
        Vector3 chordA = _u[a] + 0.5f * (float)(_h - _t[a]) * _a[a];
        Vector3 chordB = b >= 0 ? _u[b] + 0.5f * (float)(_h - _t[b]) * _a[b] : Vector3.Zero;
        float closing = Vector3.Dot(chordA - chordB, n);
        if (closing >= 0 || inverseMassSum == 0)
        {
            return;
        }

        float impulse = -closing / inverseMassSum;
        _u[a] += impulse * inverseMassA * n;
        if (b >= 0)
        {
            _u[b] -= impulse * inverseMassB * n;
        }

        contact.BodyA.linearVelocity = _u[a];
        if (b >= 0)
        {
            contact.BodyB.linearVelocity = _u[b];
        }
    }

    /// <summary>Measures a contact at the bodies' current positions: normal along the line of centres, point, depth.</summary>
    private static void Measure(ref Contact contact, ReadOnlySpan<StaticPlane> planes)
    {
        RigidBody a = contact.BodyA;
        if (contact.IsPlaneContact)
        {
            StaticPlane plane = planes[contact.PlaneIndex];
            contact.Normal = plane.Normal;
            contact.Penetration = ContactGeometry.PlanePenetration(a.position, a.radius, plane.Normal, plane.Offset);
        }
        else
        {
            contact.Penetration = ContactGeometry.CirclePenetration(a.position, a.radius, contact.BodyB.position, contact.BodyB.radius, out contact.Normal);
        }

        contact.Point = a.position - contact.Normal * (a.radius - 0.5f * contact.Penetration);
    }

    /// <summary>
    /// The depth at which a pair collides this substep: 0 (touching) if it is apart now, else its present depth
    /// plus <see cref="DepthTolerance"/> of the smaller radius (<see cref="HeldDepthTolerance"/> if a body is held by
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
            penetration = ContactGeometry.PlanePenetration(_x[a.index], a.radius, contact.Normal, contact.PlaneOffset);
        }
        else
        {
            RigidBody b = contact.BodyB;
            penetration = ContactGeometry.CirclePenetration(_x[a.index], a.radius, _x[b.index], b.radius, out _);
            smaller = MathF.Min(smaller, b.radius);
            held |= _held[b.index];
        }

        if (penetration < 0)
        {
            return 0f;
        }

        // A held pair creeping slower than the tolerance per substep is the responder's; one closing faster collides now.
        float tolerance = (held ? HeldDepthTolerance : DepthTolerance) * smaller;
        Vector3 chordB = contact.IsPlaneContact ? Vector3.Zero : _chord[contact.BodyB.index];
        float closing = -Vector3.Dot(_chord[a.index] - chordB, contact.Normal);
        return closing * _h > tolerance ? penetration : penetration + tolerance;
    }

    /// <summary>Predicts the next impact of contact <paramref name="k"/> and queues it if it falls within the substep.</summary>
    private void Predict(CollisionData contacts, int k)
    {
        ref Contact contact = ref contacts[k];
        int a = contact.BodyA.index, b = contact.BodyB.index;
        double time = b < 0 ? PlaneImpactTime(contact, a, _limit[k]) : PairImpactTime(contact, a, b, _limit[k]);
        if (time <= _h)
        {
            _queue.Push(time, k, _version[a], b >= 0 ? _version[b] : 0);
        }
    }

    private void PredictAround(CollisionData contacts, int body)
    {
        for (int e = _head[body]; e >= 0; e = _next[e])
        {
            Predict(contacts, e >> 1);
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

    /// <summary>Moves body <paramref name="i"/> along its chord to <paramref name="time"/>; its velocity follows the parabola.</summary>
    private void Advance(RigidBody body, int i, double time)
    {
        double span = time - _t[i];
        if (span <= 0)
        {
            return;
        }

        float s = (float)span;
        _x[i] += _chord[i] * s;
        _u[i] += _a[i] * s;
        _t[i] = time;
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

    /// <summary>Drops the rest of the substep's motion: bodies stay where they are now, keeping their velocities.</summary>
    private void StopAll(int n)
    {
        for (int i = 0; i < n; i++)
        {
            _t[i] = _h;
            _chord[i] = Vector3.Zero;
        }

        _queue.Clear();
    }

    /// <summary>Whether body i's path to the end of the substep leaves the sphere detection covered for it this step.</summary>
    private bool LeavesReach(int i)
    {
        Vector3 end = _x[i] + _chord[i] * (float)(_h - _t[i]);
        return Vector3.DistanceSquared(end, _stepStart[i]) > _reach[i] * _reach[i];
    }

    /// <summary>
    /// Grows body i's sphere to cover its path for the rest of the step and adds a contact for every body and plane
    /// it may now reach that has none yet (brute force over the world: this is rare).
    /// </summary>
    private void Search(StepContext step, int i, float stepTimeLeft)
    {
        Searches++;
        ReadOnlySpan<RigidBody> bodies = step.Bodies;
        CollisionData contacts = step.Contacts;
        RigidBody body = bodies[i];
        Vector3 end = _x[i] + _chord[i] * (float)(_h - _t[i]);
        float speed = MathF.Max(_chord[i].Length(), (_u[i] + _a[i] * (float)(_h - _t[i])).Length());
        _reach[i] = MathF.Max(2 * _reach[i], Vector3.Distance(end, _stepStart[i]) + speed * stepTimeLeft);
        EnsurePairs(contacts);
        for (int j = 0; j < bodies.Length; j++)
        {
            RigidBody other = bodies[j];
            if (j == i || (!body.IsDynamic && !other.IsDynamic))
            {
                continue;
            }

            float reach = body.radius + _reach[i] + other.radius + _reach[j];
            if (Vector3.DistanceSquared(_stepStart[i], _stepStart[j]) >= reach * reach)
            {
                continue;
            }

            RigidBody first = i < j ? body : other, second = i < j ? other : body;
            if (!PairFilter.Allows(first, second) || !_pairs.Add(Contact.PairKey(first.Id, second.Id)))
            {
                continue; // filtered or sensor pairs never become contacts; others may have one already
            }

            float penetration = ContactGeometry.CirclePenetration(first.position, first.radius, second.position, second.radius, out Vector3 normal);
            AddContact(contacts, new Contact(first, second, first.position - normal * (first.radius - 0.5f * penetration), normal, penetration));
        }

        if (!body.IsDynamic)
        {
            return;
        }

        ReadOnlySpan<StaticPlane> planes = step.Planes;
        for (int p = 0; p < planes.Length; p++)
        {
            if (planes[p].DistanceTo(_stepStart[i]) - body.radius < _reach[i] &&
                _pairs.Add(Contact.PlaneKey(body.Id, p)) &&
                ContactGeometry.TryCollide(body, planes[p], p, step.World.Ground, float.PositiveInfinity, 0f, out Contact contact))
            {
                AddContact(contacts, contact);
            }
        }
    }

    private void AddContact(CollisionData contacts, in Contact contact)
    {
        contacts.Add(contact);
        int k = contacts.Count - 1;
        EnsureContacts(contacts.Count);
        Link(k, contact.BodyA.index, contact.BodyB.index);
        _limit[k] = DepthLimit(contacts[k]);
        Predict(contacts, k);
    }

    private void EnsurePairs(CollisionData contacts)
    {
        if (_pairsReady)
        {
            return;
        }

        _pairs.Reset(contacts.Count + 16);
        foreach (ref readonly Contact contact in contacts.Contacts)
        {
            _pairs.Add(contact.Key);
        }

        _pairsReady = true;
    }

    /// <summary>Lists each body's contacts (a linked list through the contacts' two ends), so an impact can re-predict its neighbours.</summary>
    private void LinkContacts(CollisionData contacts, int n)
    {
        EnsureContacts(contacts.Count);
        for (int i = 0; i < n; i++)
        {
            _head[i] = -1;
        }

        for (int k = 0; k < contacts.Count; k++)
        {
            ref Contact contact = ref contacts[k];
            Link(k, contact.BodyA.index, contact.BodyB.index);
        }

    }

    private void Link(int k, int a, int b)
    {
        _next[2 * k] = _head[a];
        _head[a] = 2 * k;
        if (b >= 0)
        {
            _next[2 * k + 1] = _head[b];
            _head[b] = 2 * k + 1;
        }
    }

    private void EnsureBodies(int n)
    {
        Buffers.EnsureCapacity(ref _stepStart, n);
        Buffers.EnsureCapacity(ref _reach, n);
        Buffers.EnsureCapacity(ref _startVelocity, n);
        Buffers.EnsureCapacity(ref _forcedVelocity, n);
        Buffers.EnsureCapacity(ref _x, n);
        Buffers.EnsureCapacity(ref _u, n);
        Buffers.EnsureCapacity(ref _a, n);
        Buffers.EnsureCapacity(ref _chord, n);
        Buffers.EnsureCapacity(ref _t, n);
        Buffers.EnsureCapacity(ref _version, n);
        Buffers.EnsureCapacity(ref _impacts, n);
        Buffers.EnsureCapacity(ref _held, n);
        Buffers.EnsureCapacity(ref _head, n);
    }

    private void EnsureContacts(int count)
    {
        Buffers.EnsureCapacity(ref _next, 2 * count);
        Buffers.EnsureCapacity(ref _limit, count);
    }
}
