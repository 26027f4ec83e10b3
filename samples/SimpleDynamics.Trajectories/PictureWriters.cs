using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Net;
using System.Numerics;
using System.Text;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Trajectories;

/// <summary>One scene as recorded for a picture: every body's position and spin angle per frame, and the energies.</summary>
public sealed class Recording
{
    /// <summary>Starts recording <paramref name="scene"/>.</summary>
    public Recording(Scene scene)
    {
        Scene = scene;
        Labels = Enumerable.Range(0, scene.World.Bodies.Count)
            .Select(i => i < scene.Labels.Count ? scene.Labels[i] : (i + 1).ToString(CultureInfo.InvariantCulture)).ToArray();
        Radii = scene.World.Bodies.Select(b => b.Radius).ToArray();
        Planes = scene.World.Planes.ToArray();
    }

    /// <summary>The scene recorded.</summary>
    public Scene Scene { get; }

    /// <summary>A label per body.</summary>
    public IReadOnlyList<string> Labels { get; }

    /// <summary>A radius per body (m).</summary>
    public IReadOnlyList<float> Radii { get; }

    /// <summary>The world's planes (walls, ground).</summary>
    public IReadOnlyList<StaticPlane> Planes { get; }

    /// <summary>The frames, in time order.</summary>
    public List<Frame> Frames { get; } = new();

    /// <summary>Warnings the run raised.</summary>
    public IReadOnlyList<string> Warnings { get; set; } = Array.Empty<string>();

    /// <summary>Records the world's state now.</summary>
    public void Capture()
    {
        World world = Scene.World;
        var positions = new Vector2[world.Bodies.Count];
        var angles = new float[world.Bodies.Count];
        for (int i = 0; i < positions.Length; i++)
        {
            RigidBody body = world.Bodies[i];
            positions[i] = new Vector2(body.Position.X, body.Position.Y);
            Quaternion q = body.Orientation;
            angles[i] = 2 * MathF.Atan2(q.Z, q.W); // the rotation about z of a planar body
        }

        WorldDiagnostics d = world.Diagnostics;
        Frames.Add(new Frame(world.Time, positions, angles, d.KineticEnergy, d.PotentialEnergy));
    }

    /// <summary>One recorded instant.</summary>
    /// <param name="Time">s</param>
    /// <param name="Positions">x, y per body (m)</param>
    /// <param name="Angles">rotation about z per body (rad)</param>
    /// <param name="Kinetic">J</param>
    /// <param name="Potential">J</param>
    public sealed record Frame(double Time, Vector2[] Positions, float[] Angles, double Kinetic, double Potential)
    {
        /// <summary>Mechanical energy (J).</summary>
        public double Mechanical => Kinetic + Potential;
    }
}

/// <summary>Records every scene, then writes the whole run at <see cref="TrajectoryWriter.Complete"/>.</summary>
public abstract class PictureWriter : TrajectoryWriter
{
    /// <summary>
    /// The body colours, in order (then repeated). Used for bodies only, nowhere else in a picture, so a test can
    /// find the balls in a screenshot by colour.
    /// </summary>
    public static readonly IReadOnlyList<string> BodyColours = new[] { "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#17becf" };

    /// <summary>Colours of the energy curves: kinetic, potential, mechanical.</summary>
    protected static readonly string[] EnergyColours = { "#b8860b", "#708090", "#000000" };

    private Recording? _current;

    /// <summary>Writes to <paramref name="output"/>.</summary>
    protected PictureWriter(TextWriter output) => Output = output;

    /// <summary>The scenes recorded so far.</summary>
    protected List<Recording> Recordings { get; } = new();

    /// <summary>Where the picture goes.</summary>
    protected TextWriter Output { get; }

    /// <inheritdoc />
    public override void BeginScene(Scene scene)
    {
        _current = new Recording(scene);
        Recordings.Add(_current);
    }

    /// <inheritdoc />
    public override void WriteStep(Scene scene, int step) => _current?.Capture();

    /// <inheritdoc />
    public override void EndScene(Scene scene, RunSummary summary, IReadOnlyList<string> warnings)
    {
        if (_current is not null)
        {
            _current.Warnings = warnings;
        }
    }

