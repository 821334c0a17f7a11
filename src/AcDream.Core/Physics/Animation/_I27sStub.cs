// TEMPORARY: stand-ins for branch i27s's types, deleted when i27s is merged.
#pragma warning disable CS1591
using System.Numerics;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Animation;

public readonly struct AnimData
{
    public const float MaxFramerate = 10000f;
    public AnimData(uint animId, int lowFrame, int highFrame, float framerate) { AnimId = animId; LowFrame = lowFrame; HighFrame = highFrame; Framerate = framerate; }
    public uint AnimId { get; }
    public int LowFrame { get; }
    public int HighFrame { get; }
    public float Framerate { get; }
    internal static bool IsFramerateInDomain(float framerate) => float.IsFinite(framerate) && System.Math.Abs(framerate) <= MaxFramerate;
    internal static AnimData UnPack(ref RetailDataReader reader) => new(reader.ReadUInt32(), reader.ReadInt32(), reader.ReadInt32(), reader.ReadSingle());
}

internal sealed class AnimSequence
{
    public Vector3 Velocity;
    public Vector3 Omega;
    public int Count;
    public void SetVelocity(Vector3 v) => Velocity = v;
    public void SetOmega(Vector3 o) => Omega = o;
    public void CombinePhysics(Vector3 v, Vector3 o) { Velocity += v; Omega += o; }
    public void SubtractPhysics(Vector3 v, Vector3 o) { Velocity -= v; Omega -= o; }
    public void ClearPhysics() { Velocity = default; Omega = default; }
    public void RemoveCyclicAnims() { }
    public void ClearAnimations() { Count = 0; }
    public void AppendAnimation(in AnimData a) { Count++; }
    public bool HasAnims() => Count != 0;
    public void MultiplyCyclicAnimationFramerate(float m) { }
    public void RemoveLinkAnimations(uint n) { }
    public void RemoveAllLinkAnimations() { }
    public void Update(double quantum, ref Frame frame) { }
}
