using System.Collections.Generic;
using System.Numerics;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// A creature's motion table (retail <c>CMotionTable</c>, PORTAL/canim/CMTable.c; data file type 0x09): for each style its
/// default substate, the cycles keyed by style and substate, the modifiers, and the links (transition animations) keyed by
/// style and the motion they start from. <c>GetObjectSequence</c> turns a motion into the links and cycle it queues on a
/// <see cref="AnimSequence"/>, and the velocity and omega the sequence moves the body by.
/// </summary>
/// <remarks>
/// Retail keeps each table in its own hash (<c>LongNIValHash</c> / <c>LongHash</c>); the port keeps a dictionary per table
/// with the same keys. Retail inserts at the head of a bucket, so of two entries with one key the later one is found; the
/// unpacker's dictionary keeps the later one too. Read-only after <see cref="UnPack"/>: many objects may share one table.
/// </remarks>
public sealed partial class MotionTable
{
    /// <summary>The data file id (retail <c>DBObj::m_DID</c>): the entry's first dword.</summary>
    public uint Id { get; private set; }

    /// <summary>The style a new object starts in (retail <c>CMotionTable::default_style</c>).</summary>
    public Motion.MotionCommand DefaultStyle => (Motion.MotionCommand)_defaultStyle;

    // retail: default_style
    private uint _defaultStyle;

    /// <summary>Number of styles with a default substate (retail <c>style_defaults</c>).</summary>
    public int StyleCount => StyleDefaults.Count;

    /// <summary>Number of cycles (retail <c>cycles</c>).</summary>
    public int CycleCount => Cycles.Count;

    /// <summary>Number of modifiers (retail <c>modifiers</c>).</summary>
    public int ModifierCount => Modifiers.Count;

    /// <summary>Number of links, counted over every starting motion (retail <c>links</c>).</summary>
    public int LinkCount
    {
        get
        {
            int n = 0;
            foreach (Dictionary<uint, MotionData> inner in Links.Values)
            {
                n += inner.Count;
            }

            return n;
        }
    }

    /// <summary>The default substate of <paramref name="style"/> (retail's <c>style_defaults</c> lookup).</summary>
    /// <returns>False when the table has no default for the style.</returns>
    public bool TryGetDefaultSubstate(Motion.MotionCommand style, out Motion.MotionCommand substate)
    {
        bool found = StyleDefaults.TryGetValue((uint)style, out uint s);
        substate = (Motion.MotionCommand)s;
        return found;
    }

    /// <summary>Each style's default substate (retail <c>style_defaults</c>).</summary>
    internal readonly Dictionary<uint, uint> StyleDefaults = new();

    /// <summary>The cycles, keyed <c>(style &lt;&lt; 16) | (substate &amp; 0xFFFFFF)</c> (retail <c>cycles</c>).</summary>
    internal readonly Dictionary<uint, MotionData> Cycles = new();

    /// <summary>The modifiers, keyed <c>(style &lt;&lt; 16) | (modifier &amp; 0xFFFFFF)</c> or the bare
    /// <c>modifier &amp; 0xFFFFFF</c> for every style (retail <c>modifiers</c>).</summary>
    internal readonly Dictionary<uint, MotionData> Modifiers = new();

    /// <summary>The links: outer key <c>(style &lt;&lt; 16) | (from &amp; 0xFFFFFF)</c>, inner key the motion they lead to
    /// (retail <c>links</c>).</summary>
    internal readonly Dictionary<uint, Dictionary<uint, MotionData>> Links = new();

    // retail: LongNIValHash<unsigned long>::lookup (acclient.c:304098), on style_defaults
    private bool TryStyleDefault(uint style, out uint substate) => StyleDefaults.TryGetValue(style, out substate);

    private MotionData? Cycle(uint key) => Cycles.TryGetValue(key, out MotionData? d) ? d : null;

    private MotionData? Modifier(uint key) => Modifiers.TryGetValue(key, out MotionData? d) ? d : null;

    // retail: LongHash<MotionData>::lookup (acclient.c:337534), on one inner links hash
    private static MotionData? Lookup(Dictionary<uint, MotionData> hash, uint key) =>
        hash.TryGetValue(key, out MotionData? d) ? d : null;

    /// <summary>True when <paramref name="a"/> and <paramref name="b"/> are both negative or both not (a NaN counts as not
    /// negative, as the x87 compare sets no "below" flag for it).</summary>
    // retail: same_sign (acclient.c:337250)
    internal static bool SameSign(float a, float b)
    {
        if (a < 0f)
        {
            if (b >= 0f)
            {
                return false;
            }
        }
        else if (b < 0f)
        {
            return false;
        }

        return true;
    }

    /// <summary>Scales the cyclic animations' framerate by <paramref name="newSpeed"/> / <paramref name="oldSpeed"/> (to 0
    /// when both are nearly 0; unchanged when only the old one is).</summary>
    // retail: change_cycle_speed (acclient.c:337268)
    internal static void ChangeCycleSpeed(AnimSequence sequence, MotionData? data, float oldSpeed, float newSpeed)
    {
        if (System.Math.Abs(oldSpeed) <= (double)Spatial.PhysicsGlobals.Epsilon)
        {
            if (System.Math.Abs(newSpeed) < (double)Spatial.PhysicsGlobals.Epsilon)
            {
                sequence.MultiplyCyclicAnimationFramerate(0f);
            }
        }
        else
        {
            float multiplier = newSpeed / oldSpeed;
            sequence.MultiplyCyclicAnimationFramerate(multiplier);
        }
    }

