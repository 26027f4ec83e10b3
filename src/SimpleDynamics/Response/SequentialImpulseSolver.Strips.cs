using System;
using SimpleDynamics.Collision;
using SimpleDynamics.Threading;

namespace SimpleDynamics.Response;

/// <summary>
/// The velocity passes on several threads (<see cref="World.ThreadCount"/>): the strips of a large pile
/// (<see cref="Strips"/>) at once, then the seam contacts between them, with exactly the result of one thread
/// (see <see cref="SweepStrips"/>). Those are the passes over every contact and the local sweeps over the contacts
/// still changing (SequentialImpulseSolver.LocalSweeps.cs), which a deep pile that stirs spends most of its sweeps in,
/// and the layer correction's passes (SequentialImpulseSolver.Layers.cs): its gathering sweep, and the building of its
/// band system from each strip's bodies and the moving of them by its factors; and the position sweeps of such a substep
/// (SequentialImpulseSolver.PositionSweeps.cs). The threads share the strips of a pass
/// as <see cref="ShareQueue"/> hands them out: with more strips than threads, a thread that is done takes over the
/// strips another has not begun.
/// </summary>
public sealed partial class SequentialImpulseSolver
{
    /// <summary>Floats between two strips' results: 64 bytes, so that each thread writes its own cache line.</summary>
    private const int Padding = 16;

    private readonly SweepStrips _strips = new();
    private WorkerThreads? _threads; // the world's, for the step begun last; null on one thread
    private readonly int[] _contactStart = new int[SweepStrips.MaxStrips + 2]; // per group (strips, then seams): its first contact, and the end
    private readonly int[] _activeStart = new int[SweepStrips.MaxStrips + 2]; // the same in _active, for the substep
    private readonly int[] _bodyStart = new int[SweepStrips.MaxStrips + 2]; // per group (bodies nothing moves, then strips): its first place in the body order, and the end
    private int[] _bodyScratch = new int[InitialCapacity]; // where SweepStrips.Group puts the bodies in strips
    private int[] _contactScratch = new int[InitialCapacity]; // and the contacts
    private StripJob? _stripJob;
    private readonly float[] _stripResults = new float[(SweepStrips.MaxStrips + 1) * Padding]; // per strip, and the seams: what its part of a pass measured
    private readonly int[] _stripCounts = new int[(SweepStrips.MaxStrips + 1) * Padding]; // the same, for what a local sweep counted (SweepMarkedRange)
    private readonly ShareQueue _stripQueue = new(SweepStrips.MaxStrips); // which thread sweeps which strip, in a pass in strips
    private int _resultSlots; // the results the last pass wrote

    /// <summary>The cut of the step begun last, for tests (its <see cref="SweepStrips.ContactsPerStrip"/> may be lowered).</summary>
    internal SweepStrips Cut => _strips;

    /// <summary>The seam contacts of the step begun last (between two strips), for tests.</summary>
    internal int SeamContacts => _strips.Count > 1 ? _contactStart[_strips.Count + 1] - _contactStart[_strips.Count] : 0;

    /// <summary>The passes that run in strips.</summary>
    private enum StripPass
    {
        Measure,
        WarmStart,
        Sweep,
        MeasuredSweep,
        Shock,
        LocalSweep,
        SweepWithBands,
        BuildBands,
        ApplyBands,
        Positions,
        PlanFours,
    }

    /// <summary>
    /// Whether this substep's passes over every contact run on several threads: from its start in a pile of
    /// <see cref="SharedPileContacts"/> or more, else once the first sweep has found the contacts unsolved
    /// (<see cref="SplitSubstep"/>). A smaller settled pile (one sweep a substep) stays on one thread:
    /// there a pass is over in about 100 µs for 9,000 contacts, and a worker that must first fetch its half of the
    /// contacts and bodies from the caller's cache takes about as long (measured on a settled 4,000-disc pit: the warm
    /// start on two threads 148 µs against 67 µs on one, a sweep 115 µs against 132 µs). A pile that needs many sweeps
    /// fetches them once.
    /// </summary>
    private bool _substepInStrips;

    /// <summary>Lets this substep's remaining passes over every contact run in strips, if the step has strips and threads.</summary>
    private void SplitSubstep() => _substepInStrips = _threads is not null && _strips.Count > 1;

