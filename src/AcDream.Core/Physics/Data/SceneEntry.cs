using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// A scene (data-file entry 0x12xxxxxx, DBO type 27, retail <c>Scene::GetDBOType</c> acclient.c:462739) as retail's
/// <c>Scene::UnPack</c> reads it: the object spots the procedural scenery draws from at each terrain vertex that picks it.
/// </summary>
public sealed class SceneEntry
{
    private SceneEntry(uint id, ObjectDesc[] objects)
    {
        Id = id;
        Objects = Array.AsReadOnly(objects);
    }

    /// <summary>The entry id (0x12xxxxxx).</summary>
    public uint Id { get; }

    /// <summary>The object spots, in stored order (the order the scenery visits them; the index is the hash's <c>k</c>).
    /// Retail: <c>objects</c>.</summary>
    public IReadOnlyList<ObjectDesc> Objects { get; }

    /// <summary>Unpacks one scene entry's bytes: the id, the spot count, then each spot (76 bytes).</summary>
    /// <exception cref="RetailDataFormatException">The bytes are not a scene (also: the id is not 0x12xxxxxx, a spot's
    /// frame is not a unit quaternion, or a float is not finite).</exception>
    // retail: Scene::UnPack (acclient.c:463119)
    public static SceneEntry UnPack(ReadOnlySpan<byte> data)
    {
        var r = new RetailDataReader(data, "Scene");
        uint id = r.ReadUInt32("id");
        if (id >> 24 != 0x12)
        {
            throw r.ErrorAt(0, $"0x{id:X8} is not a scene id (0x12xxxxxx)");
        }

        int count = r.ReadCount("object count", ObjectDesc.PackedSize);
        var objects = new ObjectDesc[count];
        r.Structure = "ObjectDesc";
        for (int i = 0; i < count; i++)
        {
            objects[i] = ObjectDesc.UnPack(ref r);
        }

        return new SceneEntry(id, objects);
    }
}
