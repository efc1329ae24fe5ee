#!/usr/bin/python3
"""Size sweep: TemplateQuad, Gmsh 4.8 and SMESH (FreeCAD 0.20) on the same rectangles.

    /usr/bin/python3 bench/sweep.py --markdown bench/RESULTS.md --plot bench/sweep.png \\
        [--json raw.json] [--sizes 1e2,1e3,1e4,1e5,1e6,1e7] [--budget 300]

The boundary. For each target size Q (quads) a planar W x H = 1.2 x 1.0 rectangle gets
evenly spaced boundary points with UNEQUAL opposite counts: bottom, right, top, left =
1.2n, 1.0n, 1.3n, 1.1n, each rounded to an even number (Gmsh's subdivision route needs
even sides; the total is then even too), with n = sqrt(Q / (1.25 * 1.05)), so that a
grid of the mean counts would hold Q quads. The meshers' own quad counts differ from Q
and are reported as measured. Gmsh's transfinite route needs equal opposite counts: it
runs on the equal-count rectangle of the same size (bottom = top = the mean of the
horizontal counts, left = right = the mean of the vertical ones), and so does the row
"TemplateQuad, equal counts", for a like-for-like view of that route.

The routes, every case in its own child process:
  * TemplateQuad: the whole command `tquad mesh boundary.json -o out.vtu`, as a user runs
    it, with its default smoothing and with --no-smooth. Quads and the min / mean scaled
    Jacobian come from the command's printed summary; its "meshing" time is the time the
    command prints (reading, meshing, smoothing, quality and writing, inside the process).
  * Gmsh 4.8 (python3-gmsh; this script re-invoked with --gmsh-case), single-threaded,
    General.AbortOnError 0, per-curve setTransfiniteCurve with the boundary counts:
    (a) transfinite surface + recombination, equal counts;
    (b) frontal-Delaunay (Mesh.Algorithm 6) + Blossom recombination
        (Mesh.RecombinationAlgorithm 1), which may leave triangles;
    (c) all-quad subdivision: frontal-Delaunay + Blossom on the curves at HALF the counts,
        then Mesh.SubdivisionAlgorithm 1 splits every element into quads, which doubles
        the boundary counts back to the same ones (checked: the boundary segments found are
        reported when they differ).
    "Meshing" time = gmsh.model.mesh.generate(2). The child writes the mesh as binary .msh.
  * SMESH inside FreeCAD 0.20 (bench/smesh_case.py run by `freecadcmd -c "exec(...)"`):
    Regular_1D + NumberOfSegments per edge with the same counts, Quadrangle_2D +
    QuadranglePreference on the face. "Meshing" time = FemMesh.compute(). The child writes
    the mesh as .vtu.

What is measured, per case:
  * whole process: wall time from spawning the child (under GNU /usr/bin/time, about a
    millisecond more) until it exits: start-up, meshing, writing the mesh file; peak
    memory = the child's ru_maxrss as GNU time's %M reports it, the whole process, so at
    small sizes it is the process's baseline (Python + Gmsh, or FreeCAD);
  * quads and triangles in the written file (read with meshio);
  * min and mean scaled Jacobian of the quads, computed here from the node coordinates for
    the peers (and for TemplateQuad too, kept in --json beside its printed values): for a
    planar quad with corners p0..p3 in order, at corner i with e1 = p[i+1] - p[i] and
    e2 = p[i-1] - p[i],  J_i = (e1 x e2)_z / (|e1| |e2|),  and the quad's value is
    min_i J_i (1 for a rectangle, 0 for a straight angle, negative when inverted; -1 when an
    edge has zero length). The sign is taken against the mesh's orientation (the sign of its
    total signed area), so a clockwise mesh scores like a counter-clockwise one;
  * repeats: a case whose whole process took under --repeat-under seconds (default 10)
    runs --repeat times (default 3) and the fastest run is reported (all its times are in
    --json); slower cases run once;
  * ratios: each route's whole-process time over TemplateQuad's (default options, unequal
    counts) whole-process time in the same run, and the route's meshing-only time over
    that same reference.

Limits. Every child has a wall-time budget (--budget, default 300 s) and a memory guard
(--memory-guard-gb, default 80% of the memory available at start): a child over either is
killed and reported as such ("over budget (> N s)", "memory guard"), never dropped; the
larger sizes of that route are then skipped and reported as skipped. A child that fails
(non-zero exit, empty mesh) is reported with its error. Nothing here asserts a speed.

The load of the machine: the CPU time other processes used during the run is measured from
/proc/stat (total busy time minus this script's and its children's) and printed as the
average number of cores they kept busy.
"""

