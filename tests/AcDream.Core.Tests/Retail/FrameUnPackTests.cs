using System;
using System.Buffers.Binary;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>Frame::UnPack</c> (acclient.c:357132) copies the origin and the four quaternion floats as stored, tests
/// <c>Frame::IsValid</c> (357024) and calls <c>Frame::cache</c>; it never normalises (no <c>set_rotate</c>). Every frame a
/// data-file structure stores through it keeps its bits: setup holding locations and lights (<c>CSetup::UnPack</c> 335520),
/// the cell frame (<c>CEnvCell::UnPack</c> 349133), landblock objects (<c>CLandBlockInfo::UnPack</c> 351048) and the
/// <c>CreateParticleHook</c> offset (343212).
/// </summary>
public class FrameUnPackTests
{
    // |q|² = 0.8003² + 0.6002² = 1.000720…: valid (within 5 × 0.0002 of 1) and not a unit quaternion, so set_rotate would
    // change both components (to about 0.80001 and 0.59998).
    private const float Qw = 0.8003f, Qz = 0.6002f;

    private static void Quaternion(byte[] b, int at)
    {
        BinaryPrimitives.WriteSingleLittleEndian(b.AsSpan(at), Qw);
        BinaryPrimitives.WriteSingleLittleEndian(b.AsSpan(at + 4), 0f);
        BinaryPrimitives.WriteSingleLittleEndian(b.AsSpan(at + 8), 0f);
        BinaryPrimitives.WriteSingleLittleEndian(b.AsSpan(at + 12), Qz);
    }

    private static void AssertStored(in Frame f)
    {
        Assert.Equal(Qw, f.Qw);
        Assert.Equal(0f, f.Qx);
        Assert.Equal(0f, f.Qy);
        Assert.Equal(Qz, f.Qz);
        // Frame::cache from the stored (unnormalised) values: m11 = 1 - yc - zd with zd = qz (qz + qz) in double, yc = 0;
        // m12 = xc + wd with wd = qw (qz + qz), xc = 0.
        Assert.Equal((float)(1.0 - 0.0 - Qz * ((double)Qz + Qz)), f.RotationMatrix.M11);
        Assert.Equal((float)(0.0 + Qw * ((double)Qz + Qz)), f.RotationMatrix.M12);
    }

    [Fact]
    public void TheCellFrame_KeepsItsStoredQuaternion()
    {
        // Entry id @0, flags @4, cell id @8, counts @12..16 (no surfaces), environment @16, structure @18, frame @20: the
        // origin @20, the quaternion @32.
        byte[] b = RetailEntries.EnvCell(0x80800100, 0, 0x0101, 0, Frame.Identity, []);
        Quaternion(b, 32);
        AssertStored(EnvCellEntry.UnPack(b).Frame);
    }

    [Fact]
    public void ALandblockObjectFrame_KeepsItsStoredQuaternion()
    {
        // Id @0, cell count @4, object count @8, object id @12, frame @16: the quaternion @28.
        byte[] b = RetailEntries.LandBlockInfo(0x8080FFFE, 0, [(0x01000001u, Frame.Identity)], []);
        Quaternion(b, 28);
        AssertStored(LandBlockInfoEntry.UnPack(b).Objects[0].Frame);
    }

    [Fact]
    public void SetupHoldingLocationAndLightFrames_KeepTheirStoredQuaternions()
    {
        // CSetup::UnPack with flags 0: id @0, flags @4, part count @8 (0), holding count @12 (1): key @16, part @20, frame @24
        // (quaternion @36); connection count @52, placement count @56, cylinder count @60, sphere count @64 (all 0); height,
        // radius, step up, step down @68..84; sorting and selection spheres @84..116; light count @116 (1): type @120,
        // frame @124 (quaternion @136), colour @152, intensity, falloff, cone angle @156..168; five ids @168..188.
        var b = new byte[188];
        BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(0), 0x02000001);
        BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(12), 1);
        BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(16), 2);
        Quaternion(b, 36);
        BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(116), 1);
        Quaternion(b, 136);
        SetupEntry s = SetupEntry.UnPack(b);
        Assert.Equal(2u, s.HoldingLocations[0].Key);
        AssertStored(s.HoldingLocations[0].Frame);
        AssertStored(s.Lights[0].Offset);
    }

    [Fact]
    public void TheCreateParticleHookOffset_KeepsItsStoredQuaternion()
    {
        // CAnimHook::UnPackHook: type @0, direction @4; CreateParticleHook::UnPack: emitter info id @8, part index @12,
        // offset frame @16 (quaternion @28), emitter id @44.
        var b = new byte[48];
        BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(0), (uint)AnimHookType.CreateParticle);
        Quaternion(b, 28);
        BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(44), 9);
        var r = new RetailDataReader(b, "CAnimation");
        var hook = Assert.IsType<CreateParticleHook>(AnimHook.UnPackHook(ref r));
        Assert.Equal(0, r.Remaining);
        Assert.Equal(9u, hook.EmitterId);
        AssertStored(hook.Offset);
    }
}