    /// <summary>
    /// The contacts from which every substep's passes run in strips, a settled pile's too: there each thread's half of
    /// the contacts and bodies is too large to stay in the caller's cache anyway, so the workers fetch little that one
    /// thread would not. Measured on settled 2-D pits, strips of 2 on two threads, against sharing only the substeps
    /// that need more than one sweep: the 16,000-disc pit (37,000 contacts) stepped 3–7 % faster, the 8,000-disc one
    /// (about 17,500) 6 % slower; at 4,000 discs (8,800 contacts) the warm start alone took twice as long on two threads
    /// (see <see cref="_substepInStrips"/>). benchmarks/README.md, twenty-third session.
    /// </summary>
    /// <remarks>Settable for tests, which share every substep of a small pile so.</remarks>
    internal int SharedPileContacts { get; set; } = 32_768;

    /// <summary>Whether a pile of <paramref name="contacts"/> shares every substep's passes among threads (see <see cref="SharedPileContacts"/>).</summary>
    private bool SharesEverySubstep(int contacts) => _threads is not null && _strips.Count > 1 && contacts >= SharedPileContacts;

    /// <summary>
    /// Where each group of contacts (<see cref="SweepStrips.Group"/>) begins in <see cref="_active"/>, which lists the
    /// active contacts in storage order: the first active contact at or after the group's first contact.
    /// </summary>
    private void FindStripsInActive()
    {
        if (_strips.Count == 1)
        {
            return;
        }

        ReadOnlySpan<int> active = _active.AsSpan(0, _activeCount);
        for (int g = 0; g <= _strips.Count; g++)
        {
            int place = active.BinarySearch(_contactStart[g]);
            _activeStart[g] = place >= 0 ? place : ~place;
        }
    }

    /// <summary>Runs <paramref name="pass"/> over every active contact, in strips on several threads if the step has them.</summary>
    private void RunPass(StripPass pass)
    {
        if (_substepInStrips)
        {
            RunInStrips(pass);
            _resultSlots = _strips.Count + 1;
        }
        else
        {
            RunRange(0, 0, _activeCount, pass);
            _resultSlots = 1;
        }
    }

    /// <summary>
    /// Runs <paramref name="pass"/> over every active contact: the strips on every thread (see <see cref="RunStrips"/>),
    /// then the seam contacts on this one.
    /// </summary>
    private void RunInStrips(StripPass pass)
    {
        RunStripsOnThreads(pass);
        RunRange(_strips.Count, _activeStart[_strips.Count], _activeCount, pass);
    }

    /// <summary>Runs <paramref name="pass"/> over the strips on every thread (see <see cref="RunStrips"/>), and returns when all are done.</summary>
    private void RunStripsOnThreads(StripPass pass)
    {
        _stripQueue.Reset(_strips.Count);
        _stripJob ??= new StripJob(this);
        _stripJob.Pass = pass;
        _threads!.Run(_stripJob);
    }

    /// <summary>
    /// <see cref="MeasureConstraints"/> in strips: each strip's contacts on the threads, then the seams' (and any the
    /// impact pass added in this step) on this one. Each group lists its solved contacts in <see cref="_active"/> where
    /// its own contacts begin, and the lists are then moved together, group after group: the same list, in storage
    /// order, as one pass over every contact makes.
    /// </summary>
    private void MeasureInStrips(ReadOnlySpan<Contact> contacts)
    {
        int strips = _strips.Count;
        RunStripsOnThreads(StripPass.Measure);
        _stripCounts[strips * Padding + 2] = MeasureRange(contacts, _contactStart[strips], contacts.Length);
        int listed = 0;
        for (int g = 0; g <= strips; g++)
        {
            int count = _stripCounts[g * Padding + 2];
            Array.Copy(_active, _contactStart[g], _active, listed, count); // down, or in place: never over a list still to move
            _activeStart[g] = listed;
            listed += count;
        }

        _activeCount = listed;
    }

    /// <summary>The largest of what the last pass measured in slot <paramref name="result"/> of each strip's results (and the seams').</summary>
    private float LargestOfPass(int result)
    {
        float largest = 0;
        for (int t = 0; t < _resultSlots; t++)
        {
            largest = MathF.Max(largest, _stripResults[t * Padding + result]);
        }

        return largest;
    }

