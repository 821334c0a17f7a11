using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Cells;

// The cell's object list and its voyeur table: the objects standing in the cell (retail object_list), and the objects whose
// global detection watches it (retail voyeur_table), told when an object enters or leaves the cell.
public abstract partial class ObjCell
{
    /// <summary>Growth step of the object list. Retail grows by 5 (<c>add_object</c>, acclient.c:347702).</summary>
    internal const int ObjectListGrowth = 5;

    // Allocated with the cell (one growth step), so that the first objects to walk in do not allocate inside a tick.
    private PhysicsObj[] _objectList = new PhysicsObj[ObjectListGrowth];

    // Retail LongNIValHash<GlobalVoyeurInfo> voyeur_table (32 buckets), null until the first add_voyeur. Kept as one list:
    // each voyeur's reports go to its own detection table, so the order voyeurs are told in cannot be seen.
    private List<GlobalVoyeurInfo>? _voyeurTable;

    /// <summary>Number of objects in the cell. Retail: <c>num_objects</c>.</summary>
    internal int NumObjects { get; private set; }

    /// <summary>The objects in the cell, <see cref="NumObjects"/> long, in retail's list order (swap-removed).</summary>
    internal ReadOnlySpan<PhysicsObj> ObjectList => _objectList.AsSpan(0, NumObjects);

    /// <summary>Number of voyeurs watching the cell.</summary>
    internal int NumVoyeurs => _voyeurTable?.Count ?? 0;

    /// <summary>The reference count of voyeur <paramref name="voyeurId"/> in this cell, 0 when it does not watch it.</summary>
    internal int VoyeurRefCount(uint voyeurId)
    {
        int i = FindVoyeur(voyeurId);
        return i < 0 ? 0 : _voyeurTable![i].RefCount;
    }

    /// <summary>Appends <paramref name="obj"/> to the object list; unless it has id 0, a parent or is hidden, every voyeur
    /// other than itself is told it entered.</summary>
    // retail: CObjCell::add_object (acclient.c:347702)
    internal void AddObject(PhysicsObj obj)
    {
        if (NumObjects >= _objectList.Length)
        {
            Array.Resize(ref _objectList, _objectList.Length + ObjectListGrowth);
        }

        _objectList[NumObjects++] = obj;
        if (obj.Id != 0 && obj.Parent is null && (obj.State & PhysicsState.Hidden) == 0)
        {
            TellVoyeurs(obj, DetectionStatus.Entered);
        }
    }

    /// <summary>Removes <paramref name="obj"/> from the object list, the last object filling its slot (retail's
    /// swap-remove), and tells the voyeurs it left. Nothing when it is not in the list.</summary>
    /// <remarks>Retail shrinks the array when more than 10 slots are spare; the port keeps its capacity
    /// (docs/divergences.md, "Cell object lists keep their capacity").</remarks>
    // retail: CObjCell::remove_object (acclient.c:347764)
    internal void RemoveObject(PhysicsObj obj)
    {
        int n = NumObjects;
        for (int i = 0; i < n; i++)
        {
            if (_objectList[i] == obj)
            {
                NumObjects = n - 1;
                _objectList[i] = _objectList[n - 1];
                _objectList[n - 1] = null!;
                UpdateAllVoyeur(obj, DetectionStatus.Left);
                return;
            }
        }
    }

    /// <summary>The object with id <paramref name="objectId"/> in the cell, or null.</summary>
    // retail: CObjCell::get_object (acclient.c:347258)
    internal PhysicsObj? GetObject(uint objectId)
    {
        for (int i = 0; i < NumObjects; i++)
        {
            PhysicsObj o = _objectList[i];
            if (o is not null && o.Id == objectId)
            {
                return o;
            }
        }

        return null;
    }

    /// <summary>
    /// Object <paramref name="voyeur"/>'s global detection watches this cell: a voyeur already watching gets one more
    /// reference; a new one gets reference 1 and is told every object already in the cell entered (id not 0, no parent,
    /// itself excepted; hidden objects included, as retail). False for voyeur id 0.
    /// </summary>
    // retail: CObjCell::add_voyeur (acclient.c:347422)
    internal bool AddVoyeur(PhysicsObj voyeur)
    {
        uint voyeurId = voyeur.Id;
        if (voyeurId == 0)
        {
            return false;
        }

        _voyeurTable ??= new List<GlobalVoyeurInfo>(4);
        int at = FindVoyeur(voyeurId);
        if (at >= 0)
        {
            GlobalVoyeurInfo v = _voyeurTable[at];
            v.RefCount++;
            _voyeurTable[at] = v;
            return true;
        }

        _voyeurTable.Add(new GlobalVoyeurInfo(voyeurId, 1));
        for (int i = 0; i < NumObjects; i++)
        {
            PhysicsObj o = _objectList[i];
            if (o.Id != voyeurId && o.Id != 0 && o.Parent is null)
            {
                voyeur.World.GetObjectById(voyeurId)?.ReceiveDetectionUpdate(new DetectionInfo(o.Id, DetectionStatus.Entered));
            }
        }

        return true;
    }

