using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision;

internal sealed partial class SpherePath
{
    /// <summary>Places the local spheres at <see cref="CurrPos"/> into <see cref="GlobalCurrCenter"/>.</summary>
    // retail: SPHEREPATH::cache_global_curr_center (acclient.c:313696)
    public void CacheGlobalCurrCenter() => CacheGlobalCurrCenter(CurrPos.Frame);

    /// <summary>
    /// <see cref="CacheGlobalCurrCenter()"/> from <paramref name="f"/>, a frame with the bits of
    /// <see cref="CurrPos"/>'s (the one it was just copied from: reading the source of a fresh copy instead of the copy
    /// avoids waiting for the copy's stores).
    /// </summary>
    // retail: SPHEREPATH::cache_global_curr_center (acclient.c:313696)
    public void CacheGlobalCurrCenter(in Frame f)
    {
        for (int i = 0; i < NumSphere; i++)
        {
            Vector3 c = LocalSphere[i].Center;
            float x = (float)((double)c.X * f.M11 + (double)c.Y * f.M21 + (double)c.Z * f.M31 + f.Origin.X);
            float y = (float)((double)f.M32 * c.Z + (double)c.X * f.M12 + (double)f.M22 * c.Y + f.Origin.Y);
            double zs = (double)f.M33 * c.Z + (double)f.M23 * c.Y;
            double z = zs + (double)f.M13 * c.X + f.Origin.Z;
            GlobalCurrCenter[i] = new Vector3(x, y, (float)z);
        }
    }

    /// <summary>Places the local spheres and low point at <see cref="CheckPos"/> (a full recompute from the frame).</summary>
    // retail: SPHEREPATH::cache_global_sphere (acclient.c:313747), null-offset branch
    public void CacheGlobalSphere()
    {
        ref readonly Frame f = ref CheckPos.Frame;
        for (int i = 0; i < NumSphere; i++)
        {
            Vector3 c = LocalSphere[i].Center;
            float x = (float)((double)c.X * f.M11 + (double)c.Y * f.M21 + (double)c.Z * f.M31 + f.Origin.X);
            float y = (float)((double)f.M32 * c.Z + (double)c.X * f.M12 + (double)f.M22 * c.Y + f.Origin.Y);
            double zs = (double)f.M33 * c.Z + (double)f.M13 * c.X;
            double z = zs + (double)f.M23 * c.Y + f.Origin.Z;
            GlobalSphere[i] = new Sphere(new Vector3(x, y, (float)z), LocalSphere[i].Radius);
        }

        Vector3 l = LocalLowPoint;
        float lx = (float)((double)f.M31 * l.Z + (double)f.M11 * l.X + (double)f.M21 * l.Y + f.Origin.X);
        float ly = (float)((double)f.M32 * l.Z + (double)f.M12 * l.X + (double)f.M22 * l.Y + f.Origin.Y);
        float lz = (float)((double)f.M33 * l.Z + (double)f.M13 * l.X + (double)f.M23 * l.Y + f.Origin.Z);
        GlobalLowPoint = new Vector3(lx, ly, lz);
    }

