using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Managers;

/// <summary>An object that tracks this one (retail <c>TargettedVoyeurInfo</c>, acclient.h:52807): it is sent a report
/// whenever this object's predicted position moves more than <see cref="Radius"/> from the last one sent.</summary>
public sealed class TargettedVoyeurInfo
{
    /// <summary>Id of the tracking object.</summary>
    public uint ObjectId { get; internal set; }

    /// <summary>Look-ahead of the predicted position, seconds.</summary>
    public double Quantum { get; internal set; }

    /// <summary>Distance the prediction must move before the next report, metres.</summary>
    public float Radius { get; internal set; }

    /// <summary>The predicted position last sent.</summary>
    public Position LastSentPosition { get; internal set; }
}

/// <summary>
/// An object's target tracking (retail <c>TargetManager</c>, acclient.h:31024, PORTAL/cphysobj/CTargetting.c): the object it
/// tracks (<see cref="TargetInfo"/>: a move-to's or a stick's target) and the objects that track it (voyeurs). Every half
/// second of physics time (<see cref="HandleTargetting"/>, from the object's step) each voyeur whose predicted position of
/// this object (position + velocity × quantum) moved more than its radius since the last report is sent a new one, which
/// reaches that voyeur's move-to and sticky managers; so a MoveToObject follows a target that walks away. Objects are found
/// by id in the world's object table (<see cref="World.PhysicsWorld.GetObjectById"/>; retail <c>CObjectMaint</c>). Created on
/// first use by the object (<c>set_target</c> or <c>add_voyeur</c>).
/// </summary>
public sealed class TargetManager
{
    // Retail LongNIHash<TargettedVoyeurInfo> with 4 buckets (<c>AddVoyeur</c>), each a list the newest entry is prepended to:
    // kept here as one list in retail's iteration order (bucket, then newest first). Removed entries are pooled.
    internal const int VoyeurBuckets = 4;

    /// <summary>Least physics time between two voyeur passes, seconds: 0.5 (<c>HandleTargetting</c>).</summary>
    internal const double UpdateInterval = 0.5;

    /// <summary>Client time a target may stay unanswered before it times out, seconds: 10.0 (<c>HandleTargetting</c>).</summary>
    internal const double TargetTimeout = 10.0;
    private readonly List<TargettedVoyeurInfo> _voyeurs = new(4);
    private readonly Stack<TargettedVoyeurInfo> _freeVoyeurs = new();
    private TargetInfo _targetInfo;
    private bool _hasTarget;
    private bool _hasVoyeurTable;

    /// <summary>Creates the manager of <paramref name="physicsObj"/> (no target, no voyeurs, last update 0).</summary>
    // retail: TargetManager::TargetManager (acclient.c:327973)
    internal TargetManager(PhysicsObj physicsObj)
    {
        PhysicsObj = physicsObj;
        LastUpdateTime = 0.0;
    }

    /// <summary>The object.</summary>
    public PhysicsObj PhysicsObj { get; }

    /// <summary>True while the object tracks a target (retail <c>target_info != NULL</c>).</summary>
    public bool HasTarget => _hasTarget;

    /// <summary>The tracked target's last report (meaningful while <see cref="HasTarget"/>).</summary>
    public TargetInfo TargetInfo => _targetInfo;

    /// <summary>Physics time of the last voyeur pass, seconds (retail <c>last_update_time</c>).</summary>
    public double LastUpdateTime { get; private set; }

    /// <summary>Number of objects tracking this one.</summary>
    public int VoyeurCount => _voyeurs.Count;

    /// <summary>The voyeur at <paramref name="index"/>, in retail's iteration order.</summary>
    public TargettedVoyeurInfo GetVoyeur(int index) => _voyeurs[index];

    /// <summary>The voyeur with id <paramref name="objectId"/>, or null.</summary>
    public TargettedVoyeurInfo? FindVoyeur(uint objectId)
    {
        for (int i = 0; i < _voyeurs.Count; i++)
        {
            if (_voyeurs[i].ObjectId == objectId)
            {
                return _voyeurs[i];
            }
        }

        return null;
    }

