using System;
using AcDream.Core.Physics.Input;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>The jump charge's constants (<c>ClientCombatSystem::DoJump</c>, acclient.c:408145, and <c>GetPowerBarLevel</c>,
/// 407918), pinned by value and bits.</summary>
public class PlayerInputConstantsTests
{
    [Fact]
    public void MinJumpExtent_IsRetailsMinimum()
    {
        // MIN_JUMP_EXTENT 0.001 as a float: 0x3A83126F (1.00000005e-3).
        Assert.Equal(0.001f, PlayerInput.MinJumpExtent);
        Assert.Equal(0x3A83126Fu, BitConverter.SingleToUInt32Bits(PlayerInput.MinJumpExtent));
    }

    [Fact]
    public void FastPowerBar_FillsIn0_8Seconds()
    {
        // 0.8 as a double: 0x3FE999999999999A.
        Assert.Equal(0.8, PlayerInput.FastPowerBarSeconds);
        Assert.Equal(0x3FE999999999999AUL, BitConverter.DoubleToUInt64Bits(PlayerInput.FastPowerBarSeconds));
    }
}