    /// <summary>Sets the sequence's velocity and omega to the data's times <paramref name="speedMod"/> and appends its
    /// animations with their framerate times <paramref name="speedMod"/>.</summary>
    // retail: add_motion (acclient.c:337430)
    internal static void AddMotion(AnimSequence sequence, MotionData? data, float speedMod)
    {
        if (data is null)
        {
            return;
        }

        sequence.SetVelocity(Scaled(speedMod, data.Velocity));
        sequence.SetOmega(Scaled(speedMod, data.Omega));
        AnimData[] anims = data.Anims;
        for (int i = 0; i < anims.Length; i++)
        {
            AnimData scaled = Scaled(speedMod, anims[i]);
            sequence.AppendAnimation(scaled);
        }
    }

    /// <summary>Adds the data's velocity and omega times <paramref name="speedMod"/> to the sequence's.</summary>
    // retail: combine_motion (acclient.c:337476)
    internal static void CombineMotion(AnimSequence sequence, MotionData? data, float speedMod)
    {
        if (data is null)
        {
            return;
        }

        Vector3 o = Scaled(speedMod, data.Omega);
        Vector3 v = Scaled(speedMod, data.Velocity);
        sequence.CombinePhysics(v, o);
    }

    /// <summary>Subtracts the data's velocity and omega times <paramref name="speedMod"/> from the sequence's.</summary>
    // retail: subtract_motion (acclient.c:337505)
    internal static void SubtractMotion(AnimSequence sequence, MotionData? data, float speedMod)
    {
        if (data is null)
        {
            return;
        }

        Vector3 o = Scaled(speedMod, data.Omega);
        Vector3 v = Scaled(speedMod, data.Velocity);
        sequence.SubtractPhysics(v, o);
    }

    // operator*(AnimData, float, AnimData) (acclient.c:341050): the framerate times the speed.
    // non-retail: the product is clamped to ±AnimData.MaxFramerate (the library's framerate bound), so that no speed makes the
    // tick throw; see docs/divergences.md.
    private static AnimData Scaled(float speedMod, in AnimData a)
    {
        float f = (float)((double)a.Framerate * speedMod);
        if (!AnimData.IsFramerateInDomain(f))
        {
            f = float.IsNaN(f) ? 0f : System.Math.Clamp(f, -AnimData.MaxFramerate, AnimData.MaxFramerate);
        }

        return new AnimData(a.AnimId, a.LowFrame, a.HighFrame, f);
    }

    // speed_mod * data, each product rounded to float (the x87 product of two floats is exact in double; one rounding).
    private static Vector3 Scaled(float s, Vector3 d) =>
        new((float)((double)s * d.X), (float)((double)s * d.Y), (float)((double)s * d.Z));

    /// <summary>Whether <paramref name="mdata"/> may start from <paramref name="state"/>: an entry flagged
    /// <see cref="MotionData.OnlyFromDefault"/> only from the style's default substate (or when it is the substate already).
    /// </summary>
    // retail: CMotionTable::is_allowed (acclient.c:337559)
    internal bool IsAllowed(uint motion, MotionData? mdata, MotionState state)
    {
        if (mdata is null)
        {
            return false;
        }

        if ((mdata.Bitfield & MotionData.OnlyFromDefault) != 0 && motion != state.Substate)
        {
            uint substate = state.Substate;
            // Retail looks the default up into the mdata variable and compares it with the substate; a style with no default
            // leaves the pointer there, which never equals a substate id.
            return TryStyleDefault(state.Style, out uint def) && def == substate;
        }

        return true;
    }

    /// <summary>The link from <paramref name="substate"/> to <paramref name="motion"/> in <paramref name="style"/> (played
    /// backwards from <paramref name="motion"/> when either speed is negative), falling back to the style-wide link.</summary>
    /// <returns>The link, or null.</returns>
    // retail: CMotionTable::get_link (acclient.c:337584)
    internal MotionData? GetLink(uint style, uint substate, float substateSpeed, uint motion, float speed)
    {
        MotionData? retval = null;
        uint styleKey = style << 16;
        if (speed < 0f || substateSpeed < 0f)
        {
            if (Links.TryGetValue(styleKey | (motion & 0xFFFFFF), out Dictionary<uint, MotionData>? inner))
            {
                retval = Lookup(inner, substate);
                if (retval is not null)
                {
                    return retval;
                }
            }
        }
        else if (Links.TryGetValue(styleKey | (substate & 0xFFFFFF), out Dictionary<uint, MotionData>? inner))
        {
            retval = Lookup(inner, motion);
            if (retval is not null)
            {
                return retval;
            }
        }

        if (speed < 0f || substateSpeed < 0f)
        {
            if (TryStyleDefault(style, out uint def)
                && Links.TryGetValue(styleKey | (substate & 0xFFFFFF), out Dictionary<uint, MotionData>? inner))
            {
                return Lookup(inner, def);
            }
        }
        else if (Links.TryGetValue(styleKey, out Dictionary<uint, MotionData>? inner))
        {
            return Lookup(inner, motion);
        }

        return retval;
    }

    // (MotionData*)x + 16 read as a byte: num_anims, 0 for a missing entry.
    private static uint N(MotionData? d) => d is null ? 0u : (uint)d.NumAnims;
}