    /// <summary>A number for SVG, JSON or JavaScript: invariant, at most <paramref name="decimals"/> decimals.</summary>
    protected static string N(double value, int decimals = 2)
    {
        if (!double.IsFinite(value))
        {
            return "0";
        }

        double rounded = Math.Round(value, decimals);
        return rounded == 0 ? "0" : rounded.ToString("0.######", CultureInfo.InvariantCulture);
    }

    /// <summary>Text escaped for XML and HTML.</summary>
    protected static string E(string text) => WebUtility.HtmlEncode(text);
}

/// <summary>
/// A standalone SVG: per scene, position over time (x solid, y dashed per body; y only above 10 bodies), the path
/// of each body in the plane (one &lt;path class="body-path"&gt; per body, equal scales, walls as grey lines) and
/// kinetic, potential and mechanical energy over time.
/// </summary>
public sealed class SvgTrajectoryWriter : PictureWriter
{
    private const int Width = 1100, PanelWidth = 300, PanelHeight = 240, SceneHeight = 330, Left = 50;

    /// <summary>Writes to <paramref name="output"/>.</summary>
    public SvgTrajectoryWriter(TextWriter output)
        : base(output)
    {
    }

    /// <inheritdoc />
    public override void Complete()
    {
        int height = Math.Max(1, Recordings.Count) * SceneHeight + 12 * Recordings.Sum(r => r.Warnings.Count) + 10;
        var svg = new StringBuilder();
        svg.Append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        svg.Append($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{Width}\" height=\"{height}\" viewBox=\"0 0 {Width} {height}\" font-family=\"sans-serif\" font-size=\"11\">\n");
        svg.Append("<title>SimpleDynamics trajectories</title>\n");
        svg.Append($"<rect width=\"{Width}\" height=\"{height}\" fill=\"#ffffff\"/>\n");
        for (int s = 0; s < Recordings.Count; s++)
        {
            Recording r = Recordings[s];
            int top = s * SceneHeight + 12 * Recordings.Take(s).Sum(previous => previous.Warnings.Count) + 10;
            svg.Append($"<g id=\"scene-{E(r.Scene.Name)}\" transform=\"translate(0,{top})\">\n");
            svg.Append($"<text x=\"10\" y=\"14\" font-size=\"13\" font-weight=\"bold\">{E(r.Scene.Name)}: {E(r.Scene.Description)}</text>\n");
            for (int w = 0; w < r.Warnings.Count; w++)
            {
                svg.Append($"<text x=\"10\" y=\"{26 + 12 * w}\" fill=\"#b00000\">warning: {E(r.Warnings[w])}</text>\n");
            }

            int panels = 40 + 12 * r.Warnings.Count;
            TimePlot(svg, r, Left, panels);
            PathPlot(svg, r, Left + PanelWidth + 60, panels);
            EnergyPlot(svg, r, Left + 2 * (PanelWidth + 60), panels);
            svg.Append("</g>\n");
        }

        svg.Append("</svg>\n");
        Output.Write(svg.ToString());
        Output.Flush();
    }

