using System;

namespace SimpleDynamics.Laws;

/// <summary>
/// A responder broke a law: the message names the law, the smallest failing collision FsCheck found, what was
/// measured and how to replay the run.
/// </summary>
public sealed class ResponderLawException : Exception
{
    /// <summary>Creates the exception.</summary>
    public ResponderLawException(ResponderLaw law, string replaySeed, string message, Exception? inner)
        : base(message, inner)
    {
        Law = law;
        ReplaySeed = replaySeed;
    }

    /// <summary>The law that failed.</summary>
    public ResponderLaw Law { get; }

    /// <summary>The pair "seed,gamma" to put in FSCHECK_REPLAY to run the same cases again.</summary>
    public string ReplaySeed { get; }
}
