using AcDream.Core.Physics.Spatial;
using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Retail's detection manager (<c>DetectionManager</c>, CDetectionCylsphere.c): an object's detection cylinders, each a radius
/// around the object watching one other object; once a second of physics time (<see cref="UpdateInterval"/>, from the
/// object's step) each cylinder is checked and the client's <see cref="IDetectionListener"/> told when its object came inside
/// (distance below the cylinder's radius plus the object's radius) or went outside (or is no longer in the world). Objects are
/// found by id in the world's object table (<see cref="World.PhysicsWorld.GetObjectById"/>). Set it on its object with
/// <see cref="PhysicsObj.DetectionManager"/>; an object without one costs nothing per tick.
/// </summary>
/// <remarks>A cylinder with object id 0 is retail's global detection: the detector watches, through the cells' voyeur tables,
/// every object in the loaded cells its radius reaches (the cell list refreshed once it moved 5 m), and each check reports
/// the objects that entered or left them (DetectionManager.Global.cs; docs/world.md).</remarks>
public sealed partial class DetectionManager : IDetectionManager
{
    /// <summary>Least physics time between two checks, seconds: 1.0 (<c>DetectionManager::CheckDetection</c>).</summary>
    internal const double UpdateInterval = 1.0;

    // Retail LongNIHash<DetectionCylsphere> detection_table: kept as one list in creation order (docs/divergences.md).
    private readonly List<DetectionCylsphere> _detectionTable = new(4);
    private readonly Stack<DetectionCylsphere> _free = new();

    // Retail SmartArray<unsigned long> pending_deletions.
    private readonly List<uint> _pendingDeletions = new(4);

    // Retail LongNIHash<DetectionInfo> detection_objects (global detection only; null until InitializeGlobalDetection).
    private Dictionary<uint, DetectionEntry>? _detectionObjects;
    private readonly Stack<DetectionEntry> _freeEntries = new();
    private uint _numPendingGlobalDetectUpdates;
    private bool _destroyed;

    /// <summary>Creates the manager of <paramref name="physicsObj"/>, reporting to <paramref name="listener"/>: no cylinders,
    /// last check at time 0. Assign it to <see cref="PhysicsObj.DetectionManager"/> of the same object.</summary>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    public DetectionManager(PhysicsObj physicsObj, IDetectionListener listener)
    {
        ArgumentNullException.ThrowIfNull(physicsObj);
        ArgumentNullException.ThrowIfNull(listener);
        PhysicsObj = physicsObj;
        Listener = listener;
        LastUpdateTime = 0.0;
    }

    /// <summary>The detecting object (retail <c>physobj</c>).</summary>
    public PhysicsObj PhysicsObj { get; }

    /// <summary>Where reports go (retail: the object's weenie).</summary>
    public IDetectionListener Listener { get; }

    /// <summary>Physics time of the last check (retail <c>last_update_time</c>).</summary>
    public double LastUpdateTime { get; private set; }

    /// <summary>Number of cylinders, those destroyed but not yet dropped (at the next check) included.</summary>
    public int Count => _detectionTable.Count;

    /// <summary>True when cylinder <paramref name="contextId"/> exists (possibly destroyed, until the next check).</summary>
    public bool Contains(uint contextId) => Find(contextId) is not null;

    /// <summary>
    /// Adds a detection cylinder watching <paramref name="objectId"/>: at the next checks it reports
    /// <see cref="DetectionStatus.Entered"/> when the object is closer than <paramref name="radius"/> plus the object's radius
    /// (centre to centre, <c>Position::distance</c>), and <see cref="DetectionStatus.Left"/> when it is not (or is no longer in the
    /// world). Not in the retail client (its server creates the cylinders); the fields are retail's <c>DetectionCylsphere</c>.
    /// </summary>
    /// <param name="contextId">The client's id of the cylinder, reported back; unique among this manager's cylinders.</param>
    /// <param name="objectId">The watched object's id; 0 for global detection (every object entering or leaving the loaded cells
    /// within <paramref name="radius"/> of the detector, reported at each check).</param>
    /// <param name="radius">Metres, finite and above 0, at most <see cref="Spatial.InputLimits.MaxCoordinate"/>.</param>
    /// <exception cref="ArgumentException">The radius is not finite, not above 0 or too large, or
    /// <paramref name="contextId"/> is in use (nothing changed).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public void CreateDetectionCylsphere(uint contextId, uint objectId, float radius)
    {
        if (!float.IsFinite(radius) || !(radius > 0f) || radius > Spatial.InputLimits.MaxCoordinate)
        {
            throw new ArgumentException("The detection radius must be finite, above 0 and at most 65,536 m.", nameof(radius));
        }

        if (Find(contextId) is not null)
        {
            throw new ArgumentException("A detection cylinder with this context id exists.", nameof(contextId));
        }

        if (_destroyed || PhysicsObj.RemovedFromWorld)
        {
            throw new InvalidOperationException("The detecting object was removed from its world.");
        }

        DetectionCylsphere c = _free.Count != 0 ? _free.Pop() : new DetectionCylsphere();
        c.ContextId = contextId;
        c.ObjectId = objectId;
        c.Radius = radius;
        c.ObjectStatus = DetectionStatus.NoChange;
        c.ObjectDetected = false;
        _detectionTable.Add(c);
    }

