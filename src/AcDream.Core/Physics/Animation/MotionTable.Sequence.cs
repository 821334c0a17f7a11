namespace AcDream.Core.Physics.Animation;

// CMotionTable's state logic: from a motion and the current state to the links and cycle queued on the sequence.
public sealed partial class MotionTable
{
    /// <summary>
    /// Plays <paramref name="motion"/> from <paramref name="state"/>: a style change (the links out of the old style and into
    /// the new one, then its default cycle), a substate (the link and the new cycle, or only a new speed for the same cycle),
    /// an action (its link, then back into the cycle) or a modifier (its velocity and omega on top of the cycle). Updates the
    /// state and gives in <paramref name="numAnims"/> the number of animations that end before the motion counts as done.
    /// </summary>
    /// <returns>False when the table has nothing for the motion from this state (nothing changes then).</returns>
    // retail: CMotionTable::GetObjectSequence (acclient.c:337640)
    internal bool GetObjectSequence(uint motion, MotionState state, AnimSequence sequence, float speedMod, out uint numAnims,
        bool stopModifiers)
    {
        numAnims = 0;
        if (state.Style == 0)
        {
            return false;
        }

        uint mtype2 = state.Substate;
        if (mtype2 == 0)
        {
            return false;
        }

        MotionData? link2 = null;
        MotionData? preLink = null;
        // Retail's lookups write into reused locals only on success; each local starts as what retail leaves there.
        uint newSubstate = 0;
        TryStyleDefault(state.Style, out newSubstate);
        if (motion == newSubstate && !stopModifiers && (mtype2 & 0x20000000) != 0)
        {
            return true;
        }

        // stop_modifiers is reused as a dword local below; it holds the flag (0 or 1) until a lookup writes it.
        uint stopVar = stopModifiers ? 1u : 0u;
        if ((motion & 0x80000000) != 0)
        {
            if (state.Style == motion)
            {
                return true;
            }

            if (TryStyleDefault(state.Style, out uint d0))
            {
                newSubstate = d0;
            }

            if (mtype2 != newSubstate)
            {
                preLink = GetLink(state.Style, mtype2, state.SubstateMod, newSubstate, speedMod);
            }

            if (TryStyleDefault(motion, out uint d1))
            {
                stopVar = d1;
                MotionData? link = Cycle((motion << 16) | (stopVar & 0xFFFFFF));
                if (link is not null)
                {
                    if ((link.Bitfield & MotionData.ClearsModifiers) != 0)
                    {
                        state.ClearModifiers();
                    }

                    MotionData? motiona = GetLink(state.Style, newSubstate, state.SubstateMod, motion, speedMod);
                    if (motiona is null && motion != state.Style)
                    {
                        motiona = GetLink(state.Style, newSubstate, 1f, _defaultStyle, 1f);
                        if (TryStyleDefault(_defaultStyle, out uint d2))
                        {
                            mtype2 = d2;
                        }

                        link2 = GetLink(_defaultStyle, mtype2, 1f, motion, 1f);
                    }

                    sequence.ClearPhysics();
                    sequence.RemoveCyclicAnims();
                    AddMotion(sequence, preLink, speedMod);
                    AddMotion(sequence, motiona, speedMod);
                    AddMotion(sequence, link2, speedMod);
                    AddMotion(sequence, link, speedMod);
                    state.Substate = stopVar;
                    state.Style = motion;
                    state.SubstateMod = speedMod;
                    ReModify(sequence, state);
                    numAnims = N(motiona) + N(link2) + N(link) + N(preLink) - 1;
                    return true;
                }
            }
        }

        if ((motion & 0x40000000) != 0)
        {
            MotionData? linka = Cycle((motion & 0xFFFFFF) | (state.Style << 16))
                                ?? Cycle((motion & 0xFFFFFF) | (_defaultStyle << 16));
            if (linka is not null && IsAllowed(motion, linka, state))
            {
                if (motion == mtype2 && SameSign(speedMod, state.SubstateMod) && sequence.HasAnims)
                {
                    ChangeCycleSpeed(sequence, linka, state.SubstateMod, speedMod);
                    SubtractMotion(sequence, linka, state.SubstateMod);
                    CombineMotion(sequence, linka, speedMod);
                    state.SubstateMod = speedMod;
                    return true;
                }

                if ((linka.Bitfield & MotionData.ClearsModifiers) != 0)
                {
                    state.ClearModifiers();
                }

                MotionData? motionb = GetLink(state.Style, state.Substate, state.SubstateMod, motion, speedMod);
                if (motionb is null || !SameSign(speedMod, state.SubstateMod))
                {
                    if (TryStyleDefault(state.Style, out uint d3))
                    {
                        stopVar = d3;
                    }

                    motionb = GetLink(state.Style, state.Substate, state.SubstateMod, stopVar, 1f);
                    link2 = GetLink(state.Style, stopVar, 1f, motion, speedMod);
                }

                sequence.ClearPhysics();
                sequence.RemoveCyclicAnims();
                if (link2 is not null)
                {
                    AddMotion(sequence, motionb, state.SubstateMod);
                    AddMotion(sequence, link2, speedMod);
                }
                else
                {
                    float s = state.SubstateMod >= 0f || speedMod <= 0f ? speedMod : -speedMod;
                    AddMotion(sequence, motionb, s);
                }

                AddMotion(sequence, linka, speedMod);
                uint old = state.Substate;
                if (old != motion && (old & 0x20000000) != 0)
                {
                    if (TryStyleDefault(state.Style, out uint d4))
                    {
                        stopVar = d4;
                    }

                    if (stopVar != motion)
                    {
                        state.AddModifierNoCheck(old, state.SubstateMod);
                    }
                }

                state.SubstateMod = speedMod;
                state.Substate = motion;
                ReModify(sequence, state);
                numAnims = N(motionb) + N(link2) + N(linka) - 1;
                return true;
            }
        }

        if ((motion & 0x10000000) != 0)
        {
            uint cycleKey = (mtype2 & 0xFFFFFF) | (state.Style << 16);
            MotionData? linkb = Cycle(cycleKey);
            if (linkb is not null)
            {
                MotionData? motionc = GetLink(state.Style, mtype2, state.SubstateMod, motion, speedMod);
                if (motionc is not null)
                {
                    state.AddAction(motion, speedMod);
                    sequence.ClearPhysics();
                    sequence.RemoveCyclicAnims();
                    AddMotion(sequence, motionc, speedMod);
                    AddMotion(sequence, linkb, state.SubstateMod);
                    ReModify(sequence, state);
                    numAnims = N(motionc);
                    return true;
                }

                if (TryStyleDefault(state.Style, out uint d5))
                {
                    newSubstate = d5;
                }

                MotionData? motiond = GetLink(state.Style, mtype2, state.SubstateMod, newSubstate, 1f);
                MotionData? link2a;
                MotionData? linkc;
                if (motiond is not null
                    && (link2a = GetLink(state.Style, newSubstate, 1f, motion, speedMod)) is not null
                    && (linkc = Cycle(cycleKey)) is not null)
                {
                    MotionData? back = GetLink(state.Style, newSubstate, 1f, mtype2, state.SubstateMod);
                    state.AddAction(motion, speedMod);
                    sequence.ClearPhysics();
                    sequence.RemoveCyclicAnims();
                    AddMotion(sequence, motiond, 1f);
                    AddMotion(sequence, link2a, speedMod);
                    AddMotion(sequence, back, 1f);
                    AddMotion(sequence, linkc, state.SubstateMod);
                    ReModify(sequence, state);
                    numAnims = N(motiond) + N(link2a);
                    if (back is not null)
                    {
                        numAnims += N(back);
                    }

                    return true;
                }
            }
        }

        // LABEL_80: a modifier on top of a cycle that keeps modifiers.
        if ((motion & 0x20000000) != 0)
        {
            uint styleKey = state.Style << 16;
            MotionData? cycle = Cycle(styleKey | (mtype2 & 0xFFFFFF));
            if (cycle is not null && (cycle.Bitfield & MotionData.ClearsModifiers) == 0)
            {
                MotionData? mod = Modifier(styleKey | (motion & 0xFFFFFF)) ?? Modifier(motion & 0xFFFFFF);
                if (mod is not null)
                {
                    // Retail hands StopSequenceMotion the address of its own num_anims parameter, so the caller's count
                    // stays the 0 set above.
                    bool added = state.AddModifier(motion, speedMod);
                    if (!added)
                    {
                        // Already on (or the substate): stop it, then add it again at the new speed.
                        StopSequenceMotion(motion, 1f, state, sequence, out _);
                        added = state.AddModifier(motion, speedMod);
                    }

                    if (added)
                    {
                        CombineMotion(sequence, mod, speedMod);
                        return true;
                    }
                }
            }
        }

        return false;
    }

