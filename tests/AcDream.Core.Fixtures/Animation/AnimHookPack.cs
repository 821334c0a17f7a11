using System;
using System.Buffers.Binary;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Fixtures.Animation;

/// <summary>
/// Retail's animation-hook pack (<c>CAnimHook::PackHook</c>, <c>CAnimHook::PackSize</c> and each hook type's <c>Pack</c> and
/// <c>pack_size</c>): a hook written as <c>AnimHook.UnPackHook</c> reads it (type word, direction word, the type's fields, zero
/// padding to four), from what the hook holds, so a hook read from bytes writes back to the very same bytes. The library
/// ships the reader only; the writer lives here, switching on the hook's kind.
/// </summary>
public static class AnimHookPack
{
    /// <summary>The hook's packed size: type and direction words, its fields, padded to a multiple of four.</summary>
    // retail: CAnimHook::PackSize (acclient.c:342142)
    public static int PackSize(AnimHook hook)
    {
        ArgumentNullException.ThrowIfNull(hook);
        int result = BodySize(hook) + 8;
        if ((result & 3) != 0)
        {
            result += 4 - (result & 3);
        }

        return result;
    }

    /// <summary>
    /// Writes <paramref name="hook"/> at <paramref name="destination"/>[<paramref name="offset"/>..]: type word, direction word,
    /// the type's fields, zero padding to a multiple of four from the start of <paramref name="destination"/> (retail
    /// <c>PackObj::ALIGN_PTR</c>); <see cref="PackSize"/> bytes from an offset that is a multiple of four. Too small a
    /// destination is an <see cref="ArgumentException"/>, before anything is written.
    /// </summary>
    // retail: CAnimHook::PackHook (acclient.c:342153)
    public static void PackHook(AnimHook hook, Span<byte> destination, ref int offset)
    {
        ArgumentNullException.ThrowIfNull(hook);
        int size = 8 + BodySize(hook);
        int need = size + ((4 - ((offset + size) & 3)) & 3);
        if (offset < 0 || destination.Length - offset < need)
        {
            throw new ArgumentException($"The hook needs {need} bytes from offset {offset}.", nameof(destination));
        }

        U32(destination, ref offset, (uint)hook.HookType);
        U32(destination, ref offset, (uint)(int)hook.Direction);
        PackBody(hook, destination, ref offset);
        while ((offset & 3) != 0)
        {
            destination[offset++] = 0;
        }
    }

    /// <summary>The hook's packed bytes (<see cref="PackSize"/> of them).</summary>
    public static byte[] Pack(AnimHook hook)
    {
        var bytes = new byte[PackSize(hook)];
        int at = 0;
        PackHook(hook, bytes, ref at);
        return bytes;
    }

    // The hook's own fields' packed size in bytes (retail: the type's pack_size).
    private static int BodySize(AnimHook hook) => hook switch
    {
        SoundHook or SoundTableHook => 4,
        SoundTweakedHook => 16,
        AttackHook => 28,
        ReplaceObjectHook r => PartChangeSize(r.PartId),
        CreateParticleHook => 40,
        DestroyParticleHook or StopParticleHook or NoDrawHook or DefaultScriptPartHook or SetLightHook or EtherealHook => 4,
        TextureVelocityHook or ScaleHook or CallPesHook => 8,
        TextureVelocityPartHook => 12,
        FadeHook => 12,
        PartFadeHook => 16,
        SetOmegaHook => 12,
        _ => 0, // NoOp, DefaultScript, AnimDone: no fields
    };

