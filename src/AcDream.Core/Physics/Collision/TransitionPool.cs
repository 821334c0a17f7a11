using System;
using AcDream.Core.Physics.Cells;

namespace AcDream.Core.Physics.Collision;

/// <summary>
/// The ten transitions a world sweeps with, handed out by nesting level: a sweep takes the next free one and gives it
/// back when done, so a sweep started from inside another (an object callback) gets its own. Retail: the static
/// <c>transit[10]</c> array with <c>CTransition::transition_level</c> (makeTransition acclient.c:312542,
/// cleanupTransition acclient.c:311588); the port keeps it per world instead of global.
/// </summary>
/// <remarks>A transition stays readable after <see cref="Cleanup"/> until the next <see cref="Make"/> takes its slot —
/// retail's <c>CPhysicsObj::transition</c> cleans up before its caller reads the result. The tick keeps its slot until the
/// commit is done instead, so that a sweep started from a collision report cannot overwrite it (docs/divergences.md).</remarks>
internal sealed class TransitionPool
{
    /// <summary>Number of transitions, the deepest nesting. Retail: 10 (acclient.c:312542).</summary>
    public const int Capacity = 10;

    private readonly Transition[] _transitions = new Transition[Capacity];

    /// <summary>Creates the pool; every transition looks cells up in <paramref name="cells"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="cells"/> is null.</exception>
    public TransitionPool(ICellSource cells)
    {
        ArgumentNullException.ThrowIfNull(cells);
        for (int i = 0; i < Capacity; i++)
        {
            _transitions[i] = new Transition(cells);
        }
    }

    /// <summary>Whether every transition runs the plain retail paths (<see cref="Transition.ReferencePaths"/>).</summary>
    public bool ReferencePaths
    {
        get => _transitions[0].ReferencePaths;
        set
        {
            for (int i = 0; i < Capacity; i++)
            {
                _transitions[i].ReferencePaths = value;
            }
        }
    }

    /// <summary>Number of transitions in use (retail <c>transition_level</c>).</summary>
    public int Level { get; private set; }

    /// <summary>The transition of slot <paramref name="index"/> (0 &lt;= index &lt; <see cref="Capacity"/>).</summary>
    /// <exception cref="ArgumentOutOfRangeException">Index out of range.</exception>
    public Transition this[int index] => (uint)index < Capacity ? _transitions[index] : throw new ArgumentOutOfRangeException(nameof(index));

    /// <summary>Takes the next transition, reset; null when all ten are in use (the caller's sweep then fails, as in retail).</summary>
    // retail: CTransition::makeTransition (acclient.c:312542)
    public Transition? Make()
    {
        if (Level >= Capacity)
        {
            return null;
        }

        Transition t = _transitions[Level++];
        t.Init();
        return t;
    }

    /// <summary>Gives the innermost transition back.</summary>
    /// <exception cref="InvalidOperationException">No transition is in use (retail would underflow its counter).</exception>
    // retail: CTransition::cleanupTransition (acclient.c:311588)
    public void Cleanup()
    {
        if (Level == 0)
        {
            throw new InvalidOperationException("No transition is in use.");
        }

        Level--;
    }
}
