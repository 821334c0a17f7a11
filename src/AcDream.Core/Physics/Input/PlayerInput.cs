using System;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Input;

/// <summary>
/// The player's movement keys turned into motion commands as retail's command interpreter sends them (retail
/// <c>CommandInterpreter</c>, PORTAL/cmdinterp/CmdInterp.c, with <c>ACCmdInterp</c>'s key table and
/// <c>ClientCombatSystem</c>'s jump charge): the keyboard path of an autonomous player without mouse turning. A client
/// drives it from its own input, by events (<see cref="KeyDown"/>, <see cref="KeyUp"/>) or by the keys held each frame
/// (<see cref="SetHeldKeys"/>), before <see cref="World.PhysicsWorld.Tick"/>.
/// </summary>
/// <remarks>
/// <para>What each key sends (acclient.c lines of the decompilation):</para>
/// <list type="bullet">
/// <item>Forward / Backward / TurnRight / TurnLeft / StrafeRight / StrafeLeft down: <c>DoMotion(command)</c> with speed 1 and
/// hold key Invalid (the raw state's current hold key applies), the command becoming the head of its list (forward and
/// backward share the substate list; the two turns the turn list; the two side-steps the side-step list)
/// (<c>ACCmdInterp::OnAction</c> 435950, <c>CommandInterpreter::HandleKeyboardCommand</c> 717224, <c>AddCommand</c> 717428,
/// <c>MovePlayer</c> 717799).</item>
/// <item>Its key up: when it was the head of its list, the key held before it in the list takes over
/// (<c>DoMotion</c> of that command), or, none held, <c>StopMotion(command)</c>; a key that was not the head sends nothing
/// (<c>NukeCommand</c> 717457). So the newest of two opposite keys wins, and releasing it returns to the other.</item>
/// <item>Run down / up: the hold-run key (<c>CommandInterpreter::SetHoldRun</c> 716977): the interpreter's
/// <c>set_hold_run(held XOR RunByDefault, cancel_moveto = 1)</c>, which re-applies the movement (walk becomes run).</item>
/// <item>Jump down: <c>charge_jump</c> and the power bar starts (<c>ClientCombatSystem::CommenceJump</c> 408032). Jump up: the
/// bar's level, (now - start) / 1 s clamped to [0, 1] (0.8 s in style 0x80000046) and at least 0.001, is the extent of
/// <c>jump(extent)</c> (<c>DoJump</c> 408145, <c>GetPowerBarLevel</c> 407918, <c>FinishJump</c> 407624).</item>
/// </list>
/// <para>Times are the world's client clock (<see cref="World.PhysicsWorld.CurrentTime"/>, retail <c>Timer::cur_time</c>).
/// Network messages (retail's movement events) are the client's. Not ported: mouse turning and mouse-look, auto-run, the
/// side-step hold key, emotes and postures. Server control (retail <c>controlled_by_server</c>, the autonomy level) is in
/// <c>PlayerInput.ServerControl.cs</c>: it implements <see cref="Motion.Wire.IPlayerControl"/> for
/// <see cref="Motion.Wire.ServerMessageHandler.PlayerControl"/>.</para>
/// </remarks>
public sealed partial class PlayerInput
{
    // Retail MIN_JUMP_EXTENT (acclient_data.h: 0.001).
    internal const float MinJumpExtent = 0.001f;

    // The power bar's fill time in that style, seconds (1 s in the others).
    internal const double FastPowerBarSeconds = 0.8;

    // The style whose power bar fills in 0.8 s instead of 1 s (ClientCombatSystem::GetPowerBarLevel, acclient.c:407918).
    private const MotionCommand FastPowerBarStyle = (MotionCommand)0x80000046u;

    private readonly PhysicsObj _player;
    private readonly MovementManager _movement;
    private readonly MotionInterp _interp;
    private CommandList _substateList;
    private CommandList _turnList;
    private CommandList _sidestepList;
    private MovementKeys _held;
    private bool _holdRun;
    private bool _runByDefault;
    private bool _jumpPending;
    private double _buildStartTime;
    private readonly uint _actionStamp = 1;

    /// <summary>Creates the input of <paramref name="player"/>, the world's player: its retail movement manager and motion
    /// interpreter (created when absent) receive the commands.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="player"/> is null.</exception>
    /// <exception cref="InvalidOperationException">The player was removed from its world, or its movement manager is a client's
    /// own (not the retail <see cref="MovementManager"/>).</exception>
    public PlayerInput(PhysicsObj player)
    {
        ArgumentNullException.ThrowIfNull(player);
        if (player.RemovedFromWorld)
        {
            throw new InvalidOperationException("The player was removed from its world.");
        }

        _player = player;
        _movement = MovementManager.Of(player);
        _interp = _movement.GetOrCreateMotionInterpreter();
    }

