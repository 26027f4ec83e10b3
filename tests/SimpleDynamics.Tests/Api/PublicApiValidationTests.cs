using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using System.Reflection;
using System.Reflection.Emit;
using System.Runtime.CompilerServices;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Mathematics;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Api;

/// <summary>
/// Every public constructor, method and property setter of the library, found by reflection (so new ones are
/// checked as soon as they exist), rejects bad arguments with the right parameter name and changes nothing:
/// <list type="bullet">
/// <item>null for a reference-type parameter not annotated nullable → <see cref="ArgumentNullException"/>;</item>
/// <item>NaN or +∞ for a float or double (nullable included) → <see cref="ArgumentException"/> (or a subclass);</item>
/// <item>a NaN component of a <see cref="Vector3"/>, <see cref="Quaternion"/> or <see cref="Matrix3"/> →
///   <see cref="ArgumentException"/>.</item>
/// </list>
/// ParamName is the parameter's name; for a property setter it is the property's name (as the library's
/// <c>Guard</c> does). When the call throws, the receiver's public state is the same as before.
/// Every other argument is a valid sample from <see cref="Sample"/>; a call with all-valid samples must succeed,
/// so that the bad one is what is rejected. Methods with span parameters (the detectors, the queries) are called
/// too, through <see cref="CallWithSpans"/>.
/// </summary>
public class PublicApiValidationTests
{
    private static readonly Assembly Library = typeof(World).Assembly;

    /// <summary>
    /// Parameters that legitimately accept the bad value, by "Type.Member(parameter)", "Type.Member" or "Type.*".
    /// </summary>
    private static readonly Dictionary<string, string> Accepts = new()
    {
        // Plain value arithmetic, as System.Numerics: NaN in, NaN out, no checks in the hot path; IsFinite() asks.
        ["Matrix3.*"] = "value arithmetic like System.Numerics",
        // The test for NaN must accept NaN.
        ["Vectors.IsFinite"] = "it is the finiteness test",
        // Comparisons and hashing take any value.
        ["*.Equals"] = "equality accepts any value",
        // Validate names the caller's parameter (its paramName argument), by design.
        ["Inertia.Validate(inertia)"] = "names the caller's paramName, not its own parameter",
    };

    /// <summary>Members that cannot be exercised by reflection this way, by "Type.Member", with the reason.</summary>
    private static readonly Dictionary<string, string> Skips = new()
    {
        // The responder stages and StepContext.Expect run only inside World.Step, with the world's own context; called
        // with any other context they throw InvalidOperationException by design (tested in Api/StepLifecycleTests).
        ["*.BeginStep"] = "a stage: only World.Step calls it",
        ["*.SolveVelocities"] = "a stage: only World.Step calls it",
        ["*.Collide"] = "a stage: only World.Step calls it",
        ["*.SolvePositions"] = "a stage: only World.Step calls it",
        ["*.EndStep"] = "a stage: only World.Step calls it",
        ["StepContext.Expect"] = "only meaningful during World.Step",
    };

    [Fact]
    public void Every_public_member_rejects_null_NaN_and_infinity_naming_the_parameter_and_changes_nothing()
    {
        var failures = new List<string>();
        int checkedCases = 0;
        foreach (Member member in PublicMembers())
        {
            if (Listed(Skips, member.Type, member.Name) is not null)
            {
                continue;
            }

            if (member.Parameters.Any(p => Element(p.ParameterType).IsByRefLike && SpanElement(p.ParameterType) is null) || member.Method.ContainsGenericParameters)
            {
                failures.Add($"{member}: cannot be called by reflection (a by-ref-like parameter other than a span, or a generic one); test it directly and add it to Skips with the reason.");
                continue;
            }

            string? baseline = Call(member, badIndex: -1, badValue: null, out _);
            if (baseline is not null)
            {
                failures.Add($"{member}: the call with valid samples threw {baseline}; teach Sample a valid value.");
                continue;
            }

            for (int i = 0; i < member.Parameters.Length; i++)
            {
                ParameterInfo parameter = member.Parameters[i];
                if (parameter.IsOut)
                {
                    continue;
                }

                string name = member.IsSetter ? member.Name : parameter.Name!;
                if (Listed(Accepts, member.Type, member.Name, name) is not null)
                {
                    continue;
                }

                foreach ((string label, object? bad, Type expected) in BadValues(member, parameter))
                {
                    checkedCases++;
                    string? problem = Call(member, i, bad, out Exception? thrown);
                    if (thrown is null)
                    {
                        failures.Add($"{member} with {name} = {label}: no exception.");
                    }
                    else if (!expected.IsInstanceOfType(thrown))
                    {
                        failures.Add($"{member} with {name} = {label}: {thrown.GetType().Name} ({thrown.Message}), expected {expected.Name}.");
                    }
                    else if (((ArgumentException)thrown).ParamName != name)
                    {
                        failures.Add($"{member} with {name} = {label}: ParamName was '{((ArgumentException)thrown).ParamName}', expected '{name}'.");
                    }
                    else if (problem is not null)
                    {
                        failures.Add($"{member} with {name} = {label}: {problem}");
                    }
                }
            }
        }

        Assert.True(checkedCases > 100, $"only {checkedCases} cases: is the reflection finding the API?");
        Assert.True(failures.Count == 0, string.Join(Environment.NewLine, failures));
    }

