using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
using SimpleDynamics.Response;

namespace SimpleDynamics;

/// <summary>
/// A quiet pile's later substeps predict only the contacts that can come near their depth limits.
/// </summary>
/// <remarks>
/// <para>At the start of each substep every contact's first impact is predicted (see Predict), and in a pile at rest
/// none comes: left out altogether, the settled pits stepped 9–13 % faster (benchmarks/README.md, twenty-eighth
/// session). So under gravity, when most bodies are held by resting contacts and move little, the substep that
/// predicts every contact also sorts them: a contact whose distance lies farther than a margin m from touching, apart
/// or deep, is far from its limit; every other one is listed. m is half of <see cref="HeldDepthTolerance"/> times the
/// smallest radius (50 µm among 0.1 m discs). The later substeps of the same step predict the listed contacts and
/// every contact of a body that is not calm, and no other, as long as the world has the same bodies and contacts and
/// no impact has happened since the sorting.</para>
/// <para>A body is calm if it is static, or held by resting contacts with D + M &lt; m/2 − δ: D is how far it has moved
/// since the sorting (its chords, the position pass, anything), M how far its chord takes it in the substep, and δ an
/// allowance for float rounding. For a pair of calm bodies sorted far from touching, the distance has changed since by
/// at most D_A + D_B and the chords close it by at most M_A + M_B in the substep, together less than m − 2δ: a pair
/// sorted apart cannot come to touch, and a pair sorted deep stays deep, is held, and sinks by less than m ≤ half its
/// limit's tolerance. Such a contact would queue nothing, and the others are predicted in the order of the contacts, as
/// the pass over every contact reaches them: the queue, and so every result, is the same bit for bit (tested, and
/// by <c>Compare</c> on the pits).</para>
/// <para>Measured with <c>Compare</c> on settled pits, both ways round: 4.5 % faster at 1,000 discs, 3.5 % at 4,000, 2.4 %
/// at 16,000, 2.7 % at 4,000 spheres (where one sphere or another still rolls at about 1 cm/s, and its contacts are
/// predicted).</para>
/// </remarks>
internal sealed partial class ImpactStepper
{
    /// <summary>The margin m as a fraction of <see cref="HeldDepthTolerance"/> times the smallest radius.</summary>
    private const float QuietMarginShare = 0.5f;

    /// <summary>
    /// δ as a fraction of the largest coordinate and radius, 2⁻²¹: four units in the last place of the largest
    /// coordinate, against the one or two by which a float difference of centres, or a distance worked out from one,
    /// is rounded.
    /// </summary>
    private const float QuietRounding = 1f / (1 << 21);

    private int[] _nearLimit = new int[InitialContacts]; // the contacts sorted near their limits, in order
    private int _nearLimitCount;
    private ulong[] _toPredict = new ulong[1]; // a quiet substep's contacts to predict, one bit each
    private Vector3[] _sortedAt = new Vector3[InitialBodies]; // per body: its centre when the contacts were sorted
    private int[] _restless = new int[InitialBodies]; // the substep's bodies that are not calm (see NoteQuiet)
    private int _restlessCount, _slowCount;
    private long _sortedStep = -1; // the step whose contacts were sorted (−1: none are)
    private int _sortedContacts, _sortedBodies;
    private float _farMargin, _calm2; // m + δ, and (m/2 − δ)² (see EndScale)
    private float _substep2; // h², for the substep's chords (see BeginQuietCheck)

    // The step's smallest and largest radius and largest coordinate (see NoteScale).
    private float _smallestRadius, _largestRadius, _largestCoordinate;

    /// <summary>For tests: whether quiet substeps predict only the contacts that can come near their limits (default true).</summary>
    internal bool PredictQuietly { get; set; } = true;

    /// <summary>Substeps of the last step that predicted only the contacts that can come near their limits, for tests.</summary>
    internal int QuietSubsteps { get; private set; }

    /// <summary>Begins the step's look at the bodies' sizes and places (see <see cref="NoteScale"/>).</summary>
    private void BeginScale()
    {
        _smallestRadius = float.PositiveInfinity;
        _largestRadius = _largestCoordinate = 0;
    }

    /// <summary>
    /// Notes body <paramref name="body"/>'s radius and place at the start of the step: they set the margin m and the
    /// rounding δ. A calm body moves by far less than m within the step, which changes δ by nothing that counts.
    /// </summary>
    private void NoteScale(RigidBody body)
    {
        _smallestRadius = MathF.Min(_smallestRadius, body.radius);
        _largestRadius = MathF.Max(_largestRadius, body.radius);
        _largestCoordinate = MathF.Max(_largestCoordinate, Vectors.LargestCoordinate(body.position));
    }

    /// <summary>Works out m and the reach within which a body is calm, from the step's scale.</summary>
    private void EndScale()
    {
        float margin = QuietMarginShare * HeldDepthTolerance * _smallestRadius, rounding = QuietRounding * (_largestCoordinate + _largestRadius);
        _farMargin = margin + rounding;
        float calm = 0.5f * margin - rounding;
        _calm2 = calm > 0 ? calm * calm : -1f; // −1: no body is calm (a world too far from the origin for its sizes)
    }

