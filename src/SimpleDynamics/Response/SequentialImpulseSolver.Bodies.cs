using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics.Response;

/// <summary>The solver's working copies of the bodies: each body's slot, its velocities, shape and world inverse inertia.</summary>
public sealed partial class SequentialImpulseSolver
{
    private SolverBody[] _bodies = new SolverBody[InitialCapacity];
    private Matrix3[] _inverseInertias = new Matrix3[InitialCapacity]; // per slot, world I⁻¹: at the step's start, and each substep where it is not k·1
    private Vector3[] _positions = new Vector3[InitialCapacity];
    private int[] _bodyOrder = new int[InitialCapacity];
    private int[] _slotOf = new int[InitialCapacity];
    private float[] _bodyHeights = new float[InitialCapacity];
    private float[] _radii = new float[InitialCapacity];
    private float[] _inertiaScalars = new float[InitialCapacity]; // per slot: k when the world I⁻¹ is k·1 (spheres, the ground), else NaN
    private Vector3 _gravity;
    private bool _planar;
    private int _gatheredBodies; // the bodies given slots this step (GatherBodies, AdmitWokenBodies)

    /// <summary>Whether the last step began was solved on the planar path (see IsPlanar), for tests.</summary>
    internal bool SolvedPlanar => _planar;

    /// <summary>Whether the last step began on the planar path (a body woken during it may end that), for tests.</summary>
    internal bool BeganPlanar { get; private set; }

    /// <summary>
    /// Gives each body a slot in contiguous arrays; slot 0 is the ground (all zero). The slots follow the bodies'
    /// height along gravity, like the contacts (<see cref="OrderAlongGravity"/>), so that a sweep finds the bodies of
    /// neighbouring contacts close together in memory instead of anywhere in a large world.
    /// </summary>
    private void GatherBodies(ReadOnlySpan<RigidBody> bodies, Vector3 gravity)
    {
        int n = bodies.Length;
        Buffers.EnsureCapacity(ref _bodies, n + 1);
        Buffers.EnsureCapacity(ref _positions, n + 1);
        Buffers.EnsureCapacity(ref _bodyOrder, n);
        Buffers.EnsureCapacity(ref _slotOf, n);
        Buffers.EnsureCapacity(ref _bodyHeights, n);
        Buffers.EnsureCapacity(ref _radii, n + 1);
        Buffers.EnsureCapacity(ref _inertiaScalars, n + 1);
        Buffers.EnsureCapacity(ref _inverseInertias, n + 1);
        for (int i = 0; i < n; i++)
        {
            _bodyHeights[i] = -Vectors.Dot(bodies[i].position, gravity);
        }

        _gravity = gravity;
        _planar = BeganPlanar = IsPlanar(bodies, gravity);
        _heightOrder.Sort(_bodyHeights.AsSpan(0, n), _bodyOrder.AsSpan(0, n));
        if (_strips.Count > 1)
        {
            // Each strip's bodies together (SweepStrips.cs), so that threads sweeping strips write apart in memory.
            Buffers.EnsureCapacity(ref _bodyScratch, n);
            _strips.Group(_bodyOrder.AsSpan(0, n), bodies: true, _bodyScratch, _bodyStart);
        }
        else
        {
            _bodyStart[0] = _bodyStart[1] = 0; // one group of every body (those nothing moves among them)
            _bodyStart[2] = n;
        }

        for (int k = 0; k < n; k++)
        {
            _slotOf[_bodyOrder[k]] = k + 1;
        }

        _bodies[0] = default;
        _positions[0] = Vector3.Zero;
        _radii[0] = 0;
        _inertiaScalars[0] = 0;
        _inverseInertias[0] = default;
        for (int i = 0; i < n; i++)
        {
            GatherShape(bodies[i], _slotOf[i]);
        }

        _gatheredBodies = n;
    }

    private void GatherShape(RigidBody body, int slot)
    {
        _radii[slot] = body.radius;
        _inertiaScalars[slot] = !body.IsDynamic ? 0f : body.isotropic ? body.inverseInertia.M11 : float.NaN;
        _inverseInertias[slot] = body.inverseInertiaWorld; // then each substep where it turns with the body (GatherState)
    }

