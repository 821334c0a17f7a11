using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.World;

/// <summary>
/// <c>update_object</c>'s time slicing as an allocation-free iterator, shared by the tick (which runs a step for each slice)
/// and by the scene (which needs only the update_time an idle object would end with). Retail (acclient.c:323080): nothing
/// when dt &lt;= EPSILON or dt &gt; HugeQuantum (update_time = now); one whole step when dt &lt;= MaxQuantum; otherwise
/// MaxQuantum slices while dt &gt; MaxQuantum, then the remainder only above MinQuantum, and update_time = the consumed time.
/// ACE (<see cref="PhysicsProfile.AccumulateBelowMinQuantum"/>): dt &lt; MinQuantum keeps update_time (time accumulates).
/// </summary>
internal struct QuantumSlicer
{
    private readonly double _max;
    private readonly double _min;
    private readonly double _now;
    private double _dt;
    private readonly bool _wholeStep; // retail, dt <= MaxQuantum: one step of dt with no MinQuantum test
    private int _state; // 0 slicing, 1 remainder due, 2 done (consumed time), 3 done (update_time = now), 4 done (kept)

    /// <summary>Starts slicing the time from <paramref name="updateTime"/> to <paramref name="now"/>.</summary>
    public QuantumSlicer(PhysicsProfile profile, double updateTime, double now)
    {
        _max = profile.MaxQuantum;
        _min = profile.MinQuantum;
        _now = now;
        _dt = now - updateTime;
        Time = updateTime;
        if (profile.AccumulateBelowMinQuantum)
        {
            _state = _dt < _min ? 4 : _dt > profile.HugeQuantum ? 3 : 0;
        }
        else if (!(_dt > PhysicsGlobals.Epsilon) || _dt > profile.HugeQuantum)
        {
            _state = 3;
        }
        else
        {
            // One whole step when dt <= MaxQuantum, with no MinQuantum test (acclient.c:323080), so a 60 fps frame does run a step.
            _state = _dt > _max ? 0 : 1;
            _wholeStep = _dt <= _max;
        }
    }

    /// <summary>The consumed physics time so far (retail <c>PhysicsTimer::curr_time</c> during the object's update).</summary>
    public double Time { get; private set; }

    /// <summary>The next step, seconds; false when no step remains.</summary>
    public bool Next(out double quantum)
    {
        switch (_state)
        {
            case 0:
                if (_dt > _max)
                {
                    Time += _max;
                    _dt -= _max;
                    quantum = _max;
                    if (!(_dt > _max))
                    {
                        _state = 1;
                    }

                    return true;
                }

                _state = 1;
                goto case 1;
            case 1:
                _state = 2;
                if (_wholeStep || _dt > _min)
                {
                    Time += _dt;
                    quantum = _dt;
                    return true;
                }

                quantum = 0;
                return false;
            default:
                quantum = 0;
                return false;
        }
    }

    /// <summary>The object's update_time once every step has run: the consumed time, now, or unchanged (ACE, short dt).</summary>
    public readonly double EndTime(double updateTime) => _state switch
    {
        3 => _now,
        4 => updateTime,
        _ => Time,
    };
}
