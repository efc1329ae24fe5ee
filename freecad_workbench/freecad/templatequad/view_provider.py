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
        if obj.FemMesh.FaceCount > LARGE_MESH_QUADS and vobj.DisplayMode == DISPLAY_MODE:
            vobj.DisplayMode = FACES_MODE
        if showing_quality(vobj):
            show_quality(vobj, True)  # the colours of the new mesh, not the old one's

    def getIcon(self):
        return paths.icon("TemplateQuad_Mesh")

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
