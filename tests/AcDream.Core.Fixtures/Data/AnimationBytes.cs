using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Animation;

namespace AcDream.Core.Fixtures.Data;

/// <summary>
/// Writes an animation entry (data file type 0x03) to the decompiled layout, field by field: the entry's id, then
/// <c>CAnimation::UnPack</c>'s flags, part count, frame count, root-motion frames (when flag 1), then per frame the part frames,
/// the hook count and each hook (<c>CAnimHook::PackHook</c>: type, direction, fields, padding to four).
/// </summary>
internal sealed class AnimationBytes
{
    private readonly uint _id;
    private readonly int _numParts;
    private readonly List<(Vector3 Origin, Quaternion Rotation)> _pos = new();
    private readonly List<List<Action<RetailDataWriter>>> _frameHooks = new();
    private readonly List<(Vector3 Origin, Quaternion Rotation)[]> _partFrames = new();
    private bool _withPos;
    private bool _hasHooksFlag;

    public AnimationBytes(uint id, int numParts = 1)
    {
        _id = id;
        _numParts = numParts;
    }

    /// <summary>Adds a frame: its root-motion step (when any frame has one, every frame must) and its parts at identity.</summary>
    public AnimationBytes Frame(Vector3? posOrigin = null, Quaternion? posRotation = null)
    {
        if (posOrigin is not null || posRotation is not null)
        {
            _withPos = true;
            _pos.Add((posOrigin ?? Vector3.Zero, posRotation ?? Quaternion.Identity));
        }

        var parts = new (Vector3, Quaternion)[_numParts];
        for (int i = 0; i < _numParts; i++)
        {
            parts[i] = (new Vector3(i, 0, 0), Quaternion.Identity);
        }

        _partFrames.Add(parts);
        _frameHooks.Add(new List<Action<RetailDataWriter>>());
        return this;
    }

    /// <summary>Sets part <paramref name="part"/>'s frame in the last frame added.</summary>
    public AnimationBytes Part(int part, Vector3 origin, Quaternion rotation)
    {
        _partFrames[^1][part] = (origin, rotation);
        return this;
    }

    /// <summary>Adds a hook to the last frame added: type, direction and the fields written by <paramref name="fields"/>.</summary>
    public AnimationBytes Hook(AnimHookType type, AnimHookDirection direction, Action<RetailDataWriter>? fields = null)
    {
        _hasHooksFlag = true;
        _frameHooks[^1].Add(w =>
        {
            w.UInt32((uint)type).Int32((int)direction);
            fields?.Invoke(w);
            w.Align4();   // CAnimHook::UnPackHook (acclient.c:342736) ends with PackObj::ALIGN_PTR, always
        });
        return this;
    }

    /// <summary>A sound hook whose sound id names it (for order checks).</summary>
    public AnimationBytes Sound(uint soundId, AnimHookDirection direction) =>
        Hook(AnimHookType.Sound, direction, w => w.UInt32(soundId));

    public byte[] ToArray()
    {
        var w = new RetailDataWriter();
        w.UInt32(_id);
        uint flags = (_withPos ? 1u : 0u) | (_hasHooksFlag ? 2u : 0u);
        w.UInt32(flags).UInt32((uint)_numParts).UInt32((uint)_partFrames.Count);
        if (_withPos)
        {
            foreach ((Vector3 o, Quaternion q) in _pos)
            {
                w.Frame(o, q);
            }
        }

        for (int f = 0; f < _partFrames.Count; f++)
        {
            foreach ((Vector3 o, Quaternion q) in _partFrames[f])
            {
                w.Frame(o, q);
            }

            w.UInt32((uint)_frameHooks[f].Count);
            foreach (Action<RetailDataWriter> hook in _frameHooks[f])
            {
                hook(w);
            }
        }

        return w.ToArray();
    }

    public AnimClip Build() => AnimClip.UnPack(ToArray());
}
