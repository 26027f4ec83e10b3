using System;
using System.Diagnostics;
using System.Numerics;
using System.Runtime.CompilerServices;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>The velocity sweeps: warm start, Gauss–Seidel iterations, and the impulses' bookkeeping.</summary>
public sealed partial class SequentialImpulseSolver
{
    /// <summary>
    /// Applies the impulses accumulated so far (last step's from the cache on the first substep, the previous
    /// substep's after that), so that a resting pile starts each substep almost solved. Without warm starting they
    /// start from zero.
    /// </summary>
    private void WarmStart() => RunPass(StripPass.WarmStart);

    [MethodImpl(MethodImplOptions.AggressiveInlining)] // in the warm start's loop
    private void WarmStart(int k)
    {
        ref ContactConstraint c = ref _constraints[k];
        if (!WarmStarting)
        {
            c.NormalImpulse = c.FrictionImpulse1 = 0;
            if (!_planar)
            {
                c.FrictionImpulse2 = 0;
            }

            return;
        }

        if (_planar)
        {
            ApplyPlanar(ref c, c.NormalImpulse, c.FrictionImpulse1);
        }
        else
        {
            ref TangentFrame f = ref _frames[k];
            Apply(ref c, ref f, c.NormalImpulse, c.FrictionImpulse1, c.FrictionImpulse2);
        }
    }

    /// <summary>Velocity sweeps done in the step begun last, for tests.</summary>
    internal int SweepsThisStep { get; private set; }

    /// <summary>
    /// <see cref="VelocityIterations"/> Gauss–Seidel sweeps over every contact, bottom-up, then up to
    /// <see cref="ExtraIterations"/> more while the last one has not converged; only one when the first finds the
    /// contacts already solved.
    /// </summary>
    private void Sweeps()
    {
        // A pile that the warm start has solved shows it in the first sweep, which then changes no contact's normal
        // velocity by more than a fraction of the tolerance: the other sweeps are left out (a settled pile spends one
        // sweep a substep). A 3-D pile that the first sweep leaves within the tolerance the later sweeps converge to,
        // but not within that fraction (spheres go on turning slowly), spends the other fixed sweeps only on the
        // contacts of the bodies it changed (SequentialImpulseSolver.LocalSweeps.cs). Otherwise only the last fixed
        // sweep's convergence decides whether extra ones follow; those between need no measuring.
        bool local = _extraSweeps > 0 && _gravity != Vector3.Zero && _velocityIterations > 1;
        bool mayFinishLocally = MayFinishWhereChanging(local);
        if (mayFinishLocally)
        {
            RememberVelocities(); // what the first sweep starts from, to see which bodies it changed
        }

        float change = Sweep();
        if (change <= SolvedTolerance)
        {
            return;
        }

        SplitSubstep(); // more sweeps follow: worth sharing among threads (see _substepInStrips)
        if (mayFinishLocally && change <= SettledTolerance && FinishesWhereChanging())
        {
            return;
        }

        bool converged = _velocityIterations == 1 && change <= SettledTolerance;
        if (_velocityIterations > 1 || (!converged && _extraSweeps > 0))
        {
            PlanFours(); // and worth solving four contacts at once where they move different bodies
        }

        for (int iteration = 1; iteration < _velocityIterations; iteration++)
        {
            if (iteration < _velocityIterations - 1 || _extraSweeps == 0)
            {
                SweepUnmeasured();
            }
            else
            {
                if (local)
                {
                    RememberVelocities(); // what the last fixed sweep starts from, to see which bodies it changed
                }

                converged = Sweep() <= SettledTolerance;
            }
        }

        // Further sweeps only while the last one has not converged: under gravity, while few contacts still change,
        // only those; then (or at once, in a pile that is moving all over) over every contact.
        int extra = 0;
        if (!converged && local)
        {
            extra = SweepWhereChanging(_extraSweeps, out converged);
        }

        for (; extra < _extraSweeps && !converged; extra++)
        {
            converged = CorrectsLayersAfter(extra)
                ? SweepAndCorrectLayers() // a deep pile's smooth error, which sweeps carry only a few layers (see LayerCorrection)
                : Sweep() <= SettledTolerance;
        }

        Debug.Assert(!_bandScalePending, "a layer correction is always followed by a sweep, which scales its impulses");
    }

