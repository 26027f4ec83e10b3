using System;

namespace SimpleDynamics.Collision;

/// <summary>
/// Which bodies (and planes) may collide, by Box2D's rule: category bits say what a body is, mask bits say
/// what it collides with, and a group overrides both for bodies of the same group.
/// </summary>
/// <remarks>
/// Two filters A and B collide when
/// <list type="bullet">
/// <item>they share a non-zero <see cref="Group"/>: always if the group is positive, never if it is negative;</item>
/// <item>otherwise when <c>(A.Category &amp; B.Mask) != 0</c> and <c>(B.Category &amp; A.Mask) != 0</c>, so both
///   must agree.</item>
/// </list>
/// A filtered pair never becomes a contact: it is not in <see cref="World.Collisions"/>, the responder never
/// sees it, and the bodies pass through each other. Categories are up to 32 bits; a common pattern is one bit
/// per kind of thing (player, enemy, bullet, wall).
/// </remarks>
public readonly struct CollisionFilter : IEquatable<CollisionFilter>
{
    /// <summary>Creates a filter.</summary>
    /// <param name="category">The bits that say what this is (usually one bit).</param>
    /// <param name="mask">The categories this collides with.</param>
    /// <param name="group">0 for none; bodies of the same positive group always collide, of the same negative group never.</param>
    public CollisionFilter(uint category, uint mask, int group = 0)
    {
        Category = category;
        Mask = mask;
        Group = group;
    }

    /// <summary>The filter every body and plane starts with: category 1, collides with everything, no group.</summary>
    public static CollisionFilter Default => new(1u, uint.MaxValue, 0);

    /// <summary>The bits that say what this is.</summary>
    public uint Category { get; init; }

    /// <summary>The categories this collides with.</summary>
    public uint Mask { get; init; }

    /// <summary>
    /// 0 for none. A shared positive group always collides and a shared negative group never does, whatever the
    /// bits say (e.g. the parts of one ragdoll share a negative group).
    /// </summary>
    public int Group { get; init; }

    /// <summary>Box2D's rule: whether things with filters <paramref name="a"/> and <paramref name="b"/> collide.</summary>
    public static bool ShouldCollide(in CollisionFilter a, in CollisionFilter b)
    {
        if (a.Group == b.Group && a.Group != 0)
        {
            return a.Group > 0;
        }

        return (a.Category & b.Mask) != 0 && (b.Category & a.Mask) != 0;
    }

    /// <inheritdoc />
    public bool Equals(CollisionFilter other) => Category == other.Category && Mask == other.Mask && Group == other.Group;

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is CollisionFilter other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(Category, Mask, Group);

    /// <inheritdoc />
    public override string ToString() => $"category 0x{Category:X}, mask 0x{Mask:X}, group {Group}";
}
