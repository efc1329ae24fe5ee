"""The options of tquad.mesh_shape against the command line's: every keyword has its
flag in `tquad mesh --help` (the same name with dashes, or the one named below), so an
option added to one front end and not the other fails here. The FreeCAD object's
properties are checked in tests/freecad/test_headless.py, the stubs in test_stubs.py."""
import inspect
import os
import re
import subprocess
import unittest

import tquad

#: Keywords whose command-line form is not `--` + the keyword with dashes.
CLI_FORMS = {
    "brep_text_or_path": "INPUT",        # the positional input file
    "smooth": "--no-smooth",             # on by default; the flag turns it off
    "best_corners": "--corners",         # --corners best
}


class CommandLineOffersEveryOption(unittest.TestCase):
    def test_every_mesh_shape_keyword_has_a_flag(self):
        exe = os.environ.get("TQUAD_EXE", "")
        if not os.path.exists(exe):
            self.skipTest("no tquad executable (TQUAD_EXE)")
        help_text = subprocess.run([exe, "mesh", "--help"], capture_output=True, text=True).stdout
        flags = set(re.findall(r"--[a-z0-9-]+", help_text)) | ({"INPUT"} if "INPUT" in help_text else set())
        for keyword in inspect.signature(tquad.mesh_shape).parameters:
            form = CLI_FORMS.get(keyword, "--" + keyword.replace("_", "-"))
            with self.subTest(keyword=keyword):
                self.assertIn(form, flags)
        self.assertIn("'best'", help_text, "--corners best")


if __name__ == "__main__":
    unittest.main()
