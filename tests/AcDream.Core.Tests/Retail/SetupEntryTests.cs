using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CSetup::UnPack</c> (acclient.c:335520), a test per field group, the bytes written field by field in the order the
/// decompiled function reads them: id; flags; part count and ids; parent indices (flag 1); default scales (flag 2); holding
/// locations and connection points (count, then key, part, frame); placement frames (count, then key, one AFrame per part, hook
/// count); cylinder spheres (low point, radius, height); spheres; height, radius, step up, step down; sorting and selection
/// spheres; lights (type, frame, colour, intensity, falloff, cone angle); five default ids; 4-alignment.
/// </summary>
public class SetupEntryTests
{
    private static readonly Quaternion Yaw90 = new(0f, 0f, MathF.Sqrt(0.5f), MathF.Sqrt(0.5f));

    // A two-part setup with every group filled.
    internal static byte[] TwoPartSetup(uint flags = 0xF, uint hooks = 0)
    {
        var w = new RetailDataWriter();
        w.UInt32(0x02000123).UInt32(flags).UInt32(2).UInt32(0x01000010).UInt32(0x01000011);
        if ((flags & 1) != 0)
        {
            w.UInt32(0xFFFFFFFF).UInt32(0);
        }

        if ((flags & 2) != 0)
        {
            w.Vector3(new Vector3(1f, 1f, 1f)).Vector3(new Vector3(0.5f, 2f, 1.5f));
        }

        w.UInt32(1).UInt32(2).UInt32(1).Frame(new Vector3(0.1f, 0.2f, 0.3f), Quaternion.Identity); // holding location key 2 on part 1
        w.UInt32(0);                                                                             // no connection points
        w.UInt32(2);                                                                             // two placements
        w.UInt32(0x65).Frame(Vector3.Zero, Quaternion.Identity).Frame(new Vector3(0f, 0f, 1f), Yaw90).UInt32(hooks);
        for (uint h = 0; h < hooks; h++)
        {
            w.UInt32(6).Int32(1).Int32(1);   // EtherealHook (type 6), direction Forward (1), ethereal 1
        }
        w.UInt32(0).Frame(new Vector3(1f, 0f, 0f), Quaternion.Identity).Frame(Vector3.Zero, Quaternion.Identity).UInt32(0);
        w.UInt32(1).Vector3(new Vector3(0f, 0f, 0f)).Single(0.75f).Single(2f);                  // cylinder sphere r 0.75 h 2
        w.UInt32(2).Vector3(new Vector3(0f, 0f, 0.48f)).Single(0.48f).Vector3(new Vector3(0f, 0f, 1.2f)).Single(0.48f);
        w.Single(1.835f).Single(0.48f).Single(0.6f).Single(1.5f);                               // height, radius, up, down
        w.Vector3(new Vector3(0f, 0f, 0.9f)).Single(1f);                                         // sorting sphere
        w.Vector3(new Vector3(0f, 0f, 0.95f)).Single(1.1f);                                      // selection sphere
        w.UInt32(1).UInt32(3).Frame(new Vector3(0f, 0f, 2f), Quaternion.Identity).UInt32(0xFFFFCC00).Single(0.5f).Single(4f).Single(1f);
        w.UInt32(0x03000001).UInt32(0x33000002).UInt32(0x09000001).UInt32(0x20000003).UInt32(0x34000004);
        return w.Align4().ToArray();   // CSetup::UnPack (acclient.c:335520) rounds its cursor up to 4 at its end, always
    }

    [Fact]
    public void Parts_ParentIndices_AndDefaultScales()
    {
        SetupEntry s = SetupEntry.UnPack(TwoPartSetup());
        Assert.Equal(0x02000123u, s.Id);
        Assert.Equal(new uint[] { 0x01000010, 0x01000011 }, s.Parts.ToArray());
        Assert.Equal(new uint[] { 0xFFFFFFFF, 0 }, s.ParentIndices.ToArray());
        Assert.Equal(new Vector3(0.5f, 2f, 1.5f), s.DefaultScales[1]);
        Assert.True(s.AllowFreeHeading);   // flag 4
        Assert.True(s.HasPhysicsBsp);      // flag 8
    }

