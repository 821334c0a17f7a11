using AcDream.Core.Physics.Motion;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class MovementSystemTests
{
    [Theory]
    // GetRunRate (acclient.c:713789), no load (LoadMod 1), scaling 1: (skill / (skill + 200) * 11 + 4) / 4.
    [InlineData(0, 1.0)]          // (0 + 4) / 4
    [InlineData(200, 2.375)]      // (0.5 * 11 + 4) / 4 = 9.5 / 4
    [InlineData(800, 4.5)]        // the special case 18 / 4 (the formula would give (0.8 * 11 + 4) / 4 = 3.2)
    public void GetRunRate_NoLoad(int skill, double expected) =>
        Assert.Equal(expected, MovementSystem.GetRunRate(0f, skill, 1f));

    [Fact]
    public void GetRunRate_Skill395_Is2Point8256()
    {
        // (395 / 595 * 11 + 4) / 4 = (7.302521 + 4) / 4 = 2.825630.
        Assert.Equal(2.82563, MovementSystem.GetRunRate(0f, 395, 1f), 5);
    }

    [Fact]
    public void GetRunRate_SkillAbove800_StaysBelow3Point75()
    {
        // 9999 / 10199 * 11 = 10.784; (10.784 + 4) / 4 = 3.696: only 800 exactly gets 4.5.
        Assert.Equal(3.696, MovementSystem.GetRunRate(0f, 9999, 1f), 3);
    }

    [Theory]
    // LoadMod (acclient.c:296776): 1 below a full load, 2 - load up to twice, 0 beyond.
    [InlineData(0f, 1.0)]
    [InlineData(0.99f, 1.0)]
    [InlineData(1.5f, 0.5)]
    [InlineData(2f, 0.0)]
    [InlineData(3f, 0.0)]
    public void LoadMod_Piecewise(float load, double expected) => Assert.Equal(expected, MovementSystem.LoadMod(load));

    [Fact]
    public void GetRunRate_HalfOverloaded_HalvesTheSkillTerm()
    {
        // Skill 200 at load 1.5: (0.5 * (0.5 * 11) + 4) / 4 = (2.75 + 4) / 4 = 1.6875.
        Assert.Equal(1.6875, MovementSystem.GetRunRate(1.5f, 200, 1f));
    }

    [Fact]
    public void Capacity_AndLoad()
    {
        // EncumbranceCapacity (acclient.c:296730): 150 * str + str * min(30 * aug, 150).
        Assert.Equal(1500, MovementSystem.EncumbranceCapacity(10, 0));
        Assert.Equal(15000 + 100 * 60, MovementSystem.EncumbranceCapacity(100, 2));
        Assert.Equal(15000 + 100 * 150, MovementSystem.EncumbranceCapacity(100, 9));
        Assert.Equal(0, MovementSystem.EncumbranceCapacity(0, 3));
        // Load (acclient.c:296757): burden / capacity; 3 with no capacity; 0 for a negative burden.
        Assert.Equal(0.5, MovementSystem.Load(1500, 750));
        Assert.Equal(3.0, MovementSystem.Load(0, 10));
        Assert.Equal(0.0, MovementSystem.Load(1500, -1));
    }

    [Theory]
    // GetJumpHeight (acclient.c:713805), no load: (s / (s + 1300) * 22.2f + 0.05f) * power, at least 0.35f.
    // s = 100: 100 / 1400 * 22.2 = 1.585714, + 0.05 = 1.635714; s = 300: 300 / 1600 * 22.2 = 4.1625, + 0.05 = 4.2125.
    [InlineData(100, 0f, 0.35)]
    [InlineData(100, 0.5f, 0.817857)]
    [InlineData(100, 1f, 1.635714)]
    [InlineData(300, 0.5f, 2.10625)]
    [InlineData(300, 1f, 4.2125)]
    [InlineData(300, 2f, 4.2125)]    // power clamped to 1
    public void GetJumpHeight(int skill, float power, double expected) =>
        Assert.Equal(expected, MovementSystem.GetJumpHeight(0f, skill, power, 1f), 5);

    [Theory]
    // InqJumpVelocity (acclient.c:443772): sqrt(h * 19.6). 0.35 * 19.6 = 6.86 -> 2.619160; 0.817857 * 19.6 = 16.0300
    // -> 4.003748; 1.635714 * 19.6 = 32.06 -> 5.662155; 2.10625 * 19.6 = 41.2825 -> 6.425146; 4.2125 * 19.6 = 82.565 -> 9.086529.
    [InlineData(100, 0f, 2.619160)]
    [InlineData(100, 0.5f, 4.003748)]
    [InlineData(100, 1f, 5.662155)]
    [InlineData(300, 0f, 2.619160)]
    [InlineData(300, 0.5f, 6.425146)]
    [InlineData(300, 1f, 9.086529)]
    public void PlayerWeenie_JumpVelocity(int skill, float extent, double expected)
    {
        var w = new PlayerWeenie { JumpSkill = skill };
        Assert.True(w.InqJumpVelocity(extent, out float vz));
        Assert.Equal(expected, vz, 5);
    }

    [Fact]
    public void JumpStaminaCost_Retail()
    {
        // JumpStaminaCost (acclient.c:713829): ceil((load + 0.5) * power * 8 + 2); PK: (power + 1) * 100.
        Assert.Equal(6, MovementSystem.JumpStaminaCost(1f, 0f, false));      // ceil(0.5 * 8 + 2) = 6
        Assert.Equal(4, MovementSystem.JumpStaminaCost(0.5f, 0f, false));    // ceil(2 + 2) = 4
        Assert.Equal(10, MovementSystem.JumpStaminaCost(1f, 0.5f, false));   // ceil(1.0 * 8 + 2) = 10
        Assert.Equal(150, MovementSystem.JumpStaminaCost(0.5f, 0f, true));   // 1.5 * 100
    }

    [Fact]
    public void PlayerWeenie_RunRate_FromSkillAndBurden_AndZeroStamina()
    {
        var w = new PlayerWeenie { RunSkill = 200, Strength = 10 };
        Assert.True(w.InqRunRate(out float r));
        Assert.Equal(2.375f, r);
        w.Burden = 2250;   // capacity 1500: load 1.5, LoadMod 0.5 -> 1.6875
        Assert.True(w.InqRunRate(out r));
        Assert.Equal(1.6875f, r);
        Assert.True(w.CanJump(1f));
        w.Burden = 3000;   // load 2: no jump (CanJump: load < 2)
        Assert.False(w.CanJump(1f));
        w.Burden = 0;
        w.Stamina = 0;     // exhausted: skill counts as 0 -> rate 1
        Assert.True(w.InqRunRate(out r));
        Assert.Equal(1f, r);
    }

    [Fact]
    public void RemoteCreatureWeenie_AnswersNothing()
    {
        IMotionWeenie w = RemoteCreatureWeenie.Creature;
        Assert.False(w.IsThePlayer);
        Assert.True(w.IsCreature);
        Assert.False(w.InqRunRate(out _));
        Assert.False(w.InqJumpVelocity(1f, out _));
        Assert.False(w.CanJump(1f));
        Assert.False(w.JumpStaminaCost(1f, out _));
    }
}
