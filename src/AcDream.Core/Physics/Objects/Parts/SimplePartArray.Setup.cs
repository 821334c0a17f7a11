using System;

namespace AcDream.Core.Physics.Objects.Parts;

// The built-in part array built from a Setup's physics fields.
public sealed partial class SimplePartArray
{
    /// <summary>Creates a part array with <paramref name="numParts"/> parts and the collision shape, sizes and step heights of
    /// <paramref name="setup"/> (e.g. <see cref="SetupPhysics.Human"/>): the part array of a creature built from its Setup.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="setup"/> is null.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="numParts"/> is negative.</exception>
    public SimplePartArray(SetupPhysics setup, int numParts = 1)
        : this(numParts, 0)
    {
        ArgumentNullException.ThrowIfNull(setup);
        _spheres = setup.Spheres.ToArray();
        SetCylSpheres(setup.CylSpheres);
        _radius = setup.Radius;
        _height = setup.Height;
        _stepUpHeight = setup.StepUpHeight;
        _stepDownHeight = setup.StepDownHeight;
    }
}
