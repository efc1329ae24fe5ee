"""Run unittest modules inside FreeCAD and leave a machine-readable tally.

Used two ways by run_freecad_tests.sh:
- headless: ``freecadcmd -c "exec(open('.../freecad_test_runner.py').read())"``; the
  environment says what to run (TQ_TEST_DIR, TQ_TEST_MODULES, TQ_RESULT_FILE) and the
  process exits 0 when every test passed, 1 otherwise. (``freecadcmd script.py`` would
  exit 0 even when the script raises: see PLATFORM.md.)
- GUI: gui_test_macro.py imports this module and calls run_modules().

The tally file is JSON: {"passed": n, "failed": n, "skipped": n, "modules": [...]}.
"""
import json
import os
import sys
import unittest


def run_modules(names, result_file):
    """run_modules(): run the named test modules (from TQ_TEST_DIR); True if all passed."""
    test_dir = os.environ["TQ_TEST_DIR"]
    if test_dir not in sys.path:
        sys.path.insert(0, test_dir)
    suite = unittest.TestSuite()
    loader = unittest.TestLoader()
    for name in names:
        suite.addTests(loader.loadTestsFromName(name))
    result = unittest.TextTestRunner(stream=sys.stdout, verbosity=2).run(suite)
    failed = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses)
    skipped = len(result.skipped)
    tally = {"passed": result.testsRun - failed - skipped, "failed": failed,
             "skipped": skipped, "modules": list(names)}
    with open(result_file, "w") as out:
        json.dump(tally, out)
    sys.stdout.flush()
    return failed == 0


def main():
    names = [n for n in os.environ["TQ_TEST_MODULES"].split(",") if n]
    ok = run_modules(names, os.environ["TQ_RESULT_FILE"])
    sys.exit(0 if ok else 1)


# exec() of this file by freecadcmd -c runs it as a script; an import does not.
if os.environ.get("TQ_RUNNER_MAIN") == "1":
    main()