    /// <summary>
    /// Thread <paramref name="thread"/>'s part of a pass in strips: the strips that <see cref="_stripQueue"/> gives it,
    /// its own share first, then any of the others' still waiting. A pile that stirs in one place makes one strip's
    /// local sweeps far longer than the others'; a thread that is done takes over the strips not yet begun. Strips share
    /// no moving body, so which thread sweeps a strip, and when, changes nothing in the result.
    /// </summary>
    private void RunStrips(int thread, int threads, StripPass pass)
    {
        int cursor = 0;
        while (_stripQueue.TryTake(thread, threads, ref cursor, out int strip))
        {
            if (pass is StripPass.BuildBands or StripPass.ApplyBands)
            {
                BodyShare(pass, strip); // over the strip's bodies, not its contacts
            }
            else if (pass == StripPass.Measure)
            {
                _stripCounts[strip * Padding + 2] = MeasureRange(_step!.Contacts.Contacts, _contactStart[strip], _contactStart[strip + 1]);
            }
            else if (pass == StripPass.Positions)
            {
                CorrectPositionRange(strip, _contactStart[strip], _contactStart[strip + 1], shared: true); // SequentialImpulseSolver.PositionSweeps.cs
            }
            else
            {
                RunRange(strip, _activeStart[strip], _activeStart[strip + 1], pass); // its results in the strip's slot
            }
        }
    }

    /// <summary>
    /// Visits <see cref="_active"/>[<paramref name="start"/>..<paramref name="end"/>) in order and keeps what the pass
    /// measured in the results of <paramref name="slot"/>.
    /// </summary>
    private void RunRange(int slot, int start, int end, StripPass pass)
    {
        ReadOnlySpan<int> active = _active.AsSpan(start, end - start);
        switch (pass)
        {
            case StripPass.WarmStart:
                foreach (int k in active)
                {
                    WarmStart(k);
                }

                break;

            case StripPass.Sweep:
                for (int i = start; i < end;)
                {
                    i += SolveNext(i);
                }

                break;

            case StripPass.MeasuredSweep:
                MeasuredSweepRange(slot, start, end);
                break;

            case StripPass.Shock:
            {
                float tolerance = ShockTolerance();
                bool changed = false;
                foreach (int k in active)
                {
                    changed |= StopSinking(ref _constraints[k]) > tolerance;
                }

                _stripResults[slot * Padding] = changed ? 1f : 0f;
                break;
            }

            case StripPass.LocalSweep:
                SweepMarkedRange(slot, start, end);
                break;

            case StripPass.SweepWithBands:
                SweepWithBandsRange(slot, start, end);
                break;

#if NET8_0_OR_GREATER
            case StripPass.PlanFours:
                PlanFoursRange(slot, start, end);
                break;
#endif

            case StripPass.BuildBands or StripPass.ApplyBands:
                BodyShare(pass, _strips.Count); // in place of the seam contacts: the bodies woken during the step
                break;
        }
    }

    /// <summary>
    /// Runs a pass over the bodies (<see cref="StripPass.BuildBands"/> or <see cref="StripPass.ApplyBands"/>) share by
    /// share: each strip's bodies on the thread that swept the strip, if this substep runs in strips, then the bodies
    /// woken during the step; on one thread, every share in the same order.
    /// </summary>
    private void RunOverBodies(StripPass pass)
    {
        if (_substepInStrips)
        {
            RunInStrips(pass);
            return;
        }

        for (int share = 0; share <= _strips.Count; share++)
        {
            BodyShare(pass, share);
        }
    }

    /// <summary>A pass over a share of the bodies (see <see cref="SlotsOfShare"/>) instead of a range of contacts.</summary>
    private void BodyShare(StripPass pass, int share)
    {
        if (pass == StripPass.BuildBands)
        {
            BuildBandShare(share);
        }
        else
        {
            ApplyBandShare(share);
        }
    }

    /// <summary>Runs a pass's strips; one per solver, reused.</summary>
    private sealed class StripJob : ParallelJob
    {
        private readonly SequentialImpulseSolver _solver;

        public StripJob(SequentialImpulseSolver solver) => _solver = solver;

        public StripPass Pass;

        public override void Run(int thread, int threads) => _solver.RunStrips(thread, threads, Pass);
    }
}
