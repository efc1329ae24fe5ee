"""A FEM user's check: the same shell analysis on TemplateQuad's mesh and on FreeCAD's
own Gmsh mesh (the FEM workbench's default mesher, its default settings) at the same
element size, solved by CalculiX; the tip deflections agree within 2%.

Model (mm, N, MPa): a U-channel 200 long (x), web 60 wide in z = 0 with a hole of
diameter 24 at mid-length, flanges 40 high at y = +-30; shell thickness 2, steel. The
x = 0 end is clamped (its three edges fixed); a force of 200 N along -z on the x = 200
end's three edges bends it. The tip deflection is the mean z displacement of the nodes
at x = 200.

The web, flanges and hole make a shell whose faces share edges, so both meshes must
conform across them; the hole makes the web a face with a hole (TemplateQuad cuts it
itself, Gmsh meshes it with triangles).
"""
import os
import shutil
import tempfile
import unittest

import FreeCAD
import Part

LENGTH, WIDTH, HEIGHT, HOLE_D = 200.0, 60.0, 40.0, 24.0
THICKNESS, FORCE = 2.0, 200.0
SIZE = 5.0  # element size for both meshers (about 3,000 quads)
TOLERANCE = 0.02


def u_channel():
    """The channel as one shape whose faces share their common edges."""
    half = WIDTH / 2
    web = Part.Face(Part.makePolygon([
        FreeCAD.Vector(0, -half, 0), FreeCAD.Vector(LENGTH, -half, 0),
        FreeCAD.Vector(LENGTH, half, 0), FreeCAD.Vector(0, half, 0), FreeCAD.Vector(0, -half, 0)]))
    hole = Part.makeCylinder(HOLE_D / 2, 2, FreeCAD.Vector(LENGTH / 2, 0, -1))
    web = web.cut(hole)
    flanges = [Part.Face(Part.makePolygon([
        FreeCAD.Vector(0, y, 0), FreeCAD.Vector(LENGTH, y, 0), FreeCAD.Vector(LENGTH, y, HEIGHT),
        FreeCAD.Vector(0, y, HEIGHT), FreeCAD.Vector(0, y, 0)])) for y in (-half, half)]
    return web.fuse(flanges).removeSplitter()


def _edge_names(obj, predicate):
    return [f"Edge{i + 1}" for i, e in enumerate(obj.Shape.Edges) if predicate(e)]