    /// <summary>Sets the tracked target's look-ahead and re-registers with the target (its voyeur entry takes the new
    /// quantum, rounded to float as <c>add_voyeur</c> takes it).</summary>
    // retail: TargetManager::SetTargetQuantum (acclient.c:328067)
    internal void SetTargetQuantum(double newQuantum)
    {
        if (!_hasTarget)
        {
            return;
        }

        _targetInfo.Quantum = newQuantum;
        PhysicsObj? target = PhysicsObj.World.GetObjectById(_targetInfo.ObjectId);
        if (target is not null)
        {
            float quantum = (float)_targetInfo.Quantum;
            target.AddVoyeur(PhysicsObj.Id, _targetInfo.Radius, quantum);
        }
    }

    /// <summary>Sends <paramref name="voyeur"/> a report of this object at predicted position <paramref name="p"/>.</summary>
    // retail: TargetManager::SendVoyeurUpdate (acclient.c:328091)
    internal void SendVoyeurUpdate(TargettedVoyeurInfo voyeur, in Position p, TargetStatus status)
    {
        voyeur.LastSentPosition = p;
        PhysicsObj obj = PhysicsObj;
        var info = new TargetInfo
        {
            ContextId = 0,
            ObjectId = obj.Id,
            Quantum = voyeur.Quantum,
            Radius = voyeur.Radius,
            TargetPosition = obj.Position,
            InterpolatedPosition = p,
            Velocity = obj.CachedVelocity,
            Status = status,
        };
        PhysicsObj? v = obj.World.GetObjectById(voyeur.ObjectId);
        v?.ReceiveTargetUpdate(info);
    }

    /// <summary>This object's position <paramref name="quantum"/> seconds ahead at its current velocity (its cached
    /// velocity: the last step's displacement over its duration).</summary>
    // retail: TargetManager::GetInterpolatedPosition (acclient.c:328130)
    internal Position GetInterpolatedPosition(double quantum)
    {
        Position p = PhysicsObj.Position;
        float pa = (float)quantum;
        Vector3 v = PhysicsObj.CachedVelocity;
        double x = (double)pa * v.X;
        double y = (double)pa * v.Y;
        float z = (float)((double)pa * v.Z);
        Vector3 o = p.Frame.Origin;
        p.Frame.Origin = new Vector3((float)(x + o.X), (float)(y + o.Y), (float)((double)z + o.Z));
        return p;
    }

    /// <summary>Sends <paramref name="voyeur"/> a report when the predicted position moved more than its radius.</summary>
    // retail: TargetManager::CheckAndUpdateVoyeur (acclient.c:328157)
    internal void CheckAndUpdateVoyeur(TargettedVoyeurInfo voyeur)
    {
        Position p = GetInterpolatedPosition(voyeur.Quantum);
        if (p.DistanceInDouble(voyeur.LastSentPosition) > voyeur.Radius)
        {
            SendVoyeurUpdate(voyeur, p, TargetStatus.Ok);
        }
    }

    /// <summary>Sends every voyeur a report with <paramref name="status"/> at this object's current position (it left the
    /// world, teleported...).</summary>
    // retail: TargetManager::NotifyVoyeurOfEvent (acclient.c:328180)
    internal void NotifyVoyeurOfEvent(TargetStatus status)
    {
        if (!_hasVoyeurTable)
        {
            return;
        }

        Position here = PhysicsObj.Position;
        // Retail steps its iterator past the entry before the call; a report that removes its own entry is safe here too.
        for (int i = 0; i < _voyeurs.Count;)
        {
            TargettedVoyeurInfo v = _voyeurs[i];
            SendVoyeurUpdate(v, here, status);
            i = NextVoyeur(i, v);
        }
    }

    /// <summary>Stops tracking the target: unregisters from it (when the world still has it) and drops the report.</summary>
    // retail: TargetManager::ClearTarget (acclient.c:328270)
    internal void ClearTarget()
    {
        if (!_hasTarget)
        {
            return;
        }

        PhysicsObj? target = PhysicsObj.World.GetObjectById(_targetInfo.ObjectId);
        target?.RemoveVoyeur(PhysicsObj.Id);
        _hasTarget = false;
        _targetInfo = new TargetInfo();
    }

