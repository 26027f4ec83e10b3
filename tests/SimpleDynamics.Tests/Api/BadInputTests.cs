using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Api;

/// <summary>
/// Bad input gets an <see cref="ArgumentException"/> (or a subclass) whose ParamName names the parameter, and
/// leaves the body, responder or world unchanged.
/// </summary>
public class BadInputTests
{
    private static readonly Vector3 Nan3 = new(float.NaN, 0, 0);
    private static readonly Vector3 Inf3 = new(0, float.PositiveInfinity, 0);

    public static TheoryData<float> BadPositive => new() { 0f, -1f, -0f, float.NaN, float.PositiveInfinity, float.NegativeInfinity };

    public static TheoryData<float> OutsideUnitInterval => new() { -0.01f, 1.01f, float.NaN, float.PositiveInfinity, float.NegativeInfinity };

    public static TheoryData<float> BadNonNegative => new() { -0.01f, -1f, float.NaN, float.PositiveInfinity };

    public static TheoryData<Vector3> BadVector => new() { Nan3, Inf3, new Vector3(0, 0, float.NegativeInfinity) };

    public static TheoryData<string, Matrix3> BadInertia => new()
    {
        { "singular", Matrix3.Diagonal(1, 1, 0) },
        { "rank one", new Matrix3(1, 1, 1, 1, 1, 1, 1, 1, 1) },
        { "non-symmetric", new Matrix3(1, 0.5f, 0, 0, 1, 0, 0, 0, 1) },
        { "negative moment", Matrix3.Diagonal(1, -1, 1) },
        { "indefinite", new Matrix3(1, 2, 0, 2, 1, 0, 0, 0, 1) },
        { "NaN", Matrix3.Diagonal(1, float.NaN, 1) },
        { "infinite", Matrix3.Diagonal(1, 1, float.PositiveInfinity) },
        { "zero", Matrix3.Zero },
    };

    private static void Throws(Action action, string paramName)
    {
        Exception? caught = Record.Exception(action);
        Assert.NotNull(caught);
        ArgumentException argument = Assert.IsAssignableFrom<ArgumentException>(caught);
        Assert.Equal(paramName, argument.ParamName);
    }

    // ---------- RigidBody ----------

    [Theory]
    [MemberData(nameof(BadPositive))]
    public void Body_mass_must_be_positive_and_finite(float mass)
    {
        Throws(() => _ = new RigidBody(mass, 1f, Vector3.Zero), "mass");
        Throws(() => _ = new RigidBody(mass, 1f, Vector3.Zero, Matrix3.Identity), "mass");
        var body = new RigidBody(2f, 1f, Vector3.Zero);
        Matrix3 inertia = body.Inertia;
        Throws(() => body.SetMass(mass, Matrix3.Identity), "mass");
        Assert.Equal(2f, body.Mass);
        Assert.Equal(inertia, body.Inertia);
    }

    [Theory]
    [MemberData(nameof(BadPositive))]
    public void Body_radius_must_be_positive_and_finite(float radius)
    {
        Throws(() => _ = new RigidBody(1f, radius, Vector3.Zero), "radius");
        Throws(() => _ = new RigidBody(1f, radius, Vector3.Zero, Matrix3.Identity), "radius");
        Throws(() => RigidBody.CreateStatic(radius, Vector3.Zero), "radius");
        Throws(() => RigidBody.CreateKinematic(radius, Vector3.Zero, Vector3.Zero), "radius");
        var body = new RigidBody(1f, 0.5f, Vector3.Zero);
        Throws(() => body.Radius = radius, nameof(RigidBody.Radius));
        Assert.Equal(0.5f, body.Radius);
    }

