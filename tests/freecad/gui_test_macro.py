"""Macro for the FreeCAD GUI: run test_gui.py once the main window is up, then exit.

Started by run_freecad_tests.sh as
    QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a -s "-screen 0 1280x1024x24" freecad gui_test_macro.py
FreeCAD runs the macro during start-up, before its event loop; a single-shot timer
runs the tests from inside the loop. os._exit() ends FreeCAD with the tests' status
(a normal quit would ask to save the documents, and never end under Xvfb).
"""
import os
import sys
import traceback

from PySide import QtCore


def _run_and_exit():
    status = 1
    try:
        sys.path.insert(0, os.environ["TQ_TEST_DIR"])
        import freecad_test_runner
        status = 0 if freecad_test_runner.run_modules(["test_gui"],
                                                      os.environ["TQ_RESULT_FILE"]) else 1
    except BaseException:  # anything, even SystemExit: the process must end here
        traceback.print_exc()
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(status)


QtCore.QTimer.singleShot(1000, _run_and_exit)
