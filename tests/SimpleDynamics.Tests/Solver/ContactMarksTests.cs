using System;
using System.Collections.Generic;
using System.Linq;
using System.Threading;
using System.Threading.Tasks;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Solver;

/// <summary>
/// <see cref="ContactMarks"/> shared by threads (the local sweeps in strips): each thread takes only the marks of its
/// own range of positions, in order, even where two ranges share a 64-bit word, and marks set by several threads at
/// once are all kept.
/// </summary>
public class ContactMarksTests
{
    /// <summary>Ranges that begin and end inside words and on word edges, and a seam range after them.</summary>
    private static readonly (int Start, int End)[] Ranges = { (0, 70), (70, 128), (128, 129), (129, 300), (300, 301) };

    [Fact]
    public void Each_range_takes_its_own_marks_in_order_and_nothing_else()
    {
        var marks = new ContactMarks();
        marks.Begin(301);
        int[] marked = Enumerable.Range(0, 301).Where(p => p % 3 == 0 || p is 69 or 70 or 127 or 128 or 129 or 300).ToArray();
        int next = 0;
        marks.MarkAroundShared(marked, position: -1, ref next); // all after −1: for this sweep
        Assert.Equal(0, next);

        foreach ((int start, int end) in Ranges.Reverse()) // a later range first: it must leave the earlier one's bits in a shared word
        {
            var taken = new List<int>();
            int word = start >> 6;
            while (marks.TryTakeShared(ref word, start, end, out int p))
            {
                taken.Add(p);
            }

            Assert.Equal(marked.Where(p => p >= start && p < end), taken);
        }

        Assert.False(marks.TryTake(out _)); // every mark was taken, by its own range
    }

    [Fact]
    public void Marks_set_by_two_threads_at_once_are_all_kept_and_counted_once_for_the_next_sweep()
    {
        const int Count = 1 << 16;
        int[] positions = Enumerable.Range(0, Count).ToArray();
        var marks = new ContactMarks();
        for (int round = 0; round < 60; round++)
        {
            marks.Begin(Count);
            int[] counts = new int[2];

            // Both threads mark every position for the next sweep, at once and in the same order, so that they meet in
            // the same words: each new mark is counted by the one thread that set it, so the counts add up to the
            // positions, and every mark is kept. (A race shows only when it happens: marks for the next sweep set
            // without atomics failed this in one run of three with 20 rounds, and in four of four with 60.)
            using var start = new Barrier(2);
            Parallel.For(0, 2, new ParallelOptions { MaxDegreeOfParallelism = 2 }, t =>
            {
                start.SignalAndWait();
                marks.MarkAroundShared(positions, position: Count, ref counts[t]);
            });
            Assert.Equal(Count, counts[0] + counts[1]);

            marks.AddMarkedForNext(counts[0] + counts[1]);
            Assert.Equal(Count, marks.MarkedForNext);
            marks.NextSweep();
            int taken = 0;
            while (marks.TryTake(out int p))
            {
                Assert.Equal(taken++, p);
            }

            Assert.Equal(Count, taken);
        }
    }
}
