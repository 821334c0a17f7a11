using System;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// Retail's character movement formulas: run rate and jump height from skill and load, the jump's stamina cost, and the
/// load from strength and burden (retail <c>MovementSystem</c> and <c>EncumbranceSystem</c>, PORTAL/gameplay_misc).
/// Pure functions of their arguments.
/// </summary>
public static class MovementSystem
{
    /// <summary>The run skill that gets the fixed top rate <see cref="TopRunRate"/> (800).</summary>
    public const double TopRunSkill = 800.0;

    /// <summary>The run rate of exactly <see cref="TopRunSkill"/>: <c>18 / 4</c> = 4.5 (acclient.c:713789). Any other skill
    /// stays below 15 / 4 = 3.75.</summary>
    public const double TopRunRate = 18.0 / 4.0;

    /// <summary>The lowest jump height, metres: <c>0.35f</c> (bits 0x3EB33333; acclient.c:713805).</summary>
    public const float MinJumpHeight = 0.35f;

    /// <summary>Twice gravity, m/s²: the launch speed of a jump of height h is sqrt(19.6 h) (acclient.c:443772).</summary>
    public const double TwiceGravity = 19.6;

    /// <summary>The load modifier: 1 up to a full load, falling linearly to 0 at twice the capacity.</summary>
    // retail: EncumbranceSystem::LoadMod (acclient.c:296776)
    public static double LoadMod(float load)
    {
        if (load < 1.0)
        {
            return 1.0;
        }

        return load >= 2.0 ? 0.0 : 2.0 - load;
    }

    /// <summary>The burden a character can carry before its load exceeds 1: 150 per strength point, plus 30 per
    /// augmentation (at most 150) per strength point; 0 for no strength.</summary>
    // retail: EncumbranceSystem::EncumbranceCapacity (acclient.c:296730)
    public static int EncumbranceCapacity(int strength, int encumbranceAugmentations)
    {
        if (strength <= 0)
        {
            return 0;
        }

        int aug = 30 * encumbranceAugmentations;
        if (aug < 0)
        {
            return 150 * strength;
        }

        if (aug > 150)
        {
            aug = 150;
        }

        return 150 * strength + strength * aug;
    }

    /// <summary>The load: burden over capacity (3 with no capacity, 0 for a negative burden).</summary>
    // retail: EncumbranceSystem::Load (acclient.c:296757)
    public static double Load(int encumbranceCapacity, int burden)
    {
        if (encumbranceCapacity <= 0)
        {
            return 3.0;
        }

        return burden >= 0 ? (double)burden / encumbranceCapacity : 0.0;
    }

    /// <summary>The run rate: <c>(LoadMod(load) * (skill / (skill + 200) * 11) + 4) / scaling / 4</c>, or 4.5 for a skill
    /// of exactly 800. Skill 200, no load: (0.5 * 11 + 4) / 4 = 2.375.</summary>
    // retail: MovementSystem::GetRunRate (acclient.c:713789)
    public static double GetRunRate(float load, int runSkill, float scaling)
    {
        double mod = LoadMod(load);
        double skill = runSkill;
        if (skill == TopRunSkill)
        {
            return TopRunRate;
        }

        return (mod * (skill / (skill + 200.0) * 11.0) + 4.0) / scaling / 4.0;
    }

    /// <summary>The jump height, metres: <c>LoadMod(load) * (skill / (skill + 1300) * 22.2 + 0.05) * power / scaling</c>,
    /// power clamped to 0..1, at least <see cref="MinJumpHeight"/>.</summary>
    // retail: MovementSystem::GetJumpHeight (acclient.c:713805)
    public static double GetJumpHeight(float load, int jumpSkill, float power, float scaling)
    {
        if (power > 1.0f)
        {
            power = 1.0f;
        }
        else if (power < 0.0f)
        {
            power = 0.0f;
        }

        // Retail reuses a float argument slot for the skill: it is rounded to float.
        float skill = jumpSkill;
        double result = LoadMod(load) * ((double)skill / (skill + 1300.0) * (double)22.2f + (double)0.05f) * power / scaling;
        if (result < (double)MinJumpHeight)
        {
            result = (double)MinJumpHeight;
        }

        return result;
    }

    /// <summary>The stamina a jump costs: <c>ceil((load + 0.5) * power * 8 + 2)</c>, or <c>(power + 1) * 100</c> for a
    /// player killer who attacked in the last 20 s.</summary>
    // retail: MovementSystem::JumpStaminaCost (acclient.c:713829)
    public static long JumpStaminaCost(float power, float load, bool recentPlayerKiller)
    {
        if (recentPlayerKiller)
        {
            return (long)((power + 1.0) * 100.0);
        }

        return (long)Math.Ceiling((load + 0.5) * power * 8.0 + 2.0);
    }

    /// <summary>The launch speed of a jump of height <paramref name="height"/>: <c>(float)sqrt(height * 19.6)</c>.</summary>
    // retail: CACQualities::InqJumpVelocity (acclient.c:443772), its last statement
    public static float JumpVelocity(double height) => (float)Math.Sqrt(height * TwiceGravity);
}
