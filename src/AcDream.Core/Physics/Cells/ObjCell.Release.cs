using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Cells;

// A cell leaving and entering the loaded world: its shadows dropped and its moving objects sent to their lost cells when it
// is released; the objects lost in it brought back when it is loaded again.
public abstract partial class ObjCell
{
    /// <summary>The cell is released: every shadow in it is taken out (its objects keep the shadow, naming no cell), then its
    /// moving objects (not static, no parent) leave visibility for their lost cells, in the cell's list order.</summary>
    // retail: CObjCell::release_objects (acclient.c:346942)
    internal void ReleaseObjects(PhysicsWorld world)
    {
        while (NumShadowObjects != 0)
        {
            // retail: remove_shadow_object, then CPhysicsObj::remove_parts (the drawing parts' cell lists, not ported)
            RemoveShadowObject(_shadowObjects[0]);
        }

        if (NumObjects != 0)
        {
            world.ReleaseObjCell(this);
        }
    }

    /// <summary>The cell was loaded: the objects lost in it come back, then each moving object of the cell not shadowed in
    /// every cell it reaches is shadowed again.</summary>
    // retail: CObjCell::init_objects (acclient.c:346914)
    internal void InitObjects(PhysicsWorld world)
    {
        world.InitObjCell(Id);
        world.RecalcCrossCellsOfIncomplete(this);
    }
}
