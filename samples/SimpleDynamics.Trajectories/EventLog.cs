using System.Collections.Generic;
using System.Globalization;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Trajectories;

/// <summary>
/// Collects a world's contact and sensor events step by step (<see cref="World.ContactEvents"/> holds only the last
/// step's), so that a writer can print, per reported row, what happened since the row before.
/// </summary>
public sealed class EventLog
{
    private readonly IReadOnlyList<string> _labels;
    private readonly Dictionary<RigidBody, int> _slots = new();
    private readonly List<string> _sensorLines = new();
    private float _fastestHit;
    private string _fastestPair = "";

    /// <summary>A log naming the bodies of <paramref name="world"/> by <paramref name="labels"/> (in <see cref="World.Bodies"/> order).</summary>
    public EventLog(World world, IReadOnlyList<string> labels)
    {
        _labels = labels;
        for (int i = 0; i < world.Bodies.Count; i++)
        {
            _slots[world.Bodies[i]] = i;
        }
    }

    /// <summary>Pairs that began touching since the last row.</summary>
    public int Begins { get; private set; }

    /// <summary>Pairs that stopped touching since the last row.</summary>
    public int Ends { get; private set; }

    /// <summary>Hits since the last row.</summary>
    public int Hits { get; private set; }

    /// <summary>Reads the events of the step just taken.</summary>
    public void Observe(World world)
    {
        ContactEvents events = world.ContactEvents;
        Begins += events.BeginTouch.Length;
        Ends += events.EndTouch.Length;
        Hits += events.Hits.Length;
        foreach (HitEvent hit in events.Hits)
        {
            if (hit.Speed > _fastestHit)
            {
                _fastestHit = hit.Speed;
                _fastestPair = Name(hit.BodyA) + " on " + (hit.BodyB is RigidBody b ? Name(b) : "the ground");
            }
        }

        foreach (SensorEvent e in events.SensorBegin)
        {
            _sensorLines.Add(Format.Invariant($"{Name(e.Visitor)} enters the {Name(e.Sensor)} at t = {world.Time:F2} s"));
        }

        foreach (SensorEvent e in events.SensorEnd)
        {
            _sensorLines.Add(Format.Invariant($"{Name(e.Visitor)} leaves the {Name(e.Sensor)} at t = {world.Time:F2} s"));
        }
    }

    /// <summary>
    /// What happened since the last row, as a line of counts and the fastest hit, then one line per sensor event;
    /// and starts collecting for the next row.
    /// </summary>
    public IReadOnlyList<string> TakeRow()
    {
        var lines = new List<string>();
        string fastest = Hits > 0 ? Format.Invariant($", fastest {_fastestHit:F1} m/s ({_fastestPair})") : "";
        lines.Add(Format.Invariant($"{Begins} begin, {Ends} end, {Hits} hits{fastest}"));
        lines.AddRange(_sensorLines);
        Begins = Ends = Hits = 0;
        _fastestHit = 0;
        _fastestPair = "";
        _sensorLines.Clear();
        return lines;
    }

    private string Name(RigidBody body) =>
        _slots.TryGetValue(body, out int i) && i < _labels.Count ? _labels[i] : "body " + body.Id.ToString(CultureInfo.InvariantCulture);
}