    // Writes the hook's own fields (retail: the type's Pack) at d[at..], advancing at.
    private static void PackBody(AnimHook hook, Span<byte> d, ref int at)
    {
        switch (hook)
        {
            case SoundHook s:
                PackSoundTable(d, ref at, s.SoundId);
                break;
            case SoundTableHook s:
                PackSoundTable(d, ref at, s.SoundType);
                break;
            case SoundTweakedHook s:
                PackSoundTweaked(d, ref at, s);
                break;
            case AttackHook a:
                PackAttackCone(d, ref at, a.Cone);
                break;
            case ReplaceObjectHook r:
                PackPartChange(d, ref at, r.PartIndex, r.PartId);
                break;
            case CreateParticleHook c:
                PackCreateParticle(d, ref at, c);
                break;
            case DestroyParticleHook x:
                PackNoDraw(d, ref at, x.EmitterId);
                break;
            case StopParticleHook x:
                PackNoDraw(d, ref at, x.EmitterId);
                break;
            case NoDrawHook x:
                PackNoDraw(d, ref at, x.NoDraw ? 1u : 0u);
                break;
            case DefaultScriptPartHook x:
                PackNoDraw(d, ref at, x.PartIndex);
                break;
            case SetLightHook x:
                PackNoDraw(d, ref at, x.LightsOn ? 1u : 0u);
                break;
            case EtherealHook x:
                PackNoDraw(d, ref at, x.Ethereal ? 1u : 0u);
                break;
            case TextureVelocityHook t:
                PackTextureVelocity(d, ref at, t.USpeed, t.VSpeed);
                break;
            case ScaleHook s:
                PackTextureVelocity(d, ref at, s.End, s.Time);
                break;
            case TextureVelocityPartHook t:
                PackTextureVelocityPart(d, ref at, t);
                break;
            case FadeHook f:
                PackDiffuse(d, ref at, f);
                break;
            case PartFadeHook f:
                PackDiffusePart(d, ref at, f);
                break;
            case CallPesHook c:
                PackCallPes(d, ref at, c);
                break;
            case SetOmegaHook o:
                PackSetOmega(d, ref at, o.Axis);
                break;
            default:
                break; // NoOp, DefaultScript, AnimDone: no fields
        }
    }

    // One word (SoundHook's gid, SoundTableHook's sound type).
    // retail: SoundTableHook::Pack (acclient.c:342224)
    private static void PackSoundTable(Span<byte> d, ref int at, uint v) => U32(d, ref at, v);

    // retail: SoundTweakedHook::Pack (acclient.c:343097)
    private static void PackSoundTweaked(Span<byte> d, ref int at, SoundTweakedHook s)
    {
        U32(d, ref at, s.SoundId);
        F32(d, ref at, s.Probability);
        F32(d, ref at, s.Priority);
        F32(d, ref at, s.Volume);
    }

    // retail: AttackCone::Pack (acclient.c:342595)
    private static void PackAttackCone(Span<byte> d, ref int at, in AttackCone cone)
    {
        U32(d, ref at, (uint)cone.PartIndex);
        F32(d, ref at, cone.Left.X);
        F32(d, ref at, cone.Left.Y);
        F32(d, ref at, cone.Right.X);
        F32(d, ref at, cone.Right.Y);
        F32(d, ref at, cone.Radius);
        F32(d, ref at, cone.Height);
    }

    // AnimPartChange::Pack: the byte, then the id packed by Pack_AsDataIDOfKnownType as an offset from 0x01000000 (an id of 0
    // as offset 0): two bytes up to 0x3FFF, four up to 0x3FFFFFFF, none beyond.
    private static int PartChangeSize(uint partId)
    {
        uint offset = (partId == 0 ? 0x01000000u : partId) - 0x01000000u;
        return 1 + (offset > 0x3FFF ? (offset > 0x3FFFFFFF ? 0 : 4) : 2);
    }

    // retail: AnimPartChange::Pack (acclient.c:471681)
    private static void PackPartChange(Span<byte> d, ref int at, uint partIndex, uint partId)
    {
        d[at++] = (byte)partIndex;
        PackAsDataIdOfKnownType(d, ref at, partId);
    }

