using System;
using System.Numerics;
using System.Runtime.InteropServices;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// The sequence's root-motion memo (#38, AnimSequence.RootMotionMemo.cs): the first frame an update crosses from an identity
/// offset frame is copied from what the same key gave before. Two sequences run the same script, one with the memo and one
/// without (<see cref="AnimSequence.UsesRootMotionMemo"/>), and every offset frame (all 64 bytes) and frame number must
/// match. Each input of the key changes between updates whose other inputs repeat, so a key missing one of them gives a
/// stale frame and fails the test.
/// </summary>
[Trait("Category", "Determinism")]
public class RootMotionMemoTests
{
    private const uint ClipA = 0x03000020, ClipB = 0x03000021, ClipShort = 0x03000022, ClipLong = 0x03000023;

    private static readonly Vector3 V1 = new(0f, 1f, 0f), V2 = new(0.25f, 1.5f, -0.125f);
    private static readonly Vector3 W1 = new(0f, 0f, 0.5f), W2 = new(0.125f, -0.25f, 0.75f);

    // A clip whose frames turn and move by different amounts (frame k of A and of B differ).
    private static AnimClip Clip(uint id, int frames, int seed)
    {
        var rng = new Random(seed);
        var pos = new AFrame[frames];
        var parts = new AnimFrame[frames];
        for (int i = 0; i < frames; i++)
        {
            var axis = Vector3.Normalize(new Vector3((float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() - 0.5f, 1f));
            pos[i] = new AFrame(new Vector3((float)rng.NextDouble() * 0.2f, (float)rng.NextDouble() * 0.2f, 0f),
                Quaternion.CreateFromAxisAngle(axis, (float)rng.NextDouble() * 0.05f));
            parts[i] = new AnimFrame([AFrame.Identity], null, 0);
        }

        return new AnimClip(id, 1, pos, parts, hasHooks: false);
    }

    private static AnimationLibrary Library()
    {
        var lib = new AnimationLibrary();
        lib.Add(Clip(ClipA, 30, 1));
        lib.Add(Clip(ClipB, 30, 2));
        lib.Add(Clip(ClipShort, 6, 3));
        lib.Add(Clip(ClipLong, 70, 4));
        return lib;
    }

    // The same sequence twice, memo on and memo off, driven by the same calls.
    private sealed class Pair
    {
        public readonly AnimSequence On, Off;
        private Frame _on = Frame.Identity, _off = Frame.Identity;
        public int Updates;

        public Pair(Vector3 velocity, Vector3 omega)
        {
            AnimationLibrary lib = Library();
            On = new AnimSequence(lib);
            Off = new AnimSequence(lib) { UsesRootMotionMemo = false };
            Do(s =>
            {
                s.SetVelocity(velocity);
                s.SetOmega(omega);
            });
        }

        public void Do(Action<AnimSequence> action)
        {
            action(On);
            action(Off);
        }

        public void Play(uint clip, float framerate = 30f) => Do(s =>
        {
            s.ClearAnimations();
            s.AppendAnimation(new AnimData(clip, 0, -1, framerate));
        });

        // One update of both into a fresh identity offset frame (or on from the last one), compared bit for bit.
        public void Update(double quantum, bool fresh = true)
        {
            if (fresh)
            {
                _on = Frame.Identity;
                _off = Frame.Identity;
            }

            On.Update(quantum, ref _on);
            Off.Update(quantum, ref _off);
            Updates++;
            Assert.True(SameBits(_on, _off), $"update {Updates}: memo {Describe(_on)}, computed {Describe(_off)}");
            Assert.Equal(BitConverter.DoubleToInt64Bits(Off.FrameNumber), BitConverter.DoubleToInt64Bits(On.FrameNumber));
        }

        public void Ticks(int n, double quantum = 1.0 / 30.0)
        {
            for (int i = 0; i < n; i++)
            {
                Update(quantum);
            }
        }
    }

    private static bool SameBits(Frame a, Frame b) =>
        MemoryMarshal.AsBytes(MemoryMarshal.CreateReadOnlySpan(ref a, 1))
            .SequenceEqual(MemoryMarshal.AsBytes(MemoryMarshal.CreateReadOnlySpan(ref b, 1)));

    private static string Describe(Frame f) => $"{f.Origin} {f.Rotation}";

    // The frames of A kept at 30 frames per second in steps of 1/30 s: 0 to 28. The update that reaches the end stops at
    // the high frame (29) without crossing it, and advance_to_next_animation combines the next cycle's frame 0 (not the
    // first crossing of the loop, so not from the memo).
    private const int KeptOfA = 29;

    public enum KeyInput
    {
        Velocity,
        Omega,
        Framerate,
        Direction,
        Clip,
    }

    [Theory]
    [InlineData(KeyInput.Velocity)]
    [InlineData(KeyInput.Omega)]
    [InlineData(KeyInput.Framerate)]
    [InlineData(KeyInput.Direction)]
    [InlineData(KeyInput.Clip)]
    public void EachKeyInputChanged_GivesTheComputedFrame(KeyInput input)
    {
        // A cycle played long enough to keep every frame, then one input changes and the same frames are crossed again:
        // a key without that input would hand back the frames kept before the change.
        var pair = new Pair(V1, W1);
        pair.Play(ClipA);
        pair.Ticks(65);
        Assert.Equal(KeptOfA, pair.On.RootMotionMemoEntries());
        Assert.Equal(0, pair.Off.RootMotionMemoSize);
        double quantum = 1.0 / 30.0;
        switch (input)
        {
            case KeyInput.Velocity:
                pair.Do(s => s.SetVelocity(V2));
                break;
            case KeyInput.Omega:
                pair.Do(s => s.SetOmega(W2));
                break;
            case KeyInput.Framerate:
                // 45 frames per second: each update crosses one or two frames, the first from the memo's key (45 f/s).
                pair.Do(s => s.MultiplyCyclicAnimationFramerate(1.5f));
                break;
            case KeyInput.Direction:
                // Time run backwards through an animation queued at a negative framerate: the frames are crossed upwards
                // (framerate × quantum > 0, the same loop), apply_physics with s = -1/30.
                pair.Play(ClipA, -30f);
                quantum = -1.0 / 30.0;
                break;
            case KeyInput.Clip:
                // Another animation with as many frames: the same frame indices, other root motion.
                pair.Do(s =>
                {
                    s.RemoveCyclicAnims();
                    s.AppendAnimation(new AnimData(ClipB, 0, -1, 30f));
                });
                break;
        }

        pair.Ticks(65, quantum);

        // And back: the first input's frames again (kept or worked out anew, the same bits).
        switch (input)
        {
            case KeyInput.Velocity:
                pair.Do(s => s.SetVelocity(V1));
                break;
            case KeyInput.Omega:
                pair.Do(s => s.SetOmega(W1));
                break;
            case KeyInput.Framerate:
                pair.Do(s => s.MultiplyCyclicAnimationFramerate(1f / 1.5f));
                break;
            case KeyInput.Direction:
                pair.Play(ClipA);
                quantum = 1.0 / 30.0;
                break;
            case KeyInput.Clip:
                pair.Play(ClipA);
                break;
        }

        pair.Ticks(65, quantum);
    }

    [Fact]
    public void FramesThatShareAnEntry_AreKeptApart()
    {
        // 70 frames in 32 entries: frames k, k + 32 and k + 64 take the same entry, the same clip, framerate and physics.
        var pair = new Pair(V1, W1);
        pair.Play(ClipLong);
        pair.Ticks(250);
    }

    [Fact]
    public void TheMemoIsRead_APoisonedEntryShows()
    {
        // The check that the comparisons above compare something: with the kept frames overwritten (a NaN origin), the next
        // update from identity copies one.
        var pair = new Pair(V1, W1);
        pair.Play(ClipA);
        pair.Ticks(31);
        Assert.Equal(KeptOfA, pair.On.RootMotionMemoEntries(poison: true));
        Frame f = Frame.Identity;
        pair.On.Update(1.0 / 30.0, ref f);
        Assert.True(float.IsNaN(f.Origin.X));
    }

    [Fact]
    public void ANonIdentityStart_AndTheLaterFramesOfAnUpdate_AreComputed()
    {
        var pair = new Pair(V2, W2);
        pair.Play(ClipA);
        pair.Ticks(40);
        for (int i = 0; i < 40; i++)
        {
            pair.Update(1.0 / 30.0, fresh: false); // on from the last offset frame: never the identity
        }

        pair.Ticks(40, 3.5 / 30.0); // three or four frames per update: the first from the memo, the others computed
        pair.Ticks(40, 0.4 / 30.0); // a frame every few updates, and the remainder's apply_physics
    }

    [Fact]
    public void TheMemo_IsMadeWhenRootMotionIsQueued_SizedToTheClip()
    {
        var seq = new AnimSequence(Library());
        Assert.Equal(0, seq.RootMotionMemoSize);
        seq.AppendAnimation(new AnimData(ClipShort, 0, -1, 30f));
        Assert.Equal(8, seq.RootMotionMemoSize);
        seq.AppendAnimation(new AnimData(ClipA, 0, -1, 30f));
        Assert.Equal(32, seq.RootMotionMemoSize);
        seq.AppendAnimation(new AnimData(ClipLong, 0, -1, 30f));
        Assert.Equal(32, seq.RootMotionMemoSize);
        seq.UsesRootMotionMemo = false;
        Assert.Equal(0, seq.RootMotionMemoSize);
        seq.AppendAnimation(new AnimData(ClipA, 0, -1, 30f));
        Assert.Equal(0, seq.RootMotionMemoSize);
        seq.UsesRootMotionMemo = true;
        Assert.Equal(32, seq.RootMotionMemoSize);
    }

    [Fact]
    public void ARandomScript_MatchesWithoutTheMemo()
    {
        // Links and cycles of several lengths (a 70-frame clip shares the 32 entries: k and k + 32 collide), velocity and
        // omega from small sets (so keys repeat), framerate changes, both directions, steps of several sizes.
        var rng = new Random(3838);
        var pair = new Pair(V1, W1);
        uint[] clips = [ClipA, ClipB, ClipShort, ClipLong];
        Vector3[] velocities = [V1, V2, Vector3.Zero, new Vector3(-0f, 1f, 0f)];
        Vector3[] omegas = [W1, W2, Vector3.Zero, new Vector3(0f, 0f, -0.5f)];
        double[] quanta = [1.0 / 30.0, 1.0 / 30.0, 1.0 / 30.0, 2.0 / 30.0, 1.0 / 60.0, -1.0 / 30.0, 0.25];
        pair.Play(ClipA);
        for (int i = 0; i < 20_000; i++)
        {
            switch (rng.Next(64))
            {
                case 0:
                    Vector3 v = velocities[rng.Next(velocities.Length)];
                    pair.Do(s => s.SetVelocity(v));
                    break;
                case 1:
                    Vector3 w = omegas[rng.Next(omegas.Length)];
                    pair.Do(s => s.SetOmega(w));
                    break;
                case 2:
                    float m = rng.Next(3) switch { 0 => -1f, 1 => 2f, _ => 0.5f };
                    pair.Do(s => s.MultiplyCyclicAnimationFramerate(m));
                    break;
                case 3:
                    uint link = clips[rng.Next(clips.Length)], cycle = clips[rng.Next(clips.Length)];
                    float fr = rng.Next(3) == 0 ? -30f : 30f;
                    pair.Do(s =>
                    {
                        s.RemoveCyclicAnims();
                        s.AppendAnimation(new AnimData(link, 0, -1, fr));
                        s.AppendAnimation(new AnimData(cycle, 0, -1, 30f));
                    });
                    break;
                case 4:
                    pair.Play(clips[rng.Next(clips.Length)], rng.Next(2) == 0 ? 30f : 15f);
                    break;
            }

            pair.Update(quanta[rng.Next(quanta.Length)], fresh: rng.Next(16) != 0);
        }
    }
}
