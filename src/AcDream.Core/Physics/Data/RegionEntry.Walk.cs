using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

// The region's calendar, sky and ambient sounds: walked byte for byte in retail's order and checked, not kept (the physics and
// the scenery need only what follows them).
public sealed partial class RegionEntry
{
    /// <summary>The calendar: zero time of year (f64), zero year, day length, days per year, the year's name, then the times
    /// of day, the week days and the seasons, each a count and its records.</summary>
    /// <remarks>Retail keeps reading the region when the calendar fails (the old calendar stays); the library refuses the
    /// bytes.</remarks>
    // retail: GameTime::UnPack (acclient.c:464013)
    private static void WalkGameTime(ref RetailDataReader r)
    {
        r.Structure = "GameTime";
        r.Skip(8 + 4 + 4 + 4, "calendar header");
        ReadPString(ref r, "year name", keep: false);
        int times = r.ReadCount("time of day count", 12);
        for (int i = 0; i < times; i++)
        {
            WalkTimeOfDay(ref r);
        }

        int days = r.ReadCount("week day count", 4);
        for (int i = 0; i < days; i++)
        {
            WalkWeekDay(ref r);
        }

        int seasons = r.ReadCount("season count", 8);
        for (int i = 0; i < seasons; i++)
        {
            WalkSeason(ref r);
        }
    }

    /// <summary>A week day: its name.</summary>
    // retail: WeekDay::UnPack (acclient.c:463919)
    private static void WalkWeekDay(ref RetailDataReader r) => ReadPString(ref r, "week day name", keep: false);

    /// <summary>A time of day: its start (f32), the night flag, its name.</summary>
    // retail: TimeOfDay::UnPack (acclient.c:463951)
    private static void WalkTimeOfDay(ref RetailDataReader r)
    {
        r.Skip(4 + 4, "time of day");
        ReadPString(ref r, "time of day name", keep: false);
    }

    /// <summary>A season: its first day, its name.</summary>
    // retail: Season::UnPack (acclient.c:463881)
    private static void WalkSeason(ref RetailDataReader r)
    {
        r.Skip(4, "season start");
        ReadPString(ref r, "season name", keep: false);
    }

    /// <summary>The sky: two tick sizes (f64), then the day groups.</summary>
    // retail: SkyDesc::UnPack (acclient.c:302821)
    private static void WalkSkyDesc(ref RetailDataReader r)
    {
        r.Structure = "SkyDesc";
        r.Skip(8 + 8, "sky tick sizes");
        int groups = r.ReadCount("day group count", 16);
        for (int i = 0; i < groups; i++)
        {
            WalkDayGroup(ref r);
            r.Structure = "SkyDesc";
        }
    }

    /// <summary>A day group: its chance (f32), name, sky objects, and sky times of day.</summary>
    // retail: DayGroup::UnPack (acclient.c:302641)
    private static void WalkDayGroup(ref RetailDataReader r)
    {
        r.Structure = "DayGroup";
        r.Skip(4, "day group chance");
        ReadPString(ref r, "day group name", keep: false);
        int objects = r.ReadCount("sky object count", SkyObjectSize);
        for (int i = 0; i < objects; i++)
        {
            WalkSkyObject(ref r);
        }

        r.Structure = "DayGroup";
        int times = r.ReadCount("sky time of day count", SkyTimeOfDaySize + 4);
        for (int i = 0; i < times; i++)
        {
            WalkSkyTimeOfDay(ref r, objects);
        }
    }

    /// <summary>A sky object: begin and end time, begin and end angle, texture velocity x and y, default GfxObj, default
    /// particle emitter, properties (nine words).</summary>
    // retail: SkyObject::UnPack (acclient.c:301788)
    private static void WalkSkyObject(ref RetailDataReader r)
    {
        r.Structure = "SkyObject";
        r.Skip(SkyObjectSize, "sky object");
    }

    private const int SkyObjectSize = 9 * 4;
    private const int SkyTimeOfDaySize = 11 * 4;
    private const int SkyObjectReplaceSize = 6 * 4;

    /// <summary>A sky time of day: start, light and fog values (eleven words), then the sky object replacements, each naming
    /// a sky object of its day group by index.</summary>
    // retail: SkyTimeOfDay::UnPack (acclient.c:302256)
    private static void WalkSkyTimeOfDay(ref RetailDataReader r, int skyObjects)
    {
        r.Structure = "SkyTimeOfDay";
        r.Skip(SkyTimeOfDaySize, "sky time of day");
        int replaces = r.ReadCount("sky object replacement count", SkyObjectReplaceSize);
        for (int i = 0; i < replaces; i++)
        {
            WalkSkyObjectReplace(ref r, skyObjects);
        }
    }

    /// <summary>A sky object replacement: object index, GfxObj, rotation, transparency, luminosity, max brightness.
    /// <c>DayGroup::UnPack</c> then reads <c>sky_objects[object index]</c> (acclient.c:302641), so the index must name one
    /// of the day group's sky objects.</summary>
    // retail: SkyObjectReplace::UnPack (acclient.c:301922)
    private static void WalkSkyObjectReplace(ref RetailDataReader r, int skyObjects)
    {
        r.Structure = "SkyObjectReplace";
        int at = r.Offset;
        uint index = r.ReadUInt32("sky object index");
        if (index >= (uint)skyObjects)
        {
            throw r.ErrorAt(at, $"sky object index {index} is past the day group's {skyObjects} sky objects");
        }

        r.Skip(SkyObjectReplaceSize - 4, "sky object replacement");
    }

    /// <summary>The ambient sound tables: a count, then each table. Returns the count.</summary>
    // retail: CSoundDesc::UnPack (acclient.c:303693)
    private static int WalkSoundDesc(ref RetailDataReader r)
    {
        r.Structure = "CSoundDesc";
        int tables = r.ReadCount("sound table count", 8);
        for (int i = 0; i < tables; i++)
        {
            WalkAmbientStbDesc(ref r);
        }

        return tables;
    }

    /// <summary>An ambient sound table: its id, a count, then per ambient sound its type, volume, base chance, min and max
    /// rate.</summary>
    // retail: AmbientSTBDesc::UnPack (acclient.c:384534)
    private static void WalkAmbientStbDesc(ref RetailDataReader r)
    {
        r.Structure = "AmbientSTBDesc";
        r.Skip(4, "sound table id");
        int sounds = r.ReadCount("ambient sound count", 5 * 4);
        r.Skip(sounds * 5 * 4, "ambient sounds");
    }
}