    /// <summary>
    /// <see cref="CacheGlobalSphere()"/> for a check position whose frame is the one <see cref="GlobalCurrCenter"/> was
    /// last computed from (the caller guarantees it): the sphere centres are taken from <see cref="GlobalCurrCenter"/>
    /// when that gives the same bits, else recomputed. Both functions compute x and y with the same expressions; their z
    /// sums differ only in the order of the terms M13·c.x and M23·c.y, so when both products are zero (a centre on the
    /// local z axis, or a frame that only turns about z) both give ((M33·c.z + 0) + 0) + origin.z, whatever the signs of
    /// the zeros. The low point is computed as always.
    /// </summary>
    /// <param name="f">A frame with the bits of <see cref="CheckPos"/>'s (CheckPos's own, or the one it was just copied
    /// from).</param>
    // non-retail: SPHEREPATH::cache_global_sphere (acclient.c:313747) reusing cache_global_curr_center's equal result
    public void CacheGlobalSphereFromCurrCenter(in Frame f)
    {
        if (!ReferencePaths)
        {
            for (int i = 0; i < NumSphere; i++)
            {
                Vector3 c = LocalSphere[i].Center;
                if ((double)f.M13 * c.X != 0.0 || (double)f.M23 * c.Y != 0.0)
                {
                    CacheGlobalSphere();
                    return;
                }
            }

            for (int i = 0; i < NumSphere; i++)
            {
                GlobalSphere[i] = new Sphere(GlobalCurrCenter[i], LocalSphere[i].Radius);
            }

            Vector3 l = LocalLowPoint;
            float lx = (float)((double)f.M31 * l.Z + (double)f.M11 * l.X + (double)f.M21 * l.Y + f.Origin.X);
            float ly = (float)((double)f.M32 * l.Z + (double)f.M12 * l.X + (double)f.M22 * l.Y + f.Origin.Y);
            float lz = (float)((double)f.M33 * l.Z + (double)f.M13 * l.X + (double)f.M23 * l.Y + f.Origin.Z);
            GlobalLowPoint = new Vector3(lx, ly, lz);
            return;
        }

        CacheGlobalSphere();
    }

    /// <summary>Moves the cached global spheres and low point by <paramref name="offset"/> (no recompute from the frame).</summary>
    // retail: SPHEREPATH::cache_global_sphere (acclient.c:313747), offset branch
    public void CacheGlobalSphere(Vector3 offset)
    {
        for (int i = 0; i < NumSphere; i++)
        {
            ref Sphere s = ref GlobalSphere[i];
            s.Center = new Vector3(s.Center.X + offset.X, offset.Y + s.Center.Y, offset.Z + s.Center.Z);
        }

        GlobalLowPoint = new Vector3(offset.X + GlobalLowPoint.X, offset.Y + GlobalLowPoint.Y, offset.Z + GlobalLowPoint.Z);
    }

    /// <summary>
    /// Expresses the spheres at <see cref="CheckPos"/> and <see cref="CurrPos"/> in the local space of <paramref name="p"/>
    /// divided by <paramref name="scale"/> (the space of a walkable polygon of a scaled object).
    /// </summary>
    // retail: SPHEREPATH::cache_localspace_sphere (acclient.c:313851)
    public void CacheLocalSpaceSphere(in Position p, float scale)
    {
        float inv = (float)(1.0 / scale);
        for (int i = 0; i < NumSphere; i++)
        {
            Vector3 c = LocalSphere[i].Center;
            Vector3 a = p.LocalToLocal(CheckPos, c);
            LocalSpaceSphere[i] = new Sphere(new Vector3(inv * a.X, inv * a.Y, inv * a.Z), inv * LocalSphere[i].Radius);
            Vector3 b = p.LocalToLocal(CurrPos, c);
            LocalSpaceCurrCenter[i] = new Vector3(inv * b.X, inv * b.Y, inv * b.Z);
        }

        LocalSpacePos = p;
        ref readonly Frame f = ref p.Frame;
        float zx = (float)(((double)f.M12 + f.M11) * 0.0 + f.M13);
        float zy = (float)(((double)f.M22 + f.M21) * 0.0 + f.M23);
        float zz = (float)(((double)f.M32 + f.M31) * 0.0 + f.M33);
        LocalSpaceZ = new Vector3(zx, zy, zz);
        Sphere s = LocalSpaceSphere[0];
        float ry = s.Radius * zy;
        float rz = s.Radius * zz;
        float lx = (float)((double)s.Center.X - (double)s.Radius * zx);
        float ly = s.Center.Y - ry;
        float lz = s.Center.Z - rz;
        LocalSpaceLowPoint = new Vector3(lx, ly, lz);
    }

