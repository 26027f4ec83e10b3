using System;
using System.Collections;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Reflection;
using System.Runtime.ExceptionServices;
using System.Runtime.Loader;

namespace SimpleDynamics.Compare;

/// <summary>
/// One build of the library, loaded from a folder into a load context of its own (so that two builds of the same
/// assembly can run in one process), with a world of <c>Scenes.BallPit</c> made by it. Driven by reflection: the
/// builds compared may differ in anything but the public members used here.
/// </summary>
internal sealed class LoadedBuild
{
    private const BindingFlags Instance = BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic;
    private readonly object _world;
    private readonly Action<float> _step;
    private readonly Func<IEnumerable> _bodies;
    private readonly Func<int> _sweepsThisStep;

    /// <param name="threads">The world's <c>ThreadCount</c>; 1 leaves it alone (a build before threads had none).</param>
    /// <param name="strips">The solver's <c>Strips</c>; 1 leaves it alone likewise.</param>
    /// <param name="extra">The solver's <c>ExtraIterations</c>; −1 leaves its default.</param>
    public LoadedBuild(string folder, int bodies, bool planar, int seed, int threads = 1, int strips = 1, int extra = -1)
    {
        string path = Path.Combine(Path.GetFullPath(folder), "SimpleDynamics.dll");
        if (!File.Exists(path))
        {
            throw new ArgumentException($"no SimpleDynamics.dll in {folder}: build one there with `dotnet build src/SimpleDynamics -c Release -f net8.0 -o {folder}`.");
        }

        Assembly library = new FolderContext(Path.GetDirectoryName(path)!).LoadFromAssemblyPath(path);
        MethodInfo ballPit = library.GetType("SimpleDynamics.Scenes")!.GetMethod("BallPit")!;
        object?[] arguments = ballPit.GetParameters().Select(p => p.HasDefaultValue ? p.DefaultValue : null).ToArray();
        arguments[0] = bodies;
        arguments[1] = planar;
        arguments[2] = seed;
        _world = ballPit.Invoke(null, arguments)!;
        Type world = _world.GetType();
        world.GetProperty("SleepingEnabled")!.SetValue(_world, false); // the awake pile is what is compared
        _step = (Action<float>)Delegate.CreateDelegate(typeof(Action<float>), _world, world.GetMethod("Step", new[] { typeof(float) })!);
        PropertyInfo bodiesProperty = world.GetProperty("Bodies")!;
        _bodies = () => (IEnumerable)bodiesProperty.GetValue(_world)!;
        object responder = world.GetProperty("Responder")!.GetValue(_world)!;
        if (strips != 1)
        {
            Set(responder, "Strips", strips);
        }

        if (extra >= 0)
        {
            Set(responder, "ExtraIterations", extra);
        }

        if (threads != 1)
        {
            Set(_world, "ThreadCount", threads);
        }

        PropertyInfo? sweeps = responder.GetType().GetProperty("SweepsThisStep", Instance);
        _sweepsThisStep = sweeps is null ? () => 0 : () => (int)sweeps.GetValue(responder)!;
    }

    private static void Set(object target, string property, int value)
    {
        PropertyInfo setting = target.GetType().GetProperty(property)
            ?? throw new ArgumentException($"this build's {target.GetType().Name} has no {property}.");
        try
        {
            setting.SetValue(target, value);
        }
        catch (TargetInvocationException e) when (e.InnerException is not null)
        {
            ExceptionDispatchInfo.Capture(e.InnerException).Throw(); // the library's own message, naming the setting
        }
    }

    /// <summary>Velocity sweeps summed over the steps since this was last set to 0, where the build reports them.</summary>
    public long Sweeps { get; set; }

    public void Step(int steps, float dt)
    {
        for (int i = 0; i < steps; i++)
        {
            _step(dt);
            Sweeps += _sweepsThisStep();
        }
    }

    /// <summary>Every body's position, orientation and velocities, as floats, in the world's order.</summary>
    public float[] State()
    {
        var state = new System.Collections.Generic.List<float>();
        foreach (object body in _bodies())
        {
            Type type = body.GetType();
            Vector3 position = (Vector3)type.GetProperty("Position")!.GetValue(body)!;
            Quaternion orientation = (Quaternion)type.GetProperty("Orientation")!.GetValue(body)!;
            Vector3 linear = (Vector3)type.GetProperty("LinearVelocity")!.GetValue(body)!;
            Vector3 angular = (Vector3)type.GetProperty("AngularVelocity")!.GetValue(body)!;
            state.AddRange(new[] { position.X, position.Y, position.Z, orientation.X, orientation.Y, orientation.Z, orientation.W });
            state.AddRange(new[] { linear.X, linear.Y, linear.Z, angular.X, angular.Y, angular.Z });
        }

        return state.ToArray();
    }

    private sealed class FolderContext : AssemblyLoadContext
    {
        private readonly string _folder;

        public FolderContext(string folder)
            : base(folder, isCollectible: false) => _folder = folder;

        protected override Assembly? Load(AssemblyName name)
        {
            string path = Path.Combine(_folder, name.Name + ".dll");
            return File.Exists(path) ? LoadFromAssemblyPath(path) : null; // the framework's own from the default context
        }
    }
}