    /// <summary>Begins the substep's look at the bodies' motions (see <see cref="NoteQuiet"/>).</summary>
    private void BeginQuietCheck()
    {
        _restlessCount = _slowCount = 0;
        _substep2 = (float)(_h * _h);
    }

    /// <summary>
    /// Notes whether body <paramref name="i"/>, its motion just started, is calm: static, or held by resting contacts
    /// with D + M &lt; m/2 − δ, where D is how far it has moved since the contacts were sorted and M how far its chord
    /// takes it in the substep (2 (D² + M²) bounds (D + M)²). Counts it as slow if held with 2 M² within that bound.
    /// </summary>
    private void NoteQuiet(RigidBody body, int i)
    {
        if (body.Type == BodyType.Static)
        {
            _slowCount++;
            return;
        }

        ref Motion motion = ref _motion[i];
        float move2 = _substep2 * Vectors.LengthSquared(motion.Chord);
        bool held = _held[i];
        _slowCount += held && 2 * move2 <= _calm2 ? 1 : 0;
        if (_sortedStep != _stepNumber || i >= _sortedBodies)
        {
            return;
        }

        if (!held || 2 * (Vectors.DistanceSquared(motion.X, _sortedAt[i]) + move2) > _calm2)
        {
            if (_restlessCount < _restless.Length)
            {
                _restless[_restlessCount] = i;
            }

            _restlessCount++;
        }
    }

    /// <summary>
    /// Predicts every contact's first impact in the substep; in a quiet substep only those of the contacts sorted near
    /// their limits and of the bodies that are not calm (see the remarks above). Sorts the contacts when most bodies
    /// are slow.
    /// </summary>
    private void PredictFirstImpacts()
    {
        if (PredictQuietly && !_noGravity && _sortedStep == _stepNumber && _sortedContacts == _contactCount
            && _sortedBodies == _bodyCount && _restlessCount <= _bodyCount / 8)
        {
            PredictNearLimits();
            QuietSubsteps++;
            return;
        }

        bool sort = PredictQuietly && !_noGravity && _calm2 > 0 && _slowCount >= _bodyCount - _bodyCount / 8;
        _nearLimitCount = 0;
        for (int k = 0; k < _contactCount; k++)
        {
            _limit[k] = float.NaN;
            Predict(k);
            if (sort && !FarFromLimit(k))
            {
                _nearLimit[_nearLimitCount++] = k;
            }
        }

        _sortedStep = -1;
        if (sort)
        {
            for (int i = 0; i < _bodyCount; i++)
            {
                _sortedAt[i] = _motion[i].X;
            }

            (_sortedStep, _sortedContacts, _sortedBodies) = (_stepNumber, _contactCount, _bodyCount);
        }
    }

    /// <summary>
    /// A quiet substep's predictions: the contacts sorted near their limits and every contact of a body that is not
    /// calm, each once and in the order of the contacts, as the pass over every contact would have reached them.
    /// </summary>
    private void PredictNearLimits()
    {
        Array.Fill(_limit, float.NaN, 0, _contactCount);
        int words = (_contactCount + 63) >> 6;
        Array.Clear(_toPredict, 0, words);
        for (int u = 0; u < _nearLimitCount; u++)
        {
            int k = _nearLimit[u];
            _toPredict[k >> 6] |= 1UL << k;
        }

        if (_restlessCount > 0)
        {
            EnsureLinked();
            for (int r = 0; r < _restlessCount; r++)
            {
                for (int e = _head[_restless[r]]; e >= 0; e = _next[e])
                {
                    int k = e >> 1;
                    _toPredict[k >> 6] |= 1UL << k;
                }
            }
        }

        for (int w = 0; w < words; w++)
        {
            for (ulong bits = _toPredict[w]; bits != 0; bits &= bits - 1)
            {
                Predict((w << 6) + ContactMarks.TrailingZeros(bits));
            }
        }
    }

    /// <summary>After a substep's impacts: anything that happened in it ends the use of the sorting for the step.</summary>
    private void EndQuietSubstep(int impacts)
    {
        if (impacts > 0 || _contactCount != _sortedContacts || _jammed)
        {
            _sortedStep = -1;
        }
    }

    /// <summary>
    /// Whether contact <paramref name="k"/>'s bodies are farther than m + δ from touching, apart or deep, where they are
    /// now (see the remarks above).
    /// </summary>
    private bool FarFromLimit(int k)
    {
        float margin = _farMargin;
        Ends(k, out int a, out int b);
        ref Motion motionA = ref _motion[a];
        if (b < 0)
        {
            ref Contact contact = ref _contacts[k];
            float gap = Vectors.Dot(contact.Normal, motionA.X) - contact.PlaneOffset - motionA.Radius; // < 0: deep
            return MathF.Abs(gap) > margin;
        }

        ref Motion motionB = ref _motion[b];
        float reach = motionA.Radius + motionB.Radius;
        float distance2 = Vectors.DistanceSquared(motionA.X, motionB.X);
        float outer = reach + margin, inner = reach - margin;
        return distance2 > outer * outer || (inner > 0 && distance2 < inner * inner);
    }
}
