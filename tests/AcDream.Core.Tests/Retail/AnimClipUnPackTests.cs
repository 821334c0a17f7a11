using System;
using System.Numerics;
using AcDream.Core.Fixtures.Animation;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Tests.Support;
using AcDream.Core.Physics.Data;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// CAnimation::UnPack (acclient.c:334085), AnimFrame::UnPack (acclient.c:333869), CAnimHook::UnPackHook
/// (acclient.c:342736) and each hook type's UnPack, AnimData::UnPack (acclient.c:341178): bytes written to the decompiled
/// layout with <see cref="RetailDataWriter"/> and read back, one field group at a time.
/// </summary>
public class AnimClipUnPackTests
{
    private static RetailDataWriter Header(uint id, uint flags, uint numParts, uint numFrames) =>
        new RetailDataWriter().UInt32(id).UInt32(flags).UInt32(numParts).UInt32(numFrames);

    [Fact]
    public void Constants_DefaultFramerateAndTweakedSoundPriority()
    {
        // AnimData::AnimData stores 1106247680 = 0x41F00000 (30.0f); SoundTweakedHook's priority 1063675494 = 0x3F666666.
        Assert.Equal(0x41F00000u, BitConverter.SingleToUInt32Bits(AnimData.DefaultFramerate));
        Assert.Equal(0x41F00000u, BitConverter.SingleToUInt32Bits(AnimData.Default.Framerate));
        Assert.Equal(-1, AnimData.Default.HighFrame);
        Assert.Equal(0x461C4000u, BitConverter.SingleToUInt32Bits(AnimData.MaxFramerate)); // 10000.0f
        byte[] bytes = Header(1, 2, 0, 1).UInt32(1).UInt32((uint)AnimHookType.SoundTweaked).Int32(0).UInt32(7).ToArray();
        // Fields cut short: a format error, not the defaults; the defaults are checked on a fresh hook instead.
        Assert.Throws<RetailDataFormatException>(() => AnimClip.UnPack(bytes));
        Assert.Equal(0x3F666666u, BitConverter.SingleToUInt32Bits(new SoundTweakedHook().Priority));
        Assert.Equal(uint.MaxValue, new TextureVelocityPartHook().PartIndex);
        Assert.Equal(AnimHookDirection.Unknown, new NoOpHook().Direction);
    }

    [Fact]
    public void HeaderOnly_NoFrames()
    {
        AnimClip a = AnimClip.UnPack(Header(0x03000123, 0, 5, 0).ToArray());
        Assert.Equal(0x03000123u, a.Id);
        Assert.Equal(5, a.NumParts);
        Assert.Equal(0, a.NumFrames);
        Assert.False(a.HasPosFrames);
        Assert.False(a.HasHooks);
        Assert.True(a.PosFrames.IsEmpty);
    }

    [Fact]
    public void PosFramesAndPartFrames_ReadAsStored()
    {
        // A quaternion 0.0005 short of unit length is valid (|q|² = 0.999000... within 0.001 of 1) and kept unnormalised.
        float w = 0.9995f;
        byte[] bytes = Header(7, 1 | 2, 2, 2)
            .Frame(new Vector3(1f, 2f, 3f), new Quaternion(0f, 0f, 0f, w))
            .Frame(new Vector3(-1f, 0.5f, 0f), Quaternion.Identity)
            // frame 0: two parts, no hooks
            .Frame(new Vector3(0f, 0f, 1f), Quaternion.Identity).Frame(new Vector3(0f, 0f, 2f), Quaternion.Identity).UInt32(0)
            // frame 1: two parts, no hooks
            .Frame(new Vector3(0f, 1f, 1f), Quaternion.Identity).Frame(new Vector3(0f, 1f, 2f), new Quaternion(0f, 0f, 1f, 0f)).UInt32(0)
            .ToArray();
        AnimClip a = AnimClip.UnPack(bytes);
        Assert.True(a.HasPosFrames);
        Assert.True(a.HasHooks); // the flag, though no frame has one
        Assert.Equal(2, a.PosFrames.Length);
        Assert.Equal(new Vector3(1f, 2f, 3f), a.PosFrames[0].Origin);
        Assert.Equal(BitConverter.SingleToUInt32Bits(w), BitConverter.SingleToUInt32Bits(a.PosFrames[0].Qw));
        Assert.Equal(new Vector3(-1f, 0.5f, 0f), a.PosFrames[1].Origin);
        Assert.Equal(2, a.PartFrames.Length);
        Assert.Equal(2, a.PartFrames[1].NumParts);
        Assert.Equal(new Vector3(0f, 1f, 2f), a.PartFrames[1].Frames[1].Origin);
        Assert.Equal(1f, a.PartFrames[1].Frames[1].Qz);
        Assert.Null(a.PartFrames[0].Hooks);
    }

