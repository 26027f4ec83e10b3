using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;
using System.Text;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Trajectories;

/// <summary>
/// Writes trajectories: per printed step the time, each body's position, velocity and angular velocity, and the
/// world's diagnostics. A run calls <see cref="BeginScene"/>, then <see cref="WriteStep"/> per printed step,
/// then <see cref="EndScene"/>, once per scene, and <see cref="Complete"/> at the end.
/// </summary>
public abstract class TrajectoryWriter
{
    /// <summary>Creates the writer for <paramref name="format"/>.</summary>
    public static TrajectoryWriter Create(OutputFormat format, System.IO.TextWriter output) => format switch
    {
        OutputFormat.Table => new TableTrajectoryWriter(output),
        OutputFormat.Csv => new CsvTrajectoryWriter(output),
        OutputFormat.Svg => new SvgTrajectoryWriter(output),
        OutputFormat.Html => new HtmlTrajectoryWriter(output),
        _ => throw new ArgumentOutOfRangeException(nameof(format), format, "Unknown format."),
    };

    /// <summary>Starts a scene.</summary>
    public abstract void BeginScene(Scene scene);

    /// <summary>Writes the state after <paramref name="step"/> steps.</summary>
    public abstract void WriteStep(Scene scene, int step);

    /// <summary>Ends a scene with what the whole run did and the warnings its checks raised.</summary>
    public abstract void EndScene(Scene scene, RunSummary summary, IReadOnlyList<string> warnings);

    /// <summary>Ends the run; writers that draw the whole run at once write it here.</summary>
    public virtual void Complete()
    {
    }

    /// <summary>
    /// The contacts whose bodies touch or overlap now, penetration ≥ 0, measured from the bodies' positions after
    /// the step. Detection also reports speculative pairs that may touch within the next step; they are not counted.
    /// Pairs of sleeping bodies are not detected (they are not in <see cref="World.Collisions"/>): they are taken from
    /// <see cref="SimpleDynamics.Collision.ContactEvents.Touching"/> and counted by the same rule.
    /// </summary>
    public static int TouchingContacts(World world)
    {
        int count = 0;
        foreach (SimpleDynamics.Collision.Contact contact in world.Collisions.Contacts)
        {
            if (Penetration(world, contact) >= 0)
            {
                count++;
            }
        }

        foreach (SimpleDynamics.Collision.ContactEvent pair in world.ContactEvents.Touching)
        {
            if (!pair.BodyA.IsAwake || pair.BodyB is { IsAwake: false })
            {
                RigidBody a = pair.BodyA;
                float penetration = pair.BodyB is RigidBody b
                    ? a.Radius + b.Radius - Vector3.Distance(a.Position, b.Position)
                    : a.Radius - world.Planes[pair.PlaneIndex].DistanceTo(a.Position);
                count += penetration >= 0 ? 1 : 0;
            }
        }

        return count;
    }

    /// <summary>r_A + r_B − d for two bodies; r_A − (distance of A's centre from the plane) for a plane contact.</summary>
    public static float Penetration(World world, in SimpleDynamics.Collision.Contact contact)
    {
        RigidBody a = contact.BodyA, b = contact.BodyB;
        if (!contact.IsPlaneContact)
        {
            return a.Radius + b.Radius - Vector3.Distance(a.Position, b.Position);
        }

        float penetration = float.NegativeInfinity;
        foreach (SimpleDynamics.Collision.StaticPlane plane in world.Planes)
        {
            if (Vector3.Dot(plane.Normal, contact.Normal) > 0.9999f)
            {
                penetration = MathF.Max(penetration, a.Radius - plane.DistanceTo(a.Position));
            }
        }

        return penetration;
    }

    /// <summary>
    /// The centre of mass of the dynamic bodies, the velocity of the centre of mass (Σ m v / Σ m), their mean
    /// angular velocity, and the largest speed: what a many-body scene prints instead of every body.
    /// </summary>
    protected static (Vector3 Position, Vector3 Velocity, Vector3 AngularVelocity, float MaxSpeed, int Count) CentreOfMass(World world)
    {
        double mass = 0;
        Vector3 weighted = Vector3.Zero, momentum = Vector3.Zero, spin = Vector3.Zero;
        float maxSpeed = 0;
        int count = 0;
        foreach (RigidBody body in world.Bodies)
        {
            if (!body.IsDynamic)
            {
                continue;
            }

            count++;
            mass += body.Mass;
            weighted += body.Mass * body.Position;
            momentum += body.Mass * body.LinearVelocity;
            spin += body.AngularVelocity;
            maxSpeed = MathF.Max(maxSpeed, body.LinearVelocity.Length());
        }

        if (count == 0)
        {
            return (Vector3.Zero, Vector3.Zero, Vector3.Zero, 0, 0);
        }

        float m = (float)mass;
        return (weighted / m, momentum / m, spin / count, maxSpeed, count);
    }
}

