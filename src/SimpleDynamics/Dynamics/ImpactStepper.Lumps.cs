using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics;

// Jams that touch nothing immovable and that the sweeps cannot settle: moved on as one lump.
internal sealed partial class ImpactStepper
{
    private int[] _lumpOf = new int[InitialBodies]; // per body: a body of the same lump, leading to its root (union–find)
    private Lump[] _lumps = new Lump[InitialBodies]; // per root body: what its lump adds up to

    /// <summary>What a lump of jammed bodies adds up to, in double precision (see <see cref="MergeFreeJams"/>).</summary>
    private struct Lump
    {
        public bool Several; // more than one body
        public bool Anchored; // a body of it is reached from something immovable (StopFromAnchors)
        public double Mass;
        public Vector3D MassMoment; // Σ m x: the centre of mass X is MassMoment / Mass
        public Vector3D Momentum; // Σ m v: the centre of mass moves at V = Momentum / Mass
        public Vector3D AngularMomentum; // Σ m r × (v − V), r = x − X
        public double Jxx, Jyy, Jzz, Jxy, Jxz, Jyz; // Σ m (|r|² 1 − r rᵀ)
        public Vector3D Spin; // Ω, solving J Ω = L

        public readonly bool Moves => Several && !Anchored;
    }

    /// <summary>
    /// A jam that touches nothing immovable, and that the sweeps have not settled, moves on as one lump. The sweeps
    /// stop one pair's approach at a time, and a light body between two far heavier ones passes on only about the mass
    /// ratio's inverse of their approach per sweep: a 0.013 kg disc between falling discs of 124 and 948 kg (generated
    /// world 669 of 2,000, seed 807: free space under gravity) left them approaching at 1.5 m/s after every substep, so
    /// they jammed again at the start of the next and stood still while gravity sped them up: the three hovered, and the
    /// world gained 198 J in a step. With nothing immovable to stop them from (<see cref="StopFromAnchors"/>), the
    /// limit of the inelastic collapse is taken at once: each lump's bodies get the velocities of a rigid motion about
    /// its centre of mass, v_i = V + Ω × r_i, with V = P / M (the perfectly inelastic collision of eq. 2 of the tutorial,
    /// for the whole lump) and Ω solving J Ω = L for the lump's orbital angular momentum L = Σ m_i r_i × (v_i − V) and
    /// J = Σ m_i (|r_i|² 1 − r_i r_iᵀ). Their spins are left alone, as every jam impulse leaves them (it acts along the
    /// line of centres). Linear and angular momentum are kept, and kinetic energy can only fall: of all velocities with
    /// the same momentum and angular momentum, a rigid motion's have the least kinetic energy. No pair of a lump
    /// approaches any more, since a rigid motion keeps every distance.
    /// </summary>
    private void MergeFreeJams(ReadOnlySpan<RigidBody> bodies)
    {
        for (int i = 0; i < _bodyCount; i++)
        {
            _lumpOf[i] = i;
            _lumps[i] = default;
        }

        for (int k = 0; k < _contactCount; k++)
        {
            Ends(k, out int a, out int b);
            if (_jamState[k] == JamState.Touching && b >= 0 && bodies[a].inverseMass > 0 && bodies[b].inverseMass > 0)
            {
                int rootA = LumpRoot(a), rootB = LumpRoot(b);
                if (rootA != rootB)
                {
                    _lumpOf[rootB] = rootA;
                    _lumps[rootA].Several = true;
                }
            }
        }

        // Each lump's mass, centre of mass and momentum, and whether anything immovable holds it.
        for (int i = 0; i < _bodyCount; i++)
        {
            ref Lump lump = ref _lumps[LumpRoot(i)];
            if (bodies[i].inverseMass > 0)
            {
                double mass = 1.0 / bodies[i].inverseMass;
                lump.Mass += mass;
                lump.MassMoment += mass * _flight[i].PreciseX;
                lump.Momentum += mass * new Vector3D(_flight[i].U);
                lump.Anchored |= _anchorDistance[i] != int.MaxValue;
            }
        }

        // Its orbital angular momentum and inertia about the centre of mass.
        for (int i = 0; i < _bodyCount; i++)
        {
            ref Lump lump = ref _lumps[LumpRoot(i)];
            if (!lump.Moves || bodies[i].inverseMass == 0)
            {
                continue;
            }

            double mass = 1.0 / bodies[i].inverseMass;
            Vector3D r = _flight[i].PreciseX - lump.MassMoment / lump.Mass;
            Vector3D u = new Vector3D(_flight[i].U) - lump.Momentum / lump.Mass;
            lump.AngularMomentum += mass * Vector3D.Cross(r, u);
            double r2 = r.LengthSquared;
            lump.Jxx += mass * (r2 - r.X * r.X);
            lump.Jyy += mass * (r2 - r.Y * r.Y);
            lump.Jzz += mass * (r2 - r.Z * r.Z);
            lump.Jxy -= mass * r.X * r.Y;
            lump.Jxz -= mass * r.X * r.Z;
            lump.Jyz -= mass * r.Y * r.Z;
        }

        // The rigid motion with that momentum and angular momentum.
        for (int i = 0; i < _bodyCount; i++)
        {
            if (_lumpOf[i] == i && _lumps[i].Moves)
            {
                _lumps[i].Spin = OrbitalSpin(in _lumps[i]);
            }
        }

        for (int i = 0; i < _bodyCount; i++)
        {
            ref Lump lump = ref _lumps[LumpRoot(i)];
            if (!lump.Moves || bodies[i].inverseMass == 0)
            {
                continue;
            }

            Vector3D r = _flight[i].PreciseX - lump.MassMoment / lump.Mass;
            Vector3D v = lump.Momentum / lump.Mass + Vector3D.Cross(lump.Spin, r);
            _flight[i].U = v.Rounded;
            bodies[i].linearVelocity = _flight[i].U;
        }
    }