    /// <summary>The keys held now.</summary>
    public MovementKeys HeldKeys => _held;

    /// <summary>The error of the last command the keys sent (<see cref="MotionError.None"/> when it was accepted): e.g.
    /// <see cref="MotionError.YouCantJumpFromThisPosition"/> for a jump charged lying down. Retail prints these.</summary>
    public MotionError LastError { get; private set; }

    /// <summary>
    /// The "run by default" option (retail's toggle-run player option, <c>PlayerModule::ToggleRun</c>): the character runs
    /// unless <see cref="MovementKeys.Run"/> is held, which then walks. Setting it applies the option alone at once, as
    /// retail's option handler does (<c>ACCmdInterp::RecvNotice_PlayerOptionChanged</c>, acclient.c:435916): set while the
    /// run key is held, the character runs with the option on and walks with it off until the key's next press or release,
    /// which applies key XOR option again.
    /// </summary>
    public bool RunByDefault
    {
        get => _runByDefault;
        // retail: ACCmdInterp::RecvNotice_PlayerOptionChanged (acclient.c:435916): set_hold_run(UITogglesRun(), 1)
        set
        {
            _runByDefault = value;
            _interp.SetHoldRun(value, cancelMoveToOnChange: true);
        }
    }

    /// <summary>The jump charge now, 0..1 (0 when no jump is being charged): the power bar's level, full after 1 s held
    /// (retail <c>ClientCombatSystem::GetJumpPowerLevel</c>, acclient.c:408080, without its 0.001 floor).</summary>
    public double JumpCharge => _jumpPending ? GetPowerBarLevel() : 0.0;

    /// <summary>Presses <paramref name="key"/> (a key already held is ignored: a key-repeat sends nothing).</summary>
    /// <param name="key">Exactly one key.</param>
    /// <exception cref="ArgumentException"><paramref name="key"/> is not exactly one defined key; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The player was removed from its world; nothing changes.</exception>
    public void KeyDown(MovementKeys key)
    {
        CheckOneKey(key);
        ThrowIfRemoved();
        if ((_held & key) == 0)
        {
            _held |= key;
            Transition(key, start: true);
        }
    }

    /// <summary>Releases <paramref name="key"/> (a key not held is ignored).</summary>
    /// <param name="key">Exactly one key.</param>
    /// <exception cref="ArgumentException"><paramref name="key"/> is not exactly one defined key; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The player was removed from its world; nothing changes.</exception>
    public void KeyUp(MovementKeys key)
    {
        CheckOneKey(key);
        ThrowIfRemoved();
        if ((_held & key) != 0)
        {
            _held &= ~key;
            Transition(key, start: false);
        }
    }

    /// <summary>Sets the keys held this frame: the keys released since the last call go up first, then the new keys go down,
    /// each in the order of <see cref="MovementKeys"/>' bits (a frame's key state does not say which came first).</summary>
    /// <param name="keys">The keys held now (any combination).</param>
    /// <exception cref="ArgumentException"><paramref name="keys"/> has a bit that is no key; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The player was removed from its world; nothing changes.</exception>
    public void SetHeldKeys(MovementKeys keys)
    {
        if ((keys & ~AllKeys) != 0)
        {
            throw new ArgumentException("Only the MovementKeys bits are keys.", nameof(keys));
        }

        ThrowIfRemoved();
        MovementKeys released = _held & ~keys;
        MovementKeys pressed = keys & ~_held;
        for (int bit = 0; bit < KeyCount; bit++)
        {
            var k = (MovementKeys)(1 << bit);
            if ((released & k) != 0)
            {
                _held &= ~k;
                Transition(k, start: false);
            }
        }

        for (int bit = 0; bit < KeyCount; bit++)
        {
            var k = (MovementKeys)(1 << bit);
            if ((pressed & k) != 0)
            {
                _held |= k;
                Transition(k, start: true);
            }
        }
    }

    /// <summary>Releases every key at once, as when the client window loses the keyboard: the lists are cleared, the run key
    /// is dropped, a jump being charged is cancelled (the jump key's later release jumps nothing) and the player stands
    /// (Ready), stops turning and side-stepping (retail <c>CommandInterpreter::LoseKeyboardFocus</c>, acclient.c:716868).</summary>
    /// <exception cref="InvalidOperationException">The player was removed from its world; nothing changes.</exception>
    // retail: CommandInterpreter::LoseKeyboardFocus (acclient.c:716868)
    public void ReleaseAll()
    {
        ThrowIfRemoved();
        _substateList.ClearKeyboardCommands();
        _turnList.ClearKeyboardCommands();
        _sidestepList.ClearKeyboardCommands();
        _held = MovementKeys.None;
        SetHoldRun(false);                                       // vtable slot 8 with 0
        FinishJump();                                            // vtable slot 20: ACCmdInterp::FinishJump, the jump cancel
        ApplyCurrentMovement();                                  // slot 7 (then slot 19, SendMovementEvent: the client's)
    }