    [Fact]
    public void Hooks_EveryTypeRoundTrips_InDataOrder_WithPadding()
    {
        var w = Header(9, 2, 0, 1).UInt32(26);
        void Hook(AnimHookType t, AnimHookDirection d) => w.UInt32((uint)t).Int32((int)d);
        Hook(AnimHookType.NoOp, AnimHookDirection.Both);
        Hook(AnimHookType.Sound, AnimHookDirection.Forward); w.UInt32(0x0A000011);
        Hook(AnimHookType.SoundTable, AnimHookDirection.Backward); w.UInt32(0x22);
        Hook(AnimHookType.Attack, AnimHookDirection.Both); w.Int32(3).Single(-1f).Single(1f).Single(1f).Single(1f).Single(2.5f).Single(1.75f);
        // ReplaceObject, short id: part byte 4, id 0x0123: body 3 bytes, padded by 1.
        Hook(AnimHookType.ReplaceObject, AnimHookDirection.Both); w.Byte(4).UInt16(0x0123).Align4();
        Hook(AnimHookType.Ethereal, AnimHookDirection.Both); w.Int32(1);
        Hook(AnimHookType.TransparentPart, AnimHookDirection.Both); w.UInt32(2).Single(0f).Single(0.5f).Single(1f);
        Hook(AnimHookType.Luminous, AnimHookDirection.Both); w.Single(0.25f).Single(0.75f).Single(2f);
        Hook(AnimHookType.LuminousPart, AnimHookDirection.Both); w.UInt32(1).Single(1f).Single(0f).Single(0.5f);
        Hook(AnimHookType.Diffuse, AnimHookDirection.Both); w.Single(0.125f).Single(0.25f).Single(3f);
        Hook(AnimHookType.DiffusePart, AnimHookDirection.Both); w.UInt32(5).Single(0.5f).Single(1f).Single(4f);
        Hook(AnimHookType.Scale, AnimHookDirection.Both); w.Single(2f).Single(0.5f);
        Hook(AnimHookType.CreateParticle, AnimHookDirection.Both); w.UInt32(0x32000001).UInt32(6).Frame(new Vector3(0f, 0f, 1f), Quaternion.Identity).UInt32(77);
        Hook(AnimHookType.DestroyParticle, AnimHookDirection.Both); w.UInt32(77);
        Hook(AnimHookType.StopParticle, AnimHookDirection.Both); w.UInt32(78);
        Hook(AnimHookType.NoDraw, AnimHookDirection.Both); w.Int32(1);
        Hook(AnimHookType.DefaultScript, AnimHookDirection.Both);
        Hook(AnimHookType.DefaultScriptPart, AnimHookDirection.Both); w.UInt32(3);
        Hook(AnimHookType.CallPes, AnimHookDirection.Both); w.UInt32(0x33000005).Single(0.5f);
        Hook(AnimHookType.Transparent, AnimHookDirection.Both); w.Single(0f).Single(1f).Single(0.25f);
        // SoundTweaked: id, then probability, priority, volume.
        Hook(AnimHookType.SoundTweaked, AnimHookDirection.Both); w.UInt32(0x0A000012).Single(0.5f).Single(0.25f).Single(0.75f);
        Hook(AnimHookType.SetOmega, AnimHookDirection.Both); w.Single(0f).Single(0f).Single(1.5f);
        Hook(AnimHookType.TextureVelocity, AnimHookDirection.Both); w.Single(0.5f).Single(-0.5f);
        Hook(AnimHookType.TextureVelocityPart, AnimHookDirection.Both); w.UInt32(2).Single(1f).Single(2f);
        Hook(AnimHookType.SetLight, AnimHookDirection.Both); w.Int32(0);
        // ReplaceObject, long id: 0x8000 | high word 0x0001, then low word 0x2345: id 0x01000000 + 0x00012345; body 5 bytes,
        // padded by 3.
        Hook(AnimHookType.ReplaceObject, (AnimHookDirection)7); w.Byte(9).UInt16(0x8001).UInt16(0x2345).Align4();
        AnimClip a = AnimClip.UnPack(w.ToArray());

        AnimFrame frame = a.PartFrames[0];
        Assert.Equal(26, frame.NumFrameHooks);
        AnimHook? h = frame.Hooks;
        T Next<T>(AnimHookDirection dir = AnimHookDirection.Both)
            where T : AnimHook
        {
            T t = Assert.IsType<T>(h);
            Assert.Equal(dir, t.Direction);
            h = h!.Next;
            return t;
        }

        Assert.Equal(AnimHookType.NoOp, Next<NoOpHook>().HookType);
        Assert.Equal(0x0A000011u, Next<SoundHook>(AnimHookDirection.Forward).SoundId);
        Assert.Equal(0x22u, Next<SoundTableHook>(AnimHookDirection.Backward).SoundType);
        Assert.Equal(new AttackCone(3, new Vector2(-1f, 1f), new Vector2(1f, 1f), 2.5f, 1.75f), Next<AttackHook>().Cone);
        ReplaceObjectHook r = Next<ReplaceObjectHook>();
        Assert.Equal(4u, r.PartIndex);
        Assert.Equal(0x01000123u, r.PartId);
        Assert.True(Next<EtherealHook>().Ethereal);
        TransparentPartHook tp = Next<TransparentPartHook>();
        Assert.Equal((2u, 0f, 0.5f, 1f), (tp.Part, tp.Start, tp.End, tp.Time));
        LuminousHook l = Next<LuminousHook>();
        Assert.Equal((0.25f, 0.75f, 2f), (l.Start, l.End, l.Time));
        LuminousPartHook lp = Next<LuminousPartHook>();
        Assert.Equal((1u, 1f, 0f, 0.5f), (lp.Part, lp.Start, lp.End, lp.Time));
        DiffuseHook d = Next<DiffuseHook>();
        Assert.Equal((0.125f, 0.25f, 3f), (d.Start, d.End, d.Time));
        DiffusePartHook dp = Next<DiffusePartHook>();
        Assert.Equal((5u, 0.5f, 1f, 4f), (dp.Part, dp.Start, dp.End, dp.Time));
        ScaleHook s = Next<ScaleHook>();
        Assert.Equal((2f, 0.5f), (s.End, s.Time));
        CreateParticleHook cp = Next<CreateParticleHook>();
        Assert.Equal((0x32000001u, 6u, 77u), (cp.EmitterInfoId, cp.PartIndex, cp.EmitterId));
        Assert.Equal(new Vector3(0f, 0f, 1f), cp.Offset.Origin);
        Assert.Equal(77u, Next<DestroyParticleHook>().EmitterId);
        Assert.Equal(78u, Next<StopParticleHook>().EmitterId);
        Assert.True(Next<NoDrawHook>().NoDraw);
        Assert.Equal(AnimHookType.DefaultScript, Next<DefaultScriptHook>().HookType);
        Assert.Equal(3u, Next<DefaultScriptPartHook>().PartIndex);
        CallPesHook pes = Next<CallPesHook>();
        Assert.Equal((0x33000005u, 0.5f), (pes.ScriptId, pes.Pause));
        TransparentHook t = Next<TransparentHook>();
        Assert.Equal((0f, 1f, 0.25f), (t.Start, t.End, t.Time));
        SoundTweakedHook st = Next<SoundTweakedHook>();
        Assert.Equal((0x0A000012u, 0.5f, 0.25f, 0.75f), (st.SoundId, st.Probability, st.Priority, st.Volume));
        Assert.Equal(new Vector3(0f, 0f, 1.5f), Next<SetOmegaHook>().Axis);
        TextureVelocityHook tv = Next<TextureVelocityHook>();
        Assert.Equal((0.5f, -0.5f), (tv.USpeed, tv.VSpeed));
        TextureVelocityPartHook tvp = Next<TextureVelocityPartHook>();
        Assert.Equal((2u, 1f, 2f), (tvp.PartIndex, tvp.USpeed, tvp.VSpeed));
        Assert.False(Next<SetLightHook>().LightsOn);
        ReplaceObjectHook r2 = Next<ReplaceObjectHook>((AnimHookDirection)7);
        Assert.Equal(9u, r2.PartIndex);
        Assert.Equal(0x01012345u, r2.PartId);
        Assert.Null(h);
        // Their packed sizes: 8 + 1 + 2 = 11 -> 12 for the short id, 8 + 1 + 4 = 13 -> 16 for the long one.
        Assert.Equal(12, AnimHookPack.PackSize(r));
        Assert.Equal(16, AnimHookPack.PackSize(r2));

        // CAnimHook::PackHook (acclient.c:342153) writes every hook back to the very bytes it was read from.
        byte[] original = w.ToArray();
        int hooksStart = 4 * 5; // id, flags, parts, frames, hook count
        byte[] packed = new byte[original.Length - hooksStart];
        int at = 0;
        for (AnimHook? p = frame.Hooks; p is not null; p = p.Next)
        {
            int before = at;
            AnimHookPack.PackHook(p, packed, ref at);
            Assert.Equal(AnimHookPack.PackSize(p), at - before);
        }

        Assert.Equal(packed.Length, at);
        Assert.Equal(original.AsSpan(hooksStart).ToArray(), packed);
        Assert.Throws<ArgumentException>(() =>
        {
            int o = 0;
            AnimHookPack.PackHook(frame.Hooks!.Next!, new byte[11], ref o); // a sound hook needs 12
        });
    }