    /// <summary>One Gauss–Seidel sweep over every contact, bottom-up, when nothing asks whether it converged.</summary>
    private void SweepUnmeasured()
    {
        SweepsThisStep++;
        RunPass(StripPass.Sweep);
    }

    /// <summary>
    /// One Gauss–Seidel sweep over every contact, bottom-up. Returns its largest change on the scale that
    /// <see cref="ConvergenceTolerance"/> is a fraction of: the sweep has converged when this is at most the tolerance.
    /// </summary>
    /// <remarks>
    /// Under gravity the measure is the largest change of a contact's normal velocity that the sweep made,
    /// |ΔP_n| (1/m_A + 1/m_B), against the speed gravity adds in a substep, g h: a scale every contact of a pile shares.
    /// Measured against the largest impulse instead, the top of a deep pile (whose impulses are a small fraction of
    /// the bottom's) counted as converged while it still sank: a 4,000-disc pit kept creeping at 1–2 cm/s with a
    /// hundred impacts per step; with this measure it is at rest (every ball under 1 mm/s) 9 s after its pour began.
    /// </remarks>
    /// <param name="gatherBands">Whether the sweep also gathers the layer correction's sums as it leaves each contact (see <see cref="SweepAndCorrectLayers"/>).</param>
    private float Sweep(bool gatherBands = false)
    {
        SweepsThisStep++;
        _gatheringBands = gatherBands;
        RunPass(gatherBands || _bandScalePending ? StripPass.SweepWithBands : StripPass.MeasuredSweep);
        _bandScalePending = false;
        float largestSpeedChange = LargestOfPass(0), largestChange = LargestOfPass(1), largestImpulse = LargestOfPass(2);
        if (_gravity != Vector3.Zero)
        {
            return largestSpeedChange / (_gravity.Length() * _step!.SubstepLength);
        }

        return largestChange == 0 ? 0 : largestChange / largestImpulse; // +∞ when every impulse fell to zero
    }

    /// <summary>
    /// The measured sweep of <see cref="Sweep"/> over <see cref="_active"/>[<paramref name="start"/>..<paramref name="end"/>),
    /// four contacts at once where this substep's plan has them (SequentialImpulseSolver.Fours.cs); keeps its largest
    /// changes in the results of <paramref name="slot"/>.
    /// </summary>
    private void MeasuredSweepRange(int slot, int start, int end)
    {
        float largestChange = 0, largestImpulse = 0, largestSpeedChange = 0;
        var fours = new FourMeasures();
        for (int i = start; i < end;)
        {
#if NET8_0_OR_GREATER
            if (ContactsSolvedFrom(i) == 4)
            {
                SolvePlanarFour(i, ref fours);
                i += 4;
                continue;
            }
#endif
            int k = _active[i++];
            largestSpeedChange = MathF.Max(largestSpeedChange, SolveContactMeasured(k, out float change));
            largestChange = MathF.Max(largestChange, change);
            largestImpulse = MathF.Max(largestImpulse, _constraints[k].NormalImpulse);
        }

        KeepSweepResults(slot, largestSpeedChange, largestChange, largestImpulse, fours);
    }

    /// <summary>
    /// <see cref="SolveContact"/>, measured: returns the change of the contact's normal velocity, |ΔP_n| (1/m_A + 1/m_B)
    /// (0 for a contact that nothing can move), and gives the change of its normal impulse, |ΔP_n|.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // in the measured sweeps' inner loops
    private float SolveContactMeasured(int k, out float change)
    {
        ref ContactConstraint c = ref _constraints[k];
        float before = c.NormalImpulse;
        SolveContact(k);
        change = MathF.Abs(c.NormalImpulse - before);
        return c.NormalMass > 0 ? change / c.NormalMass : 0f;
    }

