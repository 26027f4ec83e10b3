using SimpleDynamics.Laws;
using SimpleDynamics.Response;
using Xunit;

namespace SimpleDynamics.Tests.Laws;

/// <summary>The library's own responders, checked with the laws kit as a student would check theirs.</summary>
public class LibraryResponderLawTests
{
    [Fact]
    public void Impulse_responder_keeps_the_tutorial_s_laws() =>
        ResponderLaws.Check(e => new ImpulseCollisionResponder(e));

    [Fact]
    public void Sequential_impulse_solver_keeps_the_tutorial_s_laws() =>
        ResponderLaws.Check(e => new SequentialImpulseSolver(e));

    [Fact]
    public void Perfectly_inelastic_responder_keeps_its_own_laws() =>
        ResponderLaws.Check(_ => new PerfectlyInelasticResponder(), new LawOptions { Laws = ResponderLaws.PerfectlyInelasticLaws });
}
