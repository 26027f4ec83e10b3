using System;
using FsCheck.Fluent;
using Xunit;

namespace SimpleDynamics.Tests.Properties;

/// <summary>The property runner itself: a failure carries the replay seed, and the same seed replays the same cases.</summary>
public class PropertyCheckTests
{
    [Fact]
    public void A_failing_property_reports_its_replay_seed_and_how_to_replay()
    {
        if (Environment.GetEnvironmentVariable(PropertyCheck.ReplayVariable) is { Length: > 0 })
        {
            return; // a replay overrides the seed this test checks
        }

        var failure = Assert.Throws<PropertyFailedException>(() =>
            PropertyCheck.Run(Gen.Choose(0, 1000), x => Law.Holds(x < 900, $"x = {x}"), seed: 7, maxTest: 1000));
        Assert.Contains("Replay seed: 7,", failure.Message);
        Assert.Contains($"{PropertyCheck.ReplayVariable}=7,", failure.Message);
        Assert.Contains("A_failing_property_reports_its_replay_seed_and_how_to_replay", failure.Message);
        Assert.Contains("x = 9", failure.Message); // the law's own message, with the failing value
    }

    [Fact]
    public void The_same_seed_generates_the_same_cases()
    {
        if (Environment.GetEnvironmentVariable(PropertyCheck.ReplayVariable) is { Length: > 0 })
        {
            return;
        }

        var first = new System.Collections.Generic.List<ContactCase>();
        var second = new System.Collections.Generic.List<ContactCase>();
        PropertyCheck.Run(Generators.Contact(), first.Add, seed: 11, maxTest: 50);
        PropertyCheck.Run(Generators.Contact(), second.Add, seed: 11, maxTest: 50);
        Assert.Equal(50, first.Count);
        Assert.Equal(first, second);
    }
}