    [Theory]
    [MemberData(nameof(BadVector))]
    public void Body_position_and_velocities_must_be_finite(Vector3 bad)
    {
        Throws(() => _ = new RigidBody(1f, 1f, bad), "position");
        Throws(() => RigidBody.CreateStatic(1f, bad), "position");
        Throws(() => RigidBody.CreateKinematic(1f, bad, Vector3.Zero), "position");
        Throws(() => RigidBody.CreateKinematic(1f, Vector3.Zero, bad), "velocity");

        var p = new Vector3(1, 2, 3);
        var v = new Vector3(4, 5, 6);
        var w = new Vector3(7, 8, 9);
        var body = new RigidBody(1f, 1f, p) { LinearVelocity = v, AngularVelocity = w };
        Throws(() => body.Position = bad, nameof(RigidBody.Position));
        Throws(() => body.LinearVelocity = bad, nameof(RigidBody.LinearVelocity));
        Throws(() => body.AngularVelocity = bad, nameof(RigidBody.AngularVelocity));
        Throws(() => body.ApplyForce(bad), "force");
        Throws(() => body.ApplyForce(Vector3.One, bad), "point");
        Throws(() => body.ApplyTorque(bad), "torque");
        Throws(() => body.ApplyImpulse(bad, p), "impulse");
        Throws(() => body.ApplyImpulse(Vector3.One, bad), "point");
        Assert.Equal(p, body.Position);
        Assert.Equal(v, body.LinearVelocity);
        Assert.Equal(w, body.AngularVelocity);
        Assert.Equal(Vector3.Zero, body.Force);
        Assert.Equal(Vector3.Zero, body.Torque);
    }

    [Theory]
    [MemberData(nameof(BadInertia))]
    public void Inertia_tensor_must_be_symmetric_positive_definite_and_finite(string what, Matrix3 inertia)
    {
        _ = what;
        Throws(() => _ = new RigidBody(1f, 1f, Vector3.Zero, inertia), "inertia");
        Throws(() => Inertia.Validate(inertia, "tensor"), "tensor");
        var body = new RigidBody(1f, 1f, Vector3.Zero);
        Matrix3 before = body.Inertia, inverseBefore = body.InverseInertiaWorld;
        Throws(() => body.SetMass(3f, inertia), "inertia");
        Assert.Equal(1f, body.Mass);
        Assert.Equal(before, body.Inertia);
        Assert.Equal(inverseBefore, body.InverseInertiaWorld);
    }