    private static void TimePlot(StringBuilder svg, Recording r, int x0, int y0)
    {
        bool withX = r.Labels.Count <= 10;
        double t0 = r.Frames[0].Time, t1 = Math.Max(r.Frames[^1].Time, t0 + 1e-9);
        IEnumerable<float> values = r.Frames.SelectMany(f => f.Positions.SelectMany(p => withX ? new[] { p.X, p.Y } : new[] { p.Y }));
        (double lo, double hi) = Range(values);
        Frame(svg, x0, y0, withX ? "position over time (x solid, y dashed), m" : "height y over time, m", t0, t1, lo, hi, "t (s)");
        svg.Append($"<g id=\"positions-{E(r.Scene.Name)}\" fill=\"none\" stroke-width=\"1.5\">\n");
        for (int b = 0; b < r.Labels.Count; b++)
        {
            string colour = BodyColours[b % BodyColours.Count];
            for (int axis = withX ? 0 : 1; axis < 2; axis++)
            {
                var d = new StringBuilder();
                foreach (Recording.Frame f in r.Frames)
                {
                    double v = axis == 0 ? f.Positions[b].X : f.Positions[b].Y;
                    d.Append(d.Length == 0 ? "M" : " L").Append(N(x0 + (f.Time - t0) / (t1 - t0) * PanelWidth)).Append(' ')
                        .Append(N(y0 + PanelHeight - (v - lo) / (hi - lo) * PanelHeight));
                }

                svg.Append($"<path stroke=\"{colour}\"{(axis == 1 && withX ? " stroke-dasharray=\"4 3\"" : string.Empty)} d=\"{d}\"><title>{E(r.Labels[b])} {(axis == 0 ? "x" : "y")}</title></path>\n");
            }
        }

        svg.Append("</g>\n");
    }

    private static void PathPlot(StringBuilder svg, Recording r, int x0, int y0)
    {
        // Equal scales on both axes, so a circle stays a circle.
        (double xLo, double xHi) = Range(r.Frames.SelectMany(f => f.Positions.Select((p, i) => new[] { p.X - r.Radii[i], p.X + r.Radii[i] }).SelectMany(v => v)));
        (double yLo, double yHi) = Range(r.Frames.SelectMany(f => f.Positions.Select((p, i) => new[] { p.Y - r.Radii[i], p.Y + r.Radii[i] }).SelectMany(v => v)));
        double scale = Math.Min(PanelWidth / (xHi - xLo), PanelHeight / (yHi - yLo));
        double cx = (xLo + xHi) / 2, cy = (yLo + yHi) / 2;
        double X(double x) => x0 + PanelWidth / 2.0 + (x - cx) * scale;
        double Y(double y) => y0 + PanelHeight / 2.0 - (y - cy) * scale;
        svg.Append($"<text x=\"{x0}\" y=\"{y0 - 6}\">path in the plane (x right, y up; equal scales), m</text>\n");
        svg.Append($"<rect x=\"{x0}\" y=\"{y0}\" width=\"{PanelWidth}\" height=\"{PanelHeight}\" fill=\"none\" stroke=\"#cccccc\"/>\n");
        foreach (StaticPlane plane in r.Planes)
        {
            if (MathF.Abs(plane.Normal.Y) > 0.999f && plane.Offset * plane.Normal.Y is float y && y >= yLo - 1e-3 && y <= yHi + 1e-3)
            {
                svg.Append($"<line x1=\"{x0}\" x2=\"{x0 + PanelWidth}\" y1=\"{N(Y(y))}\" y2=\"{N(Y(y))}\" stroke=\"#999999\" stroke-width=\"2\"/>\n");
            }
            else if (MathF.Abs(plane.Normal.X) > 0.999f && plane.Offset * plane.Normal.X is float x && x >= xLo - 1e-3 && x <= xHi + 1e-3)
            {
                svg.Append($"<line y1=\"{y0}\" y2=\"{y0 + PanelHeight}\" x1=\"{N(X(x))}\" x2=\"{N(X(x))}\" stroke=\"#999999\" stroke-width=\"2\"/>\n");
            }
        }

        svg.Append($"<text x=\"{x0}\" y=\"{y0 + PanelHeight + 14}\">x {N(xLo)} to {N(xHi)}, y {N(yLo)} to {N(yHi)}</text>\n");
        svg.Append($"<g id=\"paths-{E(r.Scene.Name)}\" fill=\"none\" stroke-width=\"1.5\">\n");
        for (int b = 0; b < r.Labels.Count; b++)
        {
            var d = new StringBuilder();
            foreach (Recording.Frame f in r.Frames)
            {
                d.Append(d.Length == 0 ? "M" : " L").Append(N(X(f.Positions[b].X))).Append(' ').Append(N(Y(f.Positions[b].Y)));
            }

            svg.Append($"<path class=\"body-path\" data-body=\"{E(r.Labels[b])}\" stroke=\"{BodyColours[b % BodyColours.Count]}\" d=\"{d}\"><title>{E(r.Labels[b])}</title></path>\n");
        }

        svg.Append("</g>\n<g id=\"ends-").Append(E(r.Scene.Name)).Append("\" fill-opacity=\"0.35\">\n");
        Recording.Frame last = r.Frames[^1];
        for (int b = 0; b < r.Labels.Count; b++)
        {
            svg.Append($"<circle cx=\"{N(X(last.Positions[b].X))}\" cy=\"{N(Y(last.Positions[b].Y))}\" r=\"{N(r.Radii[b] * scale)}\" fill=\"{BodyColours[b % BodyColours.Count]}\"/>\n");
        }

        svg.Append("</g>\n");
    }

    private static void EnergyPlot(StringBuilder svg, Recording r, int x0, int y0)
    {
        double t0 = r.Frames[0].Time, t1 = Math.Max(r.Frames[^1].Time, t0 + 1e-9);
        (double lo, double hi) = Range(r.Frames.SelectMany(f => new[] { f.Kinetic, f.Potential, f.Mechanical }).Select(v => (float)v));
        Frame(svg, x0, y0, "energy over time, J (kinetic, potential, mechanical)", t0, t1, lo, hi, "t (s)");
        string[] names = { "kinetic", "potential", "mechanical" };
        svg.Append($"<g id=\"energy-{E(r.Scene.Name)}\" fill=\"none\" stroke-width=\"1.5\">\n");
        for (int k = 0; k < 3; k++)
        {
            var d = new StringBuilder();
            foreach (Recording.Frame f in r.Frames)
            {
                double v = k == 0 ? f.Kinetic : k == 1 ? f.Potential : f.Mechanical;
                d.Append(d.Length == 0 ? "M" : " L").Append(N(x0 + (f.Time - t0) / (t1 - t0) * PanelWidth)).Append(' ')
                    .Append(N(y0 + PanelHeight - (v - lo) / (hi - lo) * PanelHeight));
            }

            svg.Append($"<path stroke=\"{EnergyColours[k]}\" d=\"{d}\"><title>{names[k]} energy</title></path>\n");
            svg.Append($"<text x=\"{x0 + 90 * k}\" y=\"{y0 + PanelHeight + 28}\" fill=\"{EnergyColours[k]}\">{names[k]}</text>\n");
        }

        svg.Append("</g>\n");
    }

    private static void Frame(StringBuilder svg, int x0, int y0, string title, double t0, double t1, double lo, double hi, string xLabel)
    {
        svg.Append($"<text x=\"{x0}\" y=\"{y0 - 6}\">{E(title)}</text>\n");
        svg.Append($"<rect x=\"{x0}\" y=\"{y0}\" width=\"{PanelWidth}\" height=\"{PanelHeight}\" fill=\"none\" stroke=\"#cccccc\"/>\n");
        svg.Append($"<text x=\"{x0 - 4}\" y=\"{y0 + 4}\" text-anchor=\"end\">{N(hi, 3)}</text>\n");
        svg.Append($"<text x=\"{x0 - 4}\" y=\"{y0 + PanelHeight}\" text-anchor=\"end\">{N(lo, 3)}</text>\n");
        svg.Append($"<text x=\"{x0}\" y=\"{y0 + PanelHeight + 14}\">{N(t0, 3)}</text>\n");
        svg.Append($"<text x=\"{x0 + PanelWidth}\" y=\"{y0 + PanelHeight + 14}\" text-anchor=\"end\">{E(xLabel)} {N(t1, 3)}</text>\n");
    }

    /// <summary>The range of the finite values, widened to at least 1e-3 so that a constant still plots.</summary>
    private static (double Lo, double Hi) Range(IEnumerable<float> values)
    {
        double lo = double.PositiveInfinity, hi = double.NegativeInfinity;
        foreach (float v in values)
        {
            if (float.IsFinite(v))
            {
                lo = Math.Min(lo, v);
                hi = Math.Max(hi, v);
            }
        }

        if (!(hi >= lo))
        {
            return (0, 1);
        }

        double pad = Math.Max(1e-3, 0.05 * (hi - lo));
        return (lo - pad, hi + pad);
    }
}

