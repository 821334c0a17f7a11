using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// An indoor cell (a room or corridor of a building or dungeon): its place in the landblock, its geometry and its
/// portals to neighbouring cells and to the outdoors. Retail: <c>CEnvCell</c> (acclient.h:32072, PORTAL/ccell/CEnvCell.c),
/// the collision half of it.
/// </summary>
/// <remarks>Split by concern: this file (data, point test), <c>EnvCell.Collision.cs</c> (the sweep's collision calls),
/// <c>EnvCell.Transit.cs</c> (which cells a sphere reaches through the portals), <c>EnvCell.PartTransit.cs</c> (which cells a
/// static object's parts reach through them, and through a building's door).</remarks>
public sealed partial class EnvCell : ObjCell
{
    private readonly CellPortal[] _portals;
    private readonly Position _pos;

    /// <summary>Creates an indoor cell.</summary>
    /// <param name="id">The cell id (0xXXYYCCCC with CCCC ≥ 0x100).</param>
    /// <param name="frame">Where the cell's local space sits in its landblock.</param>
    /// <param name="structure">The cell's geometry.</param>
    /// <param name="portals">The portals.</param>
    /// <exception cref="ArgumentNullException"><paramref name="structure"/> or <paramref name="portals"/> is null.</exception>
    /// <exception cref="ArgumentException">The id is not an indoor cell id, or the frame is not finite and valid.</exception>
    public EnvCell(uint id, in Frame frame, CellStruct structure, CellPortal[] portals)
    {
        ArgumentNullException.ThrowIfNull(structure);
        ArgumentNullException.ThrowIfNull(portals);
        if (!LandDefs.IsEnvCell(id) || (id & 0xFFFF) > 0xFFFD)
        {
            throw new ArgumentException("An indoor cell id has a low word in 0x100..0xFFFD.", nameof(id));
        }

        if (!VectorMath.IsFinite(frame.Origin) || !frame.IsValid())
        {
            throw new ArgumentException("The cell frame must be finite with a valid rotation.", nameof(frame));
        }

        CellId = id;
        _pos = new Position(id, frame);
        Structure = structure;
        _portals = (CellPortal[])portals.Clone();
    }

    /// <summary>The cell id. Retail: <c>m_DID.id</c>.</summary>
    public uint CellId { get; }

    /// <inheritdoc />
    public override uint Id => CellId;

    /// <summary>The cell's place: its id and its local frame in the landblock. Retail: <c>pos</c>.</summary>
    public ref readonly Position Pos => ref _pos;

    /// <summary>The cell's geometry. Retail: <c>structure</c>.</summary>
    public CellStruct Structure { get; }

    /// <summary>The portals. Retail: <c>portals</c>.</summary>
    public ReadOnlySpan<CellPortal> Portals => _portals;

    /// <summary>True when the landblock-local <paramref name="point"/> lies in the cell's region (never for a cell
    /// without portals, as retail).</summary>
    // retail: CEnvCell::point_in_cell (acclient.c:347934)
    public override bool PointInCell(Vector3 point)
    {
        if (_portals.Length == 0)
        {
            return false;
        }

        Vector3 local = _pos.Frame.GlobalToLocal(point);
        return Structure.PointInCell(local);
    }
}
