using System;
using System.Collections.Generic;
using System.Globalization;
using SimpleDynamics.Bodies;
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
/// <param name="Expectation">What classical mechanics predicts, if it says something simple; else null.</param>
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
    string? Expectation);

/// <summary>
/// Builds the sample's scenes from <see cref="Scenes"/> (the geometry the tests and benchmarks share) with the
/// responder, ε and μ the command line asks for.
/// </summary>
public static class SceneFactory
{
    /// <summary>The time step when none is given (s).</summary>
    public const float DefaultDt = 0.01f;

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
        return Make("bounce", description, world, new[] { "ball" }, options, steps: 400, rows: 50, summaryOnly: false, expectation: null);
    }

    private static Scene OffCentre(Options options)
    {
        float e = options.Restitution ?? 0.8f;
        float mu = options.Friction ?? 0.3f;
        World world = Scenes.OffCentreCollision(e, mu, CreateResponder(options.Responder, e, mu));
        string description = Invariant(
            $"two discs (1 kg moving right at 3 m/s, 2 kg moving left at 1 m/s) meet off-centre, no gravity; eps = {e}, mu = {mu}, responder = {NameOf(options.Responder)}");
        return Make("offcentre", description, world, new[] { "left", "right" }, options, steps: 200, rows: 40, summaryOnly: false,
            expectation: mu > 0 ? "friction at the contact point sets both discs spinning (wz != 0 after the hit)" : "without friction neither disc spins");
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
        return Make("pile", description, world, Array.Empty<string>(), options, steps: 400, rows: 50, summaryOnly: true,
            expectation: "the pile settles: kinetic energy falls towards 0, penetration stays small");
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
        return Make("row", description, world, labels, options, steps: 250, rows: 25, summaryOnly: false,
            expectation: "with eps = 1 the striker stops and the far ball leaves at the striker's speed (Newton's cradle)");
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
        string? expectation = mu > 0
            ? Invariant($"a solid sphere starts rolling (v = wz r) at t = 2 v0 / (7 mu g) = {2 * speed / (7 * mu * Gravity):F3} s with v = 5/7 v0 = {5 * speed / 7:F3} m/s")
            : "without friction the ball slides forever and never spins";
        string description = Invariant(
            $"a solid ball (r = 0.5 m, 1 kg) set sliding at {speed} m/s on rough ground with no spin; mu = {mu}, eps = {e}, responder = {NameOf(options.Responder)}");
        return Make("slide", description, world, new[] { "ball" }, options, steps: 150, rows: 50, summaryOnly: false, expectation);
    }

    private static Scene Make(string name, string description, World world, IReadOnlyList<string> labels, Options options,
        int steps, int rows, bool summaryOnly, string? expectation)
    {
        int n = options.Steps ?? steps;
        int every = options.Every ?? Math.Max(1, (int)Math.Round(n / (double)rows));
        return new Scene(name, description, world, labels, n, options.Dt ?? DefaultDt, every, summaryOnly, Planar: true, expectation);
    }

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
