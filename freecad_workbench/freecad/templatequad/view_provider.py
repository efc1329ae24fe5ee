"""View provider of the TemplateQuad mesh object (GUI side).

The C++ side (FemGui::ViewProviderFemMeshPython) draws the FemMesh; this proxy adds
the icon, the task panel on double-click / Edit, a display mode that shows the
element edges where they stay readable, and the quality colour map.
"""
import FreeCAD
import FreeCADGui

from .stateless_proxy import StatelessProxy
from . import paths

#: ViewProviderFemMesh's display mode with shaded faces and element edges.
DISPLAY_MODE = "Faces & Wireframe"
#: Its display mode with shaded faces only.
FACES_MODE = "Faces"
#: Above this many quads, drawn edges cover the faces (a part at 1e6 quads shows
#: solid black at a whole-part zoom), so a new mesh is shown with faces only.
LARGE_MESH_QUADS = 100_000


class ViewProviderTemplateQuadMesh(StatelessProxy):
    """Proxy for the view object of a TemplateQuad mesh."""

    def __init__(self, vobj):
        vobj.Proxy = self
        if DISPLAY_MODE in vobj.listDisplayModes():
            vobj.DisplayMode = DISPLAY_MODE

    def attach(self, vobj):
        self.Object = vobj.Object

    def updateData(self, obj, prop):
        """A new mesh: faces only when it is too dense for its edges to be read."""
        if prop != "FemMesh" or not hasattr(obj, "ViewObject") or obj.ViewObject is None:
            return
        vobj = obj.ViewObject
        if list(vobj.HighlightedNodes):
            vobj.HighlightedNodes = []  # the worst elements of the mesh before
        if obj.FemMesh.FaceCount > LARGE_MESH_QUADS and vobj.DisplayMode == DISPLAY_MODE:
            vobj.DisplayMode = FACES_MODE
        if showing_quality(vobj):
            show_quality(vobj, True)  # the colours of the new mesh, not the old one's

    def getIcon(self):
        return paths.icon("TemplateQuad_Mesh")

    def claimChildren(self):
        """The mesh's FEM mesh regions and groups sit under it in the tree, as under
        FreeCAD's Gmsh mesh."""
        obj = self.Object
        return list(getattr(obj, "MeshRegionList", [])) + list(getattr(obj, "MeshGroupList", []))

    def setEdit(self, vobj, mode=0):
        """Open the task panel for the default edit mode; leave other modes to FreeCAD."""
        if mode != 0:
            return None
        from .task_panel import TemplateQuadTaskPanel
        FreeCADGui.Control.showDialog(TemplateQuadTaskPanel(vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        FreeCADGui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        gui_doc = FreeCADGui.getDocument(vobj.Object.Document)
        if gui_doc.getInEdit():
            # Another object's task panel is open; two cannot be, FreeCAD would refuse.
            FreeCAD.Console.PrintWarning(
                "TemplateQuad: close the open task panel before editing the mesh\n")
        else:
            gui_doc.setEdit(vobj.Object.Name)
        return True



def showing_quality(vobj) -> bool:
    return bool(getattr(vobj.Proxy, "quality_shown", False))


def show_quality(vobj, on: bool) -> bool:
    """show_quality(): colour each quad by its scaled Jacobian (on), or plainly (off).

    The values are the mesh object's ElementQuality (saved with the document); False
    when it has none for this mesh, as in a file saved by a version without it.
    """
    from .quality_colours import element_colours

    values = list(vobj.Object.ElementQuality) or None
    vobj.Proxy.quality_shown = bool(on)
    if not on or values is None or len(values) != vobj.Object.FemMesh.FaceCount:
        vobj.ElementColor = {}
        return not on
    vobj.ElementColor = element_colours(values)
    return True


#: The colour of the worst elements when the quality map is off.
WORST_COLOUR = (0.9, 0.0, 0.9)


def show_worst(vobj, count: int):
    """show_worst(): the `count` worst elements of the mesh (worst_elements) drawn: their
    nodes highlighted, the elements coloured (unless the quality map already colours
    them) and the view zoomed onto them; returns them as (element id, value), worst
    first ([] when the mesh has no qualities)."""
    from .worst_elements import worst_elements

    obj = vobj.Object
    values = list(obj.ElementQuality)
    femmesh = obj.FemMesh
    if not values or len(values) != (femmesh.VolumeCount or femmesh.FaceCount):
        return []
    worst = worst_elements(values, count)
    nodes = sorted({n for element, _ in worst for n in femmesh.getElementNodes(element)})
    vobj.HighlightedNodes = nodes
    if not showing_quality(vobj):
        vobj.ElementColor = {element: WORST_COLOUR for element, _ in worst}
    vobj.Visibility = True
    _zoom_to([femmesh.getNodeById(n) for n in nodes], obj.Document)
    return worst


def clear_worst(vobj) -> None:
    """Undo show_worst's highlights (the quality map, when shown, stays)."""
    vobj.HighlightedNodes = []
    if not showing_quality(vobj):
        vobj.ElementColor = {}


def _zoom_to(points, doc) -> None:
    """Zoom the document's 3D view onto points (with a margin of their own size)."""
    from pivy import coin

    view = FreeCADGui.getDocument(doc).ActiveView
    if not points or not hasattr(view, "getCameraNode"):
        return
    box = FreeCAD.BoundBox()
    for p in points:
        box.add(p)
    margin = max(box.DiagonalLength, 1e-6)
    box.enlarge(margin)
    camera = view.getCameraNode()
    width, height = view.getSize()
    camera.viewBoundingBox(coin.SbBox3f(box.XMin, box.YMin, box.ZMin, box.XMax, box.YMax, box.ZMax),
                           width / max(height, 1), 1.0)