@unittest.skipUnless(shutil.which("ccx") and shutil.which("gmsh"), "needs CalculiX (ccx) and gmsh")
class UChannelTest(unittest.TestCase):

    def setUp(self):
        self.work_dirs = []

    def tearDown(self):
        for folder in self.work_dirs:
            shutil.rmtree(folder, ignore_errors=True)

    def test_tip_deflection_agrees_with_freecads_gmsh_mesh(self):
        quads, quad_tip = self._tip_deflection("templatequad")
        triangles, gmsh_tip = self._tip_deflection("gmsh")
        ratio = quad_tip / gmsh_tip
        print(f"\nU-channel tip deflection: TemplateQuad {quad_tip:.5f} mm ({quads}); "
              f"FreeCAD's Gmsh {gmsh_tip:.5f} mm ({triangles}); ratio {ratio:.4f}")
        self.assertLess(gmsh_tip, 0, "the tip goes down")
        self.assertLess(abs(ratio - 1), TOLERANCE,
                        f"tip deflections differ by {100 * abs(ratio - 1):.2f}%")

    def _tip_deflection(self, mesher):
        """Builds the analysis in a new document, meshes, solves; (mesh text, tip)."""
        import ObjectsFem
        from femtools import ccxtools

        doc = FreeCAD.newDocument(f"UChannel_{mesher}")
        try:
            part = doc.addObject("Part::Feature", "Channel")
            part.Shape = u_channel()
            doc.recompute()
            self.assertEqual(len(part.Shape.Faces), 3, "web and two flanges")
            analysis = ObjectsFem.makeAnalysis(doc, "Analysis")
            solver = ObjectsFem.makeSolverCalculixCcxTools(doc, "CalculiX")
            solver.AnalysisType = "static"
            solver.GeometricalNonlinearity = "linear"
            analysis.addObject(solver)
            analysis.addObject(ObjectsFem.makeElementGeometry2D(doc, THICKNESS, "Thickness"))
            material = ObjectsFem.makeMaterialSolid(doc, "Steel")
            values = material.Material
            values.update({"Name": "Steel", "YoungsModulus": "210000 MPa", "PoissonRatio": "0.30"})
            material.Material = values
            analysis.addObject(material)
            fixed = ObjectsFem.makeConstraintFixed(doc, "Clamp")
            fixed.References = [(part, _edge_names(part, lambda e: e.BoundBox.XMax < 1e-6))]
            analysis.addObject(fixed)
            tip_edges = _edge_names(part, lambda e: e.BoundBox.XMin > LENGTH - 1e-6)
            self.assertEqual(len(tip_edges), 3, "the free end's edges")
            force = ObjectsFem.makeConstraintForce(doc, "Load")
            force.References = [(part, tip_edges)]
            force.Force = FORCE
            vertical = _edge_names(part, lambda e: e.BoundBox.XMax < 1e-6 and e.BoundBox.ZLength > 1)
            force.Direction = (part, [vertical[0]])
            analysis.addObject(force)
            doc.recompute()
            if force.DirectionVector.z > 0:  # the edge's orientation decides the sign
                force.Reversed = True
                doc.recompute()
            self.assertAlmostEqual(force.DirectionVector.z, -1.0, 9, "force along -z")

            mesh = self._mesh(doc, part, mesher)
            analysis.addObject(mesh)
            doc.recompute()
            femmesh = mesh.FemMesh
            description = (f"{femmesh.QuadrangleCount} quads" if mesher == "templatequad"
                           else f"{femmesh.TriangleCount} triangles, {mesh.ElementOrder} order")

            work_dir = tempfile.mkdtemp(prefix="tq_uchannel_")
            self.work_dirs.append(work_dir)
            fea = ccxtools.FemToolsCcx(analysis, solver)
            fea.update_objects()
            fea.setup_working_dir(work_dir)
            self.assertEqual(fea.check_prerequisites(), "", "FEM prerequisites")
            fea.write_inp_file()
            self.assertEqual(fea.ccx_run(), 0, "CalculiX failed")
            fea.load_results()
            result = [o for o in analysis.Group if o.isDerivedFrom("Fem::FemResultObject")][0]
            nodes = result.Mesh.FemMesh.Nodes
            tip = [d.z for n, d in zip(result.NodeNumbers, result.DisplacementVectors)
                   if nodes[n].x > LENGTH - 1e-6]
            self.assertGreater(len(tip), 10, "nodes at the tip")
            return description, sum(tip) / len(tip)
        finally:
            FreeCAD.closeDocument(doc.Name)

    def _mesh(self, doc, part, mesher):
        if mesher == "templatequad":
            from freecad.templatequad import make_mesh
            mesh = make_mesh(doc, part, size=SIZE)
            self.assertFalse(mesh.Incomplete, list(mesh.RefusedFaces))
            self.assertEqual(mesh.FemMesh.QuadrangleCount, mesh.FemMesh.FaceCount, "all quads")
            return mesh
        import ObjectsFem
        from femmesh.gmshtools import GmshTools
        mesh = ObjectsFem.makeMeshGmsh(doc, "GmshMesh")
        mesh.Part = part
        mesh.CharacteristicLengthMax = SIZE
        doc.recompute()
        error = GmshTools(mesh).create_mesh()
        self.assertFalse(error, f"Gmsh failed: {error}")
        self.assertGreater(mesh.FemMesh.FaceCount, 0, "Gmsh made elements")
        return mesh


if __name__ == "__main__":
    unittest.main()
