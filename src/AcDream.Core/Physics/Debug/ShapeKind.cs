namespace AcDream.Core.Physics.Debug;

/// <summary>What a shape handed to an <see cref="IDebugDrawSink"/> is (library addition; no retail symbol). The id that comes
/// with it is an object id for the object kinds and a cell id for the others.</summary>
public enum ShapeKind
{
    /// <summary>An object's sphere (retail <c>CPartArray::GetSphere</c>, scaled and placed); the id is the object's.</summary>
    ObjectSphere,

    /// <summary>An object's cylinder sphere (retail <c>CPartArray::GetCylsphere</c>), a vertical cylinder; the id is the
    /// object's.</summary>
    ObjectCylSphere,

    /// <summary>A polygon of an object's part physics BSP; the id is the object's.</summary>
    ObjectPolygon,

    /// <summary>A polygon of a building's shell physics BSP; the id is the land cell the building hangs on (see
    /// <see cref="PhysicsDebugDraw.DrawBuilding{TSink}"/>).</summary>
    BuildingPolygon,

    /// <summary>A polygon of an indoor cell's physics BSP; the id is the cell's.</summary>
    EnvCellPolygon,

    /// <summary>A terrain triangle of a land cell; the id is the cell's.</summary>
    TerrainTriangle,

    /// <summary>A side of a land cell's square, from corner vertex to corner vertex; the id is the cell's.</summary>
    LandCellBoundary,

    /// <summary>A portal polygon of an indoor cell; the id is the cell's.</summary>
    EnvCellPortal,

    /// <summary>An object's contact plane: the point is the object's origin dropped onto it; the id is the object's.</summary>
    ContactPlane,

    /// <summary>An object's sphere where its last update began; the id is the object's.</summary>
    SweepStart,

    /// <summary>An object's sphere where its last update ended; the id is the object's.</summary>
    SweepEnd,

    /// <summary>The segment from an object's origin where its last update began to where it ended; the id is the object's.</summary>
    SweepPath,
}
