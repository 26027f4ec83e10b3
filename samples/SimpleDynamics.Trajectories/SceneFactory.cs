using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;

namespace SimpleDynamics.Trajectories;

/// <summary>A world ready to run, with what the writer needs to present it.</summary>
/// <param name="Name">The scene's option name, e.g. "bounce".</param>
/// <param name="Description">One line saying what happens and with which settings.</param>
/// <param name="World">The world, at time 0.</param>
/// <param name="Labels">A short name per body, in <see cref="World.Bodies"/> order.</param>
/// <param name="Steps">Steps to run.</param>
/// <param name="Dt">Time step (s).</param>
/// <param name="Every">Print every K-th step.</param>
/// <param name="SummaryOnly">Print the centre of mass and diagnostics instead of every body (many bodies).</param>
/// <param name="Planar">Everything stays in the z = 0 plane, so the table can leave z out.</param>
/// <param name="Responder">The responder answering the contacts.</param>
/// <param name="Expectation">
/// What classical mechanics predicts, if it says something simple and this responder does it; else null.
/// </param>
/// <param name="ShowEvents">The table prints, per row, the contact and sensor events since the row before.</param>
public sealed record Scene(
    string Name,
    string Description,
    World World,
    IReadOnlyList<string> Labels,
    int Steps,
    float Dt,
    int Every,
    bool SummaryOnly,
    bool Planar,
    ResponderKind Responder,
    Expectation? Expectation,
    bool ShowEvents = false)
{
    /// <summary>The world's events, collected step by step for the rows (see <see cref="EventLog"/>).</summary>
    public EventLog Events { get; } = new(World, Labels);
}

/// <summary>
/// Builds the sample's scenes from <see cref="Scenes"/> (the geometry the tests and benchmarks share) with the
/// responder, ε and μ the command line asks for.
/// </summary>
public static class SceneFactory
{
    /// <summary>The time step when none is given (s).</summary>
    public const float DefaultDt = 0.01f;

    /// <summary>Frames an SVG or HTML picture records when --every is not given.</summary>
    public const int PictureFrames = 1000;

    private const float Gravity = 9.81f;

    /// <summary>The scenes to run for <paramref name="options"/>: two for the default, else one.</summary>
    public static IReadOnlyList<Scene> Build(Options options)
    {
        return options.Scene switch
        {
            SceneKind.Default => new[] { Bounce(options), OffCentre(options) },
            SceneKind.Bounce => new[] { Bounce(options) },
            SceneKind.OffCentre => new[] { OffCentre(options) },
            SceneKind.Pile => new[] { Pile(options) },
            SceneKind.Row => new[] { Row(options) },
            SceneKind.Slide => new[] { Slide(options) },
            SceneKind.Game => new[] { Game(options) },
            _ => throw new ArgumentOutOfRangeException(nameof(options), options.Scene, "Unknown scene."),
        };
    }

