using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics;

// Leaving out the pairs of a crowd that moves together, while both bodies keep to the crowd's motion.
internal sealed partial class ImpactStepper
{
    // The crowd's frame this step (see LeaveOutPairsOfTheCrowd), and each body's sphere in it.
    private bool _frameUsed;
    private int _framePause; // steps left before the frame is tried again (see FramePauseSteps)
    private int _frameBodies; // the bodies of the step when it began (not those a search wakes)
    private Vector3 _frameVelocity;
    private float _stepLength;
    private double _substepBegins; // time since the step began, at the start of the substep being moved
    private Vector3[] _frameCentre = new Vector3[InitialBodies];
    private float[] _frameReach = new float[InitialBodies];
    private bool[] _keepsToFrame = new bool[InitialBodies]; // whether some pair left out relies on the body keeping to its sphere in the frame

    // The pairs left out: the contacts detection reported for them, and each body's, listed by body.
    private Contact[] _leftOut = new Contact[InitialContacts];
    private int _leftOutCount;
    private int[] _leftOutStart = new int[InitialBodies + 1]; // body i's entries are _leftOutOf[_leftOutStart[i] .. _leftOutStart[i + 1])
    private int[] _leftOutOf = new int[2 * InitialContacts];

    /// <summary>The steps the frame rests after a step that made more than an eighth of the pairs it left out contacts again.</summary>
    private const int FramePauseSteps = 15;

    /// <summary>For tests: whether the pairs of a crowd may be left out (by default they may).</summary>
    public bool LeaveOutCrowdPairs { get; set; } = true;

    /// <summary>Pairs left out at the start of the last step because they moved together (see <see cref="LeaveOutPairsOfTheCrowd"/>).</summary>
    public int PairsLeftOut { get; private set; }

    /// <summary>Of those, the pairs made contacts again during the step because a body left the crowd's motion.</summary>
    public int PairsRestored { get; private set; }

    /// <summary>
    /// Leaves out of the step's contacts the pairs of a crowd that moves together, as long as both bodies keep to the
    /// crowd's motion.
    /// </summary>
    /// <remarks>
    /// <para>Detection gives each body a sphere around its path over the step, whose radius grows with the body's own
    /// speed, so that two bodies whose spheres do not meet cannot meet while each stays in its sphere (see
    /// ContactGeometry.TryCollide). A crowd falling together at 20 m/s is then reported neighbour to neighbour, two or
    /// three diameters apart: the 16,000-disc pit, falling, had ten contacts per disc, each measured every substep and
    /// predicted by this pass, though none of them approached.</para>
    /// <para>The same reasoning holds in any frame that moves at a constant velocity V: there a body's path over the
    /// step is x + (v − V) t, inside the sphere centred at x + (v − V) dt / 2 of radius r + margin / 2 + |v − V| dt / 2
    /// (half the margin holds the ½ |g| dt² that gravity bends every path by, as in the world). Two bodies whose
    /// spheres in the frame do not meet cannot meet while each stays in its sphere in the frame, which moves with the
    /// frame. For a crowd moving at about V these spheres are as small as a body's at rest. So with V the mean velocity
    /// of the bodies moving faster than the speed gravity adds in a step, a pair is left out when its spheres meet in
    /// the world but not in the frame; its bodies are marked as keeping to the frame.</para>
    /// <para>A body that leaves its sphere in the frame (a collision, the responder, or the landing of a crowd changed
    /// its velocity) has its pairs that were left out made contacts again, measured where the bodies are, and
    /// predicted like any other (see <see cref="LeavesFrame"/>). A body that leaves its sphere in the world is looked
    /// up against every body, as before (see <see cref="Search"/>).</para>
    /// <para>The frame is used only when it is worth it: when at least an eighth of the dynamic bodies move, and taking
    /// for each body the smaller of its two spheres at least halves the sum of the radii that grow with speed. A pile
    /// at rest, or a few balls flying about, keeps every pair detection reported. Nor while a crowd lands or is
    /// struck: a shock runs through a packed crowd within the substep, and nearly every pair left out is made a contact
    /// again in the same step, which costs more than keeping it (the 16,000-disc pit as it landed, at steps 150, 180,
    /// 210 and 240: 92–100 % of the 8,000–62,000 pairs left out). So after a step that restored more than an eighth
    /// of the pairs it left out, the frame rests for <see cref="FramePauseSteps"/> steps.</para>
    /// </remarks>
    private void LeaveOutPairsOfTheCrowd(ReadOnlySpan<RigidBody> bodies, CollisionData contacts, in CrowdMotion crowd, float margin, float lookahead)
    {
        if (_frameUsed && PairsRestored > PairsLeftOut / 8)
        {
            _framePause = FramePauseSteps; // the crowd is landing or struck: see the remarks
        }

        _frameUsed = false;
        Array.Clear(_leftOut, 0, _leftOutCount); // no body kept from being collected
        _leftOutCount = 0;
        PairsLeftOut = 0;
        PairsRestored = 0;
        _stepLength = lookahead;
        if (_framePause > 0)
        {
            _framePause--;
            return;
        }

        if (!LeaveOutCrowdPairs || !ChooseFrame(crowd) || !PlaceFrameSpheres(bodies, margin, lookahead))
        {
            return;
        }

        _frameUsed = true;
        int n = _frameBodies = bodies.Length;

        Contact[] storage = contacts.Storage;
        int count = contacts.Count, kept = 0;
        for (int k = 0; k < count; k++)
        {
            ref Contact contact = ref storage[k];
            if (!contact.IsPlaneContact && ApartInFrame(contact.BodyA, contact.BodyB))
            {
                Buffers.EnsureCapacity(ref _leftOut, _leftOutCount + 1);
                _leftOut[_leftOutCount++] = contact;
                _keepsToFrame[contact.BodyA.index] = _keepsToFrame[contact.BodyB.index] = true;
                continue;
            }

            if (kept != k)
            {
                storage[kept] = contact;
            }

            kept++;
        }

        contacts.TruncateTo(kept);
        PairsLeftOut = _leftOutCount;
        ListLeftOutByBody(n);
    }