    /// <summary>Re-applies the state's modifiers after the cycle changed: once per modifier the state had, its current head
    /// is taken off and played again.</summary>
    /// <remarks>Retail counts the passes on a copy of the state (<c>dummy_state</c>) but takes each pass's modifier from the
    /// real state's head, where <c>add_modifier_no_check</c> has just put the re-played one back; so with two modifiers the
    /// newest is played twice and the older not at all. The port counts the passes and keeps that order.</remarks>
    // retail: CMotionTable::re_modify (acclient.c:337285)
    internal void ReModify(AnimSequence sequence, MotionState state)
    {
        if (state.ModifierHead is null)
        {
            return;
        }

        int passes = state.ModifierCount;
        while (passes-- > 0)
        {
            MotionList head = state.ModifierHead!;
            uint motion = head.Motion;
            float speed = head.SpeedMod;
            state.RemoveModifier(head, null);
            GetObjectSequence(motion, state, sequence, speed, out _, false);
            if (state.ModifierHead is null)
            {
                // The dummy copy still counts passes, but a pass with an empty real list would read a null head in retail
                // (it cannot happen: a pass only empties the list when the modifier is refused and the list had one entry,
                // which was the last pass).
                break;
            }
        }
    }

    /// <summary>Stops <paramref name="motion"/>: the current substate goes back to the style's default (through
    /// <see cref="GetObjectSequence"/> with <c>stop_modifiers</c>), a modifier is subtracted and removed.</summary>
    /// <returns>False when the motion is neither the substate nor an active modifier with data.</returns>
    // retail: CMotionTable::StopSequenceMotion (acclient.c:337911)
    internal bool StopSequenceMotion(uint motion, float speed, MotionState state, AnimSequence sequence, out uint numAnims)
    {
        numAnims = 0;
        if ((motion & 0x40000000) != 0 && motion == state.Substate)
        {
            // A style without a default leaves retail's num_anims pointer in the motion variable: no motion id, so
            // GetObjectSequence refuses it; the port passes 0, which it refuses the same way.
            uint def = TryStyleDefault(state.Style, out uint d) ? d : 0u;
            GetObjectSequence(def, state, sequence, 1f, out numAnims, true);
            return true;
        }

        if ((motion & 0x20000000) == 0)
        {
            return false;
        }

        MotionList? prev = null;
        MotionList? node = state.ModifierHead;
        while (node is not null && node.Motion != motion)
        {
            prev = node;
            node = node.Next;
        }

        if (node is null)
        {
            return false;
        }

        uint low = motion & 0xFFFFFF;
        MotionData? mod = Modifier(low | (state.Style << 16)) ?? Modifier(low);
        if (mod is null)
        {
            return false;
        }

        SubtractMotion(sequence, mod, node.SpeedMod);
        state.RemoveModifier(node, prev);
        return true;
    }

