using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;

namespace SimpleDynamics.Tests.Solver;

/// <summary>What the solver tests put into a pour so that its pile meets more than discs and walls.</summary>
internal static class PitObstacles
{
    /// <summary>
    /// Adds a static post under the middle of the pour and a kinematic paddle moving through it, so that contacts
    /// with an immovable body that does not move and one that does are solved among the others.
    /// </summary>
    public static void AddPostAndPaddle(World world)
    {
        float middle = world.Bodies.Average(b => b.Position.X);
        world.Add(RigidBody.CreateStatic(0.3f, new Vector3(middle, 0.6f, 0)));
        world.Add(RigidBody.CreateKinematic(0.2f, new Vector3(middle - 1f, 1.5f, 0), new Vector3(0.5f, -0f, 0))); // −0: see GatherState
    }
}