import argparse
import datetime
import json
import math
import os
import re
import resource
import shlex
import signal
import subprocess
import sys
import tempfile
import threading
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SMESH_SCRIPT = os.path.join(REPO, "bench", "smesh_case.py")
TIME = "/usr/bin/time"  # GNU time (Debian package "time"): the peak memory of a child
WIDTH, HEIGHT = 1.2, 1.0
SIDE_FACTORS = (1.2, 1.0, 1.3, 1.1)  # bottom, right, top, left, in multiples of n
DEFAULT_SIZES = "1e2,1e3,1e4,1e5,1e6,1e7"


# ---------------------------------------------------------------- boundaries

def unequal_counts(target_quads):
    """Side counts (bottom, right, top, left), each even, for about target_quads quads."""
    n = math.sqrt(target_quads / (((SIDE_FACTORS[0] + SIDE_FACTORS[2]) / 2)
                                  * ((SIDE_FACTORS[1] + SIDE_FACTORS[3]) / 2)))
    return [max(2, 2 * round(f * n / 2)) for f in SIDE_FACTORS]


def equal_counts(counts):
    """The equal-count rectangle of the same size: opposite sides get their mean count."""
    horizontal = round((counts[0] + counts[2]) / 2)
    vertical = round((counts[1] + counts[3]) / 2)
    return [horizontal, vertical, horizontal, vertical]


def boundary_json(counts):
    """tquad's boundary file: the rectangle's points counter-clockwise and its 4 corners."""
    corners = [(0.0, 0.0), (WIDTH, 0.0), (WIDTH, HEIGHT), (0.0, HEIGHT)]
    points, corner_indices = [], []
    for side, count in enumerate(counts):
        (ax, ay), (bx, by) = corners[side], corners[(side + 1) % 4]
        corner_indices.append(len(points))
        points += [[ax + (bx - ax) * i / count, ay + (by - ay) * i / count]
                   for i in range(count)]
    return {"points": points, "corners": corner_indices}


# ---------------------------------------------------------------- quality

