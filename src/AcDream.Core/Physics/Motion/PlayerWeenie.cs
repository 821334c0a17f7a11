namespace AcDream.Core.Physics.Motion;

/// <summary>
/// A player character for the motion interpreter, with retail's formulas (retail <c>ACCWeenieObject</c> answering from
/// <c>CACQualities</c>): run rate from the run skill and the load, jump velocity from the jump skill, the charge and the
/// load, jumps refused at twice the capacity, the jump's stamina cost. The client keeps the skills and burden current.
/// </summary>
/// <remarks>
/// <para>Retail adds the skill's base, training, augmentation and enchantment terms before these formulas
/// (<c>CACQualities::InqRunRate</c>, acclient.c:443695); here <see cref="RunSkill"/> and <see cref="JumpSkill"/> are those
/// sums, the skill as the character sheet shows it.</para>
/// <para>Skills must not be negative (a skill of -200 or -1300 would divide by zero); every other value gives a finite
/// rate (negative burdens count as none, no strength gives load 3).</para>
/// </remarks>
public sealed class PlayerWeenie : IMotionWeenie
{
    /// <summary>Effective run skill (retail skill 0x18). 200 gives a run rate of 2.375.</summary>
    /// <exception cref="System.ArgumentOutOfRangeException">The value is negative (unchanged).</exception>
    public int RunSkill
    {
        get => _runSkill;
        set
        {
            System.ArgumentOutOfRangeException.ThrowIfNegative(value);
            _runSkill = value;
        }
    }

    private int _runSkill;

    /// <summary>Effective jump skill (retail skill 0x16).</summary>
    /// <exception cref="System.ArgumentOutOfRangeException">The value is negative (unchanged).</exception>
    public int JumpSkill
    {
        get => _jumpSkill;
        set
        {
            System.ArgumentOutOfRangeException.ThrowIfNegative(value);
            _jumpSkill = value;
        }
    }

    private int _jumpSkill;

    /// <summary>Strength attribute (retail attribute 1; 10 when the client has none).</summary>
    public int Strength { get; set; } = 10;

    /// <summary>Encumbrance augmentations (retail int 0xE6).</summary>
    public int EncumbranceAugmentations { get; set; }

    /// <summary>Burden carried, in burden units (retail int 5, encumbrance value).</summary>
    public int Burden { get; set; }

    /// <summary>Current stamina (retail attribute2nd 4): at 0 both skills count as 0.</summary>
    public int Stamina { get; set; } = 100;

    /// <summary>A player killer who attacked another in the last 20 s: jumps then cost (extent + 1) × 100 stamina.</summary>
    public bool RecentPlayerKiller { get; set; }

    /// <inheritdoc />
    public bool IsThePlayer { get; set; } = true;

    /// <inheritdoc />
    public bool IsCreature => true;

    /// <inheritdoc />
    public bool IsPlayer => true;

    /// <inheritdoc />
    public bool IsImpenetrable { get; set; }

    /// <inheritdoc />
    public bool IsPK { get; set; }

    /// <inheritdoc />
    public bool IsPKLite { get; set; }

    /// <summary>The load: burden over capacity, as a float.</summary>
    // retail: CACQualities::InqLoad (acclient.c:439761)
    public float InqLoad() =>
        (float)MovementSystem.Load(MovementSystem.EncumbranceCapacity(Strength, EncumbranceAugmentations), Burden);

    /// <inheritdoc />
    // retail: CACQualities::InqRunRate (acclient.c:443695), with the skill's terms summed into RunSkill
    public bool InqRunRate(out float rate)
    {
        float load = InqLoad();
        int skill = Stamina == 0 ? 0 : RunSkill;
        rate = (float)MovementSystem.GetRunRate(load, skill, 1.0f);
        return true;
    }

    /// <inheritdoc />
    // retail: CACQualities::InqJumpVelocity (acclient.c:443772), with the skill's terms summed into JumpSkill
    public bool InqJumpVelocity(float extent, out float vz)
    {
        float load = InqLoad();
        int skill = Stamina == 0 ? 0 : JumpSkill;
        vz = MovementSystem.JumpVelocity(MovementSystem.GetJumpHeight(load, skill, extent, 1.0f));
        return true;
    }

    /// <inheritdoc />
    // retail: CACQualities::CanJump (acclient.c:442877)
    public bool CanJump(float extent) => InqLoad() < 2.0;

    /// <inheritdoc />
    // retail: CACQualities::JumpStaminaCost (acclient.c:442886)
    public bool JumpStaminaCost(float extent, out int cost)
    {
        cost = (int)MovementSystem.JumpStaminaCost(extent, InqLoad(), RecentPlayerKiller);
        return true;
    }
}
