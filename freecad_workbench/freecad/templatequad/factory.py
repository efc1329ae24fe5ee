"""make_mesh(): the scriptable way to create a TemplateQuad mesh object.

    >>> from freecad.templatequad import make_mesh
    >>> mesh = make_mesh(doc, doc.Box, size=2.0)
    >>> mesh.FemMesh.QuadrangleCount, mesh.Quality, mesh.Incomplete, mesh.RefusedFaceNames

Works headless (freecadcmd) and in the GUI, where it also attaches the view provider.
The GUI command calls it; it does not touch the selection, transactions or analyses.
"""
import math
from typing import Iterable, Optional

import FreeCAD

from .mesh_object import ELEMENT_DIMENSIONS, ELEMENT_ORDERS, TemplateQuadMesh


def make_mesh(doc, part_obj, size: float = 0.0, corners: Optional[Iterable[str]] = None,
              t4_ratio: int = 2, keep_going: bool = False, name: str = "TemplateQuadMesh",
              faces: Optional[Iterable[str]] = None, raise_on_error: bool = True,
              min_size: float = 0.0, smooth: bool = True, best_corners: bool = False,
              accept_incomplete: bool = False, element_order: str = "1st", sew: bool = False,
              element_dimension: str = "2D", layers: int = 0):
    """make_mesh(): add a TemplateQuad mesh of part_obj to doc, mesh it, return it.

    Args:
        doc: the App.Document.
        part_obj: the object to mesh (a Part feature or anything with a Shape).
        size: the maximum element size (CharacteristicLengthMax) in mm, the target edge
            length; 0 = automatic (bounding-box diagonal / 25).
        corners: "FACE:V1,V2,..." entries (see the Corners property).
        t4_ratio: the k of the T4 template test (at least 2).
        keep_going: mesh the other faces when one is refused.
        name: the object name (FreeCAD appends a number when it is taken).
        faces: FreeCAD face names ("Face1", ...) to mesh; None meshes all faces.
        raise_on_error: raise when the mesh fails, after removing the new object, so
            a failed call leaves the document as it was (the reason is in the report
            view too); False keeps the object, empty, its reason in Quality, for the caller
            to look at ``obj.Proxy.last_error`` (the GUI command does, to open the task
            panel).
        min_size: CharacteristicLengthMin, the floor of the element size (0 = none).
        smooth, best_corners, accept_incomplete: the Smooth, BestCorners and
            AcceptIncomplete properties.
        element_order: "1st" (4-node quads) or "2nd" (8-node quads), ElementOrder.
        sew: the Sew property: join faces that touch without sharing their edge.
        element_dimension: "2D" (quads on the faces) or "3D" (hexahedra swept through
            the solids that are extrusions or partial revolutions), ElementDimension.
        layers: 3D: hexahedra from each solid's source face to its target (0: from
            the size), Layers.

    Returns:
        The mesh object; None when the user cancelled the meshing in the GUI's
        progress dialog (the new object is removed again).

    Raises:
        ValueError: meshing failed and raise_on_error is set; the message says why.
    """
    # FreeCAD's Length property would quietly turn a negative size into another value.
    bad = [f"{label} must be a finite length of 0 or more, not {value}"
           for label, value in (("size", size), ("min_size", min_size))
           if not (math.isfinite(float(value)) and float(value) >= 0)]
    if bad:
        message = bad[0]
        FreeCAD.Console.PrintError(f"TemplateQuad: {part_obj.Label}: {message}\n")
        raise ValueError(message)
    if element_dimension not in ELEMENT_DIMENSIONS:
        message = f"element_dimension must be one of {', '.join(ELEMENT_DIMENSIONS)}, not {element_dimension!r}"
        FreeCAD.Console.PrintError(f"TemplateQuad: {part_obj.Label}: {message}\n")
        raise ValueError(message)
    if not (isinstance(layers, int) and layers >= 0):
        message = f"layers must be a whole number of 0 or more, not {layers!r}"
        FreeCAD.Console.PrintError(f"TemplateQuad: {part_obj.Label}: {message}\n")
        raise ValueError(message)
    if element_order not in ELEMENT_ORDERS:
        message = f"element_order must be one of {', '.join(ELEMENT_ORDERS)}, not {element_order!r}"
        FreeCAD.Console.PrintError(f"TemplateQuad: {part_obj.Label}: {message}\n")
        raise ValueError(message)
    obj = doc.addObject("Fem::FemMeshObjectPython", name)
    TemplateQuadMesh(obj)
    obj.ElementOrder = element_order
    obj.ElementDimension = element_dimension
    obj.Layers = layers
    obj.Part = part_obj
    obj.CharacteristicLengthMax = float(size)
    obj.CharacteristicLengthMin = float(min_size)
    obj.Smooth = bool(smooth)
    obj.BestCorners = bool(best_corners)
    obj.AcceptIncomplete = bool(accept_incomplete)
    obj.Corners = list(corners or [])
    obj.Faces = list(faces or [])
    obj.T4Ratio = int(t4_ratio)
    obj.KeepGoing = bool(keep_going)
    obj.Sew = bool(sew)
    wrong = obj.Proxy.last_error  # an input refused as it was set (said in the report view)
    if wrong:
        doc.removeObject(obj.Name)
        doc.recompute()
        raise ValueError(wrong)
    if FreeCAD.GuiUp:
        from .view_provider import ViewProviderTemplateQuadMesh
        ViewProviderTemplateQuadMesh(obj.ViewObject)
    obj.Proxy.request_mesh(obj)
    if obj.Proxy.cancelled:
        doc.removeObject(obj.Name)
        doc.recompute()
        return None
    error = obj.Proxy.last_error
    if raise_on_error and error:
        doc.removeObject(obj.Name)
        doc.recompute()
        raise ValueError(error)
    return obj