/// <summary>
/// A self-contained HTML page (no external scripts, styles or fonts) that replays each scene on a &lt;canvas&gt;:
/// play/pause, a time slider, and the energy over time with a cursor at the current time. The run is embedded as
/// JSON; bodies are drawn in <see cref="PictureWriter.BodyColours"/> with a white line showing their rotation.
/// </summary>
public sealed class HtmlTrajectoryWriter : PictureWriter
{
    /// <summary>Writes to <paramref name="output"/>.</summary>
    public HtmlTrajectoryWriter(TextWriter output)
        : base(output)
    {
    }

    /// <inheritdoc />
    public override void Complete()
    {
        var html = new StringBuilder();
        html.Append("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>SimpleDynamics replay</title>\n");
        html.Append("<style>body{font-family:sans-serif;margin:16px;background:#fafafa;color:#222}section{margin-bottom:24px}"
            + "canvas{background:#ffffff;border:1px solid #cccccc;display:block;margin:6px 0}"
            + ".controls{display:flex;gap:10px;align-items:center}.controls input{width:480px}.warning{color:#b00000}</style>\n");
        html.Append("</head>\n<body>\n<h1>SimpleDynamics replay</h1>\n");
        for (int s = 0; s < Recordings.Count; s++)
        {
            Recording r = Recordings[s];
            html.Append($"<section id=\"scene-{s}\">\n<h2>{E(r.Scene.Name)}</h2>\n<p>{E(r.Scene.Description)}</p>\n");
            if (r.Scene.Expectation is not null)
            {
                html.Append($"<p>expect: {E(r.Scene.Expectation.Text)}</p>\n");
            }

            foreach (string warning in r.Warnings)
            {
                html.Append($"<p class=\"warning\">warning: {E(warning)}</p>\n");
            }

            html.Append($"<div class=\"controls\"><button id=\"play-{s}\">pause</button><input id=\"slider-{s}\" type=\"range\" min=\"0\" max=\"{r.Frames.Count - 1}\" value=\"0\"><span id=\"time-{s}\">t = 0 s</span></div>\n");
            html.Append($"<canvas id=\"world-{s}\" width=\"720\" height=\"360\"></canvas>\n");
            html.Append($"<canvas id=\"energy-{s}\" width=\"720\" height=\"150\"></canvas>\n</section>\n");
        }

        html.Append("<script>\nconst RUN = ");
        AppendJson(html);
        html.Append(";\n").Append(Script).Append("</script>\n</body>\n</html>\n");
        Output.Write(html.ToString());
        Output.Flush();
    }