    /// <summary>Moves the check position by <paramref name="offset"/> and invalidates the cell array.</summary>
    // retail: SPHEREPATH::add_offset_to_check_pos (acclient.c:311556; the CSphere.c copy with a radius argument, acclient.c:358525, is identical)
    public void AddOffsetToCheckPos(Vector3 offset)
    {
        CellArrayValid = false;
        Vector3 o = CheckPos.Frame.Origin;
        CheckPos.Frame.Origin = new Vector3(o.X + offset.X, offset.Y + o.Y, offset.Z + o.Z);
        CacheGlobalSphere(offset);
    }

    /// <summary>Sets the check position and cell and recomputes the global spheres.</summary>
    // retail: SPHEREPATH::set_check_pos (acclient.c:312090)
    public void SetCheckPos(in Position p, ObjCell? cell)
    {
        CheckPos = p;
        CheckCell = cell;
        CellArrayValid = false;
        CacheGlobalSphere();
    }

    /// <summary>Saves the check position and cell for <see cref="RestoreCheckPos"/>.</summary>
    // retail: SPHEREPATH::save_check_pos (acclient.c:312082)
    public void SaveCheckPos()
    {
        BackupCell = CheckCell;
        BackupCheckPos = CheckPos;
    }

    /// <summary>Returns to the saved check position and cell.</summary>
    // retail: SPHEREPATH::restore_check_pos (acclient.c:312527)
    public void RestoreCheckPos()
    {
        CheckPos = BackupCheckPos;
        CheckCell = BackupCell;
        CellArrayValid = false;
        CacheGlobalSphere();
    }

    /// <summary>
    /// Re-homes the check position into the landblock of <paramref name="cellId"/> (outdoor cells only: the origin and the
    /// global spheres move by the block offset), then sets the cell id.
    /// </summary>
    // retail: SPHEREPATH::adjust_check_pos (acclient.c:313961)
    public void AdjustCheckPos(uint cellId)
    {
        if ((cellId & 0xFFFF) < LandDefs.FirstEnvCell)
        {
            Vector3 offset = LandDefs.GetBlockOffset(cellId, CheckPos.ObjCellId);
            CacheGlobalSphere(offset);
            Vector3 o = CheckPos.Frame.Origin;
            CheckPos.Frame.Origin = new Vector3(offset.X + o.X, offset.Y + o.Y, offset.Z + o.Z);
        }

        CheckPos.ObjCellId = cellId;
    }

    /// <summary>Sets the sphere tested against the walkable polygon.</summary>
    // retail: SPHEREPATH::set_walkable_check_pos (acclient.c:311550)
    public void SetWalkableCheckPos(in Sphere sphere) => WalkableCheckPos = sphere;

    /// <summary>Records the walkable polygon a BSP found under the sphere.</summary>
    // retail: SPHEREPATH::set_walkable (acclient.c:361093)
    public void SetWalkable(in Sphere sphere, Polygon poly, Vector3 zAxis, in Position localPos, float scale)
    {
        WalkableCheckPos = sphere;
        Walkable = poly;
        WalkableUp = zAxis;
        WalkablePos = localPos;
        WalkableScale = scale;
    }

    /// <summary>Records a BSP's request for a step-up check and backs up the check position.</summary>
    // retail: SPHEREPATH::set_collide (acclient.c:359049)
    public void SetCollide(Vector3 collisionNormal)
    {
        Collide = true;
        BackupCell = CheckCell;
        BackupCheckPos = CheckPos;
        StepUpNormal = collisionNormal;
        WalkInterp = 1f;
    }

    /// <summary>True when a surface whose up-component is <paramref name="zval"/> is steep enough to stand on now.</summary>
    // retail: SPHEREPATH::is_walkable_allowable (acclient.c:358474)
    public bool IsWalkableAllowable(float zval) => zval > (double)WalkableAllowance;

    /// <summary>The movement block offset from the current to the check position's landblock.</summary>
    // retail: SPHEREPATH::get_curr_pos_check_pos_block_offset (acclient.c:311718)
    public Vector3 GetCurrPosCheckPosBlockOffset() => LandDefs.GetBlockOffset(CurrPos.ObjCellId, CheckPos.ObjCellId);
}