    private const int KeyCount = 8;

    private const MovementKeys AllKeys = (MovementKeys)((1 << KeyCount) - 1);

    private static void CheckOneKey(MovementKeys key)
    {
        if (key == MovementKeys.None || (key & ~AllKeys) != 0 || (key & (key - 1)) != 0)
        {
            throw new ArgumentException("Exactly one key is pressed or released at a time (use SetHeldKeys for a key state).", nameof(key));
        }
    }

    private void ThrowIfRemoved()
    {
        if (_player.RemovedFromWorld)
        {
            throw new InvalidOperationException("The player was removed from its world.");
        }
    }

    // retail: ACCmdInterp::OnAction (acclient.c:435950): the key table
    private void Transition(MovementKeys key, bool start)
    {
        switch (key)
        {
            case MovementKeys.Forward:
                HandleKeyboardCommand(MotionCommand.WalkForward, start);
                break;
            case MovementKeys.Backward:
                HandleKeyboardCommand(MotionCommand.WalkBackwards, start);
                break;
            case MovementKeys.TurnRight:
                HandleKeyboardCommand(MotionCommand.TurnRight, start);
                break;
            case MovementKeys.TurnLeft:
                HandleKeyboardCommand(MotionCommand.TurnLeft, start);
                break;
            case MovementKeys.StrafeRight:
                HandleKeyboardCommand(MotionCommand.SideStepRight, start);
                break;
            case MovementKeys.StrafeLeft:
                HandleKeyboardCommand(MotionCommand.SideStepLeft, start);
                break;
            case MovementKeys.Run:
                // acclient.c:717262-717275: under server control a release only records the key; a press takes control back.
                if (_controlledByServer && !start)
                {
                    _holdRun = false;
                    break;
                }

                TakeControlFromServer();
                SetHoldRun(start);
                // acclient.c:717281: the run key's change is sent unless the player stands still
                if (!_interp.IsStandingStill())
                {
                    SendMovementEvent();
                }

                break;
            case MovementKeys.Jump:
                if (start)
                {
                    CommenceJump();
                }
                else
                {
                    DoJump();
                }

                break;
        }
    }

    /// <summary>A movement key's transition: bookkeeping in its list, then the command the list's head calls for.</summary>
    // retail: CommandInterpreter::HandleKeyboardCommand (acclient.c:717224), keyboard, client-controlled
    private void HandleKeyboardCommand(MotionCommand cmd, bool start)
    {
        // acclient.c:717262: while the server controls the player, a release only updates the lists (its move goes on)
        if (_controlledByServer && !start)
        {
            BookkeepCommandAndModifyIfNecessary(ref cmd, ref start);
            return;
        }

        // acclient.c:717275: a press takes control back first (stop completely, the held keys apply)
        TakeControlFromServer();
        if (!BookkeepCommandAndModifyIfNecessary(ref cmd, ref start))
        {
            return;
        }

        MovePlayer(cmd, start);
        SendMovementEvent();
    }

    // retail: CommandInterpreter::BookkeepCommandAndModifyIfNecessary (acclient.c:717498)
    private bool BookkeepCommandAndModifyIfNecessary(ref MotionCommand cmd, ref bool start)
    {
        ref CommandList list = ref WhichList(cmd);
        if (start)
        {
            // retail: CommandInterpreter::AddCommand (acclient.c:717428)
            list.AddCommand(cmd);
            return true;
        }

        // retail: CommandInterpreter::NukeCommand (acclient.c:717457): only the head's release moves; the next key takes over
        if (!list.RemoveCommand(cmd))
        {
            return false;
        }

        MotionCommand head = list.Head;
        if (head != MotionCommand.None)
        {
            cmd = head;
            start = true;
        }

        return true;
    }

    // retail: CommandInterpreter::WhichList (acclient.c:717401)
    private ref CommandList WhichList(MotionCommand cmd)
    {
        switch (cmd)
        {
            case MotionCommand.TurnRight:
            case MotionCommand.TurnLeft:
                return ref _turnList;
            case MotionCommand.SideStepRight:
            case MotionCommand.SideStepLeft:
                return ref _sidestepList;
            default:
                return ref _substateList;
        }
    }

