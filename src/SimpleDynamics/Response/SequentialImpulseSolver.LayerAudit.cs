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

        /// <summary>The smallest normal impulse a correction left (a contact never pulls: ≥ 0).</summary>
        public float SmallestImpulse { get; private set; } = float.PositiveInfinity;

        internal void Before(SequentialImpulseSolver solver)
        {
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
                SmallestImpulse = MathF.Min(SmallestImpulse, solver._constraints[solver._active[i]].NormalImpulse);
            }
        }

        private static (double Energy, Vector3D Momentum) Totals(SequentialImpulseSolver solver)
        {
            double energy = 0;
            Vector3D momentum = default;
            int slots = solver._step!.Bodies.Length + 1;
            for (int s = 1; s < slots; s++)
            {
                ref VelocityState body = ref solver._bodies[s];
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
