using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using Xunit;

namespace SimpleDynamics.Tests.Game;

/// <summary>User data on bodies and planes, and the body's Id as the handle a game keeps.</summary>
public class UserDataAndIdentityTests
{
    private sealed class Target
    {
        public int Score { get; set; }
    }

    [Fact]
    public void Bodies_and_planes_carry_user_data_that_events_hand_back()
    {
        var world = new World(new Vector3(0, -9.81f, 0));
        world.AddPlane(StaticPlane.Ground() with { UserData = "floor" });
        var target = new Target();
        world.Add(new RigidBody(1f, 0.5f, new Vector3(0, 2, 0)) { UserData = target });
        for (int i = 0; i < 60; i++)
        {
            world.Step(1f / 60f);
            foreach (HitEvent hit in world.ContactEvents.Hits)
            {
                if (hit.BodyA.UserData is Target t && hit.IsPlaneContact && (string?)world.Planes[hit.PlaneIndex].UserData == "floor")
                {
                    t.Score++;
                }
            }
        }

        Assert.Equal(1, target.Score);
    }

    [Fact]
    public void A_plane_with_user_data_is_still_the_same_plane()
    {
        StaticPlane plain = new(Vector3.UnitX, new Vector3(2, 0, 0), restitution: 0.5f);
        StaticPlane tagged = plain with { UserData = 42 };
        Assert.Equal(plain.Normal, tagged.Normal);
        Assert.Equal(plain.Offset, tagged.Offset);
        Assert.Equal(plain.Restitution, tagged.Restitution);
        Assert.Null(plain.UserData);
        Assert.Equal(42, tagged.UserData);
    }

    [Fact]
    public void A_body_keeps_its_id_when_others_are_removed_while_its_slot_changes()
    {
        var world = new World();
        RigidBody[] bodies = Enumerable.Range(0, 5).Select(i => world.Add(new RigidBody(1, 0.1f, new Vector3(i, 0, 0)))).ToArray();
        int[] ids = bodies.Select(b => b.Id).ToArray();
        Assert.Equal(ids.Length, ids.Distinct().Count());
        RigidBody last = bodies[4];
        int lastId = last.Id;

        world.Remove(bodies[0]); // the last body moves into slot 0
        world.Remove(bodies[2]);
        Assert.Equal(lastId, last.Id);
        Assert.Same(last, world.Bodies.Single(b => b.Id == lastId));

        // Removed and added again (even to another world), a body is still the same body with the same Id.
        var other = new World();
        other.Add(bodies[0]);
        Assert.Equal(ids[0], bodies[0].Id);
        Assert.DoesNotContain(new RigidBody(1, 1, Vector3.Zero).Id, ids);
    }
}
