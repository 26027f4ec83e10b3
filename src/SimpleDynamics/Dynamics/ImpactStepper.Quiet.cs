using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
using SimpleDynamics.Response;

namespace SimpleDynamics;

/// <summary>
/// A quiet pile's substeps predict only the contacts that can come near their depth limits.
/// </summary>
/// <remarks>
/// <para>At the start of each substep every contact's first impact is predicted (see Predict), and in a pile at rest
/// none comes: left out altogether, the settled pits stepped 9–13 % faster (benchmarks/README.md, twenty-eighth
/// session). So under gravity, when most bodies are held by resting contacts and move little, a substep that predicts
/// every contact also sorts them. Each body gets a place, where it is and how large; a contact whose bodies' places lie
/// farther than a margin m from touching, apart or deep, is far from its limit, and every other one is near. m is half
/// of <see cref="HeldDepthTolerance"/> times the smallest radius (50 µm among 0.1 m discs). From then on, in this step
/// and the next ones, a substep predicts the near contacts and every contact of a restless body, and no other, as long
/// as the bodies are as many and at most one in eight is restless.</para>
/// <para>A body is calm if it is static, or held by resting contacts with D + M &lt; m/2 − δ: D is how far it is from its
/// place (moved there by its chords, the position pass, a jam settled, the user: anything), M how far its chord takes
/// it in the substep, and δ an allowance for float rounding; in either case it must have its place's radius. For a pair
/// of calm bodies far at their places, the distance differs from the places' by at most D_A + D_B and the chords close
/// it by at most M_A + M_B in the substep, together less than m − 2δ: a pair far apart cannot come to touch, and a pair
/// far deep stays deep, is held, and sinks by less than m ≤ half its limit's tolerance. Such a contact would queue
/// nothing, and the others are predicted in the order of the contacts, as the pass over every contact reaches them:
/// the queue, and so every result, is the same bit for bit (tested, and by <c>Compare</c> on the pits).</para>
/// <para>The sorting is kept from step to step. A body that is not calm is restless if it is neither static nor held
/// with 2 M² within (m/2 − δ)², and its contacts are predicted; one that is slow but far from its place has drifted,
/// and gets a new place where it is now, its contacts judged again between places (<see cref="Reanchor"/>). Detection
/// finds the contacts afresh each step: one between the same two ends (bodies, or a body and a plane) as a sorted
/// contact is as far as that one, for the places are the same, and one not found among them is near
/// (<see cref="Remap"/>). m and δ stay the sorting's.</para>
/// <para>Measured with <c>Compare</c> on settled pits, both ways round. Later substeps of the same step only
/// (twenty-eighth session): 4.5 % faster at 1,000 discs, 3.5 % at 4,000, 2.4 % at 16,000, 2.7 % at 4,000 spheres.
/// Kept from step to step, with new places for drifted bodies, against that (twenty-ninth session): a further 4–6 % at
/// 1,000 discs, 4 % at 4,000, 2–5 % at 16,000 (benchmarks/README.md).</para>
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

    private int[] _sortedPairs = new int[2 * InitialContacts]; // the contacts' ends the sorting is for (see Remap)
    private int _sortedPairCount;
    private ulong[] _nearBits = new ulong[1]; // by contact of _sortedPairs: near its limit, one bit each
    private ulong[] _toPredict = new ulong[1]; // a quiet substep's contacts to predict, one bit each
    private Place[] _sortedAt = new Place[InitialBodies]; // per body: its centre and radius when the contacts were sorted
    private int[] _restless = new int[InitialBodies]; // the substep's bodies that move too fast to be calm (see NoteQuiet)
    private int[] _drifted = new int[InitialBodies]; // the substep's slow bodies that have moved too far since the sorting
    private int _restlessCount, _driftedCount, _slowCount;
    private long _sortedEnds = -1; // the version of the contacts' ends that was sorted (−1: none is; see ReadEnds)
    private int _sortedBodies;
    private float _sortedFarMargin, _sortedCalm2, _sortedRounding; // m + δ, (m/2 − δ)² and δ of the sorting: they stay
    private float _sortedScale; // the largest coordinate then, which δ was worked out for (see Reanchor)
    private float _farMargin, _calm2, _rounding; // m + δ, (m/2 − δ)² and δ this step (see EndScale)
    private float _substep2; // h², for the substep's chords (see BeginQuietCheck)

    // The step's smallest and largest radius and largest coordinate (see NoteScale).
    private float _smallestRadius, _largestRadius, _largestCoordinate;

    /// <summary>For tests: whether quiet substeps predict only the contacts that can come near their limits (default true).</summary>
    internal bool PredictQuietly { get; set; } = true;

    /// <summary>Substeps of the last step that predicted only the contacts that can come near their limits, for tests.</summary>
    internal int QuietSubsteps { get; private set; }

    /// <summary>For tests: whether quiet substeps check the contacts they leave out (see <see cref="CountUnpredictedNearLimits"/>).</summary>
    internal bool CheckQuietSubsteps { get; set; }

    /// <summary>For tests: contacts left out by a quiet substep that its chords could bring near their limits (none, if sound).</summary>
    internal long UnpredictedNearLimits { get; private set; }

    /// <summary>Where a body was, and how large, when the contacts were sorted.</summary>
    private struct Place
    {
        public Vector3 Centre;
        public float Radius;
    }

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
        (_farMargin, _rounding) = (margin + rounding, rounding);
        float calm = 0.5f * margin - rounding;
        _calm2 = calm > 0 ? calm * calm : -1f; // −1: no body is calm (a world too far from the origin for its sizes)
    }

    /// <summary>Begins the substep's look at the bodies' motions (see <see cref="NoteQuiet"/>).</summary>
    private void BeginQuietCheck()
    {
        _restlessCount = _driftedCount = _slowCount = 0;
        _substep2 = (float)(_h * _h);
    }

    /// <summary>
    /// Notes whether body <paramref name="i"/>, its motion just started, is calm: static and where it was when the
    /// contacts were sorted, or held by resting contacts with D + M &lt; m/2 − δ, where D is how far it has moved since
    /// the sorting and M how far its chord takes it in the substep (2 (D² + M²) bounds (D + M)²); either way with the
    /// radius it had then. A body that is not calm is restless if it is neither static nor held with 2 M² within that
    /// bound, else it has drifted (see <see cref="Reanchor"/>). Counts it as slow if static, or held with 2 M² within
    /// the bound of this step's m and δ.
    /// </summary>
    private void NoteQuiet(RigidBody body, int i)
    {
        ref Motion motion = ref _motion[i];
        bool isStatic = body.Type == BodyType.Static, held = _held[i];
        float move2 = isStatic ? 0f : _substep2 * Vectors.LengthSquared(motion.Chord);
        _slowCount += isStatic || (held && 2 * move2 <= _calm2) ? 1 : 0;
        if (_sortedEnds < 0 || i >= _sortedBodies)
        {
            return;
        }

        if (!isStatic && (!held || 2 * move2 > _sortedCalm2))
        {
            _restless[_restlessCount++] = i;
            return;
        }

        ref Place sorted = ref _sortedAt[i];
        float moved2 = Vectors.DistanceSquared(motion.X, sorted.Centre);
        if (!(isStatic ? moved2 == 0 : 2 * (moved2 + move2) <= _sortedCalm2) || motion.Radius != sorted.Radius)
        {
            _drifted[_driftedCount++] = i;
        }
    }

    /// <summary>
    /// Gives each drifted body a new place, where it is now, and judges its contacts again between places: a pair's
    /// distance now differs from the distance of its bodies' places by at most D_A + D_B, whenever each place was
    /// taken, so the calm test holds as it did. Only for a body with the radius it was sorted with and within the
    /// coordinates δ was worked out for; another stays restless.
    /// </summary>
    private void Reanchor()
    {
        for (int d = 0; d < _driftedCount; d++)
        {
            int i = _drifted[d];
            ref Motion motion = ref _motion[i];
            if (motion.Radius != _sortedAt[i].Radius || Vectors.LargestCoordinate(motion.X) > _sortedScale)
            {
                _restless[_restlessCount++] = i;
                continue;
            }

            _sortedAt[i].Centre = motion.X;
            for (int e = _head[i]; e >= 0; e = _next[e])
            {
                int k = e >> 1;
                ulong bit = 1UL << k;
                _nearBits[k >> 6] = FarFromLimit(k) ? _nearBits[k >> 6] & ~bit : _nearBits[k >> 6] | bit;
            }
        }
    }

    /// <summary>
    /// Predicts every contact's first impact in the substep; in a quiet substep only those of the contacts sorted near
    /// their limits and of the bodies that are not calm (see the remarks above). Sorts the contacts when most bodies
    /// are slow.
    /// </summary>
    private void PredictFirstImpacts()
    {
        if (PredictQuietly && !_noGravity && _sortedEnds >= 0 && _sortedBodies == _bodyCount
            && _restlessCount <= _bodyCount / 8 && _driftedCount <= _bodyCount / 4)
        {
            if (_sortedEnds != _endsVersion)
            {
                Remap();
            }

            if (_driftedCount > 0)
            {
                EnsureLinked();
                Reanchor();
            }

            PredictNearLimits();
            QuietSubsteps++;
            if (CheckQuietSubsteps)
            {
                CountUnpredictedNearLimits();
            }

            return;
        }

        bool sort = PredictQuietly && !_noGravity && _calm2 > 0 && _slowCount >= _bodyCount - _bodyCount / 8;
        if (sort)
        {
            for (int i = 0; i < _bodyCount; i++)
            {
                _sortedAt[i] = new Place { Centre = _motion[i].X, Radius = _motion[i].Radius };
            }

            (_sortedFarMargin, _sortedCalm2, _sortedRounding, _sortedScale) = (_farMargin, _calm2, _rounding, _largestCoordinate);
        }

        int words = (_contactCount + 63) >> 6;
        Array.Clear(_nearBits, 0, words);
        for (int k = 0; k < _contactCount; k++)
        {
            _limit[k] = float.NaN;
            Predict(k);
            if (sort && !FarFromLimit(k))
            {
                _nearBits[k >> 6] |= 1UL << k;
            }
        }

        _sortedEnds = -1;
        if (sort)
        {
            Array.Copy(_ends, _sortedPairs, 2 * _contactCount);
            (_sortedEnds, _sortedPairCount, _sortedBodies) = (_endsVersion, _contactCount, _bodyCount);
        }
    }

    /// <summary>
    /// Carries the sorting over to contacts that changed since (detection found a pair more or less, or the same pairs
    /// in another order, or the step added one): a contact between the same two ends as a sorted one is as far from
    /// its limit as that one, for both were judged between the same places, which the calm test measures from; a
    /// contact not found among the sorted ones is near. Detection meets a quiet pile's pairs in
    /// nearly the same order every step, so each is looked for where the one before it was found, shifted alike,
    /// and then a few places either side.
    /// </summary>
    private void Remap()
    {
        const int Window = 8;
        int words = (_contactCount + 63) >> 6, offset = 0;
        Array.Clear(_toPredict, 0, words);
        for (int k = 0; k < _contactCount; k++)
        {
            int a = _ends[2 * k], b = _ends[2 * k + 1];
            int found = -1, guess = k + offset;
            for (int tries = 0; tries <= 2 * Window && found < 0; tries++)
            {
                int j = guess + ((tries & 1) == 0 ? tries >> 1 : -((tries + 1) >> 1)); // guess, guess − 1, guess + 1, …
                if ((uint)j < (uint)_sortedPairCount && _sortedPairs[2 * j] == a && _sortedPairs[2 * j + 1] == b)
                {
                    found = j;
                }
            }

            if (found >= 0)
            {
                offset = found - k;
            }

            if (found < 0 || (_nearBits[found >> 6] & (1UL << found)) != 0)
            {
                _toPredict[k >> 6] |= 1UL << k;
            }
        }

        (_nearBits, _toPredict) = (_toPredict, _nearBits);
        Array.Copy(_ends, _sortedPairs, 2 * _contactCount);
        (_sortedEnds, _sortedPairCount) = (_endsVersion, _contactCount);
    }

    /// <summary>
    /// A quiet substep's predictions: the contacts sorted near their limits and every contact of a body that is not
    /// calm, each once and in the order of the contacts, as the pass over every contact would have reached them.
    /// </summary>
    private void PredictNearLimits()
    {
        Array.Fill(_limit, float.NaN, 0, _contactCount);
        int words = (_contactCount + 63) >> 6;
        Array.Copy(_nearBits, _toPredict, words);
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

    /// <summary>
    /// For tests, what the remarks above promise of every contact a quiet substep leaves out, checked where the bodies
    /// are now: its distance lies farther from touching, apart or deep, than M_A + M_B + 2δ (it is at least m + δ − D_A −
    /// D_B away, and D_A + D_B + M_A + M_B &lt; m − 2δ). Counts the ones that do not.
    /// </summary>
    private void CountUnpredictedNearLimits()
    {
        for (int k = 0; k < _contactCount; k++)
        {
            if ((_toPredict[k >> 6] & (1UL << k)) != 0)
            {
                continue;
            }

            Ends(k, out int a, out int b);
            ref Motion motionA = ref _motion[a];
            float chords = MathF.Sqrt(_substep2 * Vectors.LengthSquared(motionA.Chord)), gap;
            if (b < 0)
            {
                ref Contact contact = ref _contacts[k];
                gap = -ContactGeometry.Unchecked.PlanePenetration(motionA.X, motionA.Radius, contact.Normal, contact.PlaneOffset);
            }
            else
            {
                ref Motion motionB = ref _motion[b];
                chords += MathF.Sqrt(_substep2 * Vectors.LengthSquared(motionB.Chord));
                gap = Vectors.Distance(motionA.X, motionB.X) - motionA.Radius - motionB.Radius;
            }

            UnpredictedNearLimits += MathF.Abs(gap) <= chords + 2 * _sortedRounding ? 1 : 0;
        }
    }

    /// <summary>
    /// Whether contact <paramref name="k"/>'s bodies are farther than m + δ from touching, apart or deep, at their
    /// places (see <see cref="Place"/> and the remarks above).
    /// </summary>
    private bool FarFromLimit(int k)
    {
        float margin = _sortedFarMargin;
        Ends(k, out int a, out int b);
        ref Place placeA = ref _sortedAt[a];
        if (b < 0)
        {
            ref Contact contact = ref _contacts[k];
            return MathF.Abs(ContactGeometry.Unchecked.PlanePenetration(placeA.Centre, placeA.Radius, contact.Normal, contact.PlaneOffset)) > margin;
        }

        ref Place placeB = ref _sortedAt[b];
        float reach = placeA.Radius + placeB.Radius;
        float distance2 = Vectors.DistanceSquared(placeA.Centre, placeB.Centre);
        float outer = reach + margin, inner = reach - margin;
        return distance2 > outer * outer || (inner > 0 && distance2 < inner * inner);
    }
}