    /// <summary>The responder for <paramref name="kind"/>; ε and μ are its defaults for surfaces that set none.</summary>
    public static ICollisionResponder CreateResponder(ResponderKind kind, float restitution, float friction) => kind switch
    {
        ResponderKind.Solver => new SequentialImpulseSolver(restitution, friction),
        ResponderKind.Impulse => new ImpulseCollisionResponder(restitution, friction),
        ResponderKind.Inelastic => new PerfectlyInelasticResponder(),
        ResponderKind.Projection => new ProjectionResponder(),
        _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "Unknown responder."),
    };

    /// <summary>The name the command line uses for <paramref name="kind"/>.</summary>
    public static string NameOf(ResponderKind kind) => kind.ToString().ToLowerInvariant();

    private static Scene Bounce(Options options)
    {
        const float height = 3f;
        float e = options.Restitution ?? 0.8f;
        float mu = options.Friction ?? 0.3f;
        World world = Scenes.DroppedBall(e, height, CreateResponder(options.Responder, e, mu));
        string description = Invariant(
            $"a ball (r = 0.5 m, 1 kg) dropped from {height} m onto the ground; eps = {e}, mu = {mu}, responder = {NameOf(options.Responder)}");
        // Projection moves positions only: gravity's speed is never taken away, so the ball gains energy.
        Expectation? expectation = options.Responder is ResponderKind.Projection ? null : new Expectation(
            "mechanical energy never rises above the start (each bounce is no higher than the last)",
            (scene, summary) => summary.MaxMechanicalEnergy - summary.StartMechanicalEnergy > Expectations.EnergyTolerance(summary)
                ? Format.Invariant($"it rose from {Format.Number(summary.StartMechanicalEnergy)} J to {Format.Number(summary.MaxMechanicalEnergy)} J")
                : null);
        return Make("bounce", description, world, new[] { "ball" }, options, steps: 400, rows: 50, summaryOnly: false, expectation);
    }

    private static Scene OffCentre(Options options)
    {
        float e = options.Restitution ?? 0.8f;
        float mu = options.Friction ?? 0.3f;
        World world = Scenes.OffCentreCollision(e, mu, CreateResponder(options.Responder, e, mu));
        string description = Invariant(
            $"two discs (1 kg moving right at 3 m/s, 2 kg moving left at 1 m/s) meet off-centre, no gravity; eps = {e}, mu = {mu}, responder = {NameOf(options.Responder)}");
        // Only the impulse responders apply an impulse at the contact point; eq. 2 and projection never spin a body.
        Expectation? expectation = options.Responder is ResponderKind.Solver or ResponderKind.Impulse && Duration(options, 200) >= 1.5
            ? mu > 0
                ? new Expectation("friction at the contact point sets both discs spinning (|wz| > 0.1 rad/s after the hit)",
                    (scene, _) => Spin(scene, 0) > 0.1 && Spin(scene, 1) > 0.1 ? null
                        : Format.Invariant($"the discs end with wz = {Format.Number(Spin(scene, 0))} and {Format.Number(Spin(scene, 1))} rad/s"))
                : new Expectation("without friction neither disc spins",
                    (scene, _) => Spin(scene, 0) < 1e-6 && Spin(scene, 1) < 1e-6 ? null
                        : Format.Invariant($"the discs end with |wz| = {Format.Number(Spin(scene, 0))} and {Format.Number(Spin(scene, 1))} rad/s"))
            : null;
        return Make("offcentre", description, world, new[] { "left", "right" }, options, steps: 200, rows: 40, summaryOnly: false, expectation);
    }

    private static Scene Pile(Options options)
    {
        const int count = 100;
        const float radius = 0.1f;
        float e = options.Restitution ?? 0.2f;
        float mu = options.Friction ?? 0.3f;
        World world = Scenes.BallPit(count, planar: true, seed: 1, radius: radius,
            responder: CreateResponder(options.Responder, e, mu));
        string description = Invariant(
            $"{count} discs (r = {radius} m) poured into a closed box under gravity; eps = {e}, mu = {mu}, responder = {NameOf(options.Responder)}");
        Expectation? expectation = options.Responder is ResponderKind.Solver && Duration(options, 400) >= 3
            ? new Expectation("the pile settles: kinetic energy ends below 5 % of its largest value, penetration stays below 10 % of the radius",
                (scene, summary) => summary.EndKineticEnergy <= 0.05 * summary.MaxKineticEnergy && summary.MaxPenetration <= 0.1 * radius ? null
                    : Format.Invariant($"kinetic energy ended at {Format.Number(summary.EndKineticEnergy)} J of at most {Format.Number(summary.MaxKineticEnergy)} J, largest penetration {Format.Number(summary.MaxPenetration)} m"))
            : null;
        return Make("pile", description, world, Array.Empty<string>(), options, steps: 400, rows: 50, summaryOnly: true, expectation);
    }

    private static Scene Row(Options options)
    {
        const int count = 3;
        const float speed = 2f;
        float e = options.Restitution ?? 1f;
        float mu = options.Friction ?? 0f;
        World world = Scenes.StruckRow(count, speed, e, CreateResponder(options.Responder, e, mu));
        if (options.Friction is float friction)
        {
            foreach (RigidBody body in world.Bodies)
            {
                body.Friction = friction; // between the balls; the table stays frictionless
            }
        }

        var labels = new List<string>();
        for (int i = 1; i <= count; i++)
        {
            labels.Add(Invariant($"row{i}"));
        }

        labels.Add("striker"); // Scenes.StruckRow adds the striker last
        string description = Invariant(
            $"{count} touching balls on a frictionless table, struck at one end by a ball at {speed} m/s; eps = {e}, mu = {mu} between balls, responder = {NameOf(options.Responder)}");
        // The solver answers simultaneous collisions as a chain of two-body collisions (Newton's cradle); one pass of a
        // pairwise responder in detection order does not pass the blow along the row.
        Expectation? expectation = options.Responder is ResponderKind.Solver && e == 1f && mu == 0f && Duration(options, 250) >= 1
            ? new Expectation(Format.Invariant($"with eps = 1 the striker stops and the far ball leaves at the striker's {speed} m/s (Newton's cradle)"),
                (scene, _) =>
                {
                    float striker = scene.World.Bodies[count].LinearVelocity.X, far = scene.World.Bodies[count - 1].LinearVelocity.X;
                    return Math.Abs(striker) < 0.05 * speed && Math.Abs(far - speed) < 0.05 * speed ? null
                        : Format.Invariant($"the striker ends at {Format.Number(striker)} m/s and the far ball at {Format.Number(far)} m/s");
                })
            : null;
        return Make("row", description, world, labels, options, steps: 250, rows: 25, summaryOnly: false, expectation);
    }

    private static Scene Slide(Options options)
    {
        const float speed = 5f;
        float mu = options.Friction ?? 0.3f;
        float e = options.Restitution ?? 0f;
        World world = Scenes.SlidingBall(speed, mu, responder: CreateResponder(options.Responder, e, mu));
        if (options.Restitution is float restitution)
        {
            world.Bodies[0].Restitution = restitution;
        }

        // A solid sphere sliding without spin: friction μ m g slows it and spins it up until v = ω r, which
        // happens at t = 2 v0 / (7 μ g) with v = 5/7 v0.
        // Friction needs an impulse at the contact point (solver, impulse responder); the run must last past the
        // time it takes to roll.
        double rollTime = mu > 0 ? 2 * speed / (7 * mu * Gravity) : double.PositiveInfinity;
        bool rollsInTime = Duration(options, 150) > 1.2 * rollTime;
        Expectation? expectation = options.Responder is not (ResponderKind.Solver or ResponderKind.Impulse)
            ? null
            : mu > 0
                ? rollsInTime
                    ? new Expectation(
                        Invariant($"a solid sphere starts rolling (v = -wz r) at t = 2 v0 / (7 mu g) = {rollTime:F3} s with v = 5/7 v0 = {5 * speed / 7:F3} m/s"),
                        (scene, _) =>
                        {
                            RigidBody ball = scene.World.Bodies[0];
                            double v = ball.LinearVelocity.X, rolling = -ball.AngularVelocity.Z * ball.Radius;
                            return Math.Abs(v - 5 * speed / 7.0) < 0.02 * speed && Math.Abs(v - rolling) < 0.02 * speed ? null
                                : Format.Invariant($"it ends with v = {Format.Number(v)} m/s and -wz r = {Format.Number(rolling)} m/s");
                        })
                    : null
                : new Expectation("without friction the ball slides on at 5 m/s and never spins",
                    (scene, _) => Math.Abs(scene.World.Bodies[0].AngularVelocity.Z) < 1e-6 && Math.Abs(scene.World.Bodies[0].LinearVelocity.X - speed) < 1e-3 * speed ? null
                        : Format.Invariant($"it ends with v = {Format.Number(scene.World.Bodies[0].LinearVelocity.X)} m/s, wz = {Format.Number(scene.World.Bodies[0].AngularVelocity.Z)} rad/s"));
        string description = Invariant(
            $"a solid ball (r = 0.5 m, 1 kg) set sliding at {speed} m/s on rough ground with no spin; mu = {mu}, eps = {e}, responder = {NameOf(options.Responder)}");
        return Make("slide", description, world, new[] { "ball" }, options, steps: 150, rows: 50, summaryOnly: false, expectation);
    }

    /// <summary>
    /// A small game: twelve balls poured into a 3 m box, beside a drain (a static sensor in the right-hand corner);
    /// the table prints the contact and sensor events of each row and how many balls sleep.
    /// </summary>
    private static Scene Game(Options options)
    {
        const int count = 12;
        const float radius = 0.2f, width = 3f;
        float e = options.Restitution ?? 0.3f;
        float mu = options.Friction ?? 0.5f;
        var world = new World(new Vector3(0, -Gravity, 0), CreateResponder(options.Responder, e, mu));
        world.AddPlanes(StaticPlane.Box(Vector3.Zero, new Vector3(width, 4 * width, 0), planar: true));
        var labels = new List<string>();
        for (int i = 0; i < count; i++)
        {
            // Poured from the left, two columns, each ball a little higher and faster to the right than the last.
            var position = new Vector3(0.4f + 0.5f * (i % 2), 1f + 0.45f * i, 0);
            world.Add(new RigidBody(1f, radius, position, Inertia.Disc(1f, radius)) { LinearVelocity = new Vector3(0.4f + 0.1f * i, 0, 0) });
            labels.Add(Invariant($"ball{i + 1}"));
        }

        RigidBody drain = world.Add(RigidBody.CreateStatic(0.5f, new Vector3(width, 0, 0)));
        drain.IsSensor = true;
        labels.Add("drain");
        string description = Invariant(
            $"{count} balls (r = {radius} m) poured into a {width} m box beside a drain sensor in the right-hand corner; eps = {e}, mu = {mu}, responder = {NameOf(options.Responder)}");
        Expectation? expectation = options.Responder is ResponderKind.Solver && Duration(options, 600) >= 5
            ? new Expectation("every ball comes to rest and falls asleep",
                (scene, _) => scene.World.SleepingBodyCount == count ? null
                    : Format.Invariant($"{scene.World.SleepingBodyCount} of {count} balls sleep at the end"))
            : null;
        return Make("game", description, world, labels, options, steps: 600, rows: 12, summaryOnly: true, expectation, showEvents: true);
    }

    private static Scene Make(string name, string description, World world, IReadOnlyList<string> labels, Options options,
        int steps, int rows, bool summaryOnly, Expectation? expectation, bool showEvents = false)
    {
        int n = options.Steps ?? steps;
        if (options.Format is OutputFormat.Svg or OutputFormat.Html)
        {
            rows = PictureFrames; // pictures want smooth curves, not a page of rows
        }

        int every = options.Every ?? Math.Max(1, (int)Math.Round(n / (double)rows));
        return new Scene(name, description, world, labels, n, options.Dt ?? DefaultDt, every, summaryOnly, Planar: true, options.Responder, expectation, showEvents);
    }

    /// <summary>The simulated time (s) of the run: the steps given or <paramref name="steps"/>, times dt.</summary>
    private static double Duration(Options options, int steps) => (options.Steps ?? steps) * (double)(options.Dt ?? DefaultDt);

    /// <summary>|ω_z| of body <paramref name="index"/> now.</summary>
    private static double Spin(Scene scene, int index) => Math.Abs(scene.World.Bodies[index].AngularVelocity.Z);

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
