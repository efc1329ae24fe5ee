#!/usr/bin/python3
"""Cancel and hand-over of a ten-million-quad run in the FreeCAD GUI; writes bench/GUI_CANCEL.md.

Runs FreeCAD's GUI under Xvfb with the add-on installed into a temporary user home
(as tests/freecad/run_freecad_tests.sh does), on the four-face plate with a hole
(resources/shapes/plate_with_hole.brep) at a size giving about 1e7 quads, through
``make_mesh`` as a script or the command would (the progress dialog, all cores):

- one run per delay (5, 30 and 120 s): Cancel pressed on the progress dialog then;
  latency = seconds from the press to ``make_mesh`` returning (a press after the
  meshing finished cancels between the hand-over's steps); whether the document
  is as before (its objects, no mesh object left); resident memory after the cancel
  against before the run. A run that finished before its delay is reported as such;
- then one whole run: seconds meshing (the worker thread), seconds of the hand-over to
  FreeCAD (``to_femmesh`` and the object's properties, main thread), seconds to draw it
  (the events processed after), the longest time the window answered no event (a 20 ms
  timer's largest gap), and the process's resident memory before and after.

Nothing is asserted. Usage: /usr/bin/python3 bench/gui_cancel.py [--out bench/GUI_CANCEL.md]
[--size 0.038] [--delays 5,30,120]  (needs freecad, xvfb-run and a built build/python/tquad)
"""
import argparse
import datetime
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHAPE = os.path.join(REPO, "resources", "shapes", "plate_with_hole.brep")

MACRO = r'''
import gc, json, os, time
from PySide import QtCore, QtGui
import FreeCAD, FreeCADGui, Part

SETTINGS = json.loads(os.environ["TQ_BENCH"])


def rss_mb():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return 0.0


class Gaps:
    """The longest wait between ticks of a 20 ms timer: how long the window froze."""
    def __init__(self):
        self.last, self.longest = time.monotonic(), 0.0
        self.timer = QtCore.QTimer()
        self.timer.timeout.connect(self.tick)
        self.timer.start(20)

    def tick(self):
        now = time.monotonic()
        self.longest = max(self.longest, now - self.last)
        self.last = now

    def stop(self):
        self.tick()
        self.timer.stop()
        return self.longest


def main():
    out = {"runs": []}
    try:
        from freecad.templatequad import make_mesh, meshing, progress_dialog
        FreeCAD.ParamGet(progress_dialog.PREFERENCES).SetInt(progress_dialog.ASK_ABOVE_QUADS, 0)
        doc = FreeCAD.newDocument("Bench")
        doc.UndoMode = 0  # a removed mesh is freed, not kept for an undo
        part = doc.addObject("Part::Feature", "Plate")
        part.Shape = Part.read(SETTINGS["shape"])
        doc.recompute()
        QtGui.QApplication.processEvents()
        size = SETTINGS["size"]
        marks = {}
        mesh_shape, to_femmesh = meshing.mesh_shape, meshing.to_femmesh

        def timed_mesh_shape(*args, **kwargs):
            result = mesh_shape(*args, **kwargs)
            marks["meshed"] = time.monotonic()
            return result

        def timed_to_femmesh(mesh):
            start = time.monotonic()
            result = to_femmesh(mesh)
            marks["femmesh"] = time.monotonic() - start
            return result

        meshing.mesh_shape, meshing.to_femmesh = timed_mesh_shape, timed_to_femmesh

        for delay in SETTINGS["delays"]:
            names = sorted(o.Name for o in doc.Objects)
            gc.collect()
            before = rss_mb()
            pressed = {}
            marks.clear()

            def press():
                dialogs = [w for w in QtGui.QApplication.topLevelWidgets()
                           if isinstance(w, QtGui.QProgressDialog) and w.isVisible()]
                if dialogs:
                    pressed["at"] = time.monotonic()
                    dialogs[0].cancel()

            QtCore.QTimer.singleShot(int(delay * 1000), press)
            start = time.monotonic()
            mesh = make_mesh(doc, part, size=size)
            end = time.monotonic()
            QtGui.QApplication.processEvents()
            gc.collect()
            run = {"delay": delay, "cancelled": mesh is None and "at" in pressed,
                   "same_document": sorted(o.Name for o in doc.Objects) == names,
                   "rss_before": before, "rss_after": rss_mb(), "seconds": end - start}
            if "at" in pressed:
                run["latency"] = end - pressed["at"]
                run["phase"] = "hand-over" if marks.get("meshed", end) < pressed["at"] else "meshing"
            if mesh is not None:
                doc.removeObject(mesh.Name)
                del mesh
            out["runs"].append(run)

        # The whole run.
        gc.collect()
        before = rss_mb()
        gaps = Gaps()
        start = time.monotonic()
        mesh = make_mesh(doc, part, size=size)
        returned = time.monotonic()
        for _ in range(5):
            QtGui.QApplication.processEvents()
            FreeCADGui.updateGui()
        drawn = time.monotonic()
        out["whole"] = {"quads": mesh.FemMesh.FaceCount, "meshing": marks["meshed"] - start,
                        "femmesh": marks["femmesh"], "handover": returned - marks["meshed"],
                        "draw": drawn - returned, "longest_freeze": gaps.stop(),
                        "rss_before": before, "rss_after": rss_mb(), "total": drawn - start}

    except BaseException as error:
        import traceback
        out["error"] = traceback.format_exc()
    finally:
        with open(SETTINGS["result"], "w") as result:
            json.dump(out, result)
        os._exit(0)


QtCore.QTimer.singleShot(1000, main)
'''


