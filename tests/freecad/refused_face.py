"""A face the mesher refuses, for the FreeCAD tests of refusals."""
import FreeCAD
import Part


def drilled_cone_face(x=0.0, y=0.0, z=0.0):
    """The side face of a cone from its tip at (x, y, z) (radius 5 at height 10),
    drilled across at height 6: a pole and a hole, which the mesher refuses as not
    supported."""
    cone = Part.makeCone(0, 5, 10, FreeCAD.Vector(x, y, z))
    drill = Part.makeCylinder(1, 20, FreeCAD.Vector(x - 10, y, z + 6), FreeCAD.Vector(1, 0, 0))
    sides = [f for f in cone.cut(drill).Faces if isinstance(f.Surface, Part.Cone)]
    assert len(sides) == 1, "one drilled cone side"
    return sides[0]
