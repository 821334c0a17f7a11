namespace AcDream.Core.Physics.Animation;

/// <summary>
/// The state a motion table plays from: the style, the substate (cycle) and its speed, the modifiers on top of the cycle
/// and the actions still playing (retail <c>MotionState</c>, PORTAL/canim/CMotionPrim.c).
/// </summary>
internal sealed class MotionState
{
    // Free nodes (non-retail: retail deletes them; see MotionList).
    private MotionList? _free;

    /// <summary>The style (retail <c>style</c>).</summary>
    public uint Style;

    /// <summary>The substate (retail <c>substate</c>).</summary>
    public uint Substate;

    /// <summary>The substate's speed (retail <c>substate_mod</c>).</summary>
    public float SubstateMod;

    /// <summary>The newest modifier first (retail <c>modifier_head</c>).</summary>
    public MotionList? ModifierHead;

    /// <summary>The oldest action still playing (retail <c>action_head</c>).</summary>
    public MotionList? ActionHead;

    /// <summary>The newest action (retail <c>action_tail</c>).</summary>
    public MotionList? ActionTail;

    /// <summary>An empty state: no style, no substate, speed 1.</summary>
    // retail: MotionState::MotionState (acclient.c:341302)
    public MotionState()
    {
        Style = 0;
        Substate = 0;
        SubstateMod = 1f; // 1065353216 = 0x3F800000
        ModifierHead = null;
        ActionHead = null;
        ActionTail = null;
    }

    /// <summary>A copy of <paramref name="s"/> (its lists copied node by node).</summary>
    // retail: MotionState::MotionState (acclient.c:341986)
    public MotionState(MotionState s)
    {
        Copy(s);
    }

    private MotionList NewNode(uint motion, float speedMod)
    {
        MotionList? n = _free;
        if (n is null)
        {
            n = new MotionList();
        }
        else
        {
            _free = n.Next;
        }

        n.Motion = motion;
        n.SpeedMod = speedMod;
        n.Next = null;
        return n;
    }

    private void Delete(MotionList node)
    {
        node.Next = _free;
        _free = node;
    }

    /// <summary>Pushes a modifier at the head without looking for a duplicate.</summary>
    // retail: MotionState::add_modifier_no_check (acclient.c:341313)
    public void AddModifierNoCheck(uint modifier, float speedMod)
    {
        MotionList node = NewNode(modifier, speedMod);
        node.Next = ModifierHead;
        ModifierHead = node;
    }

    /// <summary>Unlinks <paramref name="curr"/> (whose predecessor is <paramref name="prev"/>, null at the head).</summary>
    // retail: MotionState::remove_modifier (acclient.c:341337)
    public void RemoveModifier(MotionList curr, MotionList? prev)
    {
        if (prev is not null)
        {
            prev.Next = curr.Next;
        }
        else
        {
            ModifierHead = curr.Next;
        }

        Delete(curr);
    }

    /// <summary>Drops every modifier.</summary>
    // retail: MotionState::clear_modifiers (acclient.c:341352)
    public void ClearModifiers()
    {
        MotionList? n = ModifierHead;
        while (n is not null)
        {
            MotionList d = n;
            n = n.Next;
            Delete(d);
        }

        ModifierHead = null;
    }

    /// <summary>Appends an action at the tail.</summary>
    // retail: MotionState::add_action (acclient.c:341370)
    public void AddAction(uint action, float speedMod)
    {
        MotionList node = NewNode(action, speedMod);
        node.Next = null;
        if (ActionHead is null)
        {
            ActionHead = node;
        }

        if (ActionTail is not null)
        {
            ActionTail.Next = node;
        }

        ActionTail = node;
    }

    /// <summary>Drops every action.</summary>
    // retail: MotionState::clear_actions (acclient.c:341400)
    public void ClearActions()
    {
        MotionList? n = ActionHead;
        while (n is not null)
        {
            MotionList d = n;
            n = n.Next;
            Delete(d);
        }

        ActionHead = null;
        ActionTail = null;
    }

    /// <summary>Removes the oldest action.</summary>
    /// <returns>Its motion, or 0 when there is none.</returns>
    // retail: MotionState::remove_action_head (acclient.c:341419)
    public uint RemoveActionHead()
    {
        MotionList? head = ActionHead;
        uint result = 0;
        if (head is not null)
        {
            MotionList? next = head.Next;
            uint motion = head.Motion;
            ActionHead = next;
            if (next is null)
            {
                ActionTail = null;
            }

            Delete(head);
            result = motion;
        }

        return result;
    }

    /// <summary>Becomes a copy of <paramref name="s"/>: the same style, substate and speed, and copies of its lists in order.</summary>
    // retail: MotionState::copy (acclient.c:341489)
    public void Copy(MotionState s)
    {
        ClearModifiers();
        ClearActions();
        Style = s.Style;
        Substate = s.Substate;
        SubstateMod = s.SubstateMod;
        MotionList? tail = null;
        for (MotionList? m = s.ModifierHead; m is not null; m = m.Next)
        {
            MotionList node = NewNode(m.Motion, m.SpeedMod);
            if (tail is null)
            {
                ModifierHead = node;
            }
            else
            {
                tail.Next = node;
            }

            tail = node;
        }

        for (MotionList? a = s.ActionHead; a is not null; a = a.Next)
        {
            AddAction(a.Motion, a.SpeedMod);
        }
    }

    /// <summary>Adds a modifier unless it is already on or is the substate itself.</summary>
    /// <returns>True when added.</returns>
    // retail: MotionState::add_modifier (acclient.c:341618)
    public bool AddModifier(uint modifier, float speedMod)
    {
        for (MotionList? m = ModifierHead; m is not null; m = m.Next)
        {
            if (m.Motion == modifier)
            {
                return false;
            }
        }

        if (Substate == modifier)
        {
            return false;
        }

        AddModifierNoCheck(modifier, speedMod);
        return true;
    }

    /// <summary>Number of modifiers.</summary>
    public int ModifierCount
    {
        get
        {
            int n = 0;
            for (MotionList? m = ModifierHead; m is not null; m = m.Next)
            {
                n++;
            }

            return n;
        }
    }

    /// <summary>Number of actions.</summary>
    public int ActionCount
    {
        get
        {
            int n = 0;
            for (MotionList? a = ActionHead; a is not null; a = a.Next)
            {
                n++;
            }

            return n;
        }
    }
}