    [Fact]
    public void WithoutFlags1And2_NoParentsNorScalesAreRead()
    {
        // flags 0: the reads go from the part ids straight to the holding locations; everything after still lines up.
        SetupEntry s = SetupEntry.UnPack(TwoPartSetup(flags: 0));
        Assert.True(s.ParentIndices.IsEmpty);
        Assert.True(s.DefaultScales.IsEmpty);
        Assert.False(s.AllowFreeHeading);
        Assert.Equal(0x34000004u, s.DefaultPhysicsScriptTableId);
    }

    [Fact]
    public void HoldingLocations_AndPlacementFrames()
    {
        SetupEntry s = SetupEntry.UnPack(TwoPartSetup());
        Assert.Equal(new LocationInfo(2, 1, new Frame(new Vector3(0.1f, 0.2f, 0.3f), Quaternion.Identity)).Key, s.HoldingLocations[0].Key);
        Assert.Equal(1u, s.HoldingLocations[0].PartId);
        Assert.Equal(new Vector3(0.1f, 0.2f, 0.3f), s.HoldingLocations[0].Frame.Origin);
        Assert.True(s.ConnectionPoints.IsEmpty);
        Assert.Equal(2, s.PlacementFrames.Count);
        Frame[] resting = s.PlacementFrames[0x65];
        Assert.Equal(2, resting.Length);   // one frame per part (AnimFrame::UnPack with num_parts 2)
        Assert.Equal(new Vector3(0f, 0f, 1f), resting[1].Origin);
        Assert.Equal(new Vector3(1f, 0f, 0f), s.PlacementFrames[0][0].Origin);
    }

    [Fact]
    public void GetHoldingLocation_FindsByKey_OrNull()
    {
        SetupEntry s = SetupEntry.UnPack(TwoPartSetup());
        Assert.Equal(1u, s.GetHoldingLocation(2)!.Value.PartId);
        Assert.Null(s.GetHoldingLocation(3));
    }

    [Fact]
    public void CylinderSpheres_Spheres_AndSizes()
    {
        SetupEntry s = SetupEntry.UnPack(TwoPartSetup());
        // CCylSphere::UnPack: low point, then radius, then height.
        Assert.Equal(new CylSphere(Vector3.Zero, 0.75f, 2f), s.CylSpheres[0]);
        Assert.Equal(new Sphere(new Vector3(0f, 0f, 1.2f), 0.48f).Center, s.Spheres[1].Center);
        Assert.Equal(0x3EF5C28Fu, BitConverter.SingleToUInt32Bits(s.Spheres[1].Radius)); // 0.48f
        Assert.Equal(1.835f, s.Height);
        Assert.Equal(0.48f, s.Radius);
        Assert.Equal(0.6f, s.StepUpHeight);   // third float: step_up_height
        Assert.Equal(1.5f, s.StepDownHeight); // fourth: step_down_height
    }

    [Fact]
    public void SortingAndSelectionSpheres_Lights_AndDefaultIds()
    {
        SetupEntry s = SetupEntry.UnPack(TwoPartSetup());
        Assert.Equal(new Vector3(0f, 0f, 0.9f), s.SortingSphere.Center);
        Assert.Equal(1f, s.SortingSphere.Radius);
        Assert.Equal(1.1f, s.SelectionSphere.Radius);
        Assert.Equal(3u, s.Lights[0].Type);
        Assert.Equal(0xFFFFCC00u, s.Lights[0].Color);
        Assert.Equal(4f, s.Lights[0].Falloff);
        Assert.Equal(0x03000001u, s.DefaultAnimationId);
        Assert.Equal(0x33000002u, s.DefaultScriptId);
        Assert.Equal(0x09000001u, s.DefaultMotionTableId);
        Assert.Equal(0x20000003u, s.DefaultSoundTableId);
        Assert.Equal(0x34000004u, s.DefaultPhysicsScriptTableId);
    }

