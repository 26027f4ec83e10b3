using System;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;

namespace SimpleDynamics;

// Measuring a contact where its bodies are now: in double precision without gravity (see Precision), else in float.
internal sealed partial class ImpactStepper
{
    /// <summary>
    /// Measures contact <paramref name="contact"/> of bodies <paramref name="a"/> and <paramref name="b"/> (a plane if
    /// b &lt; 0) where they are now: in double precision without gravity (see Precision), else in float.
    /// </summary>
    private void Measure(ref Contact contact, int a, int b, ReadOnlySpan<StaticPlane> planes)
    {
        if (_noGravity)
        {
            MeasureInDouble(ref contact, a, b, planes);
        }
        else
        {
            ContactGeometry.Unchecked.Refresh(ref contact);
        }
    }

    /// <summary>
    /// Measures a contact from the bodies' double centres: the normal along the line of centres (or the plane's), the
    /// depth and the point are worked out in double and rounded once.
    /// </summary>
    private void MeasureInDouble(ref Contact contact, int a, int b, ReadOnlySpan<StaticPlane> planes)
    {
        Vector3D centreA = _flight[a].PreciseX, normal;
        double radiusA = _motion[a].Radius, depth;
        if (contact.IsPlaneContact)
        {
            StaticPlane plane = planes[contact.PlaneIndex];
            normal = new Vector3D(plane.Normal);
            depth = ContactGeometry.Unchecked.PlanePenetration(centreA, radiusA, plane.Normal, plane.Offset);
        }
        else
        {
            depth = ContactGeometry.Unchecked.CirclePenetration(centreA, radiusA, _flight[b].PreciseX, _motion[b].Radius, out normal);
        }

        contact.Normal = normal.Rounded;
        contact.Penetration = (float)depth;
        contact.Point = (centreA - (radiusA - 0.5 * depth) * normal).Rounded;
    }
}