    /// <summary>
    /// One contact's impulses given what all others did so far: friction (Coulomb, accumulated and clamped to the
    /// disc |P_t| ≤ μ P_n), then the normal impulse of eq. 16 that stops the approach, accumulated and clamped to ≥ 0
    /// (a contact pushes, never pulls).
    /// </summary>
    /// <remarks>
    /// The relative velocity at the contact, v_A + ω_A × r_A − v_B − ω_B × r_B (eq. 13–14), with r_A = −ρ_A n and
    /// r_B = ρ_B n (see MeasureConstraints) is Δv − W × n for Δv = v_A − v_B and W = ρ_A ω_A + ρ_B ω_B; along the
    /// tangents (t₂ = n × t₁) that is Δv·t₁ − W·t₂ and Δv·t₂ + W·t₁, and along n just Δv·n. Friction acts along the
    /// tangents, perpendicular to n, so it leaves Δv·n as it was: the normal impulse is found from the same
    /// velocities, and both are applied at once.
    /// </remarks>
    private void SolveContact(int k)
    {
        ref ContactConstraint c = ref _constraints[k];
        if (_planar)
        {
            SolvePlanarContact(ref c);
            return;
        }

        ref TangentFrame f = ref _frames[k];
        ref SolverBody a = ref _bodies[c.A];
        ref SolverBody b = ref _bodies[c.B];
        Vector3 linear = a.Linear - b.Linear;
        float oldNormal = c.NormalImpulse;
        float normal = c.NormalImpulse = MathF.Max(oldNormal - c.NormalMass * Vectors.Dot(linear, c.Normal), 0f);
        float change1 = 0, change2 = 0;

        // A contact that pushes nothing has no friction either (|P_t| ≤ μ P_n = 0): skip the work.
        if (oldNormal > 0 || c.FrictionImpulse1 != 0 || c.FrictionImpulse2 != 0)
        {
            Vector3 spin = c.RhoA * a.Angular + c.RhoB * b.Angular;
            float limit = c.Friction * oldNormal;
            float old1 = c.FrictionImpulse1, old2 = c.FrictionImpulse2;
            float friction1 = old1 - c.TangentMass1 * (Vectors.Dot(linear, f.Tangent1) - Vectors.Dot(spin, f.Tangent2));
            float friction2 = old2 - c.TangentMass2 * (Vectors.Dot(linear, f.Tangent2) + Vectors.Dot(spin, f.Tangent1));
            ClampFriction(ref friction1, ref friction2, limit); // on locals: the sweep's chain does not wait on a store
            c.FrictionImpulse1 = friction1;
            c.FrictionImpulse2 = friction2;
            change1 = friction1 - old1;
            change2 = friction2 - old2;
        }
        else if (normal == oldNormal)
        {
            return;
        }

        Apply(ref c, ref f, normal - oldNormal, change1, change2);
    }

    /// <summary>
    /// <see cref="SolveContact"/> in a planar step (see IsPlanar), in 2-D arithmetic: n = (n_x, n_y), the one tangent
    /// t₁ = (n_y, −n_x), and spins about z alone, so the relative velocity along n is Δv_x n_x + Δv_y n_y and along t₁
    /// Δv_x n_y − Δv_y n_x + ρ_A ω_A,z + ρ_B ω_B,z. The disc |P_t| ≤ μ P_n is the interval [−μ P_n, μ P_n]. The z parts
    /// of the 3-D path are exact zeros here, so the results are the 3-D path's, bit for bit but for the sign of a zero;
    /// what it saves is the 3-D dot products (a slow instruction on some processors) and reading the tangent frame.
    /// </summary>
    private void SolvePlanarContact(ref ContactConstraint c)
    {
        ref SolverBody a = ref _bodies[c.A];
        ref SolverBody b = ref _bodies[c.B];
        float vx = a.Linear.X - b.Linear.X, vy = a.Linear.Y - b.Linear.Y;
        float nx = c.Normal.X, ny = c.Normal.Y;
        float oldNormal = c.NormalImpulse;
        float normal = c.NormalImpulse = MathF.Max(oldNormal - c.NormalMass * (vx * nx + vy * ny), 0f);
        float pushed = normal - oldNormal, change = 0;

        // A contact that pushes nothing has no friction either (|P_t| ≤ μ P_n = 0): skip the work.
        if (oldNormal > 0 || c.FrictionImpulse1 != 0)
        {
            float limit = c.Friction * oldNormal;
            float old = c.FrictionImpulse1;
            float sliding = vx * ny + vy * -nx + (c.RhoA * a.Angular.Z + c.RhoB * b.Angular.Z);
            c.FrictionImpulse1 = Math.Clamp(old - c.TangentMass1 * sliding, -limit, limit);
            change = c.FrictionImpulse1 - old;
        }
        else if (normal == oldNormal)
        {
            return;
        }

        ApplyPlanar(ref c, pushed, change);
    }

