using System;
using System.Numerics;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>The audit of the layer correction (SequentialImpulseSolver.Layers.cs), for tests.</summary>
public sealed partial class SequentialImpulseSolver
{
    /// <summary>
    /// For tests: what the layer corrections did to the laws they must keep (see the remarks on
    /// SequentialImpulseSolver.Layers.cs), each measured in double precision over every body, before and after.
    /// </summary>
    internal sealed class LayerCorrectionAudit
    {
        private double _energyBefore;
        private Vector3D _momentumBefore, _externalImpulse;
        private double _impulseMoved;
        private double[] _direct = new double[16], _scale = new double[16];
        private double _largestBefore; // the largest |−Σ λ_i v_n,i| of a band before the correction

        /// <summary>Corrections audited.</summary>
        public int Count { get; private set; }

        /// <summary>The largest rise of the bodies' kinetic energy by a correction, as a fraction of the energy before.</summary>
        public double LargestEnergyRise { get; private set; } = double.NegativeInfinity;

        /// <summary>The largest fall of the kinetic energy by a correction, as a fraction of the energy before.</summary>
        public double LargestEnergyFall { get; private set; }

        /// <summary>
        /// The largest change of the bodies' momentum by a correction beyond what its contacts with immovable bodies
        /// (the ground, walls) gave, as a fraction of the impulse the correction moved, Σ |Δλ_i|.
        /// </summary>
        public double LargestMomentumError { get; private set; }

        /// <summary>
        /// The largest difference between a band's right-hand side −Pᵀ v_n as the solver built it (from its bodies'
        /// band sums, SequentialImpulseSolver.BuildBandSystem) and −Σ λ_i v_n,i summed contact by contact, as a fraction
        /// of Σ λ_i (|n_i · v_A| + |n_i · v_B|) over the band's pressed contacts (contacts between two immovable bodies
        /// are in neither).
        /// </summary>
        public double LargestResidualError { get; private set; }

        /// <summary>
        /// After each correction whose solution was taken whole (no factor limited, a full step), the largest of the
        /// bands' −Σ λ_i v_n,i summed contact by contact, as a fraction of the largest before it: the gradient of the
        /// energy over the band factors, which the exact solution of the band system makes zero (the energy is then at
        /// its least over every scaling of the bands).
        /// </summary>
        public double LargestGradientLeft { get; private set; }

        /// <summary>Corrections whose solution was taken whole (see <see cref="LargestGradientLeft"/>).</summary>
        public int Unlimited { get; private set; }

        /// <summary>The smallest normal impulse a correction left (a contact never pulls: ≥ 0).</summary>
        public float SmallestImpulse { get; private set; } = float.PositiveInfinity;

        internal void Before(SequentialImpulseSolver solver)
        {
            CheckResidual(solver);
            _largestBefore = 0;
            for (int band = 0; band < solver._bandCount; band++)
            {
                _largestBefore = Math.Max(_largestBefore, Math.Abs(_direct[band]));
            }

            (_energyBefore, _momentumBefore) = Totals(solver);
            _externalImpulse = default;
            _impulseMoved = 0;
            for (int i = 0; i < solver._activeCount; i++)
            {
                ref ContactConstraint c = ref solver._constraints[solver._active[i]];
                float change = (float)(solver._bandFactor[solver._bandOf[i]] * c.NormalImpulse);
                _impulseMoved += Math.Abs(change);
                var push = new Vector3D(change * c.Normal);
                if (solver._bodies[c.B].InverseMass == 0 && solver._bodies[c.A].InverseMass > 0)
                {
                    _externalImpulse += push;
                }
                else if (solver._bodies[c.A].InverseMass == 0 && solver._bodies[c.B].InverseMass > 0)
                {
                    _externalImpulse -= push;
                }
            }
        }