/// <summary>
/// Aligned columns for a person to read. Each scene starts with '#' lines (what it is, the units), then a
/// header and one line per body per printed step; the diagnostics fill the first body's line of each step.
/// A planar scene leaves out z, vz, wx, wy and pz, which stay 0.
/// </summary>
public sealed class TableTrajectoryWriter : TrajectoryWriter
{
    private const int Width = 9;
    private readonly System.IO.TextWriter _out;
    private bool _first = true;

    /// <summary>Writes to <paramref name="output"/>.</summary>
    public TableTrajectoryWriter(System.IO.TextWriter output) => _out = output;

    /// <inheritdoc />
    public override void BeginScene(Scene scene)
    {
        if (!_first)
        {
            _out.WriteLine();
        }

        _first = false;
        _out.WriteLine($"# scene: {scene.Name} - {scene.Description}");
        _out.WriteLine(Format(
            $"# dt = {scene.Dt} s, {scene.Steps} steps ({scene.Steps * (double)scene.Dt:0.###} s), a row every {scene.Every} steps ({scene.Every * (double)scene.Dt:0.####} s) and the last"));
        _out.WriteLine(scene.SummaryOnly
            ? "# per row: the dynamic bodies' centre of mass (m), its velocity (m/s), their largest speed (m/s); then the diagnostics"
            : "# per row: position (m), velocity (m/s), angular velocity (rad/s); on each step's first line the diagnostics");
        _out.WriteLine("# diagnostics: KE, PE, E = kinetic, potential, mechanical energy (J); p = linear momentum (kg m/s); contacts = touching pairs; max pen = largest penetration (m)");
        if (scene.ShowEvents)
        {
            _out.WriteLine("# asleep = sleeping bodies; under each row the contact events since the row before (begin and end touching, hits of 1 m/s or more) and the drain sensor's");
        }
        if (scene.Expectation is not null)
        {
            _out.WriteLine($"# expect: {scene.Expectation.Text}");
        }

        var header = new StringBuilder();
        header.Append(Pad("time", 8)).Append(' ').Append("body".PadRight(BodyWidth(scene)));
        string[] motion = scene.SummaryOnly
            ? (scene.Planar ? new[] { "com x", "com y", "com vx", "com vy", "max |v|" } : new[] { "com x", "com y", "com z", "com vx", "com vy", "com vz", "max |v|" })
            : (scene.Planar ? new[] { "x", "y", "vx", "vy", "wz" } : new[] { "x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz" });
        foreach (string column in motion)
        {
            header.Append(Pad(column, Width));
        }

        header.Append("  |");
        foreach (string column in scene.Planar ? new[] { "KE", "PE", "E", "px", "py" } : new[] { "KE", "PE", "E", "px", "py", "pz" })
        {
            header.Append(Pad(column, Width));
        }

        header.Append(Pad("contacts", Width)).Append(Pad("max pen", Width + 1));
        if (scene.ShowEvents)
        {
            header.Append(Pad("asleep", Width));
        }

        _out.WriteLine(header.ToString());
    }

