namespace SimpleDynamics;

/// <summary>
/// A responder or detector that keeps working memory which can be given back: <see cref="World.TrimExcess"/> calls
/// <see cref="TrimExcess"/> on its <see cref="World.Responder"/> and <see cref="World.Detector"/> when they implement
/// this interface. Optional: a responder or detector without it works as before, and simply keeps what it holds.
/// The library's <see cref="Response.SequentialImpulseSolver"/> and <see cref="Collision.SpatialHashDetector"/>
/// implement it.
/// </summary>
public interface ITrimmable
{
    /// <summary>
    /// Releases the spare room of the buffers kept for <paramref name="world"/> (and of scratch buffers shared by
    /// every world), keeping whatever the next step needs, e.g. warm-start impulses. Called between steps, never
    /// during one; it may allocate the smaller buffers.
    /// </summary>
    void TrimExcess(World world);
}
