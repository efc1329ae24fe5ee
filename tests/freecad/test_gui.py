"""GUI test of the TemplateQuad workbench; needs FreeCAD's GUI (gui_test_macro.py runs it
under Xvfb). The workbench loads, its command meshes a selected part into the active
analysis and opens the task panel, the panel re-meshes, and a screenshot of the mesh
is saved to $TQ_SCREENSHOT.
"""
import os
import unittest

import FreeCAD
import FreeCADGui
import Part
from PySide import QtGui

COMMAND = "TemplateQuad_Mesh"


def _process_events():
    QtGui.QApplication.processEvents()


class WorkbenchGuiTest(unittest.TestCase):

    def setUp(self):
        self.doc = FreeCAD.newDocument("TemplateQuadGui")
        FreeCADGui.activateWorkbench("TemplateQuadWorkbench")
        _process_events()

    def tearDown(self):
        gui_doc = FreeCADGui.getDocument(self.doc.Name)
        if gui_doc.getInEdit():
            gui_doc.resetEdit()
        FreeCADGui.Control.closeDialog()
        FreeCAD.closeDocument(self.doc.Name)

    def _filleted_box(self):
        box = Part.makeBox(40, 30, 20)
        vertical = [e for e in box.Edges
                    if abs(e.Vertexes[0].Point.z - e.Vertexes[1].Point.z) > 1e-9]
        part = self.doc.addObject("Part::Feature", "FilletedBox")
        part.Shape = box.makeFillet(6, vertical[:2])
        self.doc.recompute()
        return part

    def _mesh_objects(self):
        return [o for o in self.doc.Objects if o.TypeId == "Fem::FemMeshObjectPython"]

    def test_workbench_is_active(self):
        wb = FreeCADGui.activeWorkbench()
        self.assertEqual(wb.__class__.__name__, "TemplateQuadWorkbench", "active workbench")
        self.assertIn(COMMAND, FreeCADGui.listCommands(), "command registered")

    def test_command_meshes_the_selection_into_the_active_analysis(self):
        import FemGui
        import ObjectsFem

        part = self._filleted_box()
        analysis = ObjectsFem.makeAnalysis(self.doc, "Analysis")
        FemGui.setActiveAnalysis(analysis)
        FreeCADGui.Selection.clearSelection()
        _process_events()
        self.assertFalse(FreeCADGui.Command.get(COMMAND).isActive(),
                         "the command must be inactive without a selection")
        FreeCADGui.Selection.addSelection(self.doc.Name, part.Name)
        _process_events()
        self.assertTrue(FreeCADGui.Command.get(COMMAND).isActive(),
                        "the command must be active with a part selected")

        FreeCADGui.runCommand(COMMAND)
        _process_events()

        meshes = self._mesh_objects()
        self.assertEqual(len(meshes), 1, "one TemplateQuad mesh object")
        mesh = meshes[0]
        femmesh = mesh.FemMesh
        self.assertGreater(femmesh.FaceCount, 0, "the mesh has elements")
        self.assertEqual(femmesh.QuadrangleCount, femmesh.FaceCount, "only quadrilaterals")
        self.assertEqual(femmesh.TriangleCount, 0, "no triangles")
        self.assertIs(mesh.Part, part, "the mesh links the selected part")
        self.assertIn(mesh, analysis.Group, "the mesh joins the active analysis")
        gui_doc = FreeCADGui.getDocument(self.doc.Name)
        self.assertIsNotNone(gui_doc.getInEdit(), "the command opens the task panel")
        self.assertEqual(gui_doc.getInEdit().Object, mesh, "the panel edits the new mesh")
        self.assertEqual(mesh.ViewObject.DisplayMode, "Faces & Wireframe", "edges shown")
        gui_doc.resetEdit()
        _process_events()

        self._save_screenshot(mesh, part)

    def test_command_meshes_only_the_selected_faces(self):
        part = self._filleted_box()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(self.doc.Name, part.Name, "Face1")
        FreeCADGui.Selection.addSelection(self.doc.Name, part.Name, "Face3")
        _process_events()
        FreeCADGui.runCommand(COMMAND)
        _process_events()
        mesh = self._mesh_objects()[0]
        self.assertEqual(sorted(mesh.Faces), ["Face1", "Face3"], "the selected faces")
        self.assertEqual([t.split(":")[0] for t in mesh.TemplateTrees], ["Face1", "Face3"],
                         "only the selected faces are meshed")
        self.assertEqual(mesh.FemMesh.QuadrangleCount, mesh.FemMesh.FaceCount, "all quads")

    def test_task_panel_apply_and_cancel(self):
        from freecad.templatequad import make_mesh
        from freecad.templatequad.task_panel import TemplateQuadTaskPanel

        mesh = make_mesh(self.doc, self._filleted_box(), size=4.0)
        before = mesh.FemMesh.FaceCount
        panel = TemplateQuadTaskPanel(mesh)
        self.assertIn(f"{before} quads", panel.status.text(), "panel shows the count")
        panel.size.setValue(2.0)
        self.assertTrue(panel.apply(), "apply must re-mesh without error")
        self.assertGreater(mesh.FemMesh.FaceCount, before, "smaller size, more quads")
        self.assertIn(f"{mesh.FemMesh.FaceCount} quads", panel.status.text(), "updated")
        panel.reject()
        self.assertEqual(mesh.Size.Value, 4.0, "cancel restores the size")
        self.assertEqual(mesh.FemMesh.FaceCount, before, "cancel restores the mesh")

        panel = TemplateQuadTaskPanel(mesh)
        panel.corners.setPlainText("Face1:Vertex1")
        self.assertFalse(panel.apply(), "a bad corner entry must fail")
        self.assertIn("Not meshed", panel.status.text(), "the panel shows the error")
        panel.reject()
        self.assertEqual(mesh.FemMesh.FaceCount, before, "cancel re-meshes the old values")

    def test_double_click_opens_the_panel_and_a_saved_file_restores_the_gui(self):
        import tempfile
        from freecad.templatequad import make_mesh
        from freecad.templatequad.view_provider import ViewProviderTemplateQuadMesh

        mesh = make_mesh(self.doc, self._filleted_box(), size=4.0)
        gui_doc = FreeCADGui.getDocument(self.doc.Name)
        mesh.ViewObject.Proxy.doubleClicked(mesh.ViewObject)
        _process_events()
        self.assertIsNotNone(gui_doc.getInEdit(), "double-click opens the task panel")
        gui_doc.resetEdit()
        _process_events()

        name, path = mesh.Name, os.path.join(tempfile.mkdtemp(), "tq_gui.FCStd")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        _process_events()
        mesh = self.doc.getObject(name)
        self.assertIsInstance(mesh.ViewObject.Proxy, ViewProviderTemplateQuadMesh,
                              "view provider restored from the file")
        self.assertTrue(mesh.ViewObject.Proxy.getIcon().endswith("TemplateQuad_Mesh.svg"),
                        "tree icon")

    def _save_screenshot(self, mesh, part):
        path = os.environ.get("TQ_SCREENSHOT")
        if not path:
            return
        part.ViewObject.Visibility = False
        mesh.ViewObject.Visibility = True
        view = FreeCADGui.getDocument(self.doc.Name).ActiveView
        view.viewIsometric()
        view.fitAll()
        _process_events()
        os.makedirs(os.path.dirname(path), exist_ok=True)
        if os.path.exists(path):
            os.remove(path)
        view.saveImage(path, 1280, 960, "White")
        self.assertTrue(os.path.isfile(path) and os.path.getsize(path) > 10000,
                        f"screenshot {path} not written")
        print(f"\nscreenshot: {path}")


if __name__ == "__main__":
    unittest.main()