    /// <summary>
    /// One reference of <paramref name="voyeur"/> less; at 0 it stops watching the cell and is told every object in
    /// the cell left (id not 0, no parent, itself excepted). False when it was not watching.
    /// </summary>
    // retail: CObjCell::remove_voyeur (acclient.c:347501)
    internal bool RemoveVoyeur(PhysicsObj voyeur)
    {
        uint voyeurId = voyeur.Id;
        int at = FindVoyeur(voyeurId);
        if (at < 0)
        {
            return false;
        }

        GlobalVoyeurInfo v = _voyeurTable![at];
        int refCount = v.RefCount - 1;
        if (refCount <= 0)
        {
            _voyeurTable.RemoveAt(at);
            for (int i = 0; i < NumObjects; i++)
            {
                PhysicsObj o = _objectList[i];
                if (o.Id != voyeurId && o.Id != 0 && o.Parent is null)
                {
                    voyeur.World.GetObjectById(voyeurId)?.ReceiveDetectionUpdate(new DetectionInfo(o.Id, DetectionStatus.Left));
                }
            }
        }
        else
        {
            v.RefCount = refCount;
            _voyeurTable[at] = v;
        }

        return true;
    }

    /// <summary>Tells every voyeur (other than the object itself) that <paramref name="obj"/> entered or left; nothing for an
    /// object with id 0 or a parent, nor for a hidden object entering.</summary>
    // retail: CObjCell::update_all_voyeur (acclient.c:347568)
    internal void UpdateAllVoyeur(PhysicsObj obj, DetectionStatus type)
    {
        if (obj.Id != 0 && obj.Parent is null && ((obj.State & PhysicsState.Hidden) == 0 || type != DetectionStatus.Entered))
        {
            TellVoyeurs(obj, type);
        }
    }

    /// <summary>The object was hidden: the voyeurs are told it left.</summary>
    // retail: CObjCell::hide_object (acclient.c:347616)
    internal void HideObject(PhysicsObj obj) => UpdateAllVoyeur(obj, DetectionStatus.Left);

    /// <summary>The object was unhidden: unless it has id 0, a parent or is (still) hidden, the voyeurs are told it
    /// entered.</summary>
    // retail: CObjCell::unhide_object (acclient.c:347622)
    internal void UnhideObject(PhysicsObj obj)
    {
        if (obj.Id != 0 && obj.Parent is null && (obj.State & PhysicsState.Hidden) == 0)
        {
            TellVoyeurs(obj, DetectionStatus.Entered);
        }
    }

    // The voyeur loop of add_object, update_all_voyeur and unhide_object: each voyeur other than the object, found by id.
    private void TellVoyeurs(PhysicsObj obj, DetectionStatus status)
    {
        List<GlobalVoyeurInfo>? table = _voyeurTable;
        if (table is null)
        {
            return;
        }

        for (int i = 0; i < table.Count; i++)
        {
            uint voyeurId = table[i].ObjectIid;
            if (obj.Id != voyeurId)
            {
                obj.World.GetObjectById(voyeurId)?.ReceiveDetectionUpdate(new DetectionInfo(obj.Id, status));
            }
        }
    }

    private int FindVoyeur(uint voyeurId)
    {
        List<GlobalVoyeurInfo>? table = _voyeurTable;
        if (table is null)
        {
            return -1;
        }

        for (int i = 0; i < table.Count; i++)
        {
            if (table[i].ObjectIid == voyeurId)
            {
                return i;
            }
        }

        return -1;
    }

    // Retail GlobalVoyeurInfo (object_iid, type, ref_count); its type (the cylinder's detection_type) is never read by the
    // client, so it is not kept.
    private struct GlobalVoyeurInfo
    {
        public GlobalVoyeurInfo(uint objectIid, int refCount)
        {
            ObjectIid = objectIid;
            RefCount = refCount;
        }

        public uint ObjectIid;
        public int RefCount;
    }
}
