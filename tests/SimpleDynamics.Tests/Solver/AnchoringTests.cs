using System;
using System.Linq;
using System.Numerics;
using SimpleDynamics.Bodies;
using SimpleDynamics.Collision;
using SimpleDynamics.Response;
using SimpleDynamics.Tests.Properties;
using Xunit;
using Xunit.Abstractions;

namespace SimpleDynamics.Tests.Solver;

/// <summary>The position pass where a light body is crushed against a wall by a far heavier one, without gravity and across it.</summary>
public class AnchoringTests
{
    private readonly ITestOutputHelper _output;

    public AnchoringTests(ITestOutputHelper output) => _output = output;

    /// <summary>
    /// Generated world 233 of 2,000 (seed 801): a closed 4 m box without gravity in which a 597 kg disc at 61 m/s
    /// crushes a 0.35 kg one against the wall. Position sweeps split each correction by inverse mass, so the light
    /// disc was pushed into the wall and back and the pair ended step 21 3.9 mm deep; propagating the correction out
    /// from the wall, nearest first, leaves no pair deeper than the slop.
    /// </summary>
    [Fact]
    public void A_light_disc_crushed_against_a_wall_by_a_heavy_one_ends_no_deeper_than_the_slop()
    {
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (0.010311178f, 0.100420624f, new(0.26142025f, 2.191919f, 0), new(0.44977012f, 0.19623159f, 0), -1.2990228f),
            (0.06908223f, 0.23821373f, new(3.5807896f, 2.5253186f, 0), new(-2.0435836f, 3.4348392f, 0), -4.560047f),
            (0.34776273f, 0.30847374f, new(1.2597636f, 3.5178502f, 0), new(0.004648247f, 0.63759327f, 0), 2.4179134f),
            (0.06651836f, 0.33584017f, new(2.3203568f, 0.79267836f, 0), new(3.902747f, -6.2514486f, 0), 2.1437538f),
            (596.64374f, 0.38163942f, new(3.1490219f, 1.0845429f, 0), new(-43.764366f, 42.30773f, 0), 0.27231076f),
            (0.102169864f, 0.15122543f, new(2.5215971f, 3.3907955f, 0), new(-31.851658f, -16.856152f, 0), -3.176812f),
        };
        (World world, SequentialImpulseSolver solver, RigidBody[] bodies) = GeneratedBox(Vector3.Zero, 0.91104186f, substeps: 8, discs);

