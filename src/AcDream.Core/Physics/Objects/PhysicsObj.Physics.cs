// PhysicsObj — integration: UpdatePhysicsInternal, calc_acceleration, calc_friction, set_velocity, set_omega, set_active, set_ethereal.
using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

public sealed partial class PhysicsObj
{
    /// <summary>
    /// 10 degrees in radians, the argument of calc_friction's cosine (printed <c>cos(0.1745329251994329)</c>,
    /// acclient.c:316090). Bits 0x3FC657184AE74487: the double nearest π/18, which a compiler emits for the source constant
    /// and which prints with 16 digits as shown; parsing the printed digits would give 0x3FC657184AE74485, two ulps low.
    /// </summary>
    internal const double SleddingSteepAngle = 0.17453292519943295;

    /// <summary>cos(10 degrees) as retail evaluates it in calc_friction, a double (bits 0x3FEF838B8C811C17).</summary>
    internal static readonly double SleddingSteepCos = Math.Cos(SleddingSteepAngle);

    /// <summary>
    /// Integrates one step into <paramref name="frame"/>: the 50 m/s clamp, friction, the small-velocity stop, the origin
    /// update (v·dt + ½·a·dt²), the velocity update and the rotation by omega·dt. An object at rest on walkable ground with no
    /// movement manager deactivates itself.
    /// </summary>
    // retail: CPhysicsObj::UpdatePhysicsInternal (acclient.c:317700)
    internal void UpdatePhysicsInternal(float quantum, ref Frame frame)
    {
        // non-retail: fidelity switch (ArithmeticMode.Float32); the retail profile takes the path below
        if (World.Profile.Arithmetic == ArithmeticMode.Float32)
        {
            UpdatePhysicsInternalFloat32(quantum, ref frame);
            return;
        }

        double q = quantum;
        Vector3 v = _velocity;
        float mag2 = (float)((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z);
        if (mag2 <= 0.0f)
        {
            if (Movement is null && (_transientState & TransientState.OnWalkable) != 0)
            {
                _transientState &= ~TransientState.Active;
            }
        }
        else
        {
            if ((double)mag2 > PhysicsGlobals.MaxVelocitySquared)
            {
                v = VectorMath.Normalize(v);
                mag2 = PhysicsGlobals.MaxVelocitySquared;
                v = new Vector3(
                    (float)(50.0 * v.X),
                    (float)(50.0 * v.Y),
                    (float)(50.0 * v.Z));
                _velocity = v;
            }

            // non-retail: the scene's declared effects (retail always runs calc_friction)
            if ((World.Effects & SceneEffects.Friction) != 0)
            {
                CalcFriction(quantum, mag2);
            }

            if ((double)mag2 - 0.25 * 0.25 < PhysicsGlobals.Epsilon)
            {
                _velocity = Vector3.Zero;
            }

            v = _velocity;
            Vector3 a = _acceleration;
            Vector3 o = frame.Origin;

            // The float roundings below are retail's x87 spills to 4-byte stack slots (Hex-Rays STxx_4 temporaries).
            float halfAxQ = (float)(a.X * 0.5 * q);
            float halfAxQQ = (float)(halfAxQ * q);
            float halfAyQQ = (float)(a.Y * 0.5 * q * q);
            float halfAz = (float)(a.Z * 0.5);
            float qVz = (float)(q * v.Z);
            float dx = (float)(q * v.X + halfAxQQ);
            float dz = (float)(qVz + halfAz * q * q);
            float ox = (float)(dx + (double)o.X);
            float oy = (float)(q * v.Y + halfAyQQ + o.Y);
            float oz = (float)(dz + (double)o.Z);
            frame.Origin = new Vector3(ox, oy, oz);
        }

        Vector3 acc = _acceleration;
        Vector3 vel = _velocity;
        _velocity = new Vector3(
            (float)(q * acc.X + vel.X),
            (float)(q * acc.Y + vel.Y),
            (float)((double)(float)(q * acc.Z) + vel.Z)); // acclient.c:317773: q·a.z is spilled to a float first
        Vector3 w = _omega;
        // non-retail: fidelity switches (arithmetic, renormalisation); the retail profile runs frame.GRotate(...)
        RotateForProfile(ref frame, new Vector3((float)(q * w.X), (float)(q * w.Y), (float)(q * w.Z)));
    }

    /// <summary>
    /// Sets the acceleration from the contact state: zero (and zero omega) when resting on walkable ground and not sledding,
    /// gravity when the GRAVITY bit is set, otherwise zero.
    /// </summary>
    // retail: CPhysicsObj::calc_acceleration (acclient.c:317786)
    internal void CalcAcceleration()
    {
        Touch();
        TransientState ts = _transientState;
        if ((ts & TransientState.Contact) != 0 && (ts & TransientState.OnWalkable) != 0 && (_state & PhysicsState.Sledding) == 0)
        {
            _acceleration = Vector3.Zero;
            _omega = Vector3.Zero;
        }
        // non-retail: the scene's declared effects (retail: the GRAVITY state bit alone)
        else if ((_state & PhysicsState.Gravity) != 0 && (World.Effects & SceneEffects.Gravity) != 0)
        {
            _acceleration = new Vector3(0f, 0f, PhysicsGlobals.Gravity);
        }
        else
        {
            _acceleration = Vector3.Zero;
        }
    }

    /// <summary>
    /// Ground friction for one step: on walkable ground, unless the velocity points away from the contact plane (v·N &gt;= 0.25),
    /// removes the normal component and scales the velocity by (1 - f)^quantum; sledding uses 0.2, the object's friction or a
    /// full stop depending on speed and slope.
    /// </summary>
    // retail: CPhysicsObj::calc_friction (acclient.c:316090)
    internal void CalcFriction(float quantum, float velocityMag2)
    {
        if ((_transientState & TransientState.OnWalkable) == 0)
        {
            return;
        }

        Vector3 v = _velocity;
        Vector3 n = ContactPlaneNormal;
        double f;
        if ((_state & PhysicsState.Sledding) != 0)
        {
            double d = (double)v.Z * n.Z + (double)v.Y * n.Y + (double)v.X * n.X;
            if (d >= 0.25)
            {
                return;
            }

            float frict = 0.2f;
            v = new Vector3((float)(v.X - d * n.X), (float)(v.Y - d * n.Y), (float)(v.Z - (double)(float)(d * n.Z)));
            if (velocityMag2 >= 1.5625f)
            {
                if (velocityMag2 < 6.25f || SleddingSteepCos <= n.Z)
                {
                    frict = _friction;
                }

                f = frict;
            }
            else
            {
                f = 1.0;
            }
        }
        else
        {
            double d = (double)n.Z * v.Z + (double)n.Y * v.Y + (double)n.X * v.X;
            if (d >= 0.25)
            {
                return;
            }

            v = new Vector3((float)(v.X - d * n.X), (float)(v.Y - d * n.Y), (float)(v.Z - (double)(float)(d * n.Z)));
            f = _friction;
        }

        double k = Math.Pow(1.0 - f, quantum);
        _velocity = new Vector3((float)(k * v.X), (float)(k * v.Y), (float)(k * v.Z));
    }

    /// <summary>
    /// Sets the velocity (clamped to 50 m/s; stored and marking <see cref="JumpedThisFrame"/> only when some axis differs from
    /// the current velocity by more than EPSILON) and activates a non-static
    /// object, restarting its clock if it was inactive.
    /// </summary>
    /// <remarks>An object without a part array is in no cell and never moves, whatever its velocity (retail); its
    /// <see cref="SetupIssues"/> reports <see cref="ObjectSetupIssues.NoPartArray"/>.</remarks>
    /// <exception cref="System.ArgumentException">A component is NaN or infinite (state unchanged).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_velocity (acclient.c:318577)
    public void SetVelocity(Vector3 velocity)
    {
        ThrowIfRemoved();
        ThrowIfNotFinite(velocity, nameof(velocity));
        Touch();
        // retail: Vector3::operator!= (acclient.c:156312): some axis differs by more than EPSILON
        if (DiffersByMoreThanEpsilon(velocity, _velocity))
        {
            Vector3 v = velocity;
            if ((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z > PhysicsGlobals.MaxVelocitySquared)
            {
                v = VectorMath.Normalize(v);
                v = new Vector3((float)(50.0 * v.X), (float)(50.0 * v.Y), (float)(50.0 * v.Z));
            }

            _velocity = v;
            JumpedThisFrame = true;
        }

        if ((_state & PhysicsState.Static) == 0)
        {
            if ((_transientState & TransientState.Active) == 0)
            {
                UpdateTime = World.CurrentTime;
            }

            _transientState |= TransientState.Active;
        }
    }

    /// <summary>True when some axis of <paramref name="a"/> and <paramref name="b"/> differs by more than EPSILON
    /// (the difference in double, as the x87 computes it).</summary>
    // retail: Vector3::operator!= (acclient.c:156312)
    private static bool DiffersByMoreThanEpsilon(Vector3 a, Vector3 b) =>
        Math.Abs((double)a.X - b.X) > PhysicsGlobals.Epsilon
        || Math.Abs((double)a.Y - b.Y) > PhysicsGlobals.Epsilon
        || Math.Abs((double)a.Z - b.Z) > PhysicsGlobals.Epsilon;

    /// <summary>Sets the velocity from local axes (rotated to world axes by the object's frame), then <see cref="SetVelocity"/>.</summary>
    /// <exception cref="System.ArgumentException">A component is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_local_velocity (acclient.c:318617)
    public void SetLocalVelocity(Vector3 localVelocity)
    {
        ThrowIfRemoved();
        ThrowIfNotFinite(localVelocity, nameof(localVelocity));
        Touch();
        SetVelocity(LocalToGlobalInRetailOrder(in _position.Frame, localVelocity));
    }

    // set_local_velocity's own product sum (acclient.c:318622-318630): m[0]*x + m[3]*y + m[6]*z per row, left to right, in
    // that order (Frame::localtoglobalvec sums the z term first). Float products are exact in double; one rounding to float.
    internal static Vector3 LocalToGlobalInRetailOrder(in Frame f, Vector3 v)
    {
        double x = (double)f.M11 * v.X + (double)f.M21 * v.Y + (double)f.M31 * v.Z;
        double y = (double)f.M12 * v.X + (double)f.M22 * v.Y + (double)f.M32 * v.Z;
        double z = (double)f.M13 * v.X + (double)f.M23 * v.Y + (double)f.M33 * v.Z;
        return new Vector3((float)x, (float)y, (float)z);
    }

    /// <summary>Sets the angular velocity, rad/s in world axes (a plain store, as retail).</summary>
    /// <exception cref="System.ArgumentException">A component is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_omega (acclient.c:316612)
    public void SetOmega(Vector3 omega)
    {
        ThrowIfRemoved();
        ThrowIfNotFinite(omega, nameof(omega));
        Touch();
        _omega = omega;
    }

    /// <summary>
    /// Activates (restarting the clock of an inactive object; refused for a STATIC object) or deactivates the object.
    /// </summary>
    /// <returns>False only when activation was refused.</returns>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_active (acclient.c:316979)
    public bool SetActive(bool active)
    {
        ThrowIfRemoved();
        return SetActiveInternal(active);
    }

    /// <summary>The engine's call (no removal check).</summary>
    // retail: CPhysicsObj::set_active (acclient.c:316979)
    internal bool SetActiveInternal(bool active)
    {
        Touch();
        if (active)
        {
            if ((_state & PhysicsState.Static) != 0)
            {
                return false;
            }

            if ((_transientState & TransientState.Active) == 0)
            {
                UpdateTime = World.CurrentTime;
            }

            _transientState |= TransientState.Active;
            return true;
        }

        _transientState &= ~TransientState.Active;
        return true;
    }

    /// <summary>Sets or clears ON_WALKABLE, telling the movement manager on a change, then recomputes the acceleration.</summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_on_walkable (acclient.c:318501)
    internal void SetOnWalkable(bool onWalkable)
    {
        ThrowIfRemoved();
        SetOnWalkableInternal(onWalkable);
    }

    /// <summary>The engine's call (no removal check).</summary>
    // retail: CPhysicsObj::set_on_walkable (acclient.c:318501)
    internal void SetOnWalkableInternal(bool onWalkable)
    {
        Touch();
        bool was = (_transientState & TransientState.OnWalkable) != 0;
        if (onWalkable)
        {
            _transientState |= TransientState.OnWalkable;
        }
        else
        {
            _transientState &= ~TransientState.OnWalkable;
        }

        if (was)
        {
            if (!onWalkable && Movement is not null)
            {
                Movement.LeaveGround();
            }
        }
        else if (onWalkable)
        {
            Movement?.HitGround();
        }

        CalcAcceleration();
    }

    /// <summary>Clears contact, walkable, sliding, water, the stationary bits and ACTIVE (retail <c>clear_transient_states</c>).</summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::clear_transient_states (acclient.c:319024)
    internal void ClearTransientStates()
    {
        ThrowIfRemoved();
        Touch();
        _transientState &= ~TransientState.Contact;
        CalcAcceleration();
        bool wasOnWalkable = (_transientState & TransientState.OnWalkable) != 0;
        _transientState &= ~(TransientState.OnWalkable | TransientState.WaterContact);
        if (wasOnWalkable)
        {
            Movement?.LeaveGround();
        }

        CalcAcceleration();
        // 0xFFFFFE0B: SLIDING, the three STATIONARY bits, ACTIVE and CHECK_ETHEREAL.
        _transientState &= ~(TransientState.Sliding | TransientState.StationaryFall | TransientState.StationaryStop
                             | TransientState.StationaryStuck | TransientState.Active | TransientState.CheckEthereal);
    }

    /// <summary>
    /// Makes the object ethereal, or tries to make it solid: when it would overlap something (asked through the world's
    /// <see cref="CollisionSweep"/>) it stays ethereal and CHECK_ETHEREAL is set so the next step retries.
    /// </summary>
    /// <returns>True when the request took effect now.</returns>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_ethereal (acclient.c:319046)
    public bool SetEthereal(bool ethereal)
    {
        ThrowIfRemoved();
        return SetEtherealInternal(ethereal);
    }

    /// <summary>The engine's call (no removal check).</summary>
    // retail: CPhysicsObj::set_ethereal (acclient.c:319046)
    internal bool SetEtherealInternal(bool ethereal)
    {
        Touch();
        if (ethereal)
        {
            _state |= PhysicsState.Ethereal;
            _transientState &= ~TransientState.CheckEthereal;
            return true;
        }

        _state &= ~PhysicsState.Ethereal;
        if (Parent is not null || CellId == 0 || !World.Sweep.EtherealCheckForCollisions(this))
        {
            _transientState &= ~TransientState.CheckEthereal;
            return true;
        }

        _state |= PhysicsState.Ethereal;
        _transientState |= TransientState.CheckEthereal;
        return false;
    }
}