    [Fact]
    public void HookTypes_AreRetailsValues()
    {
        Assert.Equal(0x13, (int)AnimHookType.CallPes);
        Assert.Equal(0x1A, (int)AnimHookType.CreateBlockingParticle);
        Assert.Equal(4, (int)AnimHookType.AnimDone);
        Assert.Equal(-1, (int)AnimHookDirection.Backward);
        Assert.Equal(-2, (int)AnimHookDirection.Unknown);
        Assert.Equal(AnimHookType.CreateBlockingParticle, new CreateBlockingParticleHook().HookType);
        Assert.IsAssignableFrom<CreateParticleHook>(new CreateBlockingParticleHook());
    }

    [Fact]
    public void PackSize_IsFieldsPlusTypeAndDirection_PaddedToFour()
    {
        // CAnimHook::PackSize (acclient.c:342142): pack_size + 8, rounded up to four.
        Assert.Equal(8, AnimHookPack.PackSize(new NoOpHook()));
        Assert.Equal(16, AnimHookPack.PackSize(new ScaleHook()));
        Assert.Equal(36, AnimHookPack.PackSize(new AttackHook()));
        Assert.Equal(48, AnimHookPack.PackSize(new CreateParticleHook()));
        Assert.Equal(12, AnimHookPack.PackSize(new ReplaceObjectHook())); // 3 + 8 = 11 -> 12
    }

