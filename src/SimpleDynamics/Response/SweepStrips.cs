using System;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;

namespace SimpleDynamics.Response;

/// <summary>
/// Cuts a large pile into vertical strips that share no moving body, so that the velocity sweeps can visit the strips
/// on different threads and get, bit for bit, what one thread gets (see <see cref="World.ThreadCount"/>).
/// </summary>
/// <remarks>
/// <para><b>The order.</b> Each dynamic body belongs to one strip, by where it is across the pile. A contact whose
/// moving bodies are all in one strip belongs to that strip; a contact between two strips is a seam contact. The
/// solver sweeps the contacts strip after strip, each bottom-up, and then the seam contacts, bottom-up. Two strips'
/// contacts never touch the same moving body, so their sweeps are independent: any number of threads may do them at
/// once, in any interleaving, and each body sees the same contacts in the same order with the same velocities as on
/// one thread. The seam contacts come after all strips, on one thread. Static and kinematic bodies (and the ground)
/// belong to no strip: nothing changes their velocities, which every strip only reads.</para>
/// <para><b>Why the order is the same on one thread.</b> The cut depends only on the contacts (their number and where
/// they are) and on the solver's setting <see cref="Most"/>, never on the thread count: one thread sweeps the same
/// order front to back, so the results cannot differ. A pile of fewer than 2 × <see cref="ContactsPerStrip"/> contacts
/// is one strip, and is swept bottom-up as a whole.</para>
/// <para><b>Why it is not the default.</b> The seam contacts wait for the end of every sweep, so support crosses a cut
/// a sweep late, and a deep pile that needs hundreds of sweeps a step needs more of them. Poured 16,000 discs (126
/// deep), one pour each, sweeps summed over seconds 8–20: 2,616 a step uncut, 3,586 in 2 strips, 5,433 in 8.</para>
/// <para><b>Why vertical strips.</b> The sweeps go bottom-up so that each carries support up the pile. Cut along gravity,
/// every strip still holds its part of the pile from the floor up, and only the few contacts that straddle a cut
/// (about two per layer of a pile) wait for the end of the sweep.</para>
/// <para>The strips hold equal numbers of contacts (cuts from a histogram of the contacts' positions across the pile),
/// and their number is a power of two, up to <see cref="Most"/>, so that 2, 4 or 8 threads share them evenly.</para>
/// </remarks>
internal sealed class SweepStrips
{
    /// <summary>The contacts a strip holds at least: a pile is cut into as many strips as this many fit in it (a power of two).</summary>
    public const int DefaultContactsPerStrip = 4096;

    /// <summary>The most strips a pile is cut into.</summary>
    public const int MaxStrips = 8;

    private const int InitialCapacity = 16;
    private const int BinsPerStrip = 64;

    private int[] _stripOfBody = new int[InitialCapacity]; // per world index: its strip, or −1 if nothing moves it
    private int[] _groupOf = new int[InitialCapacity]; // per contact as reported: its strip, or Count for a seam contact
    private int[] _bins = new int[InitialCapacity];

    /// <summary>The most strips a pile is cut into: 1 (never cut, the default), 2, 4 or 8 (SequentialImpulseSolver.Strips).</summary>
    public int Most { get; set; } = 1;

    /// <summary>The contacts per strip (<see cref="DefaultContactsPerStrip"/>); tests lower it to cut small piles.</summary>
    public int ContactsPerStrip { get; set; } = DefaultContactsPerStrip;

    /// <summary>How many strips the pile of the step begun last was cut into (1: not cut).</summary>
    public int Count { get; private set; } = 1;

    /// <summary>Cuts the pile of the step's <paramref name="bodies"/> and <paramref name="contacts"/> into strips along <paramref name="gravity"/>.</summary>
    public void Cut(ReadOnlySpan<RigidBody> bodies, ReadOnlySpan<Contact> contacts, Vector3 gravity)
    {
        int strips = 1;
        while (strips < Most && contacts.Length >= 2L * strips * ContactsPerStrip)
        {
            strips *= 2;
        }

        Count = strips;
        if (strips == 1)
        {
            return;
        }

        int axis = Across(bodies, gravity, out Vector3 low, out Vector3 high);
        AssignBodies(bodies, contacts, axis, Coordinate(low, axis), Coordinate(high, axis), strips);
        Buffers.EnsureCapacity(ref _groupOf, contacts.Length);
        for (int i = 0; i < contacts.Length; i++)
        {
            int a = _stripOfBody[contacts[i].BodyA.index];
            int b = contacts[i].BodyB.index >= 0 ? _stripOfBody[contacts[i].BodyB.index] : -1;
            _groupOf[i] = a < 0 ? Math.Max(b, 0) : b < 0 || b == a ? a : strips;
        }
    }