        internal void After(SequentialImpulseSolver solver)
        {
            (double energy, Vector3D momentum) = Totals(solver);
            Count++;
            double change = (energy - _energyBefore) / Math.Max(_energyBefore, double.Epsilon);
            LargestEnergyRise = Math.Max(LargestEnergyRise, change);
            LargestEnergyFall = Math.Max(LargestEnergyFall, -change);
            if (_impulseMoved > 0)
            {
                LargestMomentumError = Math.Max(LargestMomentumError, (momentum - _momentumBefore - _externalImpulse).Length / _impulseMoved);
            }

            for (int i = 0; i < solver._activeCount; i++)
            {
                SmallestImpulse = MathF.Min(SmallestImpulse, Impulse(solver, i));
            }

            if (!solver._bandCorrectionLimited && _largestBefore > 0)
            {
                Unlimited++;
                SumGradient(solver);
                for (int band = 0; band < solver._bandCount; band++)
                {
                    LargestGradientLeft = Math.Max(LargestGradientLeft, Math.Abs(_direct[band]) / _largestBefore);
                }
            }
        }

        private void CheckResidual(SequentialImpulseSolver solver)
        {
            SumGradient(solver);
            for (int band = 0; band < solver._bandCount; band++)
            {
                if (_scale[band] > 0)
                {
                    LargestResidualError = Math.Max(LargestResidualError, Math.Abs(solver._bandResidual[band] - _direct[band]) / _scale[band]);
                }
            }
        }

        /// <summary>Contact <paramref name="i"/>'s normal impulse, as the next sweep will hold it (a pending correction scaled in).</summary>
        private static float Impulse(SequentialImpulseSolver solver, int i)
        {
            ref ContactConstraint c = ref solver._constraints[solver._active[i]];
            return solver._bandScalePending ? solver.ScaledImpulse(ref c, i) : c.NormalImpulse;
        }

        /// <summary>
        /// Each band's −Σ λ_i v_n,i over its pressed contacts (λ_i as the next sweep will hold it) into
        /// <see cref="_direct"/>, and Σ λ_i (|n_i · v_A| + |n_i · v_B|) into <see cref="_scale"/>; contacts between two
        /// immovable bodies are in neither.
        /// </summary>
        private void SumGradient(SequentialImpulseSolver solver)
        {
            int bands = solver._bandCount;
            if (_direct.Length < bands)
            {
                _direct = new double[bands];
                _scale = new double[bands];
            }

            Array.Clear(_direct, 0, bands);
            Array.Clear(_scale, 0, bands);
            for (int i = 0; i < solver._activeCount; i++)
            {
                ref ContactConstraint c = ref solver._constraints[solver._active[i]];
                ref SolverBody a = ref solver._bodies[c.A];
                ref SolverBody b = ref solver._bodies[c.B];
                float impulse = Impulse(solver, i);
                if (impulse <= 0 || (a.InverseMass == 0 && b.InverseMass == 0))
                {
                    continue;
                }

                var normal = new Vector3D(c.Normal);
                double alongA = Vector3D.Dot(normal, new Vector3D(a.Linear)), alongB = Vector3D.Dot(normal, new Vector3D(b.Linear));
                int band = solver._bandOf[i];
                _direct[band] -= impulse * (alongA - alongB); // −λ_i v_n,i (r × n = 0 for spheres)
                _scale[band] += impulse * (Math.Abs(alongA) + Math.Abs(alongB));
            }
        }

        private static (double Energy, Vector3D Momentum) Totals(SequentialImpulseSolver solver)
        {
            double energy = 0;
            Vector3D momentum = default;
            int slots = solver._step!.Bodies.Length + 1;
            for (int s = 1; s < slots; s++)
            {
                ref SolverBody body = ref solver._bodies[s];
                if (body.InverseMass > 0)
                {
                    var velocity = new Vector3D(body.Linear);
                    energy += 0.5 * velocity.LengthSquared / body.InverseMass; // normal impulses turn nothing: the spins stay
                    momentum += velocity / body.InverseMass;
                }
            }

            return (energy, momentum);
        }
    }
}