    private void AppendJson(StringBuilder json)
    {
        json.Append("{\"colours\":[").Append(string.Join(",", BodyColours.Select(c => "\"" + c + "\""))).Append("],");
        json.Append("\"energyColours\":[").Append(string.Join(",", EnergyColours.Select(c => "\"" + c + "\""))).Append("],\"scenes\":[");
        for (int s = 0; s < Recordings.Count; s++)
        {
            Recording r = Recordings[s];
            json.Append(s == 0 ? "" : ",").Append("{\"radii\":[").Append(string.Join(",", r.Radii.Select(v => N(v, 4)))).Append("],\"planes\":[");
            json.Append(string.Join(",", r.Planes.Select(p => "[" + N(p.Normal.X, 4) + "," + N(p.Normal.Y, 4) + "," + N(p.Offset, 4) + "]")));
            json.Append("],\"t\":[").Append(string.Join(",", r.Frames.Select(f => N(f.Time, 5))));
            json.Append("],\"ke\":[").Append(string.Join(",", r.Frames.Select(f => N(f.Kinetic, 4))));
            json.Append("],\"pe\":[").Append(string.Join(",", r.Frames.Select(f => N(f.Potential, 4))));
            json.Append("],\"frames\":[");
            for (int i = 0; i < r.Frames.Count; i++)
            {
                Recording.Frame f = r.Frames[i];
                json.Append(i == 0 ? "[" : ",[");
                for (int b = 0; b < f.Positions.Length; b++)
                {
                    json.Append(b == 0 ? "" : ",").Append(N(f.Positions[b].X, 4)).Append(',').Append(N(f.Positions[b].Y, 4)).Append(',').Append(N(f.Angles[b], 3));
                }

                json.Append(']');
            }

            json.Append("]}");
        }

        json.Append("]}");
    }

