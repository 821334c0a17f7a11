using System;
using AcDream.Core.Physics.Managers;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>Every retail constant of the position-manager family, with its float32 bit pattern where retail stores a float.</summary>
public class ManagerConstantsTests
{
    [Theory]
    // 0.05f: CInterpolationManager.c desired distance (acclient.c:389217) = 0x3D4CCCCD
    [InlineData(InterpolationManager.DesiredDistance, 0.05f, 0x3D4CCCCD)]
    // 0.2: near-enough success (acclient.c:389270); as float 0x3E4CCCCD
    [InlineData(InterpolationManager.NearEnoughDistance, 0.2f, 0x3E4CCCCD)]
    // 0.3f: CREATURE_FAILED_INTERPOLATION_PERCENTAGE (acclient.c:389248) = 0x3E99999A
    [InlineData(InterpolationManager.MinProgressFraction, 0.3f, 0x3E99999A)]
    // 7.5f: MAX_INTERPOLATED_VELOCITY (acclient_data.h:2589) = 0x40F00000
    [InlineData(InterpolationManager.MaxInterpolatedVelocity, 7.5f, 0x40F00000)]
    // 999999.0f: BIG_DISTANCE (acclient_data.h:2590) = 0x497423F0
    [InlineData(InterpolationManager.BigDistance, 999999.0f, 0x497423F0)]
    // 0.5f: set_target radius in StickTo (acclient.c:388687) = 0x3F000000
    [InlineData(StickyManager.TargetTrackRadius, 0.5f, 0x3F000000)]
    public void FloatConstants_HaveRetailValuesAndBitPatterns(float actual, float expected, int bits)
    {
        Assert.Equal(expected, actual);
        Assert.Equal(bits, BitConverter.SingleToInt32Bits(actual));
    }

    [Fact]
    public void StickyStandoff_IsPointThreeFloat()
    {
        // 0.3f: sticky standoff (acclient.c:388559) = 0x3E99999A
        Assert.Equal(0.3f, StickyManager.StickyRadius);
        Assert.Equal(0x3E99999A, BitConverter.SingleToInt32Bits(StickyManager.StickyRadius));
    }

    [Fact]
    public void IntegerAndDoubleConstants_HaveRetailValues()
    {
        Assert.Equal(20, InterpolationManager.MaxQueueLength);           // `count < 0x14` (acclient.c:389084)
        Assert.Equal(5u, InterpolationManager.ProgressCheckFrames);      // `frame_counter < 5` (acclient.c:389244)
        Assert.Equal(4, InterpolationManager.FarBranchFailCount);        // node_fail_counter = 4 (acclient.c:389164)
        Assert.Equal(3, InterpolationManager.BlipFailThreshold);         // `node_fail_counter > 3` (acclient.c:389302)
        Assert.Equal(2.0, InterpolationManager.SpeedMultiplier);         // `* 2.0` (acclient.c:389237)
        Assert.True(InterpolationManager.UseAdjustedSpeed);              // fUseAdjustedSpeed_ = 1 (acclient_data.h:6710)
        Assert.Equal(5.0, StickyManager.SpeedMultiplier);                // `* 5.0` (acclient.c:388572)
        Assert.Equal(15.0, StickyManager.FallbackSpeed);                 // 15.0 (acclient.c:388579)
        Assert.Equal(1.0, StickyManager.StickyTime);                     // cur_time + 1.0 (acclient.c:388684)
        Assert.Equal(0.5, StickyManager.TargetTrackQuantum);             // set_target quantum (acclient.c:388687)
        Assert.Equal(0x36u, (uint)StickyManager.UnstickMoveToError);           // cancel_moveto(0x36) (acclient.c:317420)
        Assert.Equal(0.9, ConstraintManager.FullyConstrainedFraction);   // max * 0.9 (acclient.c:389419)
    }
}