    /// <inheritdoc />
    public override void WriteStep(Scene scene, int step)
    {
        World world = scene.World;
        string time = Fixed(world.Time, TimeDecimals(scene)).PadLeft(8);
        int bodyWidth = BodyWidth(scene);
        string diagnostics = Diagnostics(scene);
        if (scene.SummaryOnly)
        {
            var (position, velocity, _, maxSpeed, count) = CentreOfMass(world);
            var line = new StringBuilder();
            line.Append(time).Append(' ').Append(count.ToString(CultureInfo.InvariantCulture).PadRight(bodyWidth));
            Append(line, position, scene.Planar);
            Append(line, velocity, scene.Planar);
            line.Append(Pad(Fixed(maxSpeed, 3), Width));
            line.Append(diagnostics);
            if (scene.ShowEvents)
            {
                line.Append(Pad(world.SleepingBodyCount.ToString(CultureInfo.InvariantCulture), Width));
            }

            _out.WriteLine(line.ToString());
            WriteEvents(scene, step);
            return;
        }

        for (int i = 0; i < world.Bodies.Count; i++)
        {
            RigidBody body = world.Bodies[i];
            var line = new StringBuilder();
            line.Append(time).Append(' ').Append(Label(scene, i).PadRight(bodyWidth));
            Append(line, body.Position, scene.Planar);
            Append(line, body.LinearVelocity, scene.Planar);
            if (scene.Planar)
            {
                line.Append(Pad(Fixed(body.AngularVelocity.Z, 3), Width));
            }
            else
            {
                Append(line, body.AngularVelocity, planar: false);
            }

            if (i == 0)
            {
                line.Append(diagnostics);
            }

            _out.WriteLine(line.ToString());
        }
    }

    /// <inheritdoc />
    public override void EndScene(Scene scene, RunSummary summary, IReadOnlyList<string> warnings)
    {
        double rise = summary.MaxMechanicalEnergy - summary.StartMechanicalEnergy;
        _out.WriteLine(Format(
            $"# summary: E {summary.StartMechanicalEnergy:F3} -> {summary.EndMechanicalEnergy:F3} J (largest rise above the start {Math.Max(0, rise):F4} J), KE {summary.StartKineticEnergy:F3} -> {summary.EndKineticEnergy:F3} J"));
        _out.WriteLine(Format(
            $"# summary: largest penetration {summary.MaxPenetration:F4} m ({100 * summary.MaxPenetration / summary.SmallestRadius:F1}% of the smallest radius {summary.SmallestRadius} m)"));
        if (scene.Planar && summary.LeftPlane)
        {
            _out.WriteLine("# warning: the motion left the z = 0 plane; the table does not show z");
        }

        if (summary.FirstNonFiniteStep is null)
        {
            _out.WriteLine("# summary: every state finite (no NaN)");
        }

        foreach (string warning in warnings)
        {
            _out.WriteLine("# warning: " + warning);
        }
    }

    /// <summary>The events since the last row, as comment lines under it (scenes that show events, after step 0).</summary>
    private void WriteEvents(Scene scene, int step)
    {
        if (!scene.ShowEvents || step == 0)
        {
            return;
        }

        foreach (string line in scene.Events.TakeRow())
        {
            _out.WriteLine("#          " + line);
        }
    }

    private string Diagnostics(Scene scene)
    {
        WorldDiagnostics d = scene.World.Diagnostics;
        var text = new StringBuilder("  |");
        text.Append(Pad(Fixed(d.KineticEnergy, 3), Width));
        text.Append(Pad(Fixed(d.PotentialEnergy, 3), Width));
        text.Append(Pad(Fixed(d.MechanicalEnergy, 3), Width));
        Append(text, d.LinearMomentum, scene.Planar);
        text.Append(Pad(TouchingContacts(scene.World).ToString(CultureInfo.InvariantCulture), Width));
        text.Append(Pad(Fixed(d.MaxPenetration, 4), Width + 1));
        return text.ToString();
    }

    private static void Append(StringBuilder line, Vector3 v, bool planar)
    {
        line.Append(Pad(Fixed(v.X, 3), Width)).Append(Pad(Fixed(v.Y, 3), Width));
        if (!planar)
        {
            line.Append(Pad(Fixed(v.Z, 3), Width));
        }
    }

    private static string Label(Scene scene, int index) =>
        index < scene.Labels.Count ? scene.Labels[index] : (index + 1).ToString(CultureInfo.InvariantCulture);

    private static int BodyWidth(Scene scene)
    {
        int width = scene.SummaryOnly ? "bodies".Length : 4;
        for (int i = 0; i < scene.World.Bodies.Count && !scene.SummaryOnly; i++)
        {
            width = Math.Max(width, Label(scene, i).Length);
        }

        return width;
    }

    /// <summary>
    /// The decimals that show every step's time exactly: 2 for dt = 0.01 s, 3 for 0.005 s; 4 when dt has no
    /// short decimal form (1/60 s).
    /// </summary>
    private static int TimeDecimals(Scene scene)
    {
        double dt = scene.Dt;
        for (int decimals = 2; decimals <= 6; decimals++)
        {
            if (Math.Abs(Math.Round(dt, decimals) - dt) <= 1e-6 * dt)
            {
                return decimals;
            }
        }

        return 4;
    }