    /// <summary>
    /// Gives slots to the bodies the impact pass woke during the step (a body knocked into a sleeping pile wakes it:
    /// see World.WakeSleepersInPath). They join the step's bodies at the end, so their slots follow the others'.
    /// </summary>
    private void AdmitWokenBodies(ReadOnlySpan<RigidBody> bodies)
    {
        int n = bodies.Length;
        if (n == _gatheredBodies)
        {
            return;
        }

        Buffers.EnsureCapacity(ref _bodies, n + 1);
        Buffers.EnsureCapacity(ref _positions, n + 1);
        Buffers.EnsureCapacity(ref _slotOf, n);
        Buffers.EnsureCapacity(ref _radii, n + 1);
        Buffers.EnsureCapacity(ref _inertiaScalars, n + 1);
        Buffers.EnsureCapacity(ref _inverseInertias, n + 1);
        for (int i = _gatheredBodies; i < n; i++)
        {
            _slotOf[i] = i + 1; // the slots of the bodies gathered at the start of the step are 1 … _gatheredBodies
            GatherShape(bodies[i], i + 1);
        }

        // The planar path leaves out the second tangent; a woken body that leaves the plane ends it for the step.
        _planar &= IsPlanar(bodies.Slice(_gatheredBodies), _gravity);
        _gatheredBodies = n;
    }

    /// <summary>
    /// Whether the step stays in the plane z = 0 whatever the contacts do: every body and its velocity, force and
    /// gravity in the plane, spins and torques along z, inverse inertias that turn a z torque into a z spin only, and
    /// no plane whose normal leaves the plane. Then every contact normal n lies in the plane, its first tangent too
    /// (<see cref="Vectors.Tangents"/>), and the second is z, along which the relative velocity is exactly zero: its
    /// friction impulse would always be zero, and the solver leaves that tangent out (one tangent, as in 2-D engines).
    /// </summary>
    private bool IsPlanar(ReadOnlySpan<RigidBody> bodies, Vector3 gravity)
    {
        if (gravity.Z != 0 || _step is null)
        {
            return false;
        }

        foreach (StaticPlane plane in _step.Planes)
        {
            if (plane.Normal.Z != 0)
            {
                return false;
            }
        }

        foreach (RigidBody body in bodies)
        {
            Matrix3 inertia = body.inverseInertiaWorld;
            if (body.position.Z != 0 || body.linearVelocity.Z != 0 || body.force.Z != 0 ||
                body.angularVelocity.X != 0 || body.angularVelocity.Y != 0 || body.torque.X != 0 || body.torque.Y != 0 ||
                inertia.M13 != 0 || inertia.M23 != 0 || inertia.M31 != 0 || inertia.M32 != 0)
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>Copies velocities, masses, positions and (where it turns with the body) the world inverse inertia as they are at the start of a substep.</summary>
    private void GatherState(ReadOnlySpan<RigidBody> bodies)
    {
        for (int i = 0; i < bodies.Length; i++)
        {
            int slot = _slotOf[i];
            RigidBody body = bodies[i];
            _bodies[slot] = SolverBody.Of(body);
            _positions[slot] = body.position;
            if (!_planar && float.IsNaN(_inertiaScalars[slot]))
            {
                // It turns with the body; k·1 does not, and in a planar step only its z–z entry is read (SolverBody),
                // which turning about z leaves as it is.
                _inverseInertias[slot] = body.inverseInertiaWorld;
            }

            if (_strips.Count > 1 && !bodies[i].IsDynamic)
            {
                // −0 as +0: the sweeps add ±0 to what nothing moves, which turns −0 into +0 or not by the order of the
                // additions, and strips on several threads add in another order than one thread (SweepStrips.cs).
                _bodies[slot].Linear += Vector3.Zero;
                _bodies[slot].Angular += Vector3.Zero;
            }
        }
    }

    private void ScatterVelocities(ReadOnlySpan<RigidBody> bodies)
    {
        for (int i = 0; i < bodies.Length; i++)
        {
            _bodies[_slotOf[i]].StoreTo(bodies[i]);
        }
    }
}