def measure(size, delays, timeout):
    home = tempfile.mkdtemp(prefix="tq_gui_bench_")
    try:
        subprocess.run(["bash", os.path.join(REPO, "freecad_workbench", "install.sh"),
                        os.path.join(REPO, "build", "python", "tquad")],
                       env=dict(os.environ, FREECAD_USER_HOME=home), check=True, capture_output=True)
        macro = os.path.join(home, "bench_macro.py")
        with open(macro, "w") as out:
            out.write(MACRO)
        result = os.path.join(home, "result.json")
        settings = {"shape": SHAPE, "size": size, "delays": delays, "result": result}
        env = dict(os.environ, FREECAD_USER_HOME=home, HOME=home, QTWEBENGINE_DISABLE_SANDBOX="1",
                   TQ_BENCH=json.dumps(settings))
        subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", "freecad", macro], env=env,
                       timeout=timeout, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(result) as data:
            return json.load(data)
    finally:
        shutil.rmtree(home, ignore_errors=True)


def report(data, size, command):
    lines = ["# Cancel and hand-over in the FreeCAD GUI", "",
             "Generated by `bench/gui_cancel.py` (its docstring defines the columns). Command:", "",
             f"    {command}", "",
             f"Date {datetime.datetime.now(datetime.timezone.utc).isoformat(timespec='seconds')}. "
             f"Machine: {platform.machine()}, {os.cpu_count()} cores; FreeCAD's GUI under Xvfb.", ""]
    if "error" in data:
        lines += ["The run failed:", "", "```", data["error"].rstrip(), "```", ""]
    whole = data.get("whole")
    if whole:
        lines += [f"Plate with a hole (four faces) at {size} mm: {whole['quads']:,} quads.", "",
                  "| meshing (s) | FemMesh (s) | hand-over (s) | drawing (s) | longest freeze (s) "
                  "| memory before (MB) | after (MB) |",
                  "|---:|---:|---:|---:|---:|---:|---:|",
                  f"| {whole['meshing']:.1f} | {whole['femmesh']:.1f} | {whole['handover']:.1f} "
                  f"| {whole['draw']:.1f} | {whole['longest_freeze']:.1f} | {whole['rss_before']:.0f} "
                  f"| {whole['rss_after']:.0f} |", ""]
    if data.get("runs"):
        lines += ["| Cancel at (s) | outcome | latency (s) | document as before | memory before (MB) "
                  "| after (MB) | after / before |", "|---:|---|---:|---|---:|---:|---:|"]
        for run in data["runs"]:
            outcome = (f"cancelled in the {run['phase']}" if run["cancelled"]
                       else f"finished first ({run['seconds']:.1f} s)")
            latency = f"{run['latency']:.2f}" if "latency" in run else ""
            lines.append(f"| {run['delay']:g} | {outcome} | {latency} | "
                         f"{'yes' if run['same_document'] else 'no'} | {run['rss_before']:.0f} | "
                         f"{run['rss_after']:.0f} | {run['rss_after'] / run['rss_before']:.2f} |")
        lines.append("")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(REPO, "bench", "GUI_CANCEL.md"))
    parser.add_argument("--size", type=float, default=0.04)
    parser.add_argument("--delays", default="5,30,120")
    parser.add_argument("--timeout", type=float, default=1800)
    args = parser.parse_args(argv)
    if not shutil.which("freecad") or not shutil.which("xvfb-run"):
        print("needs freecad and xvfb-run", file=sys.stderr)
        return 2
    delays = [float(d) for d in args.delays.split(",")]
    data = measure(args.size, delays, args.timeout)
    command = "/usr/bin/python3 bench/gui_cancel.py" + (
        f" --size {args.size:g}" if args.size != 0.04 else "") + (
        f" --delays {args.delays}" if args.delays != "5,30,120" else "")
    text = report(data, args.size, command)
    with open(args.out, "w") as out:
        out.write(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