    /// <summary>Registers (or updates: radius and quantum, no report) object <paramref name="objectId"/> as a voyeur; a new
    /// voyeur is sent a report of the current position at once.</summary>
    // retail: TargetManager::AddVoyeur (acclient.c:328299)
    internal void AddVoyeur(uint objectId, float radius, double quantum)
    {
        if (_hasVoyeurTable)
        {
            TargettedVoyeurInfo? existing = FindVoyeur(objectId);
            if (existing is not null)
            {
                existing.Radius = radius;
                existing.Quantum = quantum;
                return;
            }
        }
        else
        {
            CreateVoyeurTable();
        }

        TargettedVoyeurInfo info = _freeVoyeurs.Count != 0 ? _freeVoyeurs.Pop() : new TargettedVoyeurInfo();
        info.ObjectId = objectId;
        info.Radius = radius;
        info.Quantum = quantum;
        info.LastSentPosition = new Position(0, Frame.Identity);
        InsertInRetailOrder(info);
        SendVoyeurUpdate(info, PhysicsObj.Position, TargetStatus.Ok);
    }

    /// <summary>The voyeur table comes into being (retail: a 4-bucket hash, news its bucket array).</summary>
    // retail: LongNIHash<DetectionInfo>::LongNIHash (acclient.c:327982)
    private void CreateVoyeurTable() => _hasVoyeurTable = true;

    /// <summary>The index of the voyeur after <paramref name="current"/>, which was at <paramref name="i"/> before its report:
    /// the same index when the report removed it.</summary>
    // retail: LongNIHashIter<TargettedVoyeurInfo>::operator++ (acclient.c:327998)
    private int NextVoyeur(int i, TargettedVoyeurInfo current) =>
        i < _voyeurs.Count && _voyeurs[i] == current ? i + 1 : i;

    /// <summary>Drops every voyeur entry (pooled), as the manager's destructor does; the object left its world for good.</summary>
    // retail: LongNIHash<TargettedVoyeurInfo>::destroy_contents (acclient.c:328498)
    internal void DestroyVoyeurs()
    {
        for (int i = 0; i < _voyeurs.Count; i++)
        {
            _freeVoyeurs.Push(_voyeurs[i]);
        }

        _voyeurs.Clear();
    }

    // retail: LongNIHash<ParticleEmitter>::add (acclient.c:327166): bucket (key ^ key >> 16) % 4, prepended to its bucket
    private void InsertInRetailOrder(TargettedVoyeurInfo info)
    {
        int bucket = Bucket(info.ObjectId);
        int at = 0;
        while (at < _voyeurs.Count && Bucket(_voyeurs[at].ObjectId) < bucket)
        {
            at++;
        }

        _voyeurs.Insert(at, info);
    }

    private static int Bucket(uint key) => (int)((key ^ (ulong)(key >> 16)) % VoyeurBuckets);

    /// <summary>Applies a report of the tracked target (others are ignored): stores it, stamps its receipt time, computes
    /// the direction to the predicted position, passes it to the object's managers (<see cref="PhysicsObj.HandleUpdateTarget"/>),
    /// and stops tracking when the target left the world.</summary>
    // retail: TargetManager::ReceiveUpdate (acclient.c:328384)
    internal void ReceiveUpdate(in TargetInfo update)
    {
        if (!_hasTarget || update.ObjectId != _targetInfo.ObjectId)
        {
            return;
        }

        _targetInfo.ObjectId = update.ObjectId;
        _targetInfo.Radius = update.Radius;
        _targetInfo.Quantum = update.Quantum;
        _targetInfo.TargetPosition = update.TargetPosition;
        _targetInfo.InterpolatedPosition = update.InterpolatedPosition;
        _targetInfo.Velocity = update.Velocity;
        _targetInfo.Status = update.Status;
        _targetInfo.LastUpdateTime = PhysicsObj.World.CurrentTime;
        Vector3 heading = PhysicsObj.Position.GetOffset(_targetInfo.InterpolatedPosition);
        if (VectorMath.NormalizeCheckSmall(ref heading))
        {
            heading = new Vector3(0f, 0f, 1f);
        }

        _targetInfo.InterpolatedHeading = heading;
        // retail: TargetInfo::TargetInfo (acclient.c:317673), the copy: the report goes by value
        TargetInfo copy = _targetInfo;
        PhysicsObj.HandleUpdateTargetInternal(copy);
        if (update.Status == TargetStatus.ExitWorld)
        {
            ClearTarget();
        }
    }

