using System.Threading.Tasks;
using AcDream.Core.Physics.Motion;
using Xunit;

namespace AcDream.Core.Tests.Retail;

// Issue #25 item 7: retail's CMotionInterp::HandleExitWorld (acclient.c:343678-343713) loops "for (i = head; i; i = head)"
// and removes the head only inside "if (physics_obj && i)": with pending motions and no physics object it never removes one
// and never ends. The port's loop condition includes the physics object, so it returns and leaves the motions pending
// (docs/divergences.md).
public class HandleExitWorldWithoutObjectTests
{
    [Fact]
    public async Task HandleExitWorld_WithPendingMotionsAndNoPhysicsObject_Returns_AndKeepsThem()
    {
        MotionInterp mi = MotionInterp.Create(null, null);
        mi.PendingMotions.Add(new MotionNode(1, MotionCommand.Ready, MotionError.None));
        mi.PendingMotions.Add(new MotionNode(2, MotionCommand.WalkForward, MotionError.None));
        Task call = Task.Run(mi.HandleExitWorld);
        Task first = await Task.WhenAny(call, Task.Delay(10_000));
        Assert.True(first == call, "HandleExitWorld did not return (retail's endless loop)");
        Assert.Equal(2, mi.PendingMotions.Count);
    }
}