    // retail: Pack_AsDataIDOfKnownType (acclient.c:667688)
    private static void PackAsDataIdOfKnownType(Span<byte> d, ref int at, uint partId)
    {
        uint offset = (partId == 0 ? 0x01000000u : partId) - 0x01000000u;
        if (offset > 0x3FFF)
        {
            if (offset <= 0x3FFFFFFF)
            {
                BinaryPrimitives.WriteUInt16LittleEndian(d.Slice(at), (ushort)((offset >> 16) | 0x8000));
                BinaryPrimitives.WriteUInt16LittleEndian(d.Slice(at + 2), (ushort)offset);
                at += 4;
            }
        }
        else
        {
            BinaryPrimitives.WriteUInt16LittleEndian(d.Slice(at), (ushort)offset);
            at += 2;
        }
    }

    // retail: CreateParticleHook::Pack (acclient.c:343189)
    private static void PackCreateParticle(Span<byte> d, ref int at, CreateParticleHook c)
    {
        U32(d, ref at, c.EmitterInfoId);
        U32(d, ref at, c.PartIndex);
        FramePack(d, ref at, c.Offset);
        U32(d, ref at, c.EmitterId);
    }

    // One word (folded by the linker for every one-word hook: destroy and stop particle, no-draw, default script part, set
    // light, ethereal).
    // retail: NoDrawHook::Pack (acclient.c:342287)
    private static void PackNoDraw(Span<byte> d, ref int at, uint v) => U32(d, ref at, v);

    // Two floats (TextureVelocityHook's u and v speeds, ScaleHook's end and time).
    // retail: TextureVelocityHook::Pack (acclient.c:342479)
    private static void PackTextureVelocity(Span<byte> d, ref int at, float a, float b)
    {
        F32(d, ref at, a);
        F32(d, ref at, b);
    }

    // retail: TextureVelocityPartHook::Pack (acclient.c:342559)
    private static void PackTextureVelocityPart(Span<byte> d, ref int at, TextureVelocityPartHook t)
    {
        U32(d, ref at, t.PartIndex);
        F32(d, ref at, t.USpeed);
        F32(d, ref at, t.VSpeed);
    }

    // The whole-object fades (transparent, luminous, diffuse): start, end, time.
    // retail: DiffuseHook::Pack (acclient.c:342347)
    private static void PackDiffuse(Span<byte> d, ref int at, FadeHook f)
    {
        F32(d, ref at, f.Start);
        F32(d, ref at, f.End);
        F32(d, ref at, f.Time);
    }

    // The part fades (transparent, luminous, diffuse part): part, start, end, time.
    // retail: DiffusePartHook::Pack (acclient.c:342433)
    private static void PackDiffusePart(Span<byte> d, ref int at, PartFadeHook f)
    {
        U32(d, ref at, f.Part);
        F32(d, ref at, f.Start);
        F32(d, ref at, f.End);
        F32(d, ref at, f.Time);
    }

    // retail: CallPESHook::Pack (acclient.c:343156)
    private static void PackCallPes(Span<byte> d, ref int at, CallPesHook c)
    {
        U32(d, ref at, c.ScriptId);
        F32(d, ref at, c.Pause);
    }

    // retail: SetOmegaHook::Pack (acclient.c:343230)
    private static void PackSetOmega(Span<byte> d, ref int at, System.Numerics.Vector3 axis)
    {
        F32(d, ref at, axis.X);
        F32(d, ref at, axis.Y);
        F32(d, ref at, axis.Z);
    }

    private static void U32(Span<byte> d, ref int at, uint v)
    {
        BinaryPrimitives.WriteUInt32LittleEndian(d.Slice(at), v);
        at += 4;
    }

    private static void F32(Span<byte> d, ref int at, float v) => U32(d, ref at, BitConverter.SingleToUInt32Bits(v));

    // Frame::Pack: origin x, y, z, then w, x, y, z.
    private static void FramePack(Span<byte> d, ref int at, in Frame f)
    {
        F32(d, ref at, f.Origin.X);
        F32(d, ref at, f.Origin.Y);
        F32(d, ref at, f.Origin.Z);
        F32(d, ref at, f.Qw);
        F32(d, ref at, f.Qx);
        F32(d, ref at, f.Qy);
        F32(d, ref at, f.Qz);
    }
}
