using System.Numerics;

namespace AcDream.Core.Physics.Collision;

public sealed partial class SpherePath
{
    /// <summary>
    /// Records a negative-side polygon hit from a BSP: the sphere touched a polygon it is moving away from (or the second
    /// sphere touched one). The transition then steps up (<paramref name="stepUp"/>) or slides along the reversed normal.
    /// </summary>
    // retail: SPHEREPATH::set_neg_poly_hit (acclient.c:360742)
    public void SetNegPolyHit(bool stepUp, Vector3 collisionNormal)
    {
        NegStepUp = stepUp;
        NegPolyHit = true;
        NegCollisionNormal = new Vector3(-collisionNormal.X, -collisionNormal.Y, -collisionNormal.Z);
    }
}
