using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Tests.Support;

/// <summary>FNV-1a 64 over the exact bits of physics state, for golden-hash determinism tests.</summary>
internal struct StateHasher
{
    private ulong _h;

    public StateHasher()
    {
        _h = 14695981039346656037UL;
    }

    public readonly ulong Value => _h;

    public void Add(uint v)
    {
        for (int i = 0; i < 4; i++)
        {
            _h ^= (byte)(v >> (8 * i));
            _h *= 1099511628211UL;
        }
    }

    public void Add(ulong v)
    {
        Add((uint)v);
        Add((uint)(v >> 32));
    }

    public void Add(float f) => Add((uint)BitConverter.SingleToInt32Bits(f));

    public void Add(double d) => Add((ulong)BitConverter.DoubleToInt64Bits(d));

    public void Add(Vector3 v)
    {
        Add(v.X);
        Add(v.Y);
        Add(v.Z);
    }

    public void Add(in Frame f)
    {
        Add(f.Origin);
        Add(f.Qw);
        Add(f.Qx);
        Add(f.Qy);
        Add(f.Qz);
        Add(f.M11);
        Add(f.M12);
        Add(f.M13);
        Add(f.M21);
        Add(f.M22);
        Add(f.M23);
        Add(f.M31);
        Add(f.M32);
        Add(f.M33);
    }

    public void Add(in Position p)
    {
        Add(p.ObjCellId);
        Add(p.Frame);
    }
}