    public static TheoryData<string, byte[]> BadEntries => new()
    {
        { "truncated header", new byte[] { 1, 0, 0, 0, 0, 0 } },
        { "frames beyond the bytes", Header(1, 0, 1, 0x7FFFFFFF).ToArray() },
        { "parts beyond the bytes", Header(1, 0, 0xFFFFFFFF, 1).ToArray() },
        { "hook count beyond the bytes", Header(1, 0, 0, 1).UInt32(0x10000000).ToArray() },
        { "unknown hook type", Header(1, 2, 0, 1).UInt32(1).UInt32(27).Int32(0).ToArray() },
        { "AnimDone hook in data", Header(1, 2, 0, 1).UInt32(1).UInt32(4).Int32(0).ToArray() },
        { "scale 0", Header(1, 2, 0, 1).UInt32(1).UInt32(12).Int32(0).Single(0f).Single(1f).ToArray() },
        { "translucency NaN", Header(1, 2, 0, 1).UInt32(1).UInt32(20).Int32(0).Single(float.NaN).Single(1f).Single(1f).ToArray() },
        { "omega infinite", Header(1, 2, 0, 1).UInt32(1).UInt32(22).Int32(0).Single(0f).Single(float.PositiveInfinity).Single(0f).ToArray() },
        { "pos frame not unit", Header(1, 1, 0, 1).Frame(Vector3.Zero, new Quaternion(0f, 0f, 0f, 0.9f)).UInt32(0).ToArray() },
        { "part frame NaN", Header(1, 0, 1, 1).Frame(new Vector3(float.NaN, 0f, 0f), Quaternion.Identity).UInt32(0).ToArray() },
        { "padding missing", Header(1, 2, 0, 1).UInt32(1).UInt32(5).Int32(0).Byte(1).UInt16(2).ToArray() },
    };

