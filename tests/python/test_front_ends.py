"""Every front end against the options schema (tquad.mesh_option_schema(), declared in
src/core/mesh_option_schema.cpp): tquad.mesh_shape's keywords, their order and
defaults; `tquad mesh --help`'s flags; the docstring. An option added to one front
end and not to the schema, or to the schema and not to a front end, fails here. The
FreeCAD object's properties are checked against the schema in
tests/freecad/test_headless.py, the stubs in test_stubs.py."""
import ast
import inspect
import os
import re
import subprocess
import unittest

import tquad

#: Flags of `tquad mesh` that are the command's own, not options of meshing.
COMMAND_ONLY = {"--output", "--report", "--verbose", "--help"}


class OptionsSchema(unittest.TestCase):
    def setUp(self):
        self.schema = tquad.mesh_option_schema()

    def test_rows_are_complete_and_unique(self):
        names = [row["name"] for row in self.schema]
        self.assertEqual(len(names), len(set(names)))
        for row in self.schema:
            with self.subTest(option=row["name"]):
                self.assertRegex(row["name"], r"^[a-z][a-z0-9_]*$")
                self.assertTrue(row["help"].endswith("."), row["help"])
                self.assertTrue(row["flag"].startswith("--"), row["flag"])

    def test_mesh_shape_keywords_are_the_schema_in_order_with_its_defaults(self):
        parameters = list(inspect.signature(tquad.mesh_shape).parameters.values())
        self.assertEqual(parameters[0].name, "brep_text_or_path")
        self.assertEqual([p.name for p in parameters[1:]], [row["name"] for row in self.schema])
        for p, row in zip(parameters[1:], self.schema):
            with self.subTest(option=row["name"]):
                self.assertEqual(p.kind, inspect.Parameter.KEYWORD_ONLY)
                self.assertEqual(p.default, ast.literal_eval(row["default"]))
                self.assertIs(type(p.default), type(ast.literal_eval(row["default"])))

    def test_the_docstring_explains_every_option_in_the_schema_words(self):
        doc = " ".join(tquad.mesh_shape.__doc__.split())
        self.assertNotIn("{options}", doc)
        for row in self.schema:
            with self.subTest(option=row["name"]):
                self.assertIn("%s: %s" % (row["name"], " ".join(row["help"].split())), doc)

    def test_the_command_line_offers_every_option_and_no_other(self):
        exe = os.environ.get("TQUAD_EXE", "")
        if not os.path.exists(exe):
            self.skipTest("no tquad executable (TQUAD_EXE)")
        help_text = subprocess.run([exe, "mesh", "--help"], capture_output=True, text=True).stdout
        flags = set(re.findall(r"^\s+(?:-[a-z],)?(--[a-z0-9-]+)", help_text, re.M))
        schema_flags = {row["flag"].split()[0] for row in self.schema}
        self.assertEqual(flags - COMMAND_ONLY, schema_flags)
        words = " ".join(help_text.split())
        for row in self.schema:
            with self.subTest(option=row["name"]):
                self.assertIn(" ".join(row["help"].split()), words)
        self.assertIn("'best'", help_text, "--corners best")


if __name__ == "__main__":
    unittest.main()
