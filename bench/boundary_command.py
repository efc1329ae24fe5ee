#!/usr/bin/python3
"""The whole `tquad mesh` command on one large four-curve boundary: time and peak memory.

    /usr/bin/python3 bench/boundary_command.py [--counts 1000,1100,1200,1300] [--repeat 3]

The boundary is a W x H rectangle (W, H = the first two counts / 1000) with evenly
spaced points, the given counts on its four sides in turn (counts 1000, 1100, 1200,
1300 give 1.52 M quads through T2). It is written to a temporary .json and meshed to
a .vtu by the tquad executable, as a user runs it: smoothed (the default) and with
--no-smooth. Each variant: the least wall time of --repeat processes and the largest
peak resident memory (the child's ru_maxrss), per quad, and the stages' split from
tquad's report. With --smesh, SMESH (Quadrangle_2D + QuadranglePreference inside
FreeCAD, bench/smesh_case.py) meshes the same rectangle with the same counts in the
same run, --repeat times: the least of its compute() times, and the ratio of that to
tquad's whole process. Asserts nothing.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

from sweep import cpu_model

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def rectangle(counts):
    width, height = counts[0] / 1000.0, counts[1] / 1000.0
    corners = [(0.0, 0.0), (width, 0.0), (width, height), (0.0, height)]
    points, corner_indices = [], []
    for side, count in enumerate(counts):
        (ax, ay), (bx, by) = corners[side], corners[(side + 1) % 4]
        corner_indices.append(len(points))
        points += [[ax + (bx - ax) * i / count, ay + (by - ay) * i / count] for i in range(count)]
    return {"points": points, "corners": corner_indices}


def run_once(command):
    """Wall seconds and peak resident bytes of one child process."""
    start = time.perf_counter()
    child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(child.pid, 0)
    seconds = time.perf_counter() - start
    child.stdout.close()
    child.stderr.close()
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError(f"{' '.join(command)} failed")
    return seconds, usage.ru_maxrss * 1024


def smesh_compute_seconds(freecadcmd, counts, folder, repeat):
    """The least compute() time of SMESH on the rectangle(counts), each run in its own
    FreeCAD process (bench/smesh_case.py)."""
    script = os.path.join(REPO, "bench", "smesh_case.py")
    times = []
    for _ in range(repeat):
        result = os.path.join(folder, "smesh.json")
        spec = {"counts": counts, "width": counts[0] / 1000.0, "height": counts[1] / 1000.0,
                "output": os.path.join(folder, "smesh.vtu"), "result": result}
        subprocess.run([freecadcmd, "-c", "exec(open(%r).read())" % script], check=True, capture_output=True,
                       env=dict(os.environ, SWEEP_SMESH_SPEC=json.dumps(spec)))
        with open(result) as f:
            found = json.load(f)
        if found["quads"] == 0 or found["triangles"] > 0:
            raise RuntimeError(f"SMESH made {found['quads']} quads and {found['triangles']} triangles")
        times.append(found["compute_s"])
    return min(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tquad", default=os.path.join(REPO, "build", "bin", "tquad"))
    parser.add_argument("--counts", default="1000,1100,1200,1300")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--smesh", nargs="?", const="freecadcmd", default=None, metavar="FREECADCMD",
                        help="also time SMESH's compute() on the same rectangle (FreeCAD's freecadcmd)")
    args = parser.parse_args()
    counts = [int(c) for c in args.counts.split(",")]
    if len(counts) != 4 or min(counts) < 1 or sum(counts) % 2:
        print("--counts: four positive counts with an even sum", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as folder:
        boundary, output = os.path.join(folder, "boundary.json"), os.path.join(folder, "mesh.vtu")
        with open(boundary, "w") as f:
            json.dump(rectangle(counts), f)
        report = subprocess.run([args.tquad, "mesh", boundary, "-o", output, "--report", "json"],
                                capture_output=True, text=True, check=True)
        quads = json.loads(report.stdout)["quads"]
        print(f"machine: {cpu_model()}, {os.cpu_count()} cores (the ratio to SMESH depends on it)")
        print(f"counts {counts}: {quads:,} quads, {json.loads(report.stdout)['faces'][0]['template_tree']}")
        best = {}
        for label, extra in (("smoothed (default)", []), ("--no-smooth", ["--no-smooth"])):
            runs = [run_once([args.tquad, "mesh", boundary, "-o", output] + extra) for _ in range(args.repeat)]
            seconds = min(r[0] for r in runs)
            peak = max(r[1] for r in runs)
            best[label] = seconds
            print(f"{label:20s} {seconds:6.2f} s  peak {peak / 2**20:7.1f} MiB = {peak / quads:5.1f} bytes per quad")
            stages = json.loads(subprocess.run([args.tquad, "mesh", boundary, "-o", output, "--report", "json"] + extra,
                                               capture_output=True, text=True, check=True).stdout).get("stage_seconds")
            if stages:  # (builds before 2026-12-03 did not time the boundary route's stages)
                print(" " * 21 + ", ".join(f"{stage} {t:.2f}" for stage, t in stages.items()) + " s (one more run)")
        if args.smesh:
            compute = smesh_compute_seconds(args.smesh, counts, folder, args.repeat)
            print(f"SMESH compute()      {compute:6.2f} s  (least of {args.repeat}): "
                  + ", ".join(f"{compute / t:.1f}x tquad {label}" for label, t in best.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
