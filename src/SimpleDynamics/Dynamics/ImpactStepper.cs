using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
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
/// it arrives with, so a bounce with ε = 1 keeps the ball's mechanical energy and its apex. A body that an impact
/// leaves resting on something immovable is held up by it from then on (see RestOnImmovable), so a ball that lands
/// within a substep ends it at rest on the floor.</para>
/// <para><b>Depth limit.</b> Two bodies apart at the start of the substep collide when they touch. Two bodies
/// already touching collide as soon as they approach, unless a body is held by resting contacts and the pair only
/// creeps (it would sink less than <see cref="HeldDepthTolerance"/> of the smaller radius in the substep): then they
/// collide only if they sink that far, so that the slow creep of a resting pile is left to the responder instead of
/// becoming thousands of tiny impacts. Without gravity that creep stops at the solver's slop (see DepthCap).</para>
/// <para><b>Nothing passes through anything.</b> After the responder has answered an impact, a pair whose centres
/// still approach is stopped along the normal (an inelastic push through both centres), whatever the responder did.
/// A body whose path leaves the sphere that detection covered for it (it was knocked into motion faster than it
/// moved at the start of the step) is looked up again against every body and plane, so it is caught by what lies in
/// its path in the same step; one that leaves the crowd's motion has the pairs left out for it made contacts again
/// (ImpactStepper.Crowd.cs). A body that needs more than a generous number of impacts in one substep (an inelastic
/// collapse, where impacts come ever faster, or a jam) stands still for the rest of it, and at its end the jammed
/// cluster is made to move as one (an inelastic push along each touching line of centres); if the whole substep
/// needs too many, its remaining motion is dropped. Either way bodies stay where they are rather than pass through
/// each other.</para>
/// <para><b>Precision.</b> In a world without gravity every body moves in double precision: its centre from one
/// impact to the next, and from step to step through <see cref="RigidBody.PreciseCentre"/>; every pair is predicted
/// and measured there from the double centres and velocities. Float32 positions are 2⁻²³ of their distance from the
/// origin apart (61 µm a kilometre out) and each write rounds by up to half that; the float difference of two
/// velocities carries the rounding of the larger. For a
/// grazing hit or a near-miss either error turns the normal, or makes a miss a hit, and changes the velocities after
/// the impact by far more than 1e-4 of the pair's speed. Under gravity positions stay float32: exact motion is promised
/// only for free flight without gravity, and gravity worlds (every pile) step bit for bit as with float32 positions
/// alone (1,000-body pits compared after 300 and 400 steps).</para>
/// <para><b>Conservation.</b> The normal of an impact is the current line of centres and both impulses act at one
/// point, so every impact conserves linear and angular momentum about any point, to float rounding.</para>
/// </remarks>
internal sealed partial class ImpactStepper
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
    /// stand still for the rest of the substep, and the cluster they jam is settled at its end (see SettleJams):
    /// nothing passes through anything, and the work per substep is bounded.
    /// </summary>
    public const int ImpactsPerBody = 32;

    /// <summary>
    /// A pair closes only if its closing speed exceeds this fraction of its speeds: a pair just answered is left
    /// exactly non-approaching, up to float rounding, which must not count as a new impact.
    /// </summary>
    private const double ClosingTolerance = 1e-5;

    // Per body (ImpactStepper.Buffers.cs sizes them).
    private Vector3[] _sphereCentre = new Vector3[InitialBodies]; // the middle of the body's path over the step, as detection saw it
    private float[] _reach = new float[InitialBodies];
    private Vector3[] _startVelocity = new Vector3[InitialBodies];
    private Vector3[] _forcedVelocity = new Vector3[InitialBodies];
    private Motion[] _motion = new Motion[InitialBodies];
    private Flight[] _flight = new Flight[InitialBodies];
    private Vector3D[] _substepStart = new Vector3D[InitialBodies];
    private Vector3[] _startChord = new Vector3[InitialBodies];
    private bool[] _held = new bool[InitialBodies];
    private int[] _head = new int[InitialBodies];

    // Per contact: the world indices of its two bodies, two list nodes (one per end), and the depth limit.
    private int[] _ends = new int[2 * InitialContacts];
    private int _endsCount; // contacts whose ends were read in step _endsStep
    private long _endsStep;
    private long _endsVersion; // moves on whenever the ends change (see ReadEnds)
    private int[] _next = new int[2 * InitialContacts];
    private float[] _limit = new float[InitialContacts];
    private Contact[] _contacts = Array.Empty<Contact>(); // the step's contacts (CollisionData.Storage), _contactCount of them
    private int _contactCount;
    private int _bodyCount;
    private bool _linked; // whether _head/_next list each body's contacts yet: only needed once an impact happens, or a quiet substep
    private long _linkedEnds = -1; // the ends' version and the bodies the lists were made for: they hold as long as both do
    private int _linkedBodies;
    private readonly EventQueue _queue = new();
    private double _h;
    private long _stepNumber;
    private float _depthCap = float.PositiveInfinity; // see DepthCap
    private float _margin; // detection's margin this step (see BeginStep)
    private bool _supports; // whether a body resting on something immovable is held up by it (see RestOnImmovable)
    private bool _noGravity; // bodies move, and pairs are predicted and measured, in double precision (see Precision)

    /// <summary>
    /// What predicting a body's impacts reads of its motion within the substep: where it is at time T and the chord it
    /// moves along from there. Kept together, apart from the rest (<see cref="Flight"/>), because the impact pass looks
    /// bodies up in the order their contacts come, not one after the other: 40 bytes a look-up, not 96. Measured on
    /// the settled 16,000-disc 2-D pit, whose bodies' motions then take 640 KB instead of 1.5 MB: a step 5–7 % faster
    /// (benchmarks/README.md, twenty-third session).
    /// </summary>
    private struct Motion
    {
        public Vector3 X; // the centre at time T, rounded to float
        public float Radius;
        public Vector3 Chord; // the velocity it moves with from T to the end of the substep
        public int Version; // collisions so far: a prediction made before the latest one is stale
        public double T; // the time within the substep that X and U are at
    }

    /// <summary>The rest of a body's motion within the substep, which moving it and answering its impacts read.</summary>
    private struct Flight
    {
        public Vector3D PreciseX; // the centre at time T: moved in double without gravity, else exactly X
        public Vector3 U; // the velocity at T
        public Vector3 A; // the uniform acceleration of its free flight (zero if held by resting contacts)
        public int Impacts; // impacts this substep
    }

    /// <summary>Impacts answered in the last step.</summary>
    public int ImpactCount { get; private set; }

    /// <summary>Substeps of the last step whose impacts hit the limit (see remarks).</summary>
    public int SaturatedSubsteps { get; private set; }

    /// <summary>Bodies looked up again in the last step because their path left the sphere detection covered.</summary>
    public int Searches { get; private set; }

    /// <summary>
    /// Remembers the sphere detection looked in for each body: centred at the middle of its straight path over the step,
    /// x + v · lookahead / 2, and reaching <c>margin / 2 + lookahead · |v| / 2</c> beyond its own radius (the detector's
    /// pair test is that two such spheres overlap: see ContactGeometry.TryCollide).
    /// </summary>
    public void BeginStep(ReadOnlySpan<RigidBody> bodies, CollisionData contacts, Vector3 gravity, float margin, float lookahead)
    {
        int n = bodies.Length;
        EnsureBodies(n);
        _margin = margin;
        var crowd = new CrowdMotion(Vectors.Length(gravity) * lookahead);
        BeginScale();
        for (int i = 0; i < n; i++)
        {
            RigidBody body = bodies[i];
            NoteScale(body);
            float speed = Vectors.Length(body.linearVelocity);
            _sphereCentre[i] = ContactGeometry.Unchecked.PathMiddle(body, lookahead);
            _reach[i] = 0.5f * margin + 0.5f * lookahead * speed;
            crowd.Add(body, speed);
        }

        EndScale();
        ImpactCount = 0;
        QuietSubsteps = 0;
        SaturatedSubsteps = 0;
        Searches = 0;
        LeaveOutPairsOfTheCrowd(bodies, contacts, crowd, margin, lookahead); // see ImpactStepper.Crowd.cs
    }

    /// <summary>
    /// Where <see cref="World.Step"/>'s velocity integration writes each body's free flight in the substep: its
    /// velocity before gravity and forces (v₀ of the motion, <see cref="StartVelocities"/>) and after them, before the
    /// responder's resting contacts (<see cref="ForcedVelocities"/>).
    /// </summary>
    public Span<Vector3> StartVelocities => _startVelocity;

    /// <inheritdoc cref="StartVelocities"/>
    public Span<Vector3> ForcedVelocities => _forcedVelocity;

    /// <summary>Moves every body through the substep of length <paramref name="h"/>, answering impacts on the way.</summary>
    public void Move(StepContext step, ICollisionResponder responder, float h, float stepTimeLeft)
    {
        World world = step.World;
        ReadOnlySpan<RigidBody> bodies = step.Bodies;
        CollisionData contacts = step.Contacts;
        _h = h;
        _substepBegins = _stepLength - stepTimeLeft;
        _stepNumber = step.StepNumber;
        _noGravity = world.Gravity == Vector3.Zero;
        _depthCap = DepthCap(responder, _noGravity);
        _supports = responder is SequentialImpulseSolver; // see RestOnImmovable
        int n = bodies.Length;
        BeginQuietCheck();
        for (int i = 0; i < n; i++)
        {
            StartMotion(bodies[i], i, h);
            NoteQuiet(bodies[i], i);
        }

        _contacts = contacts.Storage;
        _contactCount = contacts.Count;
        _bodyCount = n;
        EnsureContacts(_contactCount);
        ReadEnds();
        _linked = _linkedEnds == _endsVersion && _linkedBodies == n; // the lists hold while the contacts and bodies do
        _queue.Clear();
        PredictFirstImpacts(); // in a quiet substep only the contacts that can come near their limits (ImpactStepper.Quiet.cs)

        for (int i = 0; i < n; i++) // not the bodies a search wakes: they join at the end, at rest
        {
            if (LeavesReach(i))
            {
                Search(step, i, stepTimeLeft);
            }
            else if (LeavesFrame(i))
            {
                RestorePairsOf(step, i);
            }
        }

        int impacts = 0, limit = 8 * (_contactCount + n) + 256;
        while (_queue.Count > 0)
        {
            EventQueue.Entry next = _queue.Pop();
            ref Contact contact = ref _contacts[next.Contact];
            Ends(next.Contact, out int a, out int b);
            if (_motion[a].Version != next.VersionA || (b >= 0 && _motion[b].Version != next.VersionB))
            {
                continue; // a body of this pair has collided since: its prediction is stale
            }

            if (++impacts > limit)
            {
                StopAll(_bodyCount);
                SaturatedSubsteps++;
                break;
            }

            Impact(step, responder, ref contact, next.Time);
            ImpactCount++;
            _motion[a].Version++;
            if (b >= 0)
            {
                _motion[b].Version++;
            }

            if (LeavesReach(a) || MayReachSleepers(step, a))
            {
                Search(step, a, stepTimeLeft);
            }
            else if (LeavesFrame(a))
            {
                RestorePairsOf(step, a);
            }

            if (b >= 0 && (LeavesReach(b) || MayReachSleepers(step, b)))
            {
                Search(step, b, stepTimeLeft);
            }
            else if (b >= 0 && LeavesFrame(b))
            {
                RestorePairsOf(step, b);
            }

            PredictAround(a);
            if (b >= 0)
            {
                PredictAround(b, skip: next.Contact);
            }
        }

        bodies = step.Bodies; // with any woken by a search (ImpactStepper.Search.cs)
        for (int i = 0; i < _bodyCount; i++)
        {
            Advance(bodies[i], i, h);
            if (bodies[i].Type != BodyType.Static)
            {
                bodies[i].position = _motion[i].X;
                bodies[i].preciseCentre = _flight[i].PreciseX;
                bodies[i].linearVelocity = _flight[i].U;
            }
        }

        if (_jammed)
        {
            step.ContactsPushed = true; // SlowFarther adds to contact.NormalImpulse (a jam follows an impact, which has said so already)
            SettleJams(bodies, step.Planes);
        }

        _contacts = Array.Empty<Contact>(); // not kept between substeps: the world's storage may shrink or grow
    }

    /// <summary>
    /// One impact at time <paramref name="time"/>: both bodies travel to it, the contact is measured there, the
    /// responder answers it, and a pair that still approaches is stopped along the normal.
    /// </summary>
    private void Impact(StepContext step, ICollisionResponder responder, ref Contact contact, double time)
    {
        step.ContactsPushed = true; // the responder, StopApproach and RestOnImmovable add to contact.NormalImpulse
        RigidBody bodyA = contact.BodyA, bodyB = contact.BodyB;
        int a = bodyA.index, b = bodyB.index;
        Advance(bodyA, a, time);
        bodyA.position = _motion[a].X;
        bodyA.linearVelocity = _flight[a].U;
        if (b >= 0)
        {
            Advance(bodyB, b, time);
            bodyB.position = _motion[b].X;
            bodyB.linearVelocity = _flight[b].U;
        }

        Measure(ref contact, a, b, step.Planes);
        contact.ApproachVelocity = Vectors.Dot(bodyA.VelocityAt(contact.Point) - bodyB.VelocityAt(contact.Point), contact.Normal);
        bool exhausted = _flight[a].Impacts >= ImpactsPerBody || (b >= 0 && _flight[b].Impacts >= ImpactsPerBody);
        int cost = Creeping(contact, a, b) ? ImpactsPerBody / CreepingImpactsPerBody : 1;
        _flight[a].Impacts += cost;
        if (b >= 0)
        {
            _flight[b].Impacts += cost;
        }

        if (exhausted)
        {
            StopApproach(ref contact, a, b);
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

        _flight[a].U = bodyA.linearVelocity;
        if (b >= 0)
        {
            _flight[b].U = bodyB.linearVelocity;
        }

        RestoreAcceleration(a); // a support found at an earlier impact may have been left (see RestOnImmovable)
        if (b >= 0)
        {
            RestoreAcceleration(b);
        }

        RestOnImmovable(ref contact, a, b);
        StopApproach(ref contact, a, b);
        _motion[a].Chord = _flight[a].U + 0.5f * (float)(_h - _motion[a].T) * _flight[a].A;
        if (b >= 0)
        {
            _motion[b].Chord = _flight[b].U + 0.5f * (float)(_h - _motion[b].T) * _flight[b].A;
        }
    }

    /// <summary>
    /// If the centres still approach along the normal for the rest of the substep, push them apart just enough that
    /// they do not (an inelastic impulse through both centres: it conserves momentum and angular momentum and
    /// removes kinetic energy). The responder's answer stands whenever it already separates the pair. Returns whether
    /// it pushed.
    /// </summary>
    private bool StopApproach(ref Contact contact, int a, int b)
    {
        float inverseMassA = contact.BodyA.inverseMass, inverseMassB = contact.BodyB.inverseMass;
        float inverseMassSum = inverseMassA + inverseMassB;
        Vector3 n = contact.Normal;
        Vector3 chordA = _flight[a].U + 0.5f * (float)(_h - _motion[a].T) * _flight[a].A;
        Vector3 chordB = b >= 0 ? _flight[b].U + 0.5f * (float)(_h - _motion[b].T) * _flight[b].A : Vector3.Zero;
        float closing = Vectors.Dot(chordA - chordB, n);
        if (closing >= 0 || inverseMassSum == 0)
        {
            return false;
        }

        float impulse = -closing / inverseMassSum;
        contact.NormalImpulse += impulse;
        _flight[a].U += impulse * inverseMassA * n;
        if (b >= 0)
        {
            _flight[b].U -= impulse * inverseMassB * n;
        }

        contact.BodyA.linearVelocity = _flight[a].U;
        if (b >= 0)
        {
            contact.BodyB.linearVelocity = _flight[b].U;
        }

        return true;
    }

    /// <summary>Drops the rest of the substep's motion: bodies stay where they are now, keeping their velocities.</summary>
    private void StopAll(int n)
    {
        for (int i = 0; i < n; i++)
        {
            _motion[i].T = _h;
            _motion[i].Chord = Vector3.Zero;
        }

        _queue.Clear();
    }
}