    [Fact]
    public void The_reflection_finds_the_members_it_should()
    {
        var names = PublicMembers().Select(m => $"{m.Type.Name}.{m.Name}").ToHashSet();
        Assert.Contains("RigidBody..ctor", names);
        Assert.Contains("RigidBody.Orientation", names);
        Assert.Contains("RigidBody.ApplyImpulse", names);
        Assert.Contains("World.AddPlanes", names);
        Assert.Contains("World.Gravity", names);
        Assert.Contains("Scenes.DroppedBall", names);
        Assert.Contains("Inertia.Box", names);
        Assert.Contains("ImpulseCollisionResponder.ResolveVelocity", names); // inherited member of a concrete type
        Assert.DoesNotContain("RigidBody.Position.get", names);
    }

    // ---------- The members ----------

    private sealed record Member(Type Type, string Name, MethodBase Method, ParameterInfo[] Parameters, bool IsSetter, PropertyInfo? Property)
    {
        public override string ToString() =>
            $"{Type.Name}.{Name}({string.Join(", ", Parameters.Select(p => $"{p.ParameterType.Name} {p.Name}"))})";
    }

    /// <summary>
    /// Constructors of concrete types, public methods (inherited ones through each concrete type, since an
    /// abstract type cannot be a receiver) and public setters, of every public type of the library.
    /// </summary>
    private static IEnumerable<Member> PublicMembers()
    {
        const BindingFlags all = BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static;
        foreach (Type type in Library.GetExportedTypes().OrderBy(t => t.FullName))
        {
            if (type.IsEnum || type.IsInterface || typeof(Delegate).IsAssignableFrom(type) || type.IsGenericTypeDefinition)
            {
                continue;
            }

            bool canHaveReceiver = !type.IsAbstract;
            if (canHaveReceiver)
            {
                foreach (ConstructorInfo ctor in type.GetConstructors())
                {
                    yield return new Member(type, ".ctor", ctor, ctor.GetParameters(), false, null);
                }
            }

            foreach (MethodInfo method in type.GetMethods(all))
            {
                if (method.DeclaringType?.Assembly != Library || method.IsSpecialName && !method.Name.StartsWith("op_", StringComparison.Ordinal))
                {
                    continue;
                }

                if (!method.IsStatic && !canHaveReceiver || method.IsStatic && method.DeclaringType != type)
                {
                    continue;
                }

                yield return new Member(type, method.Name, method, method.GetParameters(), false, null);
            }

            foreach (PropertyInfo property in type.GetProperties(all))
            {
                MethodInfo? setter = property.SetMethod;
                if (setter is null || !setter.IsPublic || property.GetIndexParameters().Length > 0 || property.DeclaringType?.Assembly != Library)
                {
                    continue;
                }

                if (!setter.IsStatic && !canHaveReceiver || setter.IsStatic && setter.DeclaringType != type)
                {
                    continue;
                }

                yield return new Member(type, property.Name, setter, setter.GetParameters(), true, property);
            }
        }
    }

    private static string? Listed(Dictionary<string, string> list, Type type, string member, string? parameter = null)
    {
        string[] keys =
        {
            $"{type.Name}.*", $"*.{member}", $"{type.Name}.{member}",
            parameter is null ? "" : $"{type.Name}.{member}({parameter})",
        };
        return keys.Where(list.ContainsKey).Select(k => list[k]).FirstOrDefault();
    }

    // ---------- Bad values ----------

