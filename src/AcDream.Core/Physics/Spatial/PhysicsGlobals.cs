using System;

namespace AcDream.Core.Physics.Spatial;

/// <summary>
/// The retail physics constants shared by the object tick and the collision sweep (the time quanta, gravity, the walkable
/// and landing slopes, the velocity limits, an object's defaults), with their unit, their retail value and where they come
/// from in the decompilation of acclient.exe 11.4186.
/// </summary>
/// <remarks>
/// <para>Not all of retail's constants are here: one that belongs to a single retail class stays with the class that ports it,
/// documented the same way — for example the walk and run speeds on <see cref="Motion.MotionInterp"/>, the run-rate and
/// jump terms on <see cref="Motion.MovementSystem"/>, the placement tolerance on <see cref="Collision.Sweep.RetailSweep"/>, the cell grid on <see cref="LandDefs"/>, and the
/// managers' thresholds on the managers.</para>
/// <para>Float constants keep retail's float32 bit pattern; constants that retail stores as
/// <c>long double</c> (MSVC: a 64-bit double) are doubles here. Changing any of them breaks parity
/// with the retail client; every one is pinned by a test in <c>Retail/PhysicsGlobalsTests</c>.</para>
/// <para>Conventions used across the library: +Y is north, +Z is up, headings are degrees
/// clockwise from north, quaternions are stored w, x, y, z.</para>
/// </remarks>
public static class PhysicsGlobals
{
    /// <summary>
    /// Retail's general "essentially zero" tolerance (seconds, metres or unitless, by context).
    /// Retail: float 0.0002f, bits 0x3951B717 (printed by the decompiler as 0.00019999999).
    /// (0x3949A18A, sometimes quoted for it, is 0.000192f.)
    /// </summary>
    public const float Epsilon = 0.0002f;

    /// <summary>
    /// Shortest time step that is simulated on its own, in seconds: the world ticks only once at least this
    /// much time has passed, and update_object runs a slice remainder only above it.
    /// Retail: <c>MIN_QUANTUM = 1.0 / 30.0</c>, a <c>long double</c> (acclient.c:784226, acclient_data.h:7783).
    /// Its float32 rounding is 0x3D088889.
    /// </summary>
    public const double MinQuantum = 1.0 / 30.0;

    /// <summary>
    /// Longest single substep, in seconds; a longer frame is cut into slices of this size.
    /// Retail: <c>MAX_QUANTUM = 1.0 / 5.0</c>, a <c>long double</c> (acclient.c:784232).
    /// ACE uses 0.1 s; see <see cref="AceMaxQuantum"/>.
    /// </summary>
    public const double MaxQuantum = 1.0 / 5.0;

    /// <summary>
    /// Frames longer than this, in seconds, are treated as stale and not simulated at all.
    /// Retail: the literal 2.0 compared in <c>CPhysicsObj::update_object</c> (acclient.c:323080).
    /// </summary>
    public const double HugeQuantum = 2.0;

    /// <summary>
    /// ACE's substep slice, in seconds (ACE comments 0.2 s as "buggy with MoveToManager turning").
    /// Not a retail value: used only by the <c>AceCompatible</c> profile.
    /// </summary>
    public const double AceMaxQuantum = 0.1;

    /// <summary>
    /// Gravitational acceleration along +Z, in m/s². Retail: <c>PhysicsGlobals::gravity = -9.8000002</c>
    /// (acclient_data.h:6877), float bits 0xC11CCCCD.
    /// </summary>
    public const float Gravity = -9.8f;

    /// <summary>
    /// Smallest contact-plane normal Z that counts as walkable floor. Retail computes it at start-up as
    /// <c>cos(3437.746770784939)</c> (acclient.c:800527): the argument is 60 degrees converted to degrees
    /// instead of radians, so the value is cos of 3437.7 radians = 0.66417414 (about 48.4 degrees), not cos 60.
    /// Float bits 0x3F2A0751.
    /// </summary>
    public static readonly float FloorZ = (float)Math.Cos(3437.746770784939);

    /// <summary>
    /// Smallest normal Z on which a falling object may land (cos 85 degrees). Retail: <c>z_for_landing = 0.0871557</c>
    /// (acclient_data.h:1429), used by the sweep's step-down (acclient.c CTransition). Float bits 0x3DB27EB0.
    /// </summary>
    public const float LandingZ = 0.0871557f;