    /// <summary>Sends a command to the motion interpreter: start with speed 1, the action stamp and the autonomous flag, hold key
    /// Invalid; stop with hold key Invalid. A dead player's keys send nothing and clear the lists.</summary>
    // retail: CommandInterpreter::MovePlayer (acclient.c:717799), keyboard branch (no mouse turning), autonomous player
    private void MovePlayer(MotionCommand cmd, bool start)
    {
        if (_interp.InterpretedState.ForwardCommand == MotionCommand.Dead)
        {
            // retail: PlayerIsDead (acclient.c:717694) -> ClearAllCommands, SetAutoRun(0, 0)
            _substateList.ClearKeyboardCommands();
            _turnList.ClearKeyboardCommands();
            _sidestepList.ClearKeyboardCommands();
            return;
        }

        if (start)
        {
            var p = new MovementParameters
            {
                ActionStamp = _actionStamp,
                Speed = 1f,
                HoldKeyToApply = HoldKey.Invalid,
            };
            p.Flags |= MovementParameterFlags.Autonomous;
            LastError = _movement.DoMotion(cmd, p);
        }
        else
        {
            var p = new MovementParameters { HoldKeyToApply = HoldKey.Invalid };
            LastError = _movement.StopMotion(cmd, p);
        }
    }

    /// <summary>The run key: <c>set_hold_run(held XOR UITogglesRun, 1)</c>. (<c>CommandInterpreter::UpdateToggleRun</c>,
    /// acclient.c:717626, would re-apply this XOR with the stored key, but nothing in the decompilation calls it directly
    /// and the option's handler, acclient.c:435916, calls <c>set_hold_run</c> itself.)</summary>
    // retail: CommandInterpreter::SetHoldRun (acclient.c:716977)
    private void SetHoldRun(bool held)
    {
        _holdRun = held;
        _interp.SetHoldRun(_holdRun != _runByDefault, cancelMoveToOnChange: true);
    }

    /// <summary>With no key held: stand (Ready), stop turning and side-stepping.</summary>
    // retail: CommandInterpreter::ApplyCurrentMovement (acclient.c:717026), lists empty, no auto-run
    private void ApplyCurrentMovement()
    {
        MovePlayer(MotionCommand.Ready, start: true);
        // retail's turn-list branch sends two stops, side-step right and turn right, then the side-step branch side-step right
        MovePlayer(MotionCommand.SideStepRight, start: false);
        MovePlayer(MotionCommand.TurnRight, start: false);
        MovePlayer(MotionCommand.SideStepRight, start: false);
    }

    // retail: ClientCombatSystem::CommenceJump (acclient.c:408032)
    private void CommenceJump()
    {
        if (_jumpPending)
        {
            return;
        }

        MotionError err = _interp.ChargeJump();
        LastError = err;
        if (err != MotionError.None)
        {
            return;
        }

        _jumpPending = true;
        // retail: ClientCombatSystem::StartPowerBarBuild (acclient.c:407901)
        _buildStartTime = _player.World.CurrentTime;
        // non-retail: the charge's MoveToState (the recordings show one, its contact byte with the long-jump bit) is sent
        // here; retail's send site is in the combat system, not traced
        SendMovementEvent();
    }

    // retail: ClientCombatSystem::DoJump (acclient.c:408145), autonomous
    private void DoJump()
    {
        if (!_jumpPending)
        {
            return;
        }

        double level = GetPowerBarLevel();
        float extent = (float)level;
        if (!(level >= 0.001))
        {
            extent = MinJumpExtent;
        }

        FinishJump();
        LastError = _interp.Jump(extent, out _);
        if (LastError == MotionError.None)
        {
            SendJump(extent);
        }
    }

    /// <summary>Ends the jump charge (the power bar empties) and the standing long jump; also the jump cancel, which
    /// <c>LoseKeyboardFocus</c>, Escape while charging (acclient.c:402170-402175), starting an attack and opening the chat
    /// reach through the interpreter's vtable slot 20 (<c>ACCmdInterp::FinishJump</c>, acclient.c:435852).</summary>
    // retail: ClientCombatSystem::FinishJump (acclient.c:407624)
    private void FinishJump()
    {
        _jumpPending = false;
        _interp.StandingLongJump = false;
    }

    // retail: ClientCombatSystem::GetPowerBarLevel (acclient.c:407918)
    private double GetPowerBarLevel()
    {
        double full = _interp.InterpretedState.CurrentStyle == FastPowerBarStyle ? FastPowerBarSeconds : 1.0;
        double level = (_player.World.CurrentTime - _buildStartTime) / full;
        if (level <= 1.0)
        {
            if (level < 0.0)
            {
                level = 0.0;
            }
        }
        else
        {
            level = 1.0;
        }

        return level;
    }
}