    /// <summary>
    /// What the step's first pass over the bodies gathers for the crowd's frame: the dynamic bodies, and the sum of the
    /// velocities of those faster than g dt, the speed gravity adds in a step (slower ones rest or creep).
    /// </summary>
    private struct CrowdMotion
    {
        private readonly float _slow;
        public Vector3 MovingVelocities;
        public int Moving, Dynamic;

        public CrowdMotion(float slow) => (_slow, MovingVelocities, Moving, Dynamic) = (slow, Vector3.Zero, 0, 0);

        public void Add(RigidBody body, float speed)
        {
            if (!body.IsDynamic)
            {
                return;
            }

            Dynamic++;
            if (speed > _slow)
            {
                MovingVelocities += body.linearVelocity;
                Moving++;
            }
        }
    }

    /// <summary>
    /// Takes the mean velocity of the moving bodies (see <see cref="CrowdMotion"/>) as the crowd's, if at least an
    /// eighth of the dynamic bodies move.
    /// </summary>
    private bool ChooseFrame(in CrowdMotion crowd)
    {
        if (crowd.Moving < 2 || crowd.Moving < crowd.Dynamic / 8)
        {
            return false;
        }

        _frameVelocity = crowd.MovingVelocities / crowd.Moving;
        return true;
    }

    /// <summary>
    /// Gives every body its sphere in the crowd's frame; returns whether taking for each dynamic body the smaller of
    /// its two spheres at least halves the sum of their radii that grow with speed (<see cref="_reach"/> holds the
    /// world's, from <see cref="BeginStep"/>).
    /// </summary>
    private bool PlaceFrameSpheres(ReadOnlySpan<RigidBody> bodies, float margin, float lookahead)
    {
        float grown = 0, saved = 0;
        for (int i = 0; i < bodies.Length; i++)
        {
            RigidBody body = bodies[i];
            Vector3 relative = body.linearVelocity - _frameVelocity;
            _frameCentre[i] = body.position + relative * (0.5f * lookahead);
            _frameReach[i] = 0.5f * margin + 0.5f * lookahead * Vectors.Length(relative);
            _keepsToFrame[i] = false;
            if (body.IsDynamic)
            {
                grown += _reach[i] - 0.5f * margin;
                saved += MathF.Max(_reach[i] - _frameReach[i], 0f);
            }
        }

        return saved >= 0.5f * grown && grown > 0;
    }

