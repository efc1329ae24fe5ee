"""Run a Python script inside FreeCAD's freecadcmd, for the benches that measure
FreeCAD itself (freecad_transfer.py, element_order_plate.py)."""

import os
import subprocess
import tempfile


def run_in_freecad(script: str) -> subprocess.CompletedProcess:
    """run_in_freecad(): the script's freecadcmd run (stdout and stderr captured as
    text). freecadcmd takes a file only through ``-c exec(...)``: a script given as a
    path would be opened as a document."""
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "bench_script.py")
        with open(path, "w") as f:
            f.write(script)
        return subprocess.run(["freecadcmd", "-c", f"exec(open({path!r}).read())"],
                              capture_output=True, text=True)
