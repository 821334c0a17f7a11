using System;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
namespace AcDream.Core.Physics.Objects.Parts;

/// <summary>
/// The seam to an object's parts and animation (retail <c>CPartArray</c>, PORTAL/cphysobj/CPartArray.c). A client that
/// animates models implements it; <see cref="SimplePartArray"/> is the built-in implementation for an object without
/// animations. An object with no part array costs nothing: every call site tests for null first.
/// </summary>
/// <remarks>Implementations are called inside the tick and must not allocate.</remarks>
public interface IPartArray
{
    /// <summary>
    /// True when <see cref="Update"/> would leave the offset frame at the identity and nothing else in the part array changes
    /// per step (no animation, no root motion): the scene may then skip the object while it rests. False by default, so a
    /// client's animated part array is always visited.
    /// </summary>
    bool IsIdle => false;

    /// <summary>
    /// Number of collision spheres (retail <c>CPartArray::GetNumSphere</c>). An object with none never translates through
    /// update_object (retail keeps its origin and applies only the new orientation).
    /// </summary>
    int NumSpheres { get; }

    /// <summary>
    /// The collision spheres, <see cref="NumSpheres"/> long, in the object's local frame and NOT scaled (the sweep scales
    /// them by the object's scale, as retail's <c>SPHEREPATH::init_sphere</c> does). Retail: <c>CPartArray::GetSphere</c>
    /// (acclient.c:325363), the setup's sphere array.
    /// </summary>
    ReadOnlySpan<Sphere> Spheres { get; }

    /// <summary>
    /// The motion player the motion interpreter plays motions on (retail: the part array's motion-table manager with its
    /// motion table and sequence, <c>CPartArray::motion_table_manager</c>), or null when the object has none (the interpreter's motions then fail with <see cref="Motion.MotionError.NoMotionTable"/>
    /// and only its states change). <see cref="Update"/> moves the body by its velocity and omega.
    /// </summary>
    Motion.IMotionPlayer? MotionPlayer => null;

    /// <summary>Number of parts, for <c>UpdateChild</c>'s part lookup.</summary>
    int NumParts { get; }

    /// <summary>Bounding radius of the setup times the scale, metres (retail <c>CPartArray::GetRadius</c>).</summary>
    float Radius { get; }

    /// <summary>Height of the setup times the scale, metres (retail <c>CPartArray::GetHeight</c>).</summary>
    float Height { get; }

    /// <summary>Step-up height, metres (retail <c>CPartArray::GetStepUpHeight</c>, acclient.c:325399).</summary>
    float StepUpHeight { get; }

    /// <summary>Step-down height, metres (retail <c>CPartArray::GetStepDownHeight</c>, acclient.c:325413).</summary>
    float StepDownHeight { get; }

    /// <summary>
    /// Advances the animation by <paramref name="quantum"/> seconds and adds its root motion (a local offset and rotation)
    /// into <paramref name="offsetFrame"/>, which starts as the identity frame.
    /// </summary>
    // retail: CPartArray::Update (acclient.c:325139) -> CSequence::update (acclient.c:340950)
    void Update(float quantum, ref Frame offsetFrame);

    /// <summary>The object's frame changed: place the parts (retail <c>CPartArray::SetFrame</c>).</summary>
    void SetFrame(in Frame frame);

    /// <summary>The object's cell changed (retail <c>CPartArray::SetCellID</c>).</summary>
    void SetCellId(uint cellId);

    /// <summary>Per-step motion-table bookkeeping (retail <c>CPartArray::HandleMovement</c>, acclient.c:325105).</summary>
    void HandleMovement();

    /// <summary>The object entered the world (retail <c>CPartArray::HandleEnterWorld</c>, acclient.c:325115).</summary>
    void HandleEnterWorld();

    /// <summary>Frame of part <paramref name="index"/> (0 &lt;= index &lt; <see cref="NumParts"/>), for attached children.</summary>
    Frame GetPartFrame(int index);

    /// <summary>Applies a uniform scale to every part (retail <c>CPartArray::SetScaleInternal</c>).</summary>
    /// <param name="scale">The scale; the object passes only values in [<see cref="InputLimits.MinScale"/>,
    /// <see cref="InputLimits.MaxScale"/>].</param>
    void SetScale(float scale);

    /// <summary>Applies a translucency to every part (retail <c>CPartArray::SetTranslucencyInternal</c>).</summary>
    void SetTranslucency(float translucency);

    /// <summary>Applies a translucency to one part (retail <c>CPartArray::SetPartTranslucencyInternal</c>).</summary>
    void SetPartTranslucency(uint part, float translucency);

    /// <summary>Applies a luminosity to every part (retail <c>CPartArray::SetLuminosityInternal</c>).</summary>
    void SetLuminosity(float luminosity);

    /// <summary>Applies a luminosity to one part (retail <c>CPartArray::SetPartLuminosityInternal</c>).</summary>
    void SetPartLuminosity(uint part, float luminosity);

    /// <summary>Applies a diffusion to every part (retail <c>CPartArray::SetDiffusionInternal</c>).</summary>
    void SetDiffusion(float diffusion);

    /// <summary>Applies a diffusion to one part (retail <c>CPartArray::SetPartDiffusionInternal</c>).</summary>
    void SetPartDiffusion(uint part, float diffusion);
}
