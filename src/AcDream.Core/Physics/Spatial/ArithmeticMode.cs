namespace AcDream.Core.Physics.Spatial;

/// <summary>
/// How the Frame operations of the tick evaluate their intermediates — a fidelity switch whose cost and error the
/// accuracy report measures side by side.
/// </summary>
public enum ArithmeticMode
{
    /// <summary>
    /// Retail: intermediates in double (as the client's x87 temporaries under 53-bit precision control), rounded to float exactly
    /// where retail stored a float. The default.
    /// </summary>
    RetailDouble = 0,

    /// <summary>Plain float32 throughout: every operation rounds to single precision (what a naive port computes). Not a
    /// candidate retail behaviour: retail set 53-bit precision (<c>ClientMain::ConfigureFPU</c>, acclient.c:60884) and kept it
    /// under Direct3D (<c>D3DCREATE_FPU_PRESERVE</c>, acclient.c:459978); this mode exists to measure the cost.</summary>
    Float32 = 1,
}
