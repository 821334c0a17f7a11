using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.World;

// The render clock for interpolated drawing. A library addition, not retail.
public sealed partial class PhysicsWorld
{
    /// <summary>
    /// The time to draw the world at: <see cref="CurrentTime"/> minus <see cref="PhysicsProfile.MinQuantum"/> (1/30 s under
    /// both profiles). Library addition for render interpolation (no retail symbol).
    /// </summary>
    /// <remarks>
    /// <para>The world moves its objects only when at least MinQuantum has passed since its last update
    /// (<see cref="UseTime"/>), so between updates a frame sees the same physics pose: at 60 fps an object moves on every
    /// second or third frame. Drawing each object at <see cref="PhysicsObj.GetRenderPose"/>(<c>RenderTime</c>) instead gives
    /// evenly spaced poses at any frame rate.</para>
    /// <para>Why this time: after a tick at <c>now</c>, an object the last two world updates moved holds its poses at those
    /// updates' times t0 &lt; t1 &lt;= now, and the next update comes at the first frame with now - t1 &gt;= MinQuantum. Every
    /// frame before it has now - MinQuantum &lt; t1, and t1 - t0 &gt;= MinQuantum gives now - MinQuantum &gt;= t0: the render time
    /// always lies between the two poses, so the drawn pose follows the physics path one gate period behind, never
    /// stalling and never jumping.</para>
    /// </remarks>
    public double RenderTime => CurrentTime - Profile.MinQuantum;
}
