using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects;

// The object's collision table: the objects it is touching, for once-per-contact reports.
public sealed partial class PhysicsObj
{
    private CollisionRecord[] _collisionTable = Array.Empty<CollisionRecord>();

    /// <summary>How long a touch stays in the collision table without being refreshed, seconds of physics time (an ethereal
    /// object's touch ends as soon as the clock moves on). Retail: the <c>&gt; 1.0</c> test of
    /// <c>report_collision_end</c> (acclient.c:321712).</summary>
    public const double CollisionRecordLifetime = 1.0;

    /// <summary>Number of entries in the collision table.</summary>
    public int NumCollisionRecords { get; private set; }

    /// <summary>The objects this object is touching (or touched within the last second), in insertion order (retail keeps
    /// a hash table, <c>collision_table</c>; its iteration order is not reproduced).</summary>
    public ReadOnlySpan<CollisionRecord> CollisionRecords => _collisionTable.AsSpan(0, NumCollisionRecords);

    /// <summary>Adds or refreshes the record for <paramref name="objectId"/>. Returns true when it already existed.</summary>
    // retail: LongNIValHash<CollisionRecord>::clobber, as called by track_object_collision (acclient.c:321216)
    internal bool ClobberCollisionRecord(uint objectId, double touchedTime, bool ethereal)
    {
        for (int i = 0; i < NumCollisionRecords; i++)
        {
            if (_collisionTable[i].ObjectId == objectId)
            {
                _collisionTable[i].TouchedTime = touchedTime;
                _collisionTable[i].Ethereal = ethereal;
                return true;
            }
        }

        if (NumCollisionRecords == _collisionTable.Length)
        {
            // Retail's table starts with 4 buckets; growth allocates only when more objects touch than ever before (the first
            // touch makes the table, as retail's first track_object_collision does).
            Array.Resize(ref _collisionTable, _collisionTable.Length == 0 ? 4 : _collisionTable.Length * 2);
        }

        _collisionTable[NumCollisionRecords++] = new CollisionRecord { ObjectId = objectId, TouchedTime = touchedTime, Ethereal = ethereal };
        return false;
    }

    /// <summary>Removes the record at <paramref name="index"/>, keeping the order of the others.</summary>
    internal void RemoveCollisionRecordAt(int index)
    {
        NumCollisionRecords--;
        Array.Copy(_collisionTable, index + 1, _collisionTable, index, NumCollisionRecords - index);
    }

    /// <summary>
    /// Where <paramref name="p"/> lies around this object of height <paramref name="height"/>: bit 0x10 in front (local
    /// x &gt;= 0) else 0x8; 0x20 right (y &gt;= 0) else 0x40; 0x1 high (z &gt;= 2/3 h), 0x2 middle, 0x4 low (z &lt; h/3).
    /// </summary>
    // retail: Position::determine_quadrant (acclient.c:467065)
    public static int DetermineQuadrant(in Position self, float height, in Position p)
    {
        Vector3 hit = self.LocalToLocal(p, Vector3.Zero);
        int q = hit.X >= 0.0 ? 16 : 8;
        q |= hit.Y >= 0.0 ? 0x20 : 0x40;
        if (height * 0.333333333 <= hit.Z)
        {
            return q | (height * 0.66666667 <= hit.Z ? 1 : 2);
        }

        return q | 4;
    }
}