    /// <summary>Destroys cylinder <paramref name="contextId"/>: it is dropped at the next check, with no report (retail
    /// <c>DetectionManager::DestroyDetectionCylsphere</c>). False when there is no such cylinder.</summary>
    // retail: DetectionManager::DestroyDetectionCylsphere (acclient.c:327643)
    public bool DestroyDetectionCylsphere(uint contextId)
    {
        if (Find(contextId) is null)
        {
            return false;
        }

        _pendingDeletions.Add(contextId);
        return true;
    }

    /// <summary>The object step's check (retail <c>DetectionManager::CheckDetection()</c>): drops the destroyed cylinders, then
    /// once <see cref="UpdateInterval"/> of physics time passed since the last, checks each cylinder.</summary>
    void IDetectionManager.CheckDetection() => CheckDetection();

    // retail: DetectionManager::CheckDetection (acclient.c:327672)
    internal void CheckDetection()
    {
        ClearPendingDeletions();
        double currTime = PhysicsObj.World.PhysicsTime;
        if (currTime - LastUpdateTime >= UpdateInterval)
        {
            // non-retail: the table in creation order (retail: hash order); a cylinder created by a callback waits for the
            // next check, and a callback that removed the detector ends the pass.
            int n = _detectionTable.Count;
            for (int i = 0; i < n && !PhysicsObj.RemovedFromWorld && i < _detectionTable.Count; i++)
            {
                CheckDetection(_detectionTable[i]);
            }

            LastUpdateTime = currTime;
        }
    }

    // retail: DetectionManager::CheckDetection (acclient.c:327546)
    private void CheckDetection(DetectionCylsphere detcyl)
    {
        if (detcyl.ObjectId != 0)
        {
            PhysicsObj? found = PhysicsObj.World.GetObjectById(detcyl.ObjectId);
            detcyl.ObjectStatus = found is not null ? CheckDetection(detcyl, found) : DetectionStatus.Left;
            if (detcyl.ObjectStatus == DetectionStatus.Entered || detcyl.ObjectStatus == DetectionStatus.Left)
            {
                Listener.OnDetection(PhysicsObj, detcyl.ContextId, new DetectionInfo(detcyl.ObjectId, detcyl.ObjectStatus));
            }
        }
        else
        {
            UpdateCellList(detcyl);
            ReportGlobalDetection(detcyl.ContextId);
            _numPendingGlobalDetectUpdates = 0;
        }
    }

    /// <summary>Whether <paramref name="obj"/> entered or left <paramref name="detcyl"/> since the last check: inside when the
    /// float distance is below the cylinder's radius plus the object's (summed in x87 double, the object's radius unrounded:
    /// <c>GetRadius</c>'s product straight from st0).</summary>
    // retail: DetectionManager::CheckDetection (acclient.c:327020)
    internal DetectionStatus CheckDetection(DetectionCylsphere detcyl, PhysicsObj obj)
    {
        float radius = detcyl.Radius;
        float distance = (float)PhysicsObj.Position.DistanceInDouble(obj.Position);
        double objRadius = obj.RadiusInDouble;
        bool detected = detcyl.ObjectDetected;
        if (objRadius + radius <= distance)
        {
            if (detected)
            {
                detcyl.ObjectDetected = false;
                return DetectionStatus.Left;
            }
        }
        else if (!detected)
        {
            detcyl.ObjectDetected = true;
            return DetectionStatus.Entered;
        }

        return DetectionStatus.NoChange;
    }

    // retail: DetectionManager::ClearPendingDeletions (acclient.c:327512)
    private void ClearPendingDeletions()
    {
        for (int i = _pendingDeletions.Count - 1; i >= 0; i--)
        {
            DetectionCylsphere? c = Remove(_pendingDeletions[i]);
            if (c is not null)
            {
                if (c.ObjectId == 0)
                {
                    CleanupGlobalDetection();
                }

                _free.Push(c);
            }

            _pendingDeletions.RemoveAt(i);
        }
    }