    /// <summary>
    /// Ω solving J Ω = L for a lump (see <see cref="MergeFreeJams"/>). J is singular only when the lump's centres lie on
    /// one line d, J = J⊥ (1 − d dᵀ); then L, a sum of r × u with every r along d, is perpendicular to d, and Ω = L / J⊥.
    /// </summary>
    private static Vector3D OrbitalSpin(in Lump lump)
    {
        double trace = lump.Jxx + lump.Jyy + lump.Jzz;
        if (trace <= 0)
        {
            return default; // every centre at the centre of mass
        }

        double c00 = lump.Jyy * lump.Jzz - lump.Jyz * lump.Jyz;
        double c01 = lump.Jxz * lump.Jyz - lump.Jxy * lump.Jzz;
        double c02 = lump.Jxy * lump.Jyz - lump.Jxz * lump.Jyy;
        double det = lump.Jxx * c00 + lump.Jxy * c01 + lump.Jxz * c02;
        double scale = trace / 3;
        Vector3D l = lump.AngularMomentum;
        if (Math.Abs(det) <= 1e-12 * scale * scale * scale)
        {
            return l / (0.5 * trace);
        }

        double c11 = lump.Jxx * lump.Jzz - lump.Jxz * lump.Jxz;
        double c12 = lump.Jxz * lump.Jxy - lump.Jxx * lump.Jyz;
        double c22 = lump.Jxx * lump.Jyy - lump.Jxy * lump.Jxy;
        return new Vector3D(
            (c00 * l.X + c01 * l.Y + c02 * l.Z) / det,
            (c01 * l.X + c11 * l.Y + c12 * l.Z) / det,
            (c02 * l.X + c12 * l.Y + c22 * l.Z) / det);
    }

    /// <summary>The root of body <paramref name="i"/>'s lump, halving the path to it on the way.</summary>
    private int LumpRoot(int i)
    {
        while (_lumpOf[i] != i)
        {
            _lumpOf[i] = _lumpOf[_lumpOf[i]];
            i = _lumpOf[i];
        }

        return i;
    }
}