    /// <summary>
    /// The per-step work (at most every 0.5 s of physics time): a target that never answered within 10 s of client time
    /// times out (<see cref="TargetStatus.TimedOut"/> reported to the object's managers); every voyeur is checked.
    /// </summary>
    // retail: TargetManager::HandleTargetting (acclient.c:328457)
    internal void HandleTargetting()
    {
        double physicsTime = PhysicsObj.World.PhysicsTime;
        double clientTime = PhysicsObj.World.CurrentTime;
        if (physicsTime - LastUpdateTime < UpdateInterval)
        {
            return;
        }

        if (_hasTarget && _targetInfo.Status == TargetStatus.Undefined && _targetInfo.LastUpdateTime + TargetTimeout < clientTime)
        {
            _targetInfo.Status = TargetStatus.TimedOut;
            TargetInfo copy = _targetInfo;
            PhysicsObj.HandleUpdateTargetInternal(copy);
        }

        if (_hasVoyeurTable)
        {
            for (int i = 0; i < _voyeurs.Count;)
            {
                TargettedVoyeurInfo v = _voyeurs[i];
                CheckAndUpdateVoyeur(v);
                i = NextVoyeur(i, v);
            }
        }

        LastUpdateTime = PhysicsObj.World.PhysicsTime;
    }

    /// <summary>
    /// Starts tracking <paramref name="objectId"/> (dropping the previous target): registers this object as its voyeur with
    /// <paramref name="radius"/> and <paramref name="quantum"/> (which sends the first report at once when the world has the
    /// object). Object id 0 reports a <see cref="TargetStatus.TimedOut"/> target to the object's managers instead.
    /// </summary>
    // retail: TargetManager::SetTarget (acclient.c:328573)
    internal void SetTarget(uint contextId, uint objectId, float radius, double quantum)
    {
        if (_hasTarget)
        {
            PhysicsObj? old = PhysicsObj.World.GetObjectById(_targetInfo.ObjectId);
            old?.RemoveVoyeur(PhysicsObj.Id);
            _hasTarget = false;
        }

        if (objectId != 0)
        {
            _targetInfo = new TargetInfo
            {
                ContextId = contextId,
                ObjectId = objectId,
                Radius = radius,
                Quantum = quantum,
                LastUpdateTime = PhysicsObj.World.CurrentTime,
            };
            _hasTarget = true;
            PhysicsObj? target = PhysicsObj.World.GetObjectById(_targetInfo.ObjectId);
            if (target is not null)
            {
                float q = (float)_targetInfo.Quantum;
                target.AddVoyeur(PhysicsObj.Id, _targetInfo.Radius, q);
            }
        }
        else
        {
            var failed = new TargetInfo { ContextId = contextId, ObjectId = 0, Status = TargetStatus.TimedOut };
            PhysicsObj.HandleUpdateTargetInternal(failed);
        }
    }

    /// <summary>Unregisters voyeur <paramref name="objectId"/>.</summary>
    /// <returns>True when it was registered.</returns>
    // retail: TargetManager::RemoveVoyeur (acclient.c:328643)
    internal bool RemoveVoyeur(uint objectId)
    {
        if (!_hasVoyeurTable)
        {
            return false;
        }

        for (int i = 0; i < _voyeurs.Count; i++)
        {
            TargettedVoyeurInfo v = _voyeurs[i];
            if (v.ObjectId == objectId)
            {
                _voyeurs.RemoveAt(i);
                _freeVoyeurs.Push(v);
                return true;
            }
        }

        return false;
    }
}
