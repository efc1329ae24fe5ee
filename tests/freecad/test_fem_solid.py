"""End-to-end solid FEM: a cantilever swept into hexahedra by a TemplateQuad mesh object
(ElementDimension 3D), solved by CalculiX through FreeCAD's ccxtools, against beam theory.

Model (units mm, N, MPa): a 100 x 10 x 10 steel bar (E = 210000, nu = 0.3), its x = 0
face fixed, a force of 100 N down (-z) on its x = 100 face. Timoshenko's tip deflection
P L^3 / (3 E I) + P L / (k G A), k = 5/6: 0.19196 mm. FreeCAD writes the twenty-node
hexahedra as C3D20 (CalculiX's full integration, which does not lock at this slenderness
with quadratic elements); the mean z displacement of the loaded face must be within 2%.
Eight-node hexahedra (C3D8) lock in bending: they must be valid (CalculiX runs) and
stiffer than the beam, as linear bricks are.
"""
import os
import shutil
import tempfile
import unittest

import FreeCAD

from fem_setup import steel_analysis

LENGTH, SIDE, YOUNG, POISSON, FORCE = 100.0, 10.0, 210000.0, 0.3, 100.0
INERTIA, AREA = SIDE ** 4 / 12, SIDE * SIDE
SHEAR = YOUNG / (2 * (1 + POISSON))
TIMOSHENKO = FORCE * LENGTH ** 3 / (3 * YOUNG * INERTIA) + FORCE * LENGTH / (5.0 / 6.0 * SHEAR * AREA)


def _name(obj, kind, predicate):
    """The one sub-element of obj's shape ("FaceN", "EdgeN") that predicate accepts."""
    items = obj.Shape.Faces if kind == "Face" else obj.Shape.Edges
    names = [f"{kind}{i + 1}" for i, e in enumerate(items) if predicate(e)]
    assert len(names) == 1, f"expected one {kind}, found {names}"
    return names[0]


@unittest.skipUnless(shutil.which("ccx"), "CalculiX (ccx) is not installed")
class SweptCantileverTest(unittest.TestCase):

    def setUp(self):
        self.doc = FreeCAD.newDocument("TemplateQuadCantilever")
        self.work_dir = tempfile.mkdtemp(prefix="tq_ccx_solid_")

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)
        shutil.rmtree(self.work_dir, ignore_errors=True)

    def _tip_deflection(self, order):
        import ObjectsFem
        from femtools import ccxtools
        from freecad.templatequad import make_mesh

        bar = self.doc.addObject("Part::Box", "Bar")
        bar.Length, bar.Width, bar.Height = LENGTH, SIDE, SIDE
        self.doc.recompute()
        clamped = _name(bar, "Face", lambda f: f.BoundBox.XMax < 1e-6)
        loaded = _name(bar, "Face", lambda f: f.BoundBox.XMin > LENGTH - 1e-6)
        vertical = [f"Edge{i + 1}" for i, e in enumerate(bar.Shape.Edges)
                    if e.BoundBox.XLength < 1e-6 and e.BoundBox.YLength < 1e-6][0]

        analysis, solver = steel_analysis(self.doc)
        fixed = ObjectsFem.makeConstraintFixed(self.doc, "Fixed")
        fixed.References = [(bar, clamped)]
        analysis.addObject(fixed)
        force = ObjectsFem.makeConstraintForce(self.doc, "Load")
        force.References = [(bar, loaded)]
        force.Force = FORCE
        force.Direction = (bar, [vertical])
        analysis.addObject(force)
        mesh = make_mesh(self.doc, bar, size=2.5, element_dimension="3D", element_order=order)
        analysis.addObject(mesh)
        self.doc.recompute()
        if force.DirectionVector.z > 0:  # the edge's orientation decides the sign
            force.Reversed = True
            self.doc.recompute()
        self.assertAlmostEqual(force.DirectionVector.z, -1.0, 9, "force down")
        self.assertEqual(mesh.FemMesh.VolumeCount, mesh.FemMesh.HexaCount, "hexahedra only")
        self.assertGreater(mesh.FemMesh.HexaCount, 0)
        self.assertFalse(mesh.Incomplete)

        fea = ccxtools.FemToolsCcx(analysis, solver)
        fea.update_objects()
        self.assertIs(fea.mesh, mesh, "ccxtools must take the TemplateQuad mesh")
        fea.setup_working_dir(self.work_dir)
        self.assertEqual(fea.check_prerequisites(), "", "FEM prerequisites")
        fea.write_inp_file()
        with open(fea.inp_file_name) as inp:
            self.assertIn("TYPE=C3D20" if order == "2nd" else "TYPE=C3D8", inp.read())
        self.assertEqual(fea.ccx_run(), 0, "CalculiX failed")
        fea.load_results()
        results = [o for o in analysis.Group if o.isDerivedFrom("Fem::FemResultObject")]
        self.assertEqual(len(results), 1, "one result object")
        result = results[0]
        nodes = result.Mesh.FemMesh.Nodes
        displacement = dict(zip(result.NodeNumbers, result.DisplacementVectors))
        tip = [displacement[n].z for n in displacement if nodes[n].x > LENGTH - 1e-6]
        return -sum(tip) / len(tip)

    def test_twenty_node_hexahedra_bend_as_timoshenko(self):
        deflection = self._tip_deflection("2nd")
        self.assertLess(abs(deflection / TIMOSHENKO - 1), 0.02,
                        f"tip {deflection:.5f} mm against Timoshenko's {TIMOSHENKO:.5f}")

    def test_eight_node_hexahedra_solve_and_are_stiffer(self):
        deflection = self._tip_deflection("1st")
        self.assertGreater(deflection, 0.0, "the tip goes down")
        self.assertLess(deflection, TIMOSHENKO, "linear bricks are stiffer than the beam")


if __name__ == "__main__":
    unittest.main()