    [Fact]
    public void ToSetupPhysics_FeedsTheSimplePartArray_AsIs()
    {
        SetupEntry s = SetupEntry.UnPack(TwoPartSetup());
        SetupPhysics p = s.ToSetupPhysics();
        Assert.Equal(2, p.Spheres.Length);
        Assert.Equal(0.6f, p.StepUpHeight);
        var parts = new SimplePartArray(p, s.Parts.Length);
        Assert.Equal(2, parts.NumParts);
        Assert.Equal(0.6f, parts.StepUpHeight);
        Assert.Equal(1.5f, parts.StepDownHeight);
    }

    [Fact]
    public void AZeroRadiusSphere_IsAFormatErrorOnlyWhenTheLibraryTakesIt()
    {
        byte[] bytes = TwoPartSetup();
        // The second sphere's radius: after the cylinder sphere count at the shapes' start (+4 + 20), the sphere count (+4),
        // the first sphere (16) and the second centre (12).
        SetupEntry probe = SetupEntry.UnPack(bytes);
        int shapes = FindShapes(bytes);
        BitConverter.TryWriteBytes(bytes.AsSpan(shapes + 4 + 20 + 4 + 16 + 12), 0f);
        SetupEntry s = SetupEntry.UnPack(bytes);      // retail reads it
        Assert.Equal(0f, s.Spheres[1].Radius);
        var e = Assert.Throws<RetailDataFormatException>(() => s.ToSetupPhysics());
        Assert.Equal("CSetup", e.Structure);
        Assert.Equal(shapes, e.Offset);
        Assert.Equal(probe.Spheres.Length, s.Spheres.Length);
    }

    [Fact]
    public void APlacementFrameWithAHook_ReadsItThroughUnPackHook()
    {
        // Retail's AnimFrame::UnPack (acclient.c:333869) reads each placement's hooks with CAnimHook::UnPackHook (342736):
        // type 6 (Ethereal), direction 1 (Forward), then its int. The part frames are the same as without the hook.
        SetupEntry s = SetupEntry.UnPack(TwoPartSetup(hooks: 1));
        AnimFrame resting = s.PlacementAnimFrames[0x65];
        Assert.Equal(1, resting.NumFrameHooks);
        var hook = Assert.IsType<EtherealHook>(resting.Hooks);
        Assert.True(hook.Ethereal);
        Assert.Equal(AnimHookDirection.Forward, hook.Direction);
        Assert.Equal(new Vector3(0f, 0f, 1f), resting.Frames[1].Origin);
        Assert.Equal(new Vector3(0f, 0f, 1f), s.PlacementFrames[0x65][1].Origin);
        Assert.Equal(0, s.PlacementAnimFrames[0].NumFrameHooks);
    }

    [Fact]
    public void APlacementHookOfAnUnknownType_IsAFormatError_AtTheHook()
    {
        byte[] bytes = TwoPartSetup(hooks: 1);
        // id 4 + flags 4 + count 4 + parts 8 + parents 8 + scales 24 + holding 4 + 36 + connections 4 + placements 4 + key 4
        // + two frames 56 = 160: the hook count; the hook's type word at 164.
        BitConverter.TryWriteBytes(bytes.AsSpan(164), 99u);
        var e = Assert.Throws<RetailDataFormatException>(() => SetupEntry.UnPack(bytes));
        Assert.Equal(164, e.Offset);
    }

    [Fact]
    public void APartCountBeyondTheBytes_IsRefusedBeforeAnyAllocation()
    {
        var w = new RetailDataWriter();
        w.UInt32(0x02000001).UInt32(0).UInt32(0x40000000);
        var e = Assert.Throws<RetailDataFormatException>(() => SetupEntry.UnPack(w.ToArray()));
        Assert.Equal(8, e.Offset); // the part count's own field (id @0, flags @4, count @8): 0 bytes remain for 2^30 parts
        Assert.Contains("part count", e.Reason);
    }

    // The offset of the cylinder sphere count in TwoPartSetup(): 4 + 4 + 4 + 8 + 8 + 24 + 4 + 36 + 4 + 4 + (4 + 56 + 4) × 2.
    private static int FindShapes(byte[] _) => 4 + 4 + 4 + 8 + 8 + 24 + 4 + 36 + 4 + 4 + (4 + 56 + 4) * 2;
}