    [Theory]
    [MemberData(nameof(BadEntries))]
    public void BadBytes_AreAFormatErrorNamingTheStructure(string why, byte[] bytes)
    {
        RetailDataFormatException e = Assert.Throws<RetailDataFormatException>(() => AnimClip.UnPack(bytes));
        Assert.Equal("CAnimation", e.Structure);
        Assert.False(string.IsNullOrEmpty(why));
    }

    [Fact]
    public void AnimData_UnPack_IdLowHighFramerate()
    {
        byte[] bytes = new RetailDataWriter().UInt32(0x03000AAA).Int32(2).Int32(-1).Single(-15f).ToArray();
        var r = new RetailDataReader(bytes, "AnimData");
        AnimData d = AnimData.UnPack(ref r);
        Assert.Equal(new AnimData(0x03000AAA, 2, -1, -15f), d);
        Assert.Equal(16, r.Offset);
        byte[] bad = new RetailDataWriter().UInt32(1).Int32(0).Int32(0).Single(float.NaN).ToArray();
        Assert.Throws<RetailDataFormatException>(() =>
        {
            var rb = new RetailDataReader(bad, "AnimData");
            AnimData.UnPack(ref rb);
        });
        Assert.Equal(new AnimData(1, 0, 3, 60f), 2f * new AnimData(1, 0, 3, 30f));
    }

    [Fact]
    public void Library_ResolvesById()
    {
        var lib = new AnimationLibrary();
        AnimClip a = lib.Add(Header(0x03000001, 0, 1, 0).ToArray());
        Assert.Same(a, lib.GetAnimation(0x03000001));
        Assert.Null(lib.GetAnimation(0x03000002));
        Assert.Equal(1, lib.Count);
        Assert.Throws<RetailDataFormatException>(() => lib.Add(new byte[3]));
        Assert.Equal(1, lib.Count);
    }
}