        StepsWithNoPairDeeperThanTheSlop(world, solver, bodies, steps: 40, dt: 1f / 240f);
    }

    /// <summary>
    /// Generated world 991 of 2,000 (seed 801): a closed 4 m box under gravity with discs of 0.17 to 208 kg (a ratio of
    /// 1.2·10³), where the 0.38 kg disc is driven into the bottom right-hand corner and ended step 37 1.2 mm into the
    /// wall (3.2 mm by step 60). The shock sweep answers the contacts that carry weight, bottom-up; the sideways ones, a
    /// light disc between the wall and heavier ones, were split by inverse mass as without gravity. With the distance
    /// from the walls over the sideways contacts it ended no deeper than 0.86 mm; with the contacts still too deep swept
    /// again on their own (SequentialImpulseSolver.Residual.cs) it ends within the slop, up to float rounding.
    /// </summary>
    [Fact]
    public void Under_gravity_a_light_disc_driven_sideways_into_a_wall_ends_within_the_slop()
    {
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (0.3810521f, 0.061110858f, new(3.1643286f, 1.5151507f, 0), new(-0.24509962f, -0.11402711f, 0), -4.7777753f),
            (0.17056136f, 0.07106393f, new(1.8540987f, 0.27387753f, 0), new(0.48247018f, 2.5759003f, 0), 3.4911842f),
            (208.09306f, 0.16100347f, new(1.1740032f, 0.3778564f, 0), new(2.6507401f, -2.7411118f, 0), -2.2619486f),
            (1.5375831f, 0.10187172f, new(3.4224577f, 1.8855821f, 0), new(-2.5548456f, 2.0908558f, 0), -3.595594f),
        };
        (World world, SequentialImpulseSolver solver, RigidBody[] bodies) = GeneratedBox(Scenes.EarthGravity, 0.25431308f, substeps: 4, discs);

        StepsWithNothingDeeperThanTheSlop(world, solver, bodies, steps: 60, dt: 1f / 30f);
    }

    /// <summary>
    /// Generated world 455 of 2,000 (seed 802): under gravity a 0.40 kg disc lies in the bottom right-hand corner
    /// of the box with a 62 kg disc leaning on it from the upper left, wedged against a 37 kg one. The contacts the
    /// last position sweep left deep were queued (SequentialImpulseSolver.Residual.cs), and once both discs of the
    /// wedge had been corrected four times both counted as held, so their contact was split by inverse mass again:
    /// the light disc took 99 % of each correction into the corner and back out, and the heavy one's hundredth was
    /// lost to float rounding, the same 3.7 µm at every turn until the queue's budget ran out. Step 39 ended 0.50317 mm
    /// into the wall. When both are held, the one corrected more often stays and the other makes room.
    /// </summary>
    [Fact]
    public void Under_gravity_a_light_disc_in_a_corner_wedged_by_a_heavy_one_ends_within_the_slop()
    {
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (62.386257f, 0.087393604f, new(1.6401f, 3.8616655f, 0), new(2.6019845f, 0.14119123f, 0), 1.3058938f),
            (37.30516f, 0.29896554f, new(2.9558818f, 1.1321809f, 0), new(0.46351665f, 0.42515382f, 0), -0.2663422f),
            (486.63657f, 0.09900239f, new(0.13847451f, 1.241065f, 0), new(2.1471095f, -2.4938378f, 0), -1.0045731f),
            (31.238317f, 0.09924064f, new(1.3115635f, 1.3847747f, 0), new(-0.119575806f, 0.40988117f, 0), -0.4683349f),
            (0.021072267f, 0.21556792f, new(2.4368453f, 2.367168f, 0), new(-0.017170237f, -2.9330232f, 0), 1.891984f),
            (0.39611104f, 0.21194993f, new(1.7163473f, 3.389303f, 0), new(-43.139015f, -35.575928f, 0), 3.1738505f),
        };
        (World world, SequentialImpulseSolver solver, RigidBody[] bodies) = GeneratedBox(Scenes.EarthGravity, 0.11681604f, substeps: 6, discs, friction: 0.3f);

        StepsWithNothingDeeperThanTheSlop(world, solver, bodies, steps: 40, dt: 1f / 30f);
    }

    /// <summary>
    /// Generated world 122 of 2,000 (seed 801): under gravity a 658 kg disc comes down on a 1.3 kg one in the bottom
    /// right-hand corner while a 2.1 kg disc is still 3 m up. The shock sweep goes bottom-up, but the solver's order
    /// put every contact below the high disc in one slice of its counting sort, unsorted, so the floor's contact came
    /// after the contact above it: the light disc, corrected out of the floor, was pushed back into the heavy one,
    /// which ended step 30 0.536 mm deep (0.56 mm by step 39). With each slice sorted the floor comes first and no
    /// pair ends deeper than the slop.
    /// </summary>
    [Fact]
    public void Under_gravity_a_heavy_disc_on_a_light_one_in_a_corner_ends_no_deeper_than_the_slop_with_a_disc_far_above()
    {
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (0.34545395f, 0.11770978f, new(1.0564574f, 1.2131338f, 0), new(0.36739868f, 0.51704013f, 0), -0.6578499f),
            (2.1032825f, 0.15259872f, new(1.313761f, 3.0400605f, 0), new(0.0364414f, 0.06371464f, 0), -2.865129f),
            (0.122229055f, 0.21906932f, new(0.4756853f, 1.5153953f, 0), new(8.788183f, -1.8427492f, 0), 2.971886f),
            (0.033026394f, 0.14333552f, new(0.39810386f, 3.7822406f, 0), new(4.338084f, -1.0517005f, 0), -2.4949863f),
            (657.62775f, 0.11080837f, new(3.6565819f, 3.8642304f, 0), new(7.8822107f, -11.013607f, 0), 0.28778628f),
            (0.55969816f, 0.107843146f, new(0.31713155f, 3.262113f, 0), new(-2.7258098f, 1.8455257f, 0), 0.7787706f),
            (0.20264927f, 0.05126341f, new(2.1660855f, 3.255793f, 0), new(1.8285248f, -2.3958466f, 0), -0.24795374f),
            (197.08456f, 0.10110166f, new(3.0836256f, 1.5836972f, 0), new(-9.45094f, -0.6854873f, 0), 2.889693f),
            (733.6367f, 0.07020297f, new(1.7282618f, 2.4139233f, 0), new(44.351788f, -0.06368222f, 0), -3.9916594f),
            (1.3049401f, 0.08375496f, new(3.6499588f, 3.6659167f, 0), new(0.10950058f, 0.14080267f, 0), 3.8597682f),
        };
        (World world, SequentialImpulseSolver solver, RigidBody[] bodies) = GeneratedBox(Scenes.EarthGravity, 0.04991545f, substeps: 2, discs, friction: 0.3f);

        StepsWithNoPairDeeperThanTheSlop(world, solver, bodies, steps: 40, dt: 1f / 60f);
    }

    /// <summary>
    /// Generated world 787 of 2,000 (seed 801): under gravity a 548 kg disc lands on a 0.011 kg one lying on the floor.
    /// Each of the impact pass's inelastic sweeps over the jam took away only about the mass ratio's inverse of the heavy
    /// disc's approach, so it stood still but kept driving into the light one at 23 m/s, step after step, with 270–290
    /// impacts a step from step 6 on, and the pair ended step 39 2.6 mm deep. Stopped outward from the floor, the heavy
    /// disc's approach ends in the substep it jams: the light disc is squeezed out and both go on bouncing round the
    /// box (ε = 0.75), with a few impacts a step, and no pair ends deeper than the slop.
    /// </summary>
    [Fact]
    public void Under_gravity_a_heavy_disc_landing_on_a_light_one_on_the_floor_does_not_stay_jammed_on_it()
    {
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (6.4782953f, 0.36962733f, new(3.3333046f, 1.8285652f, 0), new(-5.2274384f, -2.49096f, 0), 1.6079743f),
            (2.8716955f, 0.07640925f, new(1.0154651f, 3.1021836f, 0), new(-1.6684778f, -1.569749f, 0), 3.7875211f),
            (548.0965f, 0.06393025f, new(2.9478972f, 3.2405567f, 0), new(33.533333f, 31.050274f, 0), 3.4850333f),
            (0.011113193f, 0.19946991f, new(1.5835204f, 0.2710278f, 0), new(-0.30230963f, -0.34969682f, 0), -1.5892135f),
            (126.564705f, 0.098258f, new(0.8046996f, 0.37563258f, 0), new(0.69903946f, -3.3576977f, 0), 3.1370344f),
            (0.16330169f, 0.08964923f, new(3.8934968f, 1.7758706f, 0), new(0.063839f, -0.21223213f, 0), 2.43214f),
        };
        (World world, SequentialImpulseSolver solver, RigidBody[] bodies) = GeneratedBox(Scenes.EarthGravity, 0.75f, substeps: 8, discs, friction: 0.3f);

        float deepest = 0;
        int impacts = 0;
        for (int step = 0; step < 40; step++)
        {
            world.Step(1f / 30f);
            deepest = MathF.Max(deepest, DeepestPair(bodies));
            impacts += step >= 10 ? world.ImpactCount : 0;
        }

        _output.WriteLine($"deepest pair over 40 steps: {deepest} m (slop {solver.Slop} m); {impacts / 30.0} impacts a step over steps 10-39");
        Assert.True(impacts < 30 * 50, $"{impacts / 30.0} impacts a step over steps 10-39: still jammed");
        Assert.True(deepest <= solver.Slop + 1e-6f, $"a pair ended {deepest} m deep");
    }

    /// <summary>
    /// Generated world 1,120 of 2,000 (seed 834): under gravity a 0.10 kg disc lies in the bottom left-hand corner with a
    /// 12 kg one leaning on it. The last position sweep of step 31 corrected their contact by less than 1 % of the slop,
    /// too little to set off the queue of contacts left deep (SequentialImpulseSolver.Residual.cs), and pushed the light
    /// disc 0.5035 mm into the wall. In a step's last substep the queue now always looks.
    /// </summary>
    [Fact]
    public void Under_gravity_a_light_disc_in_a_corner_under_a_heavier_one_ends_every_step_within_the_slop()
    {
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (0.0245827f, 0.1497631f, new(0.9263234f, 0.51960635f, 0), new(1.7723248f, -1.1930903f, 0), 0.5815796f),
            (31.101946f, 0.1692903f, new(3.6090264f, 2.125482f, 0), new(6.5869327f, 24.700888f, 0), -0.14769277f),
            (0.05694996f, 0.19084358f, new(2.257015f, 0.46004668f, 0), new(-0.13610236f, -0.16952778f, 0), 0.02262909f),
            (441.28165f, 0.30196115f, new(2.2977345f, 1.3652204f, 0), new(2.4815264f, -1.3360184f, 0), 4.306416f),
            (0.10255556f, 0.14695959f, new(2.5998926f, 0.84601814f, 0), new(0.17298885f, 0.119065635f, 0), -3.2322645f),
            (12.239601f, 0.222678f, new(3.1983104f, 0.7715573f, 0), new(-1.7483575f, -0.88019615f, 0), 3.795029f),
        };
        (World world, SequentialImpulseSolver solver, RigidBody[] bodies) = GeneratedBox(Scenes.EarthGravity, 0.43526796f, substeps: 8, discs);

        StepsWithNothingDeeperThanTheSlop(world, solver, bodies, steps: 40, dt: 1f / 30f);
    }

    /// <summary>
    /// Generated world 155 of 2,000 (seed 828): a closed box under gravity stepped with one substep of 1/30 s, where a
    /// 118 kg disc lands at 8 m/s on a 0.09 kg one lying on the floor, at 47° from vertical. The light disc is squeezed
    /// sideways, their impacts collapse, and the impact pass holds both still for the rest of each substep; the heavy
    /// disc, moved by the solver's resting contacts, kept the whole substep's gain from gravity while it stood, and the
    /// world gained 79 J in step 19 (1.5 % of its energy). Held still, it forgoes the gain of the time it stands, and the
    /// mechanical energy never rises beyond float rounding (1e-5 of Σ m g times the box's height plus the kinetic energy).
    /// </summary>
    [Fact]
    public void Under_gravity_a_heavy_disc_jammed_on_a_light_one_on_the_floor_gains_no_energy_while_it_stands()
    {
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (0.21633174f, 0.05243009f, new(1.9722581f, 3.5159695f, 0), new(0.42371777f, 0.21909864f, 0), 3.3896277f),
            (11.558935f, 0.13611092f, new(1.15679f, 2.8728855f, 0), new(2.1807816f, 0.116341814f, 0), 3.833965f),
            (118.54235f, 0.0787139f, new(3.829274f, 3.7622342f, 0), new(0.632166f, -2.308912f, 0), 4.9277034f),
            (0.089125454f, 0.36554438f, new(3.2003038f, 1.1397455f, 0), new(2.1463752f, 2.5286481f, 0), -3.7458801f),
            (0.1618998f, 0.31753343f, new(3.0834615f, 2.0927427f, 0), new(0.07472674f, -0.10897674f, 0), 0.44872144f),
        };
        (World world, _, RigidBody[] bodies) = GeneratedBox(Scenes.EarthGravity, 0.1781435f, substeps: 1, discs, friction: 0.3f);
        double Energy() => Measure.KineticEnergy(bodies) - bodies.Sum(b => b.Mass * (double)Vector3.Dot(world.Gravity, b.Position));
        double start = Energy(), scale = Measure.KineticEnergy(bodies) + bodies.Sum(b => b.Mass * 9.81 * 5.0), highest = start;
        for (int step = 0; step < 40; step++)
        {
            world.Step(1f / 30f);
            highest = Math.Max(highest, Energy());
            Assert.True(Energy() <= start + 1e-5 * scale, $"step {step}: mechanical energy rose from {start} to {Energy()} J");
        }

        _output.WriteLine($"mechanical energy {start:F1} J at the start, at most {highest:F1} J, {Energy():F1} J after 40 steps");
    }

    /// <summary>
    /// Generated world 1,146 of 2,000 (seed 884): a closed box under gravity with ε = 1, two substeps of 1/60 s. A
    /// 690 kg disc falling at 4.5 m/s stops against the right wall, and the stop leaves it 5e-23 m/s towards the wall;
    /// in the next step the wall's resting contact zeroes that, and the impact pass counted the disc as held by the
    /// solver, moving it with its end-of-substep velocity from the substep's start. It reached the floor with gravity's
    /// gain for the whole substep and bounced it back with ε = 1, unearned: the world gained 639 J in step 15. A change
    /// within float rounding is not a hold, and the mechanical energy never rises beyond float rounding.
    /// </summary>
    [Fact]
    public void Under_gravity_a_disc_that_stopped_against_a_wall_bounces_off_the_floor_without_gaining_energy()
    {
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (0.049373396f, 0.27175102f, new(3.4393024f, 1.0622841f, 0), new(10.246181f, 7.898554f, 0), 3.4025357f),
            (690.64343f, 0.13005307f, new(3.770501f, 1.3326994f, 0), new(0.2071145f, 0.091501385f, 0), -3.8827367f),
            (0.35541067f, 0.31856194f, new(3.0975022f, 2.1499033f, 0), new(0.07454893f, 0.06743978f, 0), 2.9989808f),
            (0.028411351f, 0.119749606f, new(1.6075394f, 2.858023f, 0), new(3.5826235f, -3.2006526f, 0), 0.6251166f),
            (1.5939885f, 0.13764444f, new(0.45890075f, 0.30950952f, 0), new(-0.36953884f, -0.65752673f, 0), -2.1161187f),
            (51.57174f, 0.08383267f, new(3.5161707f, 0.5891719f, 0), new(0.66776407f, 13.126234f, 0), 3.0077288f),
        };
        (World world, _, RigidBody[] bodies) = GeneratedBox(Scenes.EarthGravity, 1f, substeps: 2, discs, friction: 0.3f);
        double Energy() => Measure.KineticEnergy(bodies) - bodies.Sum(b => b.Mass * (double)Vector3.Dot(world.Gravity, b.Position));
        double scale = Measure.KineticEnergy(bodies) + bodies.Sum(b => b.Mass * 9.81 * 5.0);
        for (int step = 0; step < 20; step++)
        {
            double before = Energy();
            world.Step(1f / 30f);
            Assert.True(Energy() <= before + 1e-5 * scale, $"step {step}: mechanical energy rose from {before} to {Energy()} J");
        }
    }

    /// <summary>
    /// Generated world 645 of 2,000 (seed 1,178): a closed box under gravity, five substeps of 1/150 s, sleeping on. A
    /// 54 kg disc falls asleep on the floor 6 mm from a light disc (0.06 kg) that falls beside it, moving away; landing,
    /// the light disc's spin is turned by friction into 0.25 m/s towards the sleeper. Waking at the start of the step
    /// looked only at what approached then, and the disc's new path stayed within the sphere detection covered for it,
    /// so it was not looked up again: it ended step 36 1.3 mm inside the sleeping disc. An impact that turns a body
    /// towards a sleeper within its sphere now wakes it.
    /// </summary>
    [Fact]
    public void Under_gravity_a_disc_turned_by_its_landing_towards_a_sleeping_one_wakes_it_and_stays_out_of_it()
    {
        (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs =
        {
            (54.478397f, 0.42441857f, new(2.4636922f, 0.6198826f, 0), new(8.794685f, -11.964602f, 0), -4.2206745f),
            (0.1718996f, 0.2204265f, new(1.4364591f, 0.47745702f, 0), new(-16.331774f, 9.9829855f, 0), 0.82461923f),
            (0.06177989f, 0.37329692f, new(0.44979122f, 3.597288f, 0), new(-10.948791f, -10.836172f, 0), -0.7332563f),
            (15.075704f, 0.15243715f, new(3.2164204f, 2.7450917f, 0), new(-1.5658864f, -0.8022623f, 0), -0.16031845f),
            (1.063575f, 0.2575292f, new(2.3263235f, 2.243347f, 0), new(-1.3928223f, -1.4010625f, 0), -0.8240758f),
            (158.66406f, 0.06580971f, new(0.45003676f, 1.3115597f, 0), new(0.40608466f, 1.9387158f, 0), -1.3983086f),
        };
        (World world, SequentialImpulseSolver solver, RigidBody[] bodies) = GeneratedBox(Scenes.EarthGravity, 0f, substeps: 5, discs, friction: 0.3f);
        StepsWithNothingDeeperThanTheSlop(world, solver, bodies, steps: 40, dt: 1f / 30f);
    }

    /// <summary>
    /// A generated world of the world-laws property: a closed 4 m box in the plane, the default solver with its
    /// restitution, the friction given (none unless said) and a 0.5 m/s threshold, and its discs (mass, radius, centre,
    /// velocity, spin about z).
    /// </summary>
    private static (World World, SequentialImpulseSolver Solver, RigidBody[] Bodies) GeneratedBox(
        Vector3 gravity, float restitution, int substeps, (float Mass, float Radius, Vector3 Position, Vector3 Velocity, float Spin)[] discs,
        float friction = 0f)
    {
        var solver = new SequentialImpulseSolver(restitution, friction) { RestitutionThreshold = 0.5f };
        var world = new World(gravity, solver) { Substeps = substeps };
        world.AddPlanes(StaticPlane.Box(Vector3.Zero, new Vector3(4, 4, 0), planar: true));
        RigidBody[] bodies = discs.Select(d => world.Add(new RigidBody(d.Mass, d.Radius, d.Position, Inertia.Disc(d.Mass, d.Radius))
        {
            LinearVelocity = d.Velocity,
            AngularVelocity = new Vector3(0, 0, d.Spin),
        })).ToArray();
        return (world, solver, bodies);
    }

    /// <summary>Steps the world and asserts that no pair ends any of the steps deeper than the slop.</summary>
    private void StepsWithNoPairDeeperThanTheSlop(World world, SequentialImpulseSolver solver, RigidBody[] bodies, int steps, float dt)
    {
        float deepest = 0;
        for (int step = 0; step < steps; step++)
        {
            world.Step(dt);
            deepest = MathF.Max(deepest, DeepestPair(bodies));
        }

        _output.WriteLine($"deepest pair over {steps} steps: {deepest} m (slop {solver.Slop} m)");
        Assert.True(deepest <= solver.Slop + 1e-6f, $"a pair ended {deepest} m deep");
    }

    /// <summary>
    /// Steps the world and asserts that no body ends any of the steps deeper into a wall, nor any pair into each other,
    /// than the slop, up to float rounding of where the bodies end (1e-5 of the smallest radius).
    /// </summary>
    private void StepsWithNothingDeeperThanTheSlop(World world, SequentialImpulseSolver solver, RigidBody[] bodies, int steps, float dt)
    {
        float deepest = 0;
        for (int step = 0; step < steps; step++)
        {
            world.Step(dt);
            foreach (RigidBody body in bodies)
            {
                foreach (StaticPlane plane in world.Planes)
                {
                    deepest = MathF.Max(deepest, body.Radius - (Vector3.Dot(plane.Normal, body.Position) - plane.Offset));
                }
            }

            deepest = MathF.Max(deepest, DeepestPair(bodies));
        }

        float bound = solver.Slop + 1e-5f * bodies.Min(b => b.Radius);
        _output.WriteLine($"deepest over {steps} steps: {deepest} m (slop {solver.Slop} m, bound {bound} m)");
        Assert.True(deepest <= bound, $"a body ended {deepest} m deep");
    }

    /// <summary>The largest overlap r_i + r_j − |c_i − c_j| of any pair (negative when none overlaps).</summary>
    private static float DeepestPair(RigidBody[] bodies)
    {
        float deepest = float.NegativeInfinity;
        for (int i = 0; i < bodies.Length; i++)
        {
            for (int j = i + 1; j < bodies.Length; j++)
            {
                deepest = MathF.Max(deepest, bodies[i].Radius + bodies[j].Radius - Vector3.Distance(bodies[i].Position, bodies[j].Position));
            }
        }

        return deepest;
    }
}