    /// <summary>
    /// Applies the impulse P = p_n n + p_1 t_1 + p_2 t_2 to A and −P to B: eq. 6 for the velocities, eq. 15 for the
    /// spins through the prepared I⁻¹ (r × t) of each tangent (the normal part turns nothing: r × n = 0).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // in the sweeps' inner loop
    private void Apply(ref ContactConstraint c, ref TangentFrame f, float normal, float tangent1, float tangent2)
    {
        ref SolverBody a = ref _bodies[c.A];
        ref SolverBody b = ref _bodies[c.B];
        Vector3 impulse = normal * c.Normal + tangent1 * f.Tangent1 + tangent2 * f.Tangent2;
        a.Linear += impulse * a.InverseMass;
        a.Angular += tangent1 * f.SpinA1 + tangent2 * f.SpinA2;
        b.Linear -= impulse * b.InverseMass;
        b.Angular -= tangent1 * f.SpinB1 + tangent2 * f.SpinB2;
    }

    /// <summary>
    /// <see cref="Apply"/> in a planar step: P = p_n n + p_1 t₁ with t₁ = (n_y, −n_x), to A and −P to B (eq. 6), and
    /// the spins about z (eq. 15).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // in the warm start's loop
    private void ApplyPlanar(ref ContactConstraint c, float normal, float tangent1)
    {
        ref SolverBody a = ref _bodies[c.A];
        ref SolverBody b = ref _bodies[c.B];
        float nx = c.Normal.X, ny = c.Normal.Y;
        float px = normal * nx + tangent1 * ny, py = normal * ny + tangent1 * -nx;
        a.Linear.X += px * a.InverseMass;
        a.Linear.Y += py * a.InverseMass;
        a.Angular.Z += tangent1 * c.PlanarSpinA;
        b.Linear.X -= px * b.InverseMass;
        b.Linear.Y -= py * b.InverseMass;
        b.Angular.Z -= tangent1 * c.PlanarSpinB;
    }

    /// <summary>
    /// Shock propagation in velocity: bottom-up, each resting contact that carries weight (normal within about 45° of
    /// vertical) and still approaches because its upper body moves down into the lower one is stopped by slowing the
    /// upper body alone, as if the lower one, already final, were immovable. The upper body is slowed at most to rest
    /// along the normal, never thrown up, so this only ever removes kinetic energy. Returns whether it slowed any body
    /// by more than the tolerance the sweeps converged to (see <see cref="SettledTolerance"/>).
    /// </summary>
    /// <remarks>
    /// A correction along an inclined normal also turns the upper body sideways, into the neighbours whose contacts
    /// the pass leaves alone (those that carry no weight) and, slowed, into what rests on it. So when the pass changed
    /// anything, the caller sweeps once more: that sweep stops those new approaches (a settled pile needs no such
    /// sweep: the pass then changes nothing). Without it, about ninety contacts per substep of the 8,000-disc 2-D pit
    /// (90 discs deep) approached faster than the impact pass lets a resting pile creep, and became impacts. Measured
    /// over seconds 15–25 after the pour began (two pours, seeds 2 and 3): 570–640 impacts per step, 2,060 discs
    /// faster than 5 cm/s, rms speed 3.9–4.5 cm/s, deepest overlap 2.7–4.1 mm; with the sweep, 50–200 impacts,
    /// 80–500 discs, 1.1–2.4 cm/s and 1.2–1.8 mm. Such a pile still does not come to rest.
    /// </remarks>
    private bool PropagateShock()
    {
        RunPass(StripPass.Shock);
        return LargestOfPass(0) > 0;
    }

