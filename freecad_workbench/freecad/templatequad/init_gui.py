"""The TemplateQuad workbench; FreeCAD imports this module when its GUI starts.

FreeCAD finds it as ``freecad.templatequad.init_gui`` (namespace-package add-on), so
this is a real module: the command module is imported inside Initialize(), i.e. only
when the user first activates the workbench, keeping FreeCAD's start-up light.
"""
import FreeCAD
import FreeCADGui

from . import paths


class TemplateQuadWorkbench(FreeCADGui.Workbench):
    """All-quadrilateral FEM meshes by hierarchical templates."""

    MenuText = "TemplateQuad"
    ToolTip = "All-quadrilateral FEM meshes of CAD faces by hierarchical templates"
    Icon = paths.icon("TemplateQuad")

    def Initialize(self):
        from . import commands, meshing
        commands.register()
        self.appendToolbar("TemplateQuad", commands.COMMANDS)
        self.appendMenu("TemplateQuad", commands.COMMANDS)
        # Say now, not at the first mesh, when the compiled module is missing.
        try:
            meshing.load_tquad()
        except meshing.TquadMissing as error:
            FreeCAD.Console.PrintError(str(error))

    def Activated(self):
        pass

    def Deactivated(self):
        pass

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(TemplateQuadWorkbench())
