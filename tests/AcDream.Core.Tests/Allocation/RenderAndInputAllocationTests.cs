using System.Numerics;
using AcDream.Core.Physics.Input;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

/// <summary>A client's frame allocates nothing: the player's keys (PlayerInput), the tick with its render-pose record, and the
/// drawn pose (GetRenderPose at RenderTime).</summary>
public class RenderAndInputAllocationTests
{
    [Fact]
    public void KeysTickAndDrawnPose_AllocateNothing()
    {
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        float sink = 0f;
        int frame = 0;
        void Window()
        {
            for (int i = 0; i < 60; i++)
            {
                frame++;
                MovementKeys keys = (frame / 20 % 3) switch
                {
                    0 => MovementKeys.Forward,
                    1 => MovementKeys.Forward | MovementKeys.Run | MovementKeys.TurnLeft,
                    _ => MovementKeys.Backward | MovementKeys.StrafeRight,
                };
                input.SetHeldKeys(keys);
                s.World.Tick(frame / 60.0);
                Position drawn = s.Player.GetRenderPose(s.World.RenderTime);
                sink += drawn.Frame.Origin.X;
            }
        }

        Window();   // warm-up: managers created, tables filled
        AllocationProbe.AssertSteadyStateAllocatesNothing(Window);
        Assert.True(float.IsFinite(sink));
    }
}
