"""View provider of the TemplateQuad mesh object (GUI side).

The C++ side (FemGui::ViewProviderFemMeshPython) draws the FemMesh; this proxy only
adds the icon, the task panel on double-click / Edit, and a display mode that shows
the element edges (what one wants to see of a quad mesh).
"""
import FreeCAD
import FreeCADGui

from .stateless_proxy import StatelessProxy
from . import paths

#: ViewProviderFemMesh's display mode with shaded faces and element edges.
DISPLAY_MODE = "Faces & Wireframe"


class ViewProviderTemplateQuadMesh(StatelessProxy):
    """Proxy for the view object of a TemplateQuad mesh."""

    def __init__(self, vobj):
        vobj.Proxy = self
        if DISPLAY_MODE in vobj.listDisplayModes():
            vobj.DisplayMode = DISPLAY_MODE

    def attach(self, vobj):
        self.Object = vobj.Object

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