    /// <summary>Whether the spheres of two bodies in the crowd's frame do not meet.</summary>
    private bool ApartInFrame(RigidBody a, RigidBody b)
    {
        int i = a.index, j = b.index;
        float reach = a.radius + b.radius + _frameReach[i] + _frameReach[j];
        return Vectors.DistanceSquared(_frameCentre[i], _frameCentre[j]) >= reach * reach;
    }

    /// <summary>Lists the pairs left out under each of their bodies (a counting sort by body).</summary>
    private void ListLeftOutByBody(int n)
    {
        Buffers.EnsureCapacity(ref _leftOutStart, n + 1);
        Buffers.EnsureCapacity(ref _leftOutOf, 2 * _leftOutCount);
        Array.Clear(_leftOutStart, 0, n + 1);
        for (int l = 0; l < _leftOutCount; l++)
        {
            _leftOutStart[_leftOut[l].BodyA.index + 1]++;
            _leftOutStart[_leftOut[l].BodyB.index + 1]++;
        }

        for (int i = 0; i < n; i++)
        {
            _leftOutStart[i + 1] += _leftOutStart[i];
        }

        for (int l = 0; l < _leftOutCount; l++) // each body's entries fill from its start; the starts are restored below
        {
            _leftOutOf[_leftOutStart[_leftOut[l].BodyA.index]++] = l;
            _leftOutOf[_leftOutStart[_leftOut[l].BodyB.index]++] = l;
        }

        for (int i = n; i > 0; i--)
        {
            _leftOutStart[i] = _leftOutStart[i - 1];
        }

        _leftOutStart[0] = 0;

        // Each body's pairs by their keys, so that they are restored in the same order whatever order detection
        // reported them in (insertion sort: a body of a crowd has a handful).
        for (int i = 0; i < n; i++)
        {
            for (int e = _leftOutStart[i] + 1; e < _leftOutStart[i + 1]; e++)
            {
                int l = _leftOutOf[e];
                ulong key = _leftOut[l].Key;
                int f = e;
                for (; f > _leftOutStart[i] && _leftOut[_leftOutOf[f - 1]].Key > key; f--)
                {
                    _leftOutOf[f] = _leftOutOf[f - 1];
                }

                _leftOutOf[f] = l;
            }
        }
    }

    /// <summary>
    /// Whether body i, which some pair left out relies on, leaves its sphere in the crowd's frame by the end of the
    /// substep. Its path to there is straight in the frame too, and it starts inside, so its end decides.
    /// </summary>
    private bool LeavesFrame(int i)
    {
        if (!_frameUsed || i >= _frameBodies || !_keepsToFrame[i])
        {
            return false;
        }

        Vector3 end = _motion[i].X + _motion[i].Chord * (float)(_h - _motion[i].T);
        Vector3 centre = _frameCentre[i] + _frameVelocity * (float)(_substepBegins + _h);
        return Vectors.DistanceSquared(end, centre) > _frameReach[i] * _frameReach[i];
    }

    /// <summary>
    /// Makes the pairs left out of body i contacts again, measured where the bodies are now (as a search measures
    /// them), unless the pair has one already.
    /// </summary>
    private void RestorePairsOf(StepContext step, int i)
    {
        _keepsToFrame[i] = false;
        EnsureLinked();
        CollisionData contacts = step.Contacts;
        for (int e = _leftOutStart[i]; e < _leftOutStart[i + 1]; e++)
        {
            RigidBody first = _leftOut[_leftOutOf[e]].BodyA, second = _leftOut[_leftOutOf[e]].BodyB;
            if (HasContactWith(i, first.index == i ? second.index : first.index))
            {
                continue; // restored from its other body, or found by a search
            }

            PairsRestored++;
            AddMeasuredContact(contacts, first, second);
        }
    }
}