    /// <summary>The slowing that counts as a change for <see cref="PropagateShock"/>: the sweeps' tolerance of g h (<see cref="SettledTolerance"/>).</summary>
    private float ShockTolerance() => SettledTolerance * _gravity.Length() * _step!.SubstepLength;

    /// <summary>Shock propagation at one contact (see <see cref="PropagateShock"/>): returns how much it slowed the upper body.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // in the shock pass's loop
    private float StopSinking(ref ContactConstraint c)
    {
        if (!c.CarriesWeight)
        {
            return 0;
        }

        ref SolverBody a = ref _bodies[c.A];
        ref SolverBody b = ref _bodies[c.B];
        float normalVelocity = Vectors.Dot(a.Linear - b.Linear, c.Normal); // r × n = 0: the spins add nothing along n
        if (normalVelocity >= 0)
        {
            return 0;
        }

        float slowing = 0;
        if (c.AIsUpper && a.InverseMass > 0)
        {
            float sinking = -Vectors.Dot(a.Linear, c.Normal); // A's speed into B (n points from B to A)
            slowing = MathF.Min(-normalVelocity, MathF.Max(sinking, 0f));
            a.Linear += slowing * c.Normal;
        }
        else if (!c.AIsUpper && b.InverseMass > 0)
        {
            float sinking = Vectors.Dot(b.Linear, c.Normal); // B's speed into A
            slowing = MathF.Min(-normalVelocity, MathF.Max(sinking, 0f));
            b.Linear -= slowing * c.Normal;
        }

        return slowing;
    }

    /// <summary>
    /// Scales the friction impulse (p_1, p_2) back onto the disc |P_t| ≤ <paramref name="limit"/> (Coulomb) if it lies
    /// outside; in a planar step p_2 = 0 and the disc is the interval [−limit, limit].
    /// </summary>
    private static void ClampFriction(ref float friction1, ref float friction2, float limit)
    {
        float squared = friction1 * friction1 + friction2 * friction2;
        if (squared > limit * limit)
        {
            float scale = squared > 0 ? limit / MathF.Sqrt(squared) : 0f;
            friction1 *= scale;
            friction2 *= scale;
        }
    }

    /// <summary>
    /// Adds this substep's contact impulses to the step's totals, which the contacts report, and keeps the friction
    /// impulse as a world vector for the next substep (whose tangents will have turned with the contact).
    /// </summary>
    private void AddToStepTotals()
    {
        foreach (int k in _active.AsSpan(0, _activeCount))
        {
            ref ContactConstraint c = ref _constraints[k];
            ref ContactStepImpulses step = ref _stepImpulses[k];
            step.Normal += c.NormalImpulse;
            if (_planar)
            {
                step.Friction = c.FrictionImpulse1 * c.PlanarTangent;
                step.FrictionMagnitude += MathF.Abs(c.FrictionImpulse1);
            }
            else
            {
                ref TangentFrame f = ref _frames[k];
                step.Friction = c.FrictionImpulse1 * f.Tangent1 + c.FrictionImpulse2 * f.Tangent2;
                step.FrictionMagnitude += MathF.Sqrt(c.FrictionImpulse1 * c.FrictionImpulse1 + c.FrictionImpulse2 * c.FrictionImpulse2);
            }
        }
    }

    /// <summary>Keeps the last substep's accumulated impulses for the next step's warm start (contact persistence).</summary>
    private void StoreImpulses(Span<Contact> contacts)
    {
        int count = Math.Min(contacts.Length, _prepared);
        _cache.BeginStep(count);
        for (int k = 0; k < count; k++)
        {
            ref ContactConstraint c = ref _constraints[k];
            ref Contact contact = ref contacts[k];
            _cache.Store(contact.Key, c.NormalImpulse, _stepImpulses[k].Friction);
            contact.NormalImpulse += _stepImpulses[k].Normal;
            contact.TangentImpulse += _stepImpulses[k].FrictionMagnitude;
        }

        _cache.SubstepLength = _step!.SubstepLength;
    }
}