    /// <summary>Stops <paramref name="motion"/>: retail's <c>StopObjectMotion</c> is its own 5-byte thunk (0x00523EC0 in the
    /// PDB), a tail jump to <c>StopSequenceMotion</c> (acclient.c:337911); the decompilation shows it no body.</summary>
    // retail: CMotionTable::StopObjectMotion (a 5-byte tail-jump thunk to CMotionTable::StopSequenceMotion, acclient.c:337911)
    internal bool StopObjectMotion(uint motion, float speed, MotionState state, AnimSequence sequence, out uint numAnims) =>
        StopSequenceMotion(motion, speed, state, sequence, out numAnims);

    /// <summary>Puts <paramref name="state"/> in the default style's default cycle, with no modifiers and no actions, and the
    /// sequence playing only that cycle.</summary>
    /// <returns>False when the table has no default cycle (nothing changes then).</returns>
    // retail: CMotionTable::SetDefaultState (acclient.c:337969)
    internal bool SetDefaultState(MotionState state, AnimSequence sequence, out uint numAnims)
    {
        numAnims = 0;
        if (!TryStyleDefault(_defaultStyle, out uint defaultSubstate))
        {
            return false;
        }

        state.ClearModifiers();
        state.ClearActions();
        MotionData? cycle = Cycle((_defaultStyle << 16) | (defaultSubstate & 0xFFFFFF));
        if (cycle is null)
        {
            return false;
        }

        state.Style = _defaultStyle;
        state.Substate = defaultSubstate;
        state.SubstateMod = 1f;
        numAnims = N(cycle) - 1;
        sequence.ClearPhysics();
        sequence.ClearAnimations();
        AddMotion(sequence, cycle, state.SubstateMod);
        return true;
    }

    /// <summary>Plays <paramref name="motion"/> (<see cref="GetObjectSequence"/> without stopping modifiers).</summary>
    // retail: CMotionTable::DoObjectMotion (acclient.c:339022)
    internal bool DoObjectMotion(uint motion, MotionState state, AnimSequence sequence, float speedMod, out uint numAnims) =>
        GetObjectSequence(motion, state, sequence, speedMod, out numAnims, false);

    /// <summary>Stops every modifier, then the substate.</summary>
    /// <returns>True when anything was stopped.</returns>
    // retail: CMotionTable::StopObjectCompletely (acclient.c:339028)
    internal bool StopObjectCompletely(MotionState state, AnimSequence sequence, out uint numAnims)
    {
        numAnims = 0;
        bool retval = false;
        for (MotionList? m = state.ModifierHead; m is not null; m = state.ModifierHead)
        {
            if (StopSequenceMotion(m.Motion, m.SpeedMod, state, sequence, out numAnims))
            {
                retval = true;
            }
            else
            {
                // non-retail: a modifier the table cannot stop (a substate with the modifier bit pushed by
                // GetObjectSequence, whose modifier data is missing) stayed at the head and retail looped forever; it is
                // dropped without subtracting anything. See docs/divergences.md.
                state.RemoveModifier(m, null);
            }
        }

        bool stopped = StopSequenceMotion(state.Substate, state.SubstateMod, state, sequence, out numAnims);
        return stopped || retval;
    }
}
