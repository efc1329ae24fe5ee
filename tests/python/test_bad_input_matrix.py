"""The bad-input matrix (bad_input_matrix.py) through the command line and the module.

The command line is the tquad executable named by TQUAD_EXE (ctest sets it); without
it, that half is skipped with a message.
"""
import os
import sys
import tempfile
import unittest
from pathlib import Path

import tquad

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bad_input_matrix as matrix  # noqa: E402
from test_tquad import edge_uses as _edge_uses  # noqa: E402


class BadInputMatrixTest(unittest.TestCase):

    def test_the_command_line_refuses_each_with_one_line_and_leaves_nothing(self):
        exe = os.environ.get("TQUAD_EXE")
        if not exe:
            self.skipTest("TQUAD_EXE is not set (ctest sets it to the built tquad)")
        for case in matrix.cases():
            if case.prepare is None:
                continue
            with self.subTest(case.name), tempfile.TemporaryDirectory() as folder:
                result = matrix.run_cli(exe, case, Path(folder))
                self.assertEqual(result.status, case.exit_status, result.message)
                self.assertEqual(result.left, [], "files left behind")
                if case.exit_status == 0:
                    continue
                self.assertTrue(result.message.startswith("tquad: error: "), result.message)
                self.assertNotIn("\n", result.message, "one line")
                self.assertNotIn("internal failure", result.message)
                for part in case.expect:
                    self.assertIn(part, result.message)

    def test_the_module_raises_value_error_and_the_interpreter_lives_on(self):
        for case in matrix.cases():
            if case.python is None:
                continue
            with self.subTest(case.name), tempfile.TemporaryDirectory() as folder:
                error, result = matrix.run_python(tquad, case, Path(folder))
                if case.exit_status == 0:
                    self.assertIsNone(error, error)
                    self.assertGreater(len(result.quads), 0, "a mesh")
                    continue
                self.assertIsNotNone(error, "no ValueError")
                for part in case.python_expect or case.expect:
                    if part.startswith("--"):
                        continue  # the option's CLI name; Python names its argument
                    self.assertIn(part, error)
        # After every refusal (one of them crashed OpenCASCADE's reader in its child
        # process), this interpreter still meshes.
        mesh = tquad.mesh_shape(str(matrix.SHAPES / "plate_with_hole.brep"))
        self.assertGreater(len(mesh.quads), 0)

    def test_meshed_shells_are_conforming_where_faces_meet(self):
        # The non-manifold edge of three_fins carries the same nodes in all three
        # faces, and the open box's rim is its only boundary: counted from the quads'
        # edges, every interior edge is used twice and the spine three times.
        fins = tquad.mesh_shape(str(matrix.SHAPES / "three_fins.brep"), size=4.0)
        uses = _edge_uses(fins.quads)
        spine = [e for e, n in uses.items() if n == 3]
        self.assertEqual(len(spine), 10, "40 mm spine at size 4: 10 segments shared by 3 faces")
        for edge in spine:
            self.assertTrue(all(abs(fins.nodes[v][1]) < 1e-9 and abs(fins.nodes[v][2]) < 1e-9 for v in edge),
                            "the spine lies on the x axis")
        box = tquad.mesh_shape(str(matrix.SHAPES / "open_box.brep"), size=5.0)
        uses = _edge_uses(box.quads)
        rim = [e for e, n in uses.items() if n == 1]
        self.assertEqual(len(rim), 2 * (8 + 6), "the rim of the 40 x 30 opening at size 5")
        self.assertTrue(all(abs(box.nodes[v][2] - 20.0) < 1e-9 for e in rim for v in e), "rim at z = 20")
        self.assertEqual(max(uses.values()), 2, "every other edge is shared by two quads")
        # Euler on the open box (a disk): nodes = 1 + quads + boundary_edges / 2.
        self.assertEqual(len(box.nodes), 1 + len(box.quads) + len(rim) // 2)


if __name__ == "__main__":
    unittest.main()