    /// <summary>A cell's report that an object came into or left the cells around the object (global detection): counted in
    /// the detection objects until the next report. Nothing without global detection.</summary>
    // retail: DetectionManager::ReceiveDetectionUpdate (acclient.c:327242)
    internal void ReceiveDetectionUpdate(in DetectionInfo incomingInfo)
    {
        Dictionary<uint, DetectionEntry>? table = _detectionObjects;
        if (table is null)
        {
            return;
        }

        if (table.TryGetValue(incomingInfo.ObjectId, out DetectionEntry? e))
        {
            if (incomingInfo.Status == DetectionStatus.Entered)
            {
                if (e.Status == DetectionStatus.Left)
                {
                    e.Status = DetectionStatus.NoChange;
                    DecrementPending();
                }
                else
                {
                    e.Status = DetectionStatus.Entered;
                    _numPendingGlobalDetectUpdates++;
                }
            }
            else if (e.Status == DetectionStatus.Entered)
            {
                table.Remove(incomingInfo.ObjectId);
                _freeEntries.Push(e);
                DecrementPending();
            }
            else
            {
                e.Status = DetectionStatus.Left;
                _numPendingGlobalDetectUpdates++;
            }

            return;
        }

        DetectionEntry added = _freeEntries.Count != 0 ? _freeEntries.Pop() : new DetectionEntry();
        added.ObjectId = incomingInfo.ObjectId;
        added.Status = incomingInfo.Status;
        table.Add(incomingInfo.ObjectId, added);
        _numPendingGlobalDetectUpdates++;
    }

    /// <summary>Reports each pending entered / left detection object of the global cylinder <paramref name="contextId"/>, then
    /// drops the left ones and marks the rest unchanged.</summary>
    // retail: DetectionManager::ReportGlobalDetection (acclient.c:327394)
    private void ReportGlobalDetection(uint contextId)
    {
        Dictionary<uint, DetectionEntry>? table = _detectionObjects;
        if (table is null)
        {
            return;
        }

        foreach (KeyValuePair<uint, DetectionEntry> kv in table)
        {
            DetectionEntry e = kv.Value;
            if (e.Status == DetectionStatus.Entered || e.Status == DetectionStatus.Left)
            {
                Listener.OnDetection(PhysicsObj, contextId, new DetectionInfo(e.ObjectId, e.Status));
                // non-retail: a callback that removed the detector (its manager destroyed) ends the pass
                if (_destroyed)
                {
                    return;
                }
            }

            if (e.Status == DetectionStatus.Left)
            {
                table.Remove(kv.Key);
                _freeEntries.Push(e);
            }
            else
            {
                e.Status = DetectionStatus.NoChange;
            }
        }
    }

    // retail: LongNIHash<DetectionInfo>::destroy_contents (acclient.c:327087)
    private void DestroyContents(Dictionary<uint, DetectionEntry> table)
    {
        foreach (KeyValuePair<uint, DetectionEntry> kv in table)
        {
            _freeEntries.Push(kv.Value);
        }

        table.Clear();
    }

    /// <summary>Pending entered / left reports of global detection (retail <c>num_pending_global_detect_updates</c>).</summary>
    internal uint NumPendingGlobalDetectUpdates => _numPendingGlobalDetectUpdates;

    /// <summary>The status of global detection object <paramref name="objectId"/>, or null.</summary>
    internal DetectionStatus? GlobalDetectionStatus(uint objectId) =>
        _detectionObjects is not null && _detectionObjects.TryGetValue(objectId, out DetectionEntry? e) ? e.Status : null;

    /// <summary>Internal access to one cylinder, for tests.</summary>
    internal DetectionCylsphere? Find(uint contextId)
    {
        for (int i = 0; i < _detectionTable.Count; i++)
        {
            if (_detectionTable[i].ContextId == contextId)
            {
                return _detectionTable[i];
            }
        }

        return null;
    }

    /// <summary>The object leaves the world for good: exit_world destroys cylinder 0, then retail deletes the object, whose
    /// destructor drops the pending deletions and every cylinder, with no report.</summary>
    // retail: DetectionManager::~DetectionManager (acclient.c:327591)
    internal void Destroy()
    {
        ClearPendingDeletions();
        for (int i = 0; i < _detectionTable.Count; i++)
        {
            DetectionCylsphere c = _detectionTable[i];
            if (c.ObjectId == 0)
            {
                CleanupGlobalDetection();
            }

            _free.Push(c);
        }

        _detectionTable.Clear();
        _pendingDeletions.Clear();
        _destroyed = true;
    }

    private DetectionCylsphere? Remove(uint contextId)
    {
        for (int i = 0; i < _detectionTable.Count; i++)
        {
            DetectionCylsphere c = _detectionTable[i];
            if (c.ContextId == contextId)
            {
                _detectionTable.RemoveAt(i);
                return c;
            }
        }

        return null;
    }

    private void DecrementPending()
    {
        if (_numPendingGlobalDetectUpdates != 0)
        {
            _numPendingGlobalDetectUpdates--;
        }
    }

    // Retail's DetectionInfo held in the detection_objects hash (mutable: its status changes in place).
    private sealed class DetectionEntry
    {
        public uint ObjectId;
        public DetectionStatus Status;
    }
}
