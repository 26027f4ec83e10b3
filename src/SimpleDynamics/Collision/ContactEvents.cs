using System;

namespace SimpleDynamics.Collision;

/// <summary>
/// What happened to contacts and sensors in the last <see cref="World.Step"/>: read after the step, valid until
/// the next one. The spans view arrays the world keeps and reuses, so reading them allocates nothing; copy
/// what you need to keep.
/// </summary>
/// <remarks>
/// A pair <b>touches</b> in a step when its contact's <see cref="Contact.Penetration"/> at the end of the step is
/// at least −<see cref="World.TouchTolerance"/> or when the responder pushed it during the step (a bounce that
/// starts and ends within one step); speculative contacts that pushed nothing (pairs merely close, see
/// <see cref="World.ContactMargin"/>) do not touch. <see cref="BeginTouch"/> lists the pairs that touch now and
/// did not after the previous step, <see cref="EndTouch"/> those that did and do not now (also when a body
/// was removed). So over any run, every end follows its begin, and the begins so far minus the ends so far
/// equal <see cref="Touching"/>.Length. Begins and hits come in the order of <see cref="World.Collisions"/>, ends in
/// the order the pairs touched in the step before. <see cref="Touching"/> lists first the pairs of sleeping bodies
/// (see <see cref="World.SleepingEnabled"/>), which stay touching while they sleep and neither end when they fall
/// asleep nor begin again when they wake, then the pairs of awake bodies in the order of <see cref="World.Collisions"/>.
/// </remarks>
public sealed class ContactEvents
{
    private const int InitialCapacity = 16;
    private const int InitialSensorCapacity = 8;

    private ContactEvent[] _begin = new ContactEvent[InitialCapacity];
    private ContactEvent[] _end = new ContactEvent[InitialCapacity];
    private HitEvent[] _hits = new HitEvent[InitialCapacity];
    private SensorEvent[] _sensorBegin = new SensorEvent[InitialSensorCapacity];
    private SensorEvent[] _sensorEnd = new SensorEvent[InitialSensorCapacity];
    private int _beginCount, _endCount, _hitCount, _sensorBeginCount, _sensorEndCount;
    private ShrinkPolicy _beginRoom, _endRoom, _hitRoom, _sensorBeginRoom, _sensorEndRoom;

    internal ContactEvents()
    {
    }

    /// <summary>Pairs that began touching in the last step.</summary>
    public ReadOnlySpan<ContactEvent> BeginTouch => _begin.AsSpan(0, _beginCount);

    /// <summary>Pairs that stopped touching in the last step.</summary>
    public ReadOnlySpan<ContactEvent> EndTouch => _end.AsSpan(0, _endCount);

    /// <summary>
    /// Pairs that struck in the last step at least at <see cref="World.HitSpeedThreshold"/>; a pair resting on
    /// its support approaches at about g·dt only, so it makes no hits.
    /// </summary>
    public ReadOnlySpan<HitEvent> Hits => _hits.AsSpan(0, _hitCount);

    /// <summary>Bodies that began overlapping a sensor in the last step.</summary>
    public ReadOnlySpan<SensorEvent> SensorBegin => _sensorBegin.AsSpan(0, _sensorBeginCount);

    /// <summary>Bodies that stopped overlapping a sensor in the last step.</summary>
    public ReadOnlySpan<SensorEvent> SensorEnd => _sensorEnd.AsSpan(0, _sensorEndCount);

    /// <summary>Every pair touching at the end of the last step.</summary>
    public ReadOnlySpan<ContactEvent> Touching => Touch.Items;

    /// <summary>Every (sensor, body) overlap at the end of the last step.</summary>
    public ReadOnlySpan<SensorEvent> SensorOverlaps => Sensor.Items;

    // This step's sets; the previous step's are kept by the world to compare with.
    internal PairSet<ContactEvent> Touch { get; set; } = new();

    internal PairSet<SensorEvent> Sensor { get; set; } = new();

    internal void Clear()
    {
        Array.Clear(_begin, 0, _beginCount);
        Array.Clear(_end, 0, _endCount);
        Array.Clear(_hits, 0, _hitCount);
        Array.Clear(_sensorBegin, 0, _sensorBeginCount);
        Array.Clear(_sensorEnd, 0, _sensorEndCount);
        _beginCount = _endCount = _hitCount = _sensorBeginCount = _sensorEndCount = 0;
    }

    /// <summary>
    /// Applies the <see cref="ShrinkPolicy"/> to the event lists after each step; the events are kept. A list's use is
    /// the pairs that could fill it (every touching pair may begin, end or strike in one step, every overlap may begin
    /// or end), not the few events a resting pile happens to make: so a list stays ready for a knock on the pile, and
    /// shrinks only when the scene does.
    /// </summary>
    internal void ShrinkIfIdle()
    {
        int touching = Math.Max(Touch.Count, _endCount), overlaps = Math.Max(Sensor.Count, _sensorEndCount);
        Buffers.ShrinkIfIdle(ref _begin, Math.Max(_beginCount, touching), ref _beginRoom, InitialCapacity);
        Buffers.ShrinkIfIdle(ref _end, touching, ref _endRoom, InitialCapacity);
        Buffers.ShrinkIfIdle(ref _hits, Math.Max(_hitCount, touching), ref _hitRoom, InitialCapacity);
        Buffers.ShrinkIfIdle(ref _sensorBegin, Math.Max(_sensorBeginCount, overlaps), ref _sensorBeginRoom, InitialSensorCapacity);
        Buffers.ShrinkIfIdle(ref _sensorEnd, overlaps, ref _sensorEndRoom, InitialSensorCapacity);
        Touch.ShrinkIfIdle();
        Sensor.ShrinkIfIdle();
    }

    /// <summary>Gives back all the spare room of the event lists; the events are kept.</summary>
    internal void TrimExcess()
    {
        Buffers.Shrink(ref _begin, Math.Max(_beginCount, InitialCapacity));
        Buffers.Shrink(ref _end, Math.Max(_endCount, InitialCapacity));
        Buffers.Shrink(ref _hits, Math.Max(_hitCount, InitialCapacity));
        Buffers.Shrink(ref _sensorBegin, Math.Max(_sensorBeginCount, InitialSensorCapacity));
        Buffers.Shrink(ref _sensorEnd, Math.Max(_sensorEndCount, InitialSensorCapacity));
        Touch.TrimExcess();
        Sensor.TrimExcess();
    }

    internal void AddBegin(in ContactEvent e) => Append(ref _begin, ref _beginCount, e);

    internal void AddEnd(in ContactEvent e) => Append(ref _end, ref _endCount, e);

    internal void AddHit(in HitEvent e) => Append(ref _hits, ref _hitCount, e);

    internal void AddSensorBegin(in SensorEvent e) => Append(ref _sensorBegin, ref _sensorBeginCount, e);

    internal void AddSensorEnd(in SensorEvent e) => Append(ref _sensorEnd, ref _sensorEndCount, e);

    private static void Append<T>(ref T[] array, ref int count, in T item)
    {
        Buffers.EnsureCapacity(ref array, count + 1);
        array[count++] = item;
    }
}
