using System;
using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Response;

/// <summary>The position pass: the projection of listing 2 as non-linear Gauss–Seidel sweeps.</summary>
public sealed partial class SequentialImpulseSolver
{
    private void CorrectPositions(ReadOnlySpan<RigidBody> bodies, int count)
    {
        if (_positionIterations == 0 || count == 0)
        {
            return;
        }

        for (int i = 0; i < bodies.Length; i++)
        {
            _positions[_slotOf[i]] = bodies[i].position;
        }

        count = Math.Min(count, _prepared);
        for (int iteration = 0; iteration < _positionIterations; iteration++)
        {
            for (int k = 0; k < count; k++)
            {
                CorrectPosition(ref _constraints[k], shock: false, _correctionFactor);
            }
        }

        // A last sweep removes the whole depth beyond the slop: under gravity, contacts that carry weight (normal
        // within about 45° of vertical) propagate the shock bottom-up; every other contact, and every contact without
        // gravity, is corrected in full, split by inverse mass.
        // A settled pile corrects next to nothing here; a jam against a wall corrects a sideways contact by much more,
        // and only then can the walk from what cannot move have anything to do.
        bool sidewaysCorrected = false, corrected = false;
        for (int k = 0; k < count; k++)
        {
            ref ContactConstraint c = ref _constraints[k];
            float correction = CorrectPosition(ref c, shock: c.CarriesWeight, factor: 1f);
            sidewaysCorrected |= !c.CarriesWeight && correction > 0.01f * _slop;
            corrected |= correction > 0.01f * _slop;
        }

        if (sidewaysCorrected)
        {
            PropagateFromAnchors(count, bodies.Length + 1); // see SequentialImpulseSolver.Anchoring.cs
        }

        if (corrected && TouchesAnythingImmovable(count))
        {
            SweepWhatStaysDeep(count, bodies.Length + 1); // see SequentialImpulseSolver.Residual.cs
        }

        for (int i = 0; i < bodies.Length; i++)
        {
            if (bodies[i].IsDynamic)
            {
                bodies[i].position = _positions[_slotOf[i]];
            }
        }
    }

    /// <summary>
    /// Listing 2 as a Gauss–Seidel position sweep: measure the contact at the current positions and push the
    /// bodies apart along the normal, split by inverse mass, by a bounded share of the depth beyond the slop. With
    /// <paramref name="shock"/> (the last, bottom-up sweep under gravity) the whole depth beyond the slop is removed
    /// by moving the upper body alone. <paramref name="factor"/> is the share of the excess depth removed. Returns the
    /// depth removed (0 when none).
    /// </summary>
    private float CorrectPosition(ref ContactConstraint c, bool shock, float factor)
    {
        float inverseMassA = _bodies[c.A].InverseMass, inverseMassB = _bodies[c.B].InverseMass;
        if (shock)
        {
            if (c.AIsUpper ? inverseMassA == 0 : inverseMassB == 0)
            {
                return 0;
            }

            inverseMassA = c.AIsUpper ? 1f : 0f;
            inverseMassB = c.AIsUpper ? 0f : 1f;
        }

        float inverseMassSum = inverseMassA + inverseMassB;
        if (inverseMassSum == 0 || ClearlyWithinSlop(ref c))
        {
            return 0;
        }

        float penetration = Depth(ref c, out Vector3 normal);
        float correction = shock ? penetration - _slop : MathF.Min(factor * (penetration - _slop), _maxCorrection);
        if (correction <= 0)
        {
            return 0;
        }

        Separate(ref c, normal, correction, inverseMassA, inverseMassB);
        return correction;
    }

    /// <summary>
    /// Whether two bodies' centres are so far apart that their depth is certainly below the slop: the squared distance
    /// beyond (r_A + r_B − slop)² by more than float rounding could account for. Most contacts of a settled pile are
    /// shallower than the slop (84 % of the position pass's visits in the settled 4,000-disc 2-D pit), and this spares
    /// them the square root of measuring; the rest are measured as before, so the pass's result is the same.
    /// </summary>
    private bool ClearlyWithinSlop(ref ContactConstraint c)
    {
        if (c.IsPlaneContact)
        {
            return false;
        }

        float reach = c.RadiusA + c.RadiusB - _slop;
        return reach > 0 && Vector3.DistanceSquared(_positions[c.A], _positions[c.B]) > reach * reach * (1f + 1e-5f);
    }

    /// <summary>Pushes the contact's bodies apart along the normal by <paramref name="correction"/>, split by the inverse masses given.</summary>
    private void Separate(ref ContactConstraint c, Vector3 normal, float correction, float inverseMassA, float inverseMassB)
    {
        float share = correction / (inverseMassA + inverseMassB);
        _positions[c.A] += normal * (share * inverseMassA);
        _positions[c.B] -= normal * (share * inverseMassB);
    }
}