    private static IEnumerable<(string Label, object? Value, Type Expected)> BadValues(Member member, ParameterInfo parameter)
    {
        Type type = Element(parameter.ParameterType);
        Type? underlying = Nullable.GetUnderlyingType(type);
        Type valueType = underlying ?? type;
        if (valueType == typeof(float))
        {
            yield return ("NaN", float.NaN, typeof(ArgumentException));
            yield return ("+∞", float.PositiveInfinity, typeof(ArgumentException));
        }
        else if (valueType == typeof(double))
        {
            yield return ("NaN", double.NaN, typeof(ArgumentException));
            yield return ("+∞", double.PositiveInfinity, typeof(ArgumentException));
        }
        else if (valueType == typeof(Vector3))
        {
            yield return ("(NaN, 0, 0)", new Vector3(float.NaN, 0, 0), typeof(ArgumentException));
        }
        else if (valueType == typeof(Quaternion))
        {
            yield return ("(NaN, 0, 0, 1)", new Quaternion(float.NaN, 0, 0, 1), typeof(ArgumentException));
        }
        else if (valueType == typeof(Matrix3))
        {
            yield return ("diag(1, NaN, 1)", Matrix3.Diagonal(1, float.NaN, 1), typeof(ArgumentException));
        }
        else if (!type.IsValueType && !AcceptsNull(member, parameter))
        {
            yield return ("null", null, typeof(ArgumentNullException));
        }
    }

    private static readonly NullabilityInfoContext Nullability = new();

    private static bool AcceptsNull(Member member, ParameterInfo parameter) =>
        member.Property is PropertyInfo property
            ? Nullability.Create(property).WriteState == NullabilityState.Nullable
            : Nullability.Create(parameter).WriteState == NullabilityState.Nullable;

    private static Type Element(Type type) => type.IsByRef ? type.GetElementType()! : type;

    // ---------- Calling ----------

    /// <summary>
    /// Calls the member on a fresh receiver with valid samples, argument <paramref name="badIndex"/> replaced by
    /// <paramref name="badValue"/>. Returns null if all went as it should, else what went wrong; the exception
    /// thrown, if any, comes out in <paramref name="thrown"/>.
    /// </summary>
    private static string? Call(Member member, int badIndex, object? badValue, out Exception? thrown)
    {
        thrown = null;
        object?[] args = member.Parameters
            .Select((p, i) => i == badIndex ? badValue : p.IsOut ? null : SpanElement(p.ParameterType) is Type element ? SampleSpan(element) : Sample(Element(p.ParameterType), p.Name))
            .ToArray();
        object? receiver = member.Method.IsStatic || member.Method is ConstructorInfo ? null : Sample(member.Type, "this");
        string? before = receiver is null ? null : Snapshot(receiver);
        try
        {
            if (member.Method is ConstructorInfo ctor)
            {
                ctor.Invoke(args);
            }
            else if (member.Parameters.Any(p => SpanElement(p.ParameterType) is not null))
            {
                CallWithSpans((MethodInfo)member.Method)(receiver, args);
            }
            else
            {
                member.Method.Invoke(receiver, args);
            }
        }
        catch (TargetInvocationException e) when (e.InnerException is not null)
        {
            thrown = e.InnerException;
        }
        catch (Exception e) when (e is not TargetInvocationException)
        {
            thrown = e; // from CallWithSpans, which calls the method directly
        }

        if (thrown is null)
        {
            return null;
        }

        if (badIndex < 0)
        {
            return $"{thrown.GetType().Name}: {thrown.Message}";
        }

        string? after = receiver is null ? null : Snapshot(receiver);
        return before == after ? null : $"threw, but changed the {member.Type.Name}:{Environment.NewLine}  before {before}{Environment.NewLine}  after  {after}";
    }

    /// <summary>The T of a <see cref="Span{T}"/> or <see cref="ReadOnlySpan{T}"/> parameter, else null.</summary>
    private static Type? SpanElement(Type type) =>
        type.IsGenericType && (type.GetGenericTypeDefinition() == typeof(Span<>) || type.GetGenericTypeDefinition() == typeof(ReadOnlySpan<>))
            ? type.GetGenericArguments()[0]
            : null;