    /// <summary>
    /// The axis across the pile: of the axes gravity does not point along, the one the dynamic bodies spread furthest
    /// along; gives their bounds, <paramref name="low"/> and <paramref name="high"/>, too.
    /// </summary>
    private static int Across(ReadOnlySpan<RigidBody> bodies, Vector3 gravity, out Vector3 low, out Vector3 high)
    {
        low = new Vector3(float.PositiveInfinity);
        high = new Vector3(float.NegativeInfinity);
        foreach (RigidBody body in bodies)
        {
            if (body.IsDynamic)
            {
                low = Vector3.Min(low, body.position);
                high = Vector3.Max(high, body.position);
            }
        }

        Vector3 spread = high - low;
        Vector3 down = Vector3.Abs(gravity);
        int along = gravity == Vector3.Zero ? -1 : down.X >= down.Y && down.X >= down.Z ? 0 : down.Y >= down.Z ? 1 : 2;
        int axis = along == 0 ? 1 : 0;
        for (int i = 0; i < 3; i++)
        {
            if (i != along && Coordinate(spread, i) > Coordinate(spread, axis))
            {
                axis = i;
            }
        }

        return axis;
    }

    /// <summary>Gives each dynamic body the strip its position across the pile falls in, with cuts that share the contacts out evenly.</summary>
    private void AssignBodies(ReadOnlySpan<RigidBody> bodies, ReadOnlySpan<Contact> contacts, int axis, float low, float high, int strips)
    {
        Buffers.EnsureCapacity(ref _stripOfBody, bodies.Length);

        // A histogram of the contacts across the pile (each counted at its first dynamic body), then cuts at equal
        // shares of it.
        int binCount = BinsPerStrip * strips;
        Buffers.EnsureCapacity(ref _bins, binCount);
        Span<int> bins = _bins.AsSpan(0, binCount);
        bins.Clear();
        float scale = high > low ? binCount / (high - low) : 0f;
        foreach (Contact contact in contacts)
        {
            RigidBody body = contact.BodyA.IsDynamic ? contact.BodyA : contact.BodyB;
            bins[Bin(Coordinate(body.position, axis), low, scale, binCount)]++;
        }

        int strip = 0, seen = 0;
        for (int i = 0; i < binCount; i++)
        {
            seen += bins[i];
            bins[i] = strip; // from here on, the bin's strip
            if (strip < strips - 1 && (long)seen * strips >= (long)(strip + 1) * contacts.Length)
            {
                strip++;
            }
        }

        for (int i = 0; i < bodies.Length; i++)
        {
            _stripOfBody[i] = bodies[i].IsDynamic ? bins[Bin(Coordinate(bodies[i].position, axis), low, scale, binCount)] : -1;
        }
    }

    /// <summary>
    /// Puts <paramref name="order"/> (body indices, or contact indices as reported, in sweep order) group by group,
    /// each group's in the order they had: bodies by strip, those nothing moves first; contacts by strip, the seam
    /// contacts last. <paramref name="starts"/>[g] becomes group g's first place, and <paramref name="starts"/>[groups] the end.
    /// </summary>
    public void Group(Span<int> order, bool bodies, Span<int> scratch, Span<int> starts)
    {
        int groups = Count + 1;
        starts.Slice(0, groups + 1).Clear();
        foreach (int item in order)
        {
            starts[Key(item, bodies) + 1]++;
        }

        for (int g = 0; g < groups; g++)
        {
            starts[g + 1] += starts[g];
        }

        Span<int> fill = stackalloc int[MaxStrips + 1];
        starts.Slice(0, groups).CopyTo(fill);
        foreach (int item in order)
        {
            scratch[fill[Key(item, bodies)]++] = item;
        }

        scratch.Slice(0, order.Length).CopyTo(order);
    }

    private int Key(int item, bool bodies) => bodies ? _stripOfBody[item] + 1 : _groupOf[item];

    private static int Bin(float x, float low, float scale, int binCount) =>
        x >= low ? (int)MathF.Min((x - low) * scale, binCount - 1) : 0; // NaN falls in the first bin

    private static float Coordinate(Vector3 v, int axis) => axis == 0 ? v.X : axis == 1 ? v.Y : v.Z;

    /// <summary>Shrinks the per-body array to <paramref name="capacity"/> if it is larger (it holds nothing between steps).</summary>
    public void ShrinkBodies(int capacity) => Buffers.ShrinkTo(ref _stripOfBody, capacity, 0);

    /// <summary>Shrinks the per-contact array to <paramref name="capacity"/> if it is larger (it holds nothing between steps).</summary>
    public void ShrinkContacts(int capacity) => Buffers.ShrinkTo(ref _groupOf, capacity, 0);
}