def scaled_jacobians(points, quads):
    """Per quad: min over its corners of (e1 x e2)_z / (|e1| |e2|), signed by the mesh's
    orientation (see the module docstring); -1 where an edge has zero length."""
    import numpy as np

    xy = points[:, :2]
    corners = [xy[quads[:, i]] for i in range(4)]
    area = sum(corners[i][:, 0] * corners[(i + 1) % 4][:, 1]
               - corners[(i + 1) % 4][:, 0] * corners[i][:, 1] for i in range(4))
    orientation = 1.0 if area.sum() >= 0 else -1.0
    worst = np.full(len(quads), np.inf)
    for i in range(4):
        e1 = corners[(i + 1) % 4] - corners[i]
        e2 = corners[(i - 1) % 4] - corners[i]
        lengths = np.hypot(e1[:, 0], e1[:, 1]) * np.hypot(e2[:, 0], e2[:, 1])
        cross = orientation * (e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
        with np.errstate(divide="ignore", invalid="ignore"):
            corner = np.where(lengths > 0, cross / lengths, -1.0)
        worst = np.minimum(worst, corner)
    return worst


def file_quality(path, chunk=1_000_000):
    """Quads, triangles and the quads' min / mean scaled Jacobian of a mesh file."""
    import contextlib
    import io

    import meshio
    import numpy as np

    with contextlib.redirect_stdout(io.StringIO()):  # meshio's Gmsh reader prints blank lines
        mesh = meshio.read(path)
    quads = [c.data for c in mesh.cells if c.type == "quad"]
    triangles = sum(len(c.data) for c in mesh.cells if c.type == "triangle")
    quads = np.concatenate(quads) if quads else np.zeros((0, 4), dtype=np.int64)
    result = {"quads": len(quads), "triangles": triangles, "sj_min": None, "sj_mean": None}
    if len(quads):
        values = np.concatenate([scaled_jacobians(mesh.points, quads[i:i + chunk])
                                 for i in range(0, len(quads), chunk)])
        result.update(sj_min=float(values.min()), sj_mean=float(values.mean()))
    return result


# ---------------------------------------------------------------- a child under limits

class ChildRun:
    """What one child process did: exit code, wall seconds, peak resident bytes, output,
    and `killed` ("budget" or "memory") when the watchdog ended it."""

    def __init__(self, exit_code, seconds, peak_bytes, stdout, stderr, killed):
        self.exit_code, self.seconds, self.peak_bytes = exit_code, seconds, peak_bytes
        self.stdout, self.stderr, self.killed = stdout, stderr, killed


def process_tree(pid):
    """pid and its descendants, as /proc lists them now."""
    pids = [pid]
    try:
        for task in os.listdir("/proc/%d/task" % pid):
            with open("/proc/%d/task/%s/children" % (pid, task)) as f:
                for child in f.read().split():
                    pids += process_tree(int(child))
    except OSError:
        pass
    return pids


def resident_bytes(pids):
    total = 0
    for pid in pids:
        try:
            with open("/proc/%d/status" % pid) as f:
                total += next((int(l.split()[1]) * 1024 for l in f if l.startswith("VmRSS:")), 0)
        except OSError:
            pass
    return total


def kill_tree(child, pids, exited):
    """Kills the mesher under GNU time first (time then reaps it and reports its peak, and
    its CPU time stays accounted to this script); the whole session if time lingers."""
    for pid in pids[1:]:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    if not exited.wait(5):
        os.killpg(child.pid, signal.SIGKILL)  # the session this script started


def watch(child, start, budget, memory_limit, exited, killed):
    """Watchdog thread: ends the child when over budget or memory; keeps the largest
    resident size seen."""
    while not exited.wait(0.1):
        pids = process_tree(child.pid)
        rss = resident_bytes(pids)
        killed["seen_bytes"] = max(killed.get("seen_bytes", 0), rss)
        reason = ("budget" if time.perf_counter() - start > budget
                  else "memory" if rss > memory_limit else None)
        if reason:
            killed["reason"] = reason
            kill_tree(child, pids, exited)
            return


def run_child(command, budget, memory_limit, env=None):
    """Runs one child under GNU time in its own session: wall time from spawn to exit
    measured here, peak resident size from time's %M (the child's own ru_maxrss; taking
    the rusage of a direct child of this script would count the pages of this Python
    process it was forked from)."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err, \
            tempfile.NamedTemporaryFile("r") as peak_file:
        start = time.perf_counter()
        child = subprocess.Popen([TIME, "-f", "%M", "-o", peak_file.name] + command,
                                 stdout=out, stderr=err, env=env, start_new_session=True)
        exited, killed = threading.Event(), {}
        watchdog = threading.Thread(target=watch, daemon=True,
                                    args=(child, start, budget, memory_limit, exited, killed))
        watchdog.start()
        os.waitid(os.P_PID, child.pid, os.WEXITED | os.WNOWAIT)  # exited, not yet reaped
        seconds = time.perf_counter() - start
        exited.set()
        watchdog.join()  # it may still be waiting for time to exit after a kill
        child.wait()
        peak = peak_file.read().split()
        peak_bytes = max(int(peak[-1]) * 1024 if peak and peak[-1].isdigit() else 0,
                         killed.get("seen_bytes", 0))
        out.seek(0)
        err.seek(0)
        return ChildRun(child.returncode, seconds, peak_bytes,
                        out.read().decode(errors="replace"), err.read().decode(errors="replace"),
                        killed.get("reason"))


# ---------------------------------------------------------------- gmsh child process

def gmsh_case(spec):
    """Runs in the child: meshes one Gmsh route, writes spec["output"], prints one JSON."""
    import gmsh

    from gmsh_rectangle import quiet_single_thread, rectangle

    counts, route = spec["counts"], spec["route"]
    gmsh.initialize([], False)
    quiet_single_thread(gmsh)
    gmsh.logger.start()
    halve = route == "subdivision"  # subdivision doubles every boundary segment
    lines, surface = rectangle(gmsh, WIDTH, HEIGHT, [n // 2 if halve else n for n in counts])
    if route == "transfinite":
        gmsh.model.mesh.setTransfiniteSurface(surface)
    else:
        gmsh.option.setNumber("Mesh.Algorithm", 6)  # frontal-Delaunay (8 crashes in 4.8)
        gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)  # Blossom
        gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 1 if halve else 0)
    gmsh.model.mesh.setRecombine(2, surface)
    start = time.perf_counter()
    error = None
    try:
        gmsh.model.mesh.generate(2)
    except Exception as e:  # with AbortOnError 0 Gmsh raises instead of exiting
        error = str(e)
    generate_s = time.perf_counter() - start
    boundary = [len(gmsh.model.mesh.getElements(1, line)[1][0]) for line in lines]
    gmsh.option.setNumber("Mesh.Binary", 1)
    gmsh.write(spec["output"])
    errors = [m for m in gmsh.logger.get() if m.startswith("Error")]
    version = gmsh.option.getString("General.Version")
    gmsh.finalize()
    print(json.dumps({"generate_s": generate_s, "boundary_segments": boundary,
                      "error": error, "errors": errors[:3], "gmsh": version}))


# ---------------------------------------------------------------- routes (parent side)

class Route:
    def __init__(self, key, label, kind, equal=False, options=()):
        self.key, self.label, self.kind = key, label, kind
        self.equal, self.options = equal, list(options)


ROUTES = [
    Route("tquad", "TemplateQuad (default: smoothed)", "tquad"),
    Route("tquad_nosmooth", "TemplateQuad --no-smooth", "tquad", options=["--no-smooth"]),
    Route("tquad_equal", "TemplateQuad, equal counts", "tquad", equal=True),
    Route("gmsh_transfinite", "Gmsh transfinite, equal counts", "gmsh", equal=True,
          options=["transfinite"]),
    Route("gmsh_blossom", "Gmsh frontal-Delaunay + Blossom", "gmsh", options=["blossom"]),
    Route("gmsh_subdivision", "Gmsh all-quad subdivision (Blossom at half counts, "
          "SubdivisionAlgorithm 1)", "gmsh", options=["subdivision"]),
    Route("smesh", "SMESH Quadrangle_2D + QuadranglePreference", "smesh"),
]
REFERENCE = "tquad"


def new_row(route, target, counts):
    return {"route": route.key, "label": route.label, "target": target, "counts": counts,
            "status": "ok", "note": "", "quads": None, "triangles": None, "mesh_s": None,
            "process_s": None, "peak_bytes": None, "sj_min": None, "sj_mean": None}


def child_status(row, run, budget):
    """Fills the row from a finished child; returns False when it did not succeed."""
    row.update(process_s=run.seconds, peak_bytes=run.peak_bytes)
    if run.killed == "budget":
        row.update(status="over budget", note="over budget (> %g s), killed at %.0f MB resident"
                   % (budget, run.peak_bytes / 1e6))
    elif run.killed == "memory":
        row.update(status="memory guard", note="killed by the memory guard at %.1f GB resident"
                   % (run.peak_bytes / 1e9))
    elif run.exit_code != 0:
        tail = (run.stderr.strip() or run.stdout.strip())[-200:].replace("\n", " ")
        row.update(status="failed", note="exit %d: %s" % (run.exit_code, tail))
    return row["status"] == "ok"


def add_file_quality(row, path, keep_counts=False):
    """Counts and quality from the written file; an empty or triangle mesh is flagged."""
    try:
        quality = file_quality(path)
    except Exception as e:  # an unreadable file is a result to report, not a crash
        row["note"] = "mesh file not readable: %s" % str(e)[:150]
        return
    if keep_counts:
        row.update(sj_min_recomputed=quality["sj_min"], sj_mean_recomputed=quality["sj_mean"],
                   quads_in_file=quality["quads"], triangles=quality["triangles"])
        return
    row.update(quality)
    if quality["quads"] == 0 and quality["triangles"] == 0:
        row.update(status="failed", note="empty mesh")
    elif quality["quads"] == 0:
        row["note"] = "fell back to triangles"
    elif quality["triangles"]:
        row["note"] = "not all-quad: %d triangles" % quality["triangles"]


def check_boundary(row, found, counts):
    if found is not None and list(found) != list(counts):
        row["note"] = (row["note"] + "; " if row["note"] else "") + \
            "boundary segments %s" % ",".join(map(str, found))


def parse_tquad_summary(text):
    quads = re.search(r"quads (\d+)", text)
    jacobian = re.search(r"scaled Jacobian min (-?[\d.]+) avg (-?[\d.]+)", text)
    seconds = re.search(r"; time ([\d.]+) s", text)
    if not (quads and jacobian and seconds):
        return None
    return {"quads": int(quads.group(1)), "sj_min": float(jacobian.group(1)),
            "sj_mean": float(jacobian.group(2)), "mesh_s": float(seconds.group(1))}


def run_tquad(route, counts, row, folder, args):
    boundary = os.path.join(folder, "boundary.json")
    output = os.path.join(folder, "tquad.vtu")
    with open(boundary, "w") as f:
        json.dump(boundary_json(counts), f)
    run = run_child([args.tquad, "mesh", boundary, "-o", output] + route.options,
                    args.budget, args.memory_limit)
    if not child_status(row, run, args.budget):
        return
    summary = parse_tquad_summary(run.stdout)
    if summary is None:
        row.update(status="failed", note="no summary in the output: " + run.stdout[-200:])
        return
    row.update(summary)
    add_file_quality(row, output, keep_counts=True)


def run_gmsh(route, counts, row, folder, args):
    output = os.path.join(folder, "gmsh.msh")
    spec = {"counts": counts, "route": route.options[0], "output": output}
    run = run_child([sys.executable, os.path.abspath(__file__), "--gmsh-case", json.dumps(spec)],
                    args.budget, args.memory_limit)
    if not child_status(row, run, args.budget):
        return
    lines = [l for l in run.stdout.splitlines() if l.startswith("{")]
    if not lines:
        row.update(status="failed", note="no result from the Gmsh child: " + run.stderr[-200:])
        return
    result = json.loads(lines[-1])
    row.update(mesh_s=result["generate_s"], gmsh=result["gmsh"])
    add_file_quality(row, output)
    check_boundary(row, result["boundary_segments"], counts)
    if result["error"] or result["errors"]:
        row["gmsh_errors"] = [e for e in [result["error"]] + result["errors"] if e]
        if row["status"] == "ok" and not row["note"]:
            row["note"] = "Gmsh logged errors (see --json)"


def run_smesh(route, counts, row, folder, args):
    output, result_path = os.path.join(folder, "smesh.vtu"), os.path.join(folder, "smesh.json")
    spec = {"counts": counts, "width": WIDTH, "height": HEIGHT, "output": output,
            "result": result_path}
    env = dict(os.environ, SWEEP_SMESH_SPEC=json.dumps(spec))
    command = [args.freecadcmd, "-c", "exec(open(%r).read())" % SMESH_SCRIPT]
    run = run_child(command, args.budget, args.memory_limit, env=env)
    if not child_status(row, run, args.budget):
        return
    if not os.path.exists(result_path):
        row.update(status="failed", note="no result from freecadcmd: " + run.stderr[-200:])
        return
    with open(result_path) as f:
        result = json.load(f)
    row.update(mesh_s=result["compute_s"], freecad=result["freecad"])
    add_file_quality(row, output)
    check_boundary(row, result["boundary_segments"], counts)


RUNNERS = {"tquad": run_tquad, "gmsh": run_gmsh, "smesh": run_smesh}


def route_counts(route, target):
    counts = unequal_counts(target)
    return equal_counts(counts) if route.equal else counts


def measure_once(route, target, args):
    counts = route_counts(route, target)
    row = new_row(route, target, counts)
    with tempfile.TemporaryDirectory(prefix="sweep-") as folder:
        RUNNERS[route.kind](route, counts, row, folder, args)
    return row


def measure(route, target, args):
    """One case; a successful case faster than --repeat-under seconds runs up to --repeat
    times and keeps its fastest whole-process run (every run's time is kept in the row)."""
    row = measure_once(route, target, args)
    runs = [row]
    while (row["status"] == "ok" and row["process_s"] < args.repeat_under
           and len(runs) < args.repeat):
        again = measure_once(route, target, args)
        if again["status"] != "ok":
            return again  # a run that fails is reported, however the others went
        runs.append(again)
    best = min(runs, key=lambda r: r["process_s"])
    best["process_s_runs"] = [r["process_s"] for r in runs]
    return best


# ---------------------------------------------------------------- the sweep

def sweep(args, routes):
    """All routes on all sizes, smallest first; a route over budget or memory at one size
    is skipped (and reported skipped) at the larger ones."""
    rows, stopped = [], {}
    for target in args.sizes:
        for route in routes:
            if route.key in stopped:
                row = new_row(route, target, route_counts(route, target))
                row.update(status="skipped", note="skipped: %s at %s" % stopped[route.key])
            else:
                row = measure(route, target, args)
                if row["status"] in ("over budget", "memory guard"):
                    stopped[route.key] = (row["status"], size_name(target))
            print(progress_line(row), file=sys.stderr, flush=True)
            rows.append(row)
    return rows


def progress_line(row):
    seconds = "-" if row["process_s"] is None else "%.2f s" % row["process_s"]
    return "%-8s %-40.40s %-12s quads %-10s %s %s" % (
        size_name(row["target"]), row["label"], row["status"], row["quads"], seconds, row["note"])


def size_name(target):
    return "1e%d" % round(math.log10(target)) if target > 0 and math.log10(target).is_integer() \
        else "%g" % target


# ---------------------------------------------------------------- machine and load

def cpu_model():
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    return "unknown"


def meminfo_bytes(field):
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith(field + ":"):
                return int(line.split()[1]) * 1024
    return 0


def busy_cpu_seconds():
    """Busy CPU seconds of the whole machine since boot (user..steal, no idle/iowait)."""
    with open("/proc/stat") as f:
        fields = [int(v) for v in f.readline().split()[1:]]
    busy = sum(fields[:8]) - fields[3] - fields[4]
    return busy / os.sysconf("SC_CLK_TCK")


def own_cpu_seconds():
    usage = [resource.getrusage(who) for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)]
    return sum(u.ru_utime + u.ru_stime for u in usage)


def command_output(command):
    try:
        return subprocess.run(command, capture_output=True, text=True, cwd=REPO,
                              timeout=60).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return ""


def machine_info(args):
    tquad_built = os.path.getmtime(args.tquad)
    last_src_commit = command_output(["git", "log", "-1", "--format=%ct", "--", "src"])
    return {
        "cpu": cpu_model(), "cores": os.cpu_count(), "ram_bytes": meminfo_bytes("MemTotal"),
        "available_bytes": meminfo_bytes("MemAvailable"),
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "commit": command_output(["git", "rev-parse", "--short", "HEAD"]),
        "src_dirty": bool(command_output(["git", "status", "--porcelain", "--", "src"])),
        "tquad_version": command_output([args.tquad, "--version"]),
        "tquad_built": datetime.datetime.fromtimestamp(tquad_built, datetime.timezone.utc)
        .strftime("%Y-%m-%d %H:%M UTC"),
        "tquad_older_than_src": bool(last_src_commit) and tquad_built < int(last_src_commit),
        "freecad_package": command_output(["dpkg-query", "-W", "-f", "${Version}", "freecad"]),
        "gmsh_package": command_output(["dpkg-query", "-W", "-f", "${Version}", "python3-gmsh"]),
        "python": sys.version.split()[0],
    }


# ---------------------------------------------------------------- report

def ratio_text(value, reference):
    if value is None or not reference:
        return "-"
    ratio = value / reference
    return "%.1f× slower" % ratio if ratio >= 1 else "%.1f× faster" % (1 / ratio)


def number(value, fmt):
    """value in fmt ("%.3f"-style, or "," for thousands separators); "-" when missing."""
    if value is None:
        return "-"
    return format(value, ",") if fmt == "," else fmt % value


def reference_row(rows, target):
    for row in rows:
        if row["route"] == REFERENCE and row["target"] == target and row["status"] == "ok":
            return row
    return None


def table_row(row, reference):
    ok = row["status"] == "ok"
    ref_s = reference["process_s"] if reference else None
    is_ref = row["route"] == REFERENCE
    peak = row["peak_bytes"] if ok else None
    per_quad = peak / row["quads"] if peak and row["quads"] else None
    cells = [
        row["label"], ",".join(map(str, row["counts"])) if row["counts"] else "-",
        number(row["quads"], ","), number(row["triangles"], ","),
        number(row["mesh_s"], "%.3f"),
        number(row["process_s"], "%.3f") if row["status"] != "skipped" else "-",
        "reference" if is_ref else ratio_text(row["process_s"] if ok else None, ref_s),
        ratio_text(row["mesh_s"] if ok else None, ref_s),
        number(peak / 1e6 if peak else None, "%.1f"), number(per_quad, "%.0f"),
        number(row["sj_min"], "%.3f"), number(row["sj_mean"], "%.3f"),
        row["note"] if row["note"] else ("" if ok else row["status"]),
    ]
    return "| " + " | ".join(cells) + " |"


def size_table(rows, target):
    reference = reference_row(rows, target)
    lines = ["| mesher / route | side counts (b,r,t,l) | quads | triangles | meshing (s) "
             "| whole process (s) | whole process vs TemplateQuad | meshing only vs "
             "TemplateQuad's whole process | peak MB | peak bytes/quad | SJ min | SJ mean "
             "| note |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    lines += [table_row(row, reference) for row in rows if row["target"] == target]
    return lines


def summary_table(rows, routes, sizes):
    """Sizes down, routes across: each route's whole-process time over TemplateQuad's."""
    peers = [r for r in routes if r.key != REFERENCE]
    lines = ["| size | TemplateQuad whole process (s) | "
             + " | ".join(r.label for r in peers) + " |",
             "|---|---:|" + "---:|" * len(peers)]
    for target in sizes:
        reference = reference_row(rows, target)
        cells = [size_name(target), number(reference["process_s"] if reference else None, "%.3f")]
        for route in peers:
            row = next(r for r in rows if r["route"] == route.key and r["target"] == target)
            if row["status"] == "ok":
                cells.append(ratio_text(row["process_s"], reference["process_s"]
                                        if reference else None))
            else:
                cells.append(row["status"])
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def markdown(rows, routes, info, load, args):
    gmsh_version = next((r["gmsh"] for r in rows if r.get("gmsh")), "not run")
    freecad_version = next((r["freecad"] for r in rows if r.get("freecad")), "not run")
    lines = [
        "# Size sweep: TemplateQuad against Gmsh 4.8 and SMESH (FreeCAD 0.20)",
        "",
        "Regenerate (from the repository root, with the tquad build in `build/`):",
        "",
        "    " + args.command_line,
        "",
        "Machine: %s, %d cores, %.1f GB RAM (%.1f GB available at start); run %s; "
        "%.0f s in all." % (info["cpu"], info["cores"], info["ram_bytes"] / 1e9,
                            info["available_bytes"] / 1e9, info["date"], load["wall_s"]),
        "Other processes kept on average %.2f of the %d cores busy during the run "
        "(from /proc/stat, this script's own CPU time taken out)." % (load["other_cores"],
                                                                    info["cores"]),
    ]
    if args.note:
        lines.append("Note on this run: " + args.note)
    lines += [
        "",
        "Versions: tquad commit %s%s (`tquad --version`: %s; binary built %s%s); "
        "Gmsh %s (python3-gmsh %s); FreeCAD %s (package %s); Python %s."
        % (info["commit"], " with local changes under src/" if info["src_dirty"] else "",
           info["tquad_version"] or "?", info["tquad_built"],
           ", earlier than the date of the last commit touching src/: check the build is current"
           if info["tquad_older_than_src"] else "",
           gmsh_version, info["gmsh_package"], freecad_version, info["freecad_package"],
           info["python"]),
        "",
        "Budget %g s of wall time per case, memory guard %.1f GB; a case over either is killed "
        "and the larger sizes of its route are skipped. A case under %g s runs %d times and "
        "its fastest run is shown; slower cases run once."
        % (args.budget, args.memory_limit / 1e9, args.repeat_under, args.repeat),
        "",
        "What is measured and how: see the docstring of `bench/sweep.py`. In short: every case is "
        "its own process; *whole process* = wall time from spawn to exit, start-up and writing "
        "the mesh file included (TemplateQuad .vtu, Gmsh binary .msh, SMESH .vtu); *meshing* = "
        "the time TemplateQuad prints (read, mesh, smooth, quality, write; in whole "
        "milliseconds), Gmsh's "
        "`generate(2)`, SMESH's `compute()`; *peak* = the process's ru_maxrss (at small sizes "
        "this is the process's baseline: FreeCAD, or Python with Gmsh); SJ = scaled "
        "Jacobian, TemplateQuad's as it prints it, the peers' computed from the written "
        "nodes with the same formula. The rectangle is 1.2 × 1.0 with unequal opposite side "
        "counts; the transfinite route (and the 'TemplateQuad, equal counts' row beside it) "
        "runs on the equal-count rectangle of the same size, which that route needs. Ratios "
        "are against TemplateQuad's default whole process on the unequal counts in the same "
        "run.",
        "",
        "## Whole-process time against TemplateQuad's",
        "",
    ]
    lines += summary_table(rows, routes, args.sizes)
    for target in args.sizes:
        lines += ["", "## About %s quads" % size_name(target), ""]
        lines += size_table(rows, target)
    lines += ["", consistency_note(rows), "", "![time against quads](%s)" % args.plot_link, ""]
    return "\n".join(lines)


def consistency_note(rows):
    """How far TemplateQuad's printed scaled Jacobian is from the one computed here."""
    gaps = [max(abs(r["sj_min"] - r["sj_min_recomputed"]),
                abs(r["sj_mean"] - r["sj_mean_recomputed"]))
            for r in rows if r.get("sj_min_recomputed") is not None]
    if not gaps:
        return ""
    return ("The scaled Jacobian computed here from TemplateQuad's written .vtu differs from "
            "the values it prints (3 decimals) by at most %.4f over all its runs." % max(gaps))


def plot_panel(axes, rows, routes, time_key, budget):
    """One log-log panel: time_key ("process_s" or "mesh_s") against elements, a line per
    route; on the whole-process panel, killed cases as crosses of their route's colour at
    TemplateQuad's quad count of their size."""
    markers = "osD^v<>ph*"
    any_killed = False
    for i, route in enumerate(routes):
        done = [r for r in rows if r["route"] == route.key and r["status"] == "ok"]
        line, = axes.plot([r["quads"] + (r["triangles"] or 0) for r in done],
                          [r[time_key] for r in done], marker=markers[i % len(markers)],
                          label=route.label)
        killed = [r for r in rows if r["route"] == route.key
                  and r["status"] in ("over budget", "memory guard")]
        if time_key != "process_s" or not killed:
            continue
        any_killed = True
        for r in killed:
            reference = reference_row(rows, r["target"])
            x = reference["quads"] if reference else r["target"]
            axes.plot([x], [r["process_s"]], marker="x", markersize=11, markeredgewidth=2.5,
                      color=line.get_color(), linestyle="")
    if any_killed:
        axes.axhline(budget, color="grey", linestyle=":", linewidth=1)
        axes.text(0.01, budget, "budget %g s: x = killed" % budget,
                  transform=axes.get_yaxis_transform(), fontsize=8, color="grey", va="bottom")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("elements in the mesh (quads + triangles)")
    axes.grid(True, which="both", alpha=0.3)


def plot(rows, routes, args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, (whole, meshing) = plt.subplots(1, 2, figsize=(12, 7.5), sharey=True)
    plot_panel(whole, rows, routes, "process_s", args.budget)
    plot_panel(meshing, rows, routes, "mesh_s", args.budget)
    whole.set_ylabel("wall time (s)")
    whole.set_title("whole process: start-up, meshing, writing the mesh file", fontsize=10)
    meshing.set_title("meshing only: TemplateQuad's printed time, Gmsh generate(2),\n"
                      "SMESH compute()", fontsize=10)
    meshing.tick_params(labelleft=True)
    handles, labels = whole.get_legend_handles_labels()
    figure.legend(handles, labels, loc="lower center", ncol=2, fontsize=9)
    figure.suptitle("Quad meshers on a 1.2 x 1.0 rectangle with unequal side counts "
                    "(transfinite rows: equal counts)",
                    fontsize=11)
    figure.tight_layout(rect=(0, 0.14, 1, 1))
    figure.savefig(args.plot, dpi=110)
    plt.close(figure)


# ---------------------------------------------------------------- main

def parse_sizes(text):
    sizes = [float(s) for s in text.split(",")]
    if not sizes or min(sizes) < 10:
        raise argparse.ArgumentTypeError("sizes are quad counts of at least 10, e.g. 1e2,1e3")
    return sizes


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=parse_sizes, default=parse_sizes(DEFAULT_SIZES),
                        help="target quad counts (default %s)" % DEFAULT_SIZES)
    parser.add_argument("--budget", type=float, default=300.0,
                        help="wall seconds per case before it is killed (default 300)")
    parser.add_argument("--repeat", type=int, default=3,
                        help="runs of a case faster than --repeat-under; the fastest is kept "
                             "(default 3)")
    parser.add_argument("--repeat-under", type=float, default=10.0,
                        help="seconds under which a case is repeated (default 10)")
    parser.add_argument("--memory-guard-gb", type=float,
                        help="resident GB per case before it is killed "
                             "(default 80%% of the memory available at start)")
    parser.add_argument("--routes", help="comma-separated subset of: " +
                        ",".join(r.key for r in ROUTES))
    parser.add_argument("--tquad", default=os.path.join(REPO, "build", "bin", "tquad"))
    parser.add_argument("--freecadcmd", default="freecadcmd")
    parser.add_argument("--markdown", help="write the report here (default: print it)")
    parser.add_argument("--plot", help="write the log-log time plot here (PNG)")
    parser.add_argument("--json", help="write the raw numbers here")
    parser.add_argument("--note", help="circumstances of this run, printed under the machine "
                        "description (left out of the regenerate command)")
    parser.add_argument("--gmsh-case", help=argparse.SUPPRESS)
    args = parser.parse_args()
    args.memory_limit = (args.memory_guard_gb * 1e9 if args.memory_guard_gb
                         else 0.8 * meminfo_bytes("MemAvailable"))
    args.command_line = regenerate_command(sys.argv)
    return args


def regenerate_command(argv):
    """This command as run from the repository root, without the options that do not
    change the report: --note (the circumstances of one run) and --json (a side file)."""
    words, skip = [os.path.relpath(os.path.abspath(argv[0]), REPO)], False
    for word in argv[1:]:
        if skip:
            skip = False
        elif word in ("--note", "--json"):
            skip = True
        elif not word.startswith(("--note=", "--json=")):
            words.append(word)
    return "/usr/bin/python3 " + shlex.join(words)


def selected_routes(args):
    if not args.routes:
        return ROUTES
    keys = args.routes.split(",")
    unknown = set(keys) - {r.key for r in ROUTES}
    if unknown or REFERENCE not in keys:
        sys.exit("--routes: unknown %s (the reference %r is required)"
                 % (",".join(sorted(unknown)) or "none", REFERENCE))
    return [r for r in ROUTES if r.key in keys]


def main():
    args = parse_args()
    if args.gmsh_case:
        gmsh_case(json.loads(args.gmsh_case))
        return 0
    if not os.access(TIME, os.X_OK):
        sys.exit("GNU time not found at %s (Debian package 'time')" % TIME)
    if not os.access(args.tquad, os.X_OK):
        sys.exit("tquad not found: %s (build it or pass --tquad)" % args.tquad)
    routes = selected_routes(args)
    info = machine_info(args)
    start_wall, start_busy, start_own = time.perf_counter(), busy_cpu_seconds(), own_cpu_seconds()
    rows = sweep(args, routes)
    wall = time.perf_counter() - start_wall
    other = (busy_cpu_seconds() - start_busy) - (own_cpu_seconds() - start_own)
    load = {"wall_s": wall, "other_cores": max(0.0, other / wall)}
    if args.plot:
        plot(rows, routes, args)
    args.plot_link = os.path.relpath(args.plot, os.path.dirname(os.path.abspath(args.markdown))) \
        if args.plot and args.markdown else (args.plot or "sweep.png")
    report = markdown(rows, routes, info, load, args)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(report)
    else:
        print(report)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"machine": info, "load": load, "budget_s": args.budget,
                       "memory_limit_bytes": args.memory_limit, "rows": rows}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