    /// <summary>
    /// A span cannot be boxed into the argument array that <see cref="MethodBase.Invoke(object, object[])"/> takes, so
    /// a method with span parameters is called through a small emitted method: each span argument travels as an array
    /// and is wrapped in the span (its constructor from an array) just before the call; other arguments are unboxed or
    /// cast. Exceptions come out as themselves, not wrapped.
    /// </summary>
    private static Func<object?, object?[], object?> CallWithSpans(MethodInfo method)
    {
        var call = new DynamicMethod($"Call{method.Name}", typeof(object), new[] { typeof(object), typeof(object[]) }, typeof(PublicApiValidationTests).Module, skipVisibility: true);
        ILGenerator il = call.GetILGenerator();
        if (!method.IsStatic)
        {
            il.Emit(OpCodes.Ldarg_0);
            il.Emit(OpCodes.Castclass, method.DeclaringType!); // the receivers with span methods are classes
        }

        ParameterInfo[] parameters = method.GetParameters();
        for (int i = 0; i < parameters.Length; i++)
        {
            Type type = parameters[i].ParameterType;
            il.Emit(OpCodes.Ldarg_1);
            il.Emit(OpCodes.Ldc_I4, i);
            il.Emit(OpCodes.Ldelem_Ref);
            if (SpanElement(type) is Type element)
            {
                il.Emit(OpCodes.Castclass, element.MakeArrayType());
                il.Emit(OpCodes.Newobj, type.GetConstructor(new[] { element.MakeArrayType() })!);
            }
            else if (type.IsValueType)
            {
                il.Emit(OpCodes.Unbox_Any, type);
            }
            else
            {
                il.Emit(OpCodes.Castclass, type);
            }
        }

        il.Emit(method.IsStatic ? OpCodes.Call : OpCodes.Callvirt, method);
        if (method.ReturnType == typeof(void))
        {
            il.Emit(OpCodes.Ldnull);
        }
        else if (method.ReturnType.IsValueType)
        {
            il.Emit(OpCodes.Box, method.ReturnType);
        }

        il.Emit(OpCodes.Ret);
        return (Func<object?, object?[], object?>)call.CreateDelegate(typeof(Func<object?, object?[], object?>));
    }

    /// <summary>A valid span argument, as the array it is made from: two samples (bodies, say), or two empty results to fill.</summary>
    private static Array SampleSpan(Type element)
    {
        Array items = Array.CreateInstance(element, 2);
        if (!element.IsValueType)
        {
            for (int i = 0; i < items.Length; i++)
            {
                items.SetValue(Sample(element, "item"), i);
            }
        }

        return items;
    }

    // ---------- Valid samples ----------

    /// <summary>
    /// A valid value of <paramref name="type"/> for a parameter called <paramref name="name"/> (or for the
    /// receiver, "this"): a fresh object each time, so that one call cannot affect the next. Types not in the
    /// table are built through their smallest public constructor, so new types work without a new entry when
    /// their constructor arguments are in the table.
    /// </summary>
    private static object? Sample(Type type, string? name, int depth = 0)
    {
        switch (name)
        {
            case "max" when type == typeof(Vector3):
                return new Vector3(2, 2, 2); // StaticPlane.Box(min, max): max must exceed min = (0, 1, 0)
            case "radiusSpread":
                return 1f; // Scenes.BallPit: at least 1
        }

        Type? underlying = Nullable.GetUnderlyingType(type);
        if (underlying is not null)
        {
            return Sample(underlying, name, depth);
        }

        if (type == typeof(float)) return 0.5f;
        if (type == typeof(double)) return 0.5;
        if (type == typeof(int)) return 1;
        if (type == typeof(bool)) return false;
        if (type == typeof(string)) return "name";
        if (type == typeof(Vector3)) return Vector3.UnitY;
        if (type == typeof(Quaternion)) return Quaternion.Identity;
        if (type == typeof(Matrix3)) return Matrix3.Identity;
        if (type.IsEnum) return Enum.GetValues(type).GetValue(0);
        if (type == typeof(RigidBody)) return new RigidBody(1f, 0.5f, Vector3.Zero);
        if (type == typeof(World)) return SampleWorld();
        if (type == typeof(StaticPlane)) return StaticPlane.Ground();
        if (type == typeof(Contact)) return new Contact(new RigidBody(1f, 0.5f, Vector3.Zero), new RigidBody(1f, 0.5f, Vector3.UnitX), new Vector3(0.5f, 0, 0), -Vector3.UnitX, 0.1f);
        if (type == typeof(MaterialMixing)) return MaterialMixing.Default;
        if (type == typeof(Func<float, float, float>)) return (Func<float, float, float>)MathF.Max;
        if (type == typeof(Func<RigidBody, RigidBody, bool>)) return (Func<RigidBody, RigidBody, bool>)((_, _) => true);
        if (type == typeof(Func<RigidBody, int, bool>)) return (Func<RigidBody, int, bool>)((_, _) => true);
        if (typeof(Delegate).IsAssignableFrom(type))
        {
            // A delegate built from its (object, IntPtr) constructor would point at nothing and crash when called.
            throw new InvalidOperationException($"No sample for {type.Name}: add one to PublicApiValidationTests.Sample.");
        }