    /// <summary>The replay: one player per scene, playing in real time from the start, looping.</summary>
    private const string Script = """
        function player(index, scene) {
          const world = document.getElementById('world-' + index), energy = document.getElementById('energy-' + index);
          const slider = document.getElementById('slider-' + index), button = document.getElementById('play-' + index);
          const label = document.getElementById('time-' + index);
          const n = scene.radii.length, last = scene.t.length - 1;
          let xLo = Infinity, xHi = -Infinity, yLo = Infinity, yHi = -Infinity;
          for (const f of scene.frames) {
            for (let b = 0; b < n; b++) {
              const r = scene.radii[b];
              xLo = Math.min(xLo, f[3 * b] - r); xHi = Math.max(xHi, f[3 * b] + r);
              yLo = Math.min(yLo, f[3 * b + 1] - r); yHi = Math.max(yHi, f[3 * b + 1] + r);
            }
          }
          const pad = 0.05 * Math.max(xHi - xLo, yHi - yLo, 1e-3);
          xLo -= pad; xHi += pad; yLo -= pad; yHi += pad;
          const scale = Math.min(world.width / (xHi - xLo), world.height / (yHi - yLo));
          const cx = (xLo + xHi) / 2, cy = (yLo + yHi) / 2;
          const X = x => world.width / 2 + (x - cx) * scale, Y = y => world.height / 2 - (y - cy) * scale;
          let eLo = Infinity, eHi = -Infinity;
          for (let i = 0; i <= last; i++) {
            for (const v of [scene.ke[i], scene.pe[i], scene.ke[i] + scene.pe[i]]) { eLo = Math.min(eLo, v); eHi = Math.max(eHi, v); }
          }
          if (!(eHi > eLo)) { eHi = eLo + 1; }
          const t0 = scene.t[0], t1 = Math.max(scene.t[last], t0 + 1e-9);
          let frame = 0, playing = true, clock = t0, before = null;

          function drawWorld() {
            const g = world.getContext('2d');
            g.clearRect(0, 0, world.width, world.height);
            g.strokeStyle = '#999999'; g.lineWidth = 2;
            for (const [nx, ny, offset] of scene.planes) {
              g.beginPath();
              if (Math.abs(ny) > 0.999) { const y = Y(offset * ny); g.moveTo(0, y); g.lineTo(world.width, y); }
              else if (Math.abs(nx) > 0.999) { const x = X(offset * nx); g.moveTo(x, 0); g.lineTo(x, world.height); }
              g.stroke();
            }
            const f = scene.frames[frame];
            for (let b = 0; b < n; b++) {
              const x = X(f[3 * b]), y = Y(f[3 * b + 1]), r = scene.radii[b] * scale, a = f[3 * b + 2];
              g.fillStyle = RUN.colours[b % RUN.colours.length];
              g.beginPath(); g.arc(x, y, r, 0, 2 * Math.PI); g.fill();
              g.strokeStyle = '#ffffff'; g.lineWidth = Math.max(1, r / 8);
              g.beginPath(); g.moveTo(x, y); g.lineTo(x + r * Math.cos(a), y - r * Math.sin(a)); g.stroke();
            }
          }

          function drawEnergy() {
            const g = energy.getContext('2d'), w = energy.width, h = energy.height;
            g.clearRect(0, 0, w, h);
            const T = t => 40 + (t - t0) / (t1 - t0) * (w - 50), E = e => h - 20 - (e - eLo) / (eHi - eLo) * (h - 44);
            const series = [scene.ke, scene.pe, scene.ke.map((k, i) => k + scene.pe[i])];
            const names = ['kinetic', 'potential', 'mechanical'];
            series.forEach((s, k) => {
              g.strokeStyle = RUN.energyColours[k]; g.lineWidth = 1.5; g.beginPath();
              s.forEach((e, i) => i === 0 ? g.moveTo(T(scene.t[i]), E(e)) : g.lineTo(T(scene.t[i]), E(e)));
              g.stroke();
              g.fillStyle = RUN.energyColours[k]; g.font = '12px sans-serif'; g.fillText(names[k] + ' (J)', 50 + 110 * k, 14);
            });
            g.fillStyle = '#444444';
            g.fillText(eHi.toPrecision(4), 2, 14); g.fillText(eLo.toPrecision(4), 2, h - 22);
            g.strokeStyle = '#bbbbbb'; g.beginPath(); g.moveTo(T(scene.t[frame]), 0); g.lineTo(T(scene.t[frame]), h - 18); g.stroke();
          }

          function show(i) {
            frame = Math.max(0, Math.min(last, i));
            slider.value = frame;
            label.textContent = 't = ' + scene.t[frame].toFixed(3) + ' s';
            drawWorld(); drawEnergy();
          }

          function tick(now) {
            if (playing) {
              if (before !== null) { clock += (now - before) / 1000; }
              if (clock > t1) { clock = t0; }
              let i = frame;
              if (scene.t[i] > clock) { i = 0; }
              while (i < last && scene.t[i + 1] <= clock) { i++; }
              show(i);
            }
            before = now;
            requestAnimationFrame(tick);
          }

          button.onclick = () => { playing = !playing; button.textContent = playing ? 'pause' : 'play'; before = null; };
          slider.oninput = () => { playing = false; button.textContent = 'play'; show(Number(slider.value)); clock = scene.t[frame]; };
          show(0);
          requestAnimationFrame(tick);
        }
        RUN.scenes.forEach((scene, i) => player(i, scene));

        """;
}