    /// <summary>Right-aligned in <paramref name="width"/>, and always after a space: a wide number never runs into its neighbour.</summary>
    private static string Pad(string text, int width) => text.Length < width ? text.PadLeft(width) : " " + text;

    /// <summary>Fixed-point, invariant, and without the "-0.000" of a tiny negative number.</summary>
    private static string Fixed(double value, int decimals)
    {
        if (!double.IsFinite(value))
        {
            return value.ToString(CultureInfo.InvariantCulture);
        }

        double rounded = Math.Round(value, decimals);
        if (rounded == 0)
        {
            rounded = 0; // turns −0 into +0
        }

        return rounded.ToString("F" + decimals.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture);
    }

    private static string Format(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}

/// <summary>
/// Comma-separated values with one header row for the whole run; each row is one body at one printed step,
/// with full 3-D vectors and the world's diagnostics repeated on every body's row. A summary-only scene writes
/// one row per step for its centre of mass, body "com" (its mean angular velocity in the w columns).
/// Every number has one format, floats and doubles alike: invariant, seven significant digits (what a float
/// holds; the diagnostics are summed in double from float states), "0" for zero.
/// </summary>
public sealed class CsvTrajectoryWriter : TrajectoryWriter
{
    /// <summary>The column names, in order.</summary>
    public static readonly IReadOnlyList<string> Columns = new[]
    {
        "scene", "step", "time", "body", "x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz",
        "kinetic", "potential", "mechanical", "px", "py", "pz", "contacts", "max_penetration",
        "asleep", "begin_touch", "end_touch", "hits",
    };

    private readonly System.IO.TextWriter _out;
    private bool _headerWritten;

    /// <summary>Writes to <paramref name="output"/>.</summary>
    public CsvTrajectoryWriter(System.IO.TextWriter output) => _out = output;

    /// <inheritdoc />
    public override void BeginScene(Scene scene)
    {
        if (!_headerWritten)
        {
            _out.WriteLine(string.Join(",", Columns));
            _headerWritten = true;
        }
    }

    /// <inheritdoc />
    public override void WriteStep(Scene scene, int step)
    {
        World world = scene.World;
        WorldDiagnostics d = world.Diagnostics;
        string prefix = string.Join(",", scene.Name, step.ToString(CultureInfo.InvariantCulture), Number(world.Time));
        // Event counts since the last row (a row may stand for several steps).
        EventLog events = scene.Events;
        string counts = string.Join(",", Count(world.SleepingBodyCount), Count(events.Begins), Count(events.Ends), Count(events.Hits));
        events.TakeRow();
        string diagnostics = string.Join(",", Number(d.KineticEnergy), Number(d.PotentialEnergy), Number(d.MechanicalEnergy),
            Vector(d.LinearMomentum), TouchingContacts(world).ToString(CultureInfo.InvariantCulture), Number(d.MaxPenetration), counts);
        if (scene.SummaryOnly)
        {
            var (position, velocity, spin, _, _) = CentreOfMass(world);
            _out.WriteLine(string.Join(",", prefix, "com", Vector(position), Vector(velocity), Vector(spin), diagnostics));
            return;
        }

        for (int i = 0; i < world.Bodies.Count; i++)
        {
            RigidBody body = world.Bodies[i];
            string label = i < scene.Labels.Count ? scene.Labels[i] : (i + 1).ToString(CultureInfo.InvariantCulture);
            _out.WriteLine(string.Join(",", prefix, label, Vector(body.Position), Vector(body.LinearVelocity), Vector(body.AngularVelocity), diagnostics));
        }
    }

    /// <inheritdoc />
    public override void EndScene(Scene scene, RunSummary summary, IReadOnlyList<string> warnings)
    {
        // CSV holds data rows only; the summary is for the table, warnings also go to standard error.
    }

    private static string Vector(Vector3 v) => string.Join(",", Number(v.X), Number(v.Y), Number(v.Z));

    private static string Count(int value) => value.ToString(CultureInfo.InvariantCulture);

    /// <summary>
    /// The one number format (<see cref="Trajectories.Format.Number"/>). World.Time sums float steps, so 3 × 0.01f
    /// reads 0.029999999 in double; seven digits show 0.03.
    /// </summary>
    private static string Number(double value) => Trajectories.Format.Number(value);
}
