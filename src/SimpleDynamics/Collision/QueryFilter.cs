using SimpleDynamics.Bodies;

namespace SimpleDynamics.Collision;

/// <summary>
/// Which bodies a query (ray cast, point or overlap query) reports: those whose
/// <see cref="CollisionFilter.Category"/> shares a bit with <see cref="Mask"/>, and sensors only when asked.
/// Planes are reported when their category matches. The default reports every body that is not a sensor, and
/// every plane.
/// </summary>
public readonly struct QueryFilter
{
    // Stored inverted so that default(QueryFilter), what a caller gets by leaving the argument out, reports
    // every category.
    private readonly uint _ignoredCategories;

    /// <summary>Creates a filter.</summary>
    /// <param name="mask">The categories to report.</param>
    /// <param name="includeSensors">Whether sensor bodies are reported too.</param>
    public QueryFilter(uint mask, bool includeSensors = false)
    {
        _ignoredCategories = ~mask;
        IncludeSensors = includeSensors;
    }

    /// <summary>Every body that is not a sensor, and every plane (the default).</summary>
    public static QueryFilter Default => default;

    /// <summary>Every body, sensors included, and every plane.</summary>
    public static QueryFilter Everything => new(uint.MaxValue, includeSensors: true);

    /// <summary>The categories reported.</summary>
    public uint Mask => ~_ignoredCategories;

    /// <summary>Whether sensor bodies are reported (a ray for picking or line of sight usually skips them).</summary>
    public bool IncludeSensors { get; }

    internal bool Accepts(RigidBody body) => (body.filter.Category & Mask) != 0 && (IncludeSensors || !body.isSensor);

    internal bool Accepts(in StaticPlane plane) => (plane.Filter.Category & Mask) != 0;
}