    [Fact]
    public void Orientation_must_be_a_finite_non_zero_quaternion()
    {
        var body = new RigidBody(1f, 1f, Vector3.Zero);
        Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.3f);
        body.Orientation = q;
        Throws(() => body.Orientation = new Quaternion(float.NaN, 0, 0, 1), nameof(RigidBody.Orientation));
        Throws(() => body.Orientation = default, nameof(RigidBody.Orientation));
        Assert.Equal(Quaternion.Normalize(q), body.Orientation);
    }

    [Theory]
    [MemberData(nameof(OutsideUnitInterval))]
    public void Restitution_must_lie_in_zero_one(float e)
    {
        var body = new RigidBody(1f, 1f, Vector3.Zero) { Restitution = 0.3f };
        Throws(() => body.Restitution = e, nameof(RigidBody.Restitution));
        Assert.Equal(0.3f, body.Restitution);

        var responder = new ImpulseCollisionResponder(0.4f, 0.2f);
        Throws(() => responder.Restitution = e, nameof(ImpulseCollisionResponder.Restitution));
        Assert.Equal(0.4f, responder.Restitution);

        var solver = new SequentialImpulseSolver(0.4f, 0.2f);
        Throws(() => solver.Restitution = e, nameof(SequentialImpulseSolver.Restitution));
        Assert.Equal(0.4f, solver.Restitution);

        Throws(() => _ = new StaticPlane(Vector3.UnitY, Vector3.Zero, restitution: e), "restitution");

        // The constructors' parameter is `restitution`; the exception names the property it sets, `Restitution`.
        AssertNamesIgnoringCase(() => _ = new ImpulseCollisionResponder(e), "restitution");
        AssertNamesIgnoringCase(() => _ = new SequentialImpulseSolver(e), "restitution");
    }

    [Theory]
    [MemberData(nameof(BadNonNegative))]
    public void Friction_must_be_non_negative_and_finite(float mu)
    {
        var body = new RigidBody(1f, 1f, Vector3.Zero) { Friction = 0.3f };
        Throws(() => body.Friction = mu, nameof(RigidBody.Friction));
        Assert.Equal(0.3f, body.Friction);

        var responder = new ImpulseCollisionResponder(0.4f, 0.2f);
        Throws(() => responder.Friction = mu, nameof(ImpulseCollisionResponder.Friction));
        Assert.Equal(0.2f, responder.Friction);

        var solver = new SequentialImpulseSolver(0.4f, 0.2f);
        Throws(() => solver.Friction = mu, nameof(SequentialImpulseSolver.Friction));
        Assert.Equal(0.2f, solver.Friction);

        Throws(() => _ = new StaticPlane(Vector3.UnitY, Vector3.Zero, friction: mu), "friction");
        AssertNamesIgnoringCase(() => _ = new ImpulseCollisionResponder(0.5f, mu), "friction");
        AssertNamesIgnoringCase(() => _ = new SequentialImpulseSolver(0.5f, mu), "friction");
    }

    private static void AssertNamesIgnoringCase(Action action, string paramName)
    {
        ArgumentException e = Assert.IsAssignableFrom<ArgumentException>(Record.Exception(action));
        Assert.Equal(paramName, e.ParamName, ignoreCase: true);
    }

    // ---------- Solver settings ----------

    public static TheoryData<string, Action<SequentialImpulseSolver>> BadSolverSettings => new()
    {
        { nameof(SequentialImpulseSolver.VelocityIterations), s => s.VelocityIterations = 0 },
        { nameof(SequentialImpulseSolver.VelocityIterations), s => s.VelocityIterations = -3 },
        { nameof(SequentialImpulseSolver.PositionIterations), s => s.PositionIterations = -1 },
        { nameof(SequentialImpulseSolver.ExtraIterations), s => s.ExtraIterations = -1 },
        { nameof(SequentialImpulseSolver.ConvergenceTolerance), s => s.ConvergenceTolerance = -1e-3f },
        { nameof(SequentialImpulseSolver.ConvergenceTolerance), s => s.ConvergenceTolerance = float.NaN },
        { nameof(SequentialImpulseSolver.RestitutionThreshold), s => s.RestitutionThreshold = -0.1f },
        { nameof(SequentialImpulseSolver.RestitutionThreshold), s => s.RestitutionThreshold = float.NaN },
        { nameof(SequentialImpulseSolver.RestitutionThreshold), s => s.RestitutionThreshold = float.PositiveInfinity },
        { nameof(SequentialImpulseSolver.Slop), s => s.Slop = -0.001f },
        { nameof(SequentialImpulseSolver.Slop), s => s.Slop = float.NaN },
        { nameof(SequentialImpulseSolver.CorrectionFactor), s => s.CorrectionFactor = 0f },
        { nameof(SequentialImpulseSolver.CorrectionFactor), s => s.CorrectionFactor = -0.5f },
        { nameof(SequentialImpulseSolver.CorrectionFactor), s => s.CorrectionFactor = 1.5f },
        { nameof(SequentialImpulseSolver.CorrectionFactor), s => s.CorrectionFactor = float.NaN },
        { nameof(SequentialImpulseSolver.MaxCorrection), s => s.MaxCorrection = 0f },
        { nameof(SequentialImpulseSolver.MaxCorrection), s => s.MaxCorrection = -1f },
        { nameof(SequentialImpulseSolver.MaxCorrection), s => s.MaxCorrection = float.NaN },
        { nameof(SequentialImpulseSolver.Mixing), s => s.Mixing = null! },
    };

    [Theory]
    [MemberData(nameof(BadSolverSettings))]
    public void Bad_solver_settings_are_rejected_and_change_nothing(string property, Action<SequentialImpulseSolver> set)
    {
        var solver = new SequentialImpulseSolver();
        string before = Settings(solver);
        Throws(() => set(solver), property);
        Assert.Equal(before, Settings(solver));
    }

    private static string Settings(SequentialImpulseSolver s) =>
        $"{s.VelocityIterations} {s.ExtraIterations} {s.ConvergenceTolerance} {s.PositionIterations} {s.RestitutionThreshold} {s.Slop} {s.CorrectionFactor} {s.MaxCorrection} {s.Restitution} {s.Friction} {s.WarmStarting} {s.Mixing.GetHashCode()}";

    [Fact]
    public void Other_null_and_range_arguments_name_their_parameter()
    {
        Throws(() => new ImpulseCollisionResponder().Mixing = null!, nameof(ImpulseCollisionResponder.Mixing));
        Throws(() => _ = new MaterialMixing(null!, MathF.Max), "restitution");
        Throws(() => _ = new MaterialMixing(MathF.Max, null!), "friction");
        Throws(() => _ = new CollisionData(0), "capacity");
        Throws(() => _ = new StaticPlane(new Vector3(0, 2, 0), Vector3.Zero), "normal");
        Throws(() => _ = new StaticPlane(Vector3.UnitY, Nan3), "point");
        Throws(() => new BruteForceDetector().FindContacts(ReadOnlySpan<RigidBody>.Empty, null!), "collisions");
        Throws(() => new SpatialHashDetector().FindContacts(ReadOnlySpan<RigidBody>.Empty, null!), "collisions");
        Throws(() => Inertia.SolidSphere(0f, 1f), "mass");
        Throws(() => Inertia.Disc(1f, float.NaN), "radius");
        Throws(() => Inertia.Box(1f, 1f, -1f, 1f), "sizeY");

        var world = new World();
        Throws(() => world.Add(null!), "body");
        var body = world.Add(new RigidBody(1f, 1f, Vector3.Zero));
        Throws(() => new World().Add(body), "body");
        Assert.Same(world, body.World);
        Throws(() => world.Responder = null!, nameof(World.Responder));
        Throws(() => world.Detector = null!, nameof(World.Detector));
        Throws(() => world.Gravity = Nan3, nameof(World.Gravity));
        Assert.Equal(Vector3.Zero, world.Gravity);
        Throws(() => world.Substeps = 0, nameof(World.Substeps));
        Assert.Equal(4, world.Substeps);
        Throws(() => world.ThreadCount = 0, nameof(World.ThreadCount));
        Throws(() => world.ThreadCount = World.MaxThreadCount + 1, nameof(World.ThreadCount));
        Assert.Equal(1, world.ThreadCount);
        Throws(() => world.ContactMargin = -0.01f, nameof(World.ContactMargin));
        Throws(() => world.ContactMargin = float.NaN, nameof(World.ContactMargin));
        Assert.Equal(0.01f, world.ContactMargin);
        Throws(() => new SpatialHashDetector().FindContacts(ReadOnlySpan<RigidBody>.Empty, new CollisionData(), margin: -1f), "margin");
        Throws(() => new BruteForceDetector().FindContacts(ReadOnlySpan<RigidBody>.Empty, new CollisionData(), lookahead: float.NaN), "lookahead");
        Throws(() => _ = new ImpulseCollisionResponder(restitution: 2f), "restitution");
        Throws(() => _ = new SequentialImpulseSolver(friction: -1f), "friction");
        var solver = new SequentialImpulseSolver();
        Throws(() => solver.Strips = 0, nameof(SequentialImpulseSolver.Strips));
        Throws(() => solver.Strips = 3, nameof(SequentialImpulseSolver.Strips));
        Throws(() => solver.Strips = 16, nameof(SequentialImpulseSolver.Strips));
        Assert.Equal(1, solver.Strips);
        Throws(() => world.MeasureDiagnostics(Inf3), "point");
    }

    // ---------- World.Step ----------

    [Theory]
    [MemberData(nameof(BadPositive))]
    public void World_step_rejects_a_bad_dt_and_changes_nothing(float dt)
    {
        World world = Scenes.BallPit(30, planar: false, seed: 3);
        world.Bodies[0].ApplyForce(new Vector3(1, 2, 3));
        for (int i = 0; i < 20; i++)
        {
            world.Step(1f / 60f);
        }

        world.Bodies[1].ApplyForce(new Vector3(1, 2, 3));
        List<string> before = Snapshot(world);
        Throws(() => world.Step(dt), "dt");
        Assert.Equal(before, Snapshot(world));
    }

    private static List<string> Snapshot(World world)
    {
        var lines = world.Bodies
            .Select(b => $"{b.Id} {Bits(b.Position)} {Bits(b.LinearVelocity)} {Bits(b.AngularVelocity)} {b.Orientation} {Bits(b.Force)} {Bits(b.Torque)}")
            .ToList();
        lines.Add($"time {world.Time:R} contacts {world.Collisions.Count}");
        foreach (Contact c in world.Collisions.Contacts)
        {
            lines.Add($"{c.BodyA.Id}-{c.BodyB.Id} {Bits(c.Normal)} {c.Penetration:R} {c.NormalImpulse:R}");
        }

        return lines;
    }

    private static string Bits(Vector3 v) =>
        $"{BitConverter.SingleToInt32Bits(v.X):X8}{BitConverter.SingleToInt32Bits(v.Y):X8}{BitConverter.SingleToInt32Bits(v.Z):X8}";

    // ---------- Degenerate geometry ----------

    [Fact]
    public void Coincident_centres_give_a_defined_unit_normal_never_NaN()
    {
        var p = new Vector3(1.5f, -2, 0.25f);
        float penetration = ContactGeometry.CirclePenetration(p, 0.5f, p, 0.25f, out Vector3 normal);
        Assert.Equal(Vector3.UnitY, normal);
        Assert.Equal(0.75f, penetration);

        var a = new RigidBody(1f, 0.5f, p) { LinearVelocity = new Vector3(0, -1, 0) };
        var b = new RigidBody(2f, 0.25f, p) { LinearVelocity = new Vector3(1, 1, 0) };
        Assert.True(ContactGeometry.TryCollide(a, b, out Contact contact));
        Assert.Equal(Vector3.UnitY, contact.Normal);
        Assert.True(Vectors.IsFinite(contact.Point));

        new ImpulseCollisionResponder(0.5f, 0.5f).ResolveVelocity(ref contact);
        Assert.True(Vectors.IsFinite(a.LinearVelocity) && Vectors.IsFinite(b.LinearVelocity));
        Assert.True(Vectors.IsFinite(a.AngularVelocity) && Vectors.IsFinite(b.AngularVelocity));

        var world = new World(Vector3.Zero);
        world.Add(new RigidBody(1f, 0.5f, p));
        world.Add(new RigidBody(1f, 0.5f, p));
        for (int i = 0; i < 10; i++)
        {
            world.Step(1f / 60f);
        }

        Assert.All(world.Bodies, body => Assert.True(Vectors.IsFinite(body.Position) && Vectors.IsFinite(body.LinearVelocity)));
    }

    [Fact]
    public void A_pair_of_two_infinite_mass_bodies_is_skipped()
    {
        var s1 = RigidBody.CreateStatic(1f, Vector3.Zero);
        var s2 = RigidBody.CreateStatic(1f, new Vector3(0.5f, 0, 0));
        var k = RigidBody.CreateKinematic(1f, new Vector3(0, 0.5f, 0), new Vector3(1, 0, 0));
        Assert.False(ContactGeometry.TryCollide(s1, s2, out _));
        Assert.False(ContactGeometry.TryCollide(s1, k, out _));
        RigidBody[] bodies = { s1, s2, k };
        foreach (ICollisionDetector detector in new ICollisionDetector[] { new BruteForceDetector(), new SpatialHashDetector() })
        {
            var collisions = new CollisionData();
            detector.FindContacts(bodies, collisions);
            Assert.Equal(0, collisions.Count);
        }

        var world = new World(new Vector3(0, -9.81f, 0));
        world.Add(s1);
        world.Add(s2);
        world.Step(1f / 60f);
        Assert.Equal(0, world.Collisions.Count);
        Assert.Equal(Vector3.Zero, s1.Position);
        Assert.Equal(new Vector3(0.5f, 0, 0), s2.Position);
    }
}
