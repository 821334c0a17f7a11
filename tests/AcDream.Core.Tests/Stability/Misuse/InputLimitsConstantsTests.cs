using System;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>The value-domain constants, by value and (floats) bit pattern.</summary>
public class InputLimitsConstantsTests
{
    [Fact]
    public void Constants_ArePinned()
    {
        // 2^16 m = 65,536: float 0x47800000 (exponent 127 + 16 = 143 = 0x8F, mantissa 0).
        Assert.Equal(65536f, InputLimits.MaxCoordinate);
        Assert.Equal(0x47800000, BitConverter.SingleToInt32Bits(InputLimits.MaxCoordinate));
        // One landblock, 24 × 8 = 192 m: float 0x43400000 (1.5 × 2^7).
        Assert.Equal(192f, InputLimits.OutdoorMargin);
        Assert.Equal(0x43400000, BitConverter.SingleToInt32Bits(InputLimits.OutdoorMargin));
        Assert.Equal(192f, InputLimits.MaxChildOffset);
        // 0.01f = 0x3C23D70A (the float nearest 0.01); 100f = 0x42C80000 (1.5625 × 2^6).
        Assert.Equal(0.01f, InputLimits.MinScale);
        Assert.Equal(0x3C23D70A, BitConverter.SingleToInt32Bits(InputLimits.MinScale));
        Assert.Equal(100f, InputLimits.MaxScale);
        Assert.Equal(0x42C80000, BitConverter.SingleToInt32Bits(InputLimits.MaxScale));
        // 50 m/s = 0x42480000 (1.5625 × 2^5), retail's max velocity.
        Assert.Equal(50f, InputLimits.MaxSequenceSpeed);
        Assert.Equal(0x42480000, BitConverter.SingleToInt32Bits(InputLimits.MaxSequenceSpeed));
        // 1,000 m/s² = 0x447A0000 (1.953125 × 2^9).
        Assert.Equal(1000f, InputLimits.MaxAcceleration);
        Assert.Equal(0x447A0000, BitConverter.SingleToInt32Bits(InputLimits.MaxAcceleration));
        Assert.Equal(192f, InputLimits.MaxSweepDistance);
        // Motion speeds within ±100 and run rates in (0, 100]: 100f = 0x42C80000; the sticky step at most 100 m.
        Assert.Equal(0x42C80000, BitConverter.SingleToInt32Bits(InputLimits.MaxMotionSpeed));
        Assert.Equal(0x42C80000, BitConverter.SingleToInt32Bits(InputLimits.MaxRunRate));
        Assert.Equal(0x42C80000, BitConverter.SingleToInt32Bits(AcDream.Core.Physics.Managers.StickyManager.MaxStep));
        Assert.Equal(65536, ObjCell.MaxShadowCapacity);
    }
}