        if (type == typeof(ICollisionResponder)) return new SequentialImpulseSolver();
        if (type == typeof(ICollisionDetector)) return new SpatialHashDetector();
        if (type.IsAssignableFrom(typeof(StaticPlane[]))) return new[] { StaticPlane.Ground(), StaticPlane.Ground(-1f) };

        if (depth > 3)
        {
            throw new InvalidOperationException($"No sample for {type.Name}: add one to PublicApiValidationTests.Sample.");
        }

        if (type.IsAbstract || type.IsInterface)
        {
            Type concrete = Library.GetExportedTypes().First(t => !t.IsAbstract && !t.IsInterface && type.IsAssignableFrom(t));
            return Sample(concrete, name, depth + 1);
        }

        ConstructorInfo? smallest = type.GetConstructors().OrderBy(c => c.GetParameters().Length).FirstOrDefault();
        if (smallest is null)
        {
            return type.IsValueType ? Activator.CreateInstance(type) : throw new InvalidOperationException($"No sample for {type.Name}: add one to PublicApiValidationTests.Sample.");
        }

        return smallest.Invoke(smallest.GetParameters().Select(p => Sample(Element(p.ParameterType), p.Name, depth + 1)).ToArray());
    }

    /// <summary>A small world with gravity, a ground plane and two touching bodies, stepped once so it has contacts.</summary>
    private static World SampleWorld()
    {
        var world = new World(Scenes.EarthGravity);
        world.AddPlane(StaticPlane.Ground());
        world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 0.5f, 0)));
        world.Add(new RigidBody(1f, 0.5f, new Vector3(0.9f, 0.5f, 0)));
        world.Step(1f / 60f);
        return world;
    }

    // ---------- Snapshots ----------

    /// <summary>
    /// The receiver's public state: every readable public property (spans through what they hold), bodies and
    /// contacts by value, other objects by identity.
    /// </summary>
    private static string Snapshot(object receiver)
    {
        var parts = new List<string>();
        foreach (PropertyInfo property in receiver.GetType().GetProperties(BindingFlags.Public | BindingFlags.Instance).OrderBy(p => p.Name))
        {
            if (property.GetMethod is null || property.GetIndexParameters().Length > 0 || property.PropertyType.IsByRefLike)
            {
                continue;
            }

            object? value;
            try
            {
                value = property.GetValue(receiver);
            }
            catch (TargetInvocationException e)
            {
                value = e.InnerException?.GetType().Name;
            }

            parts.Add($"{property.Name}={Describe(value)}");
        }

        if (receiver is World world)
        {
            parts.Add($"Planes=[{string.Join("; ", world.Planes.ToArray().Select(p => $"{p.Normal} {p.Offset}"))}]");
            parts.Add($"Collisions=[{string.Join("; ", world.Collisions.Contacts.ToArray().Select(c => $"{c.BodyA.Id}-{c.BodyB.Id} {c.Penetration} {c.NormalImpulse}"))}]");
        }

        if (receiver is CollisionData collisions)
        {
            parts.Add($"Contacts=[{string.Join("; ", collisions.Contacts.ToArray().Select(c => $"{c.BodyA.Id}-{c.BodyB.Id} {c.Penetration}"))}]");
        }

        return string.Join(", ", parts);
    }

    private static string Describe(object? value) => value switch
    {
        null => "null",
        RigidBody b => $"#{b.Id}({b.Position} {b.Orientation} {b.LinearVelocity} {b.AngularVelocity} {b.Force} {b.Torque} {b.Mass} {b.Inertia} {b.Radius} {b.Restitution} {b.Friction})",
        IEnumerable<RigidBody> bodies => $"[{string.Join("; ", bodies.Select(Describe))}]",
        ValueType or string => value.ToString()!,
        _ => $"{value.GetType().Name}@{RuntimeHelpers.GetHashCode(value)}",
    };
}