    /// <summary>
    /// Largest speed an object may have, in m/s; faster velocities are scaled down to it.
    /// Retail: 50.0 in <c>CPhysicsObj::set_velocity</c> and <c>UpdatePhysicsInternal</c>. Float bits 0x42480000.
    /// </summary>
    public const float MaxVelocity = 50.0f;

    /// <summary>Square of <see cref="MaxVelocity"/>, in m²/s². Retail: <c>50.0 * 50.0</c>.</summary>
    public const float MaxVelocitySquared = MaxVelocity * MaxVelocity;

    /// <summary>
    /// Speed below which a velocity is snapped to zero, in m/s. Retail: 0.25 in
    /// <c>UpdatePhysicsInternal</c> (<c>|v|² - 0.25 * 0.25 &lt; EPSILON</c>). Float bits 0x3E800000.
    /// </summary>
    public const float SmallVelocity = 0.25f;

    /// <summary>Square of <see cref="SmallVelocity"/>, in m²/s².</summary>
    public const float SmallVelocitySquared = SmallVelocity * SmallVelocity;

    /// <summary>
    /// Default friction coefficient of a new object (unitless, per second law (1 - f)^dt applies on contact).
    /// Retail: <c>DEFAULT_FRICTION = 0.94999999</c> (acclient_data.h:1430), float bits 0x3F733333.
    /// </summary>
    public const float DefaultFriction = 0.95f;

    /// <summary>
    /// Default elasticity of a new object (unitless). Retail: <c>DEFAULT_ELASTICITY = 0.050000001</c>
    /// (acclient_data.h:1431), float bits 0x3D4CCCCD.
    /// </summary>
    public const float DefaultElasticity = 0.05f;

    /// <summary>Default translucency of a new object (0 = opaque). Retail: <c>DEFAULT_TRANSLUCENCY = 0.0</c> (acclient_data.h:1432).</summary>
    public const float DefaultTranslucency = 0.0f;

    /// <summary>Default mass of a new object, in kg (retail stores 1/mass = <c>1.0 / 1.0</c> in the constructor).</summary>
    public const float DefaultMass = 1.0f;

    /// <summary>Default scale of a new object (unitless). Retail: <c>m_scale = 1.0f</c> in the constructor.</summary>
    public const float DefaultScale = 1.0f;

    /// <summary>
    /// Default PhysicsState bits of a new object: REPORT_COLLISIONS | GRAVITY | LIGHTING_ON | EDGE_SLIDE.
    /// Retail: <c>state = 4197384</c> (0x00400C08) in <c>CPhysicsObj::CPhysicsObj</c> (acclient.c, CPhysicsObj.c:3996).
    /// </summary>
    public const uint DefaultState = 0x00400C08u;

    /// <summary>
    /// Radius, in metres, of the dummy sphere swept for an object that has no collision spheres; its centre
    /// is at (0, 0, radius). Retail: <c>DUMMY_SPHERE_RADIUS = 0.1</c> (acclient_data.h:1433; acclient.c:784575).
    /// Float bits 0x3DCCCCCD.
    /// </summary>
    public const float DummySphereRadius = 0.1f;

    /// <summary>
    /// Distance from the player, in metres, beyond which an object is made inactive while object maintenance
    /// is active. Retail: the literal 96.0 in <c>CPhysicsObj::update_object</c> (acclient.c:323080).
    /// </summary>
    public const float PlayerActivityDistance = 96.0f;

    /// <summary>
    /// Initial value of retail's physics clock <c>PhysicsTimer::curr_time</c>, in seconds: -1.0
    /// (bit pattern 0xBFF0000000000000 written at acclient.c:800534).
    /// </summary>
    public const double InitialPhysicsTime = -1.0;

    /// <summary>
    /// Default object view radius, in metres: 0.1006f (bit pattern 0x3DCE075F). Retail: the float global
    /// <c>DEFAULT_VIEW_RADIUS</c> (acclient_data.h:15710) initialised to <c>EPSILON * 3.0 + 0.1</c> (acclient.c:784220): the
    /// sum is formed in double from the float EPSILON and rounded to float on the store.
    /// </summary>
    public const float DefaultViewRadius = (float)(Epsilon * 3.0 + 0.1);
}
