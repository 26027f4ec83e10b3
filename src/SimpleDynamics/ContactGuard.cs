using System;
using SimpleDynamics.Collision;

namespace SimpleDynamics;

internal static partial class Guard
{
    /// <summary>A contact must name both of its bodies (a <c>default</c> contact names none).</summary>
    public static void ContactBodies(in Contact contact, string paramName)
    {
        if (contact.BodyA is null || contact.BodyB is null)
        {
            throw new ArgumentException("The contact names no bodies; create it with its two bodies (a default Contact is empty).", paramName);
        }
    }
}
