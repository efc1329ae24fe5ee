#!/usr/bin/python3
"""Whole CAD parts: TemplateQuad's tquad against Gmsh 4.8 at the same target edge size.

Run with Debian's /usr/bin/python3 (it has python3-gmsh, meshio and numpy):

    /usr/bin/python3 bench/compare_parts.py [--cad-dir ../shared/data/cad] [--divisor 25]
        [--timeout 300] [--files a.stp,b.brep] [--json out.json] [--markdown bench/PARTS.md]

For every part (*.stp, *.step, *.brep in the CAD directory):
  * the target edge size is H = bounding-box diagonal / divisor, the diagonal taken from
    gmsh.model.getBoundingBox(-1, -1) after importing the shape with Gmsh's OpenCASCADE
    kernel; the same H goes to both meshers (25 is tquad's own default divisor);
  * TemplateQuad: `tquad mesh PART -o PART.vtu --keep-going --report json --size H`,
    timed as the wall time of the whole process (reading the CAD file included). Quads,
    refused faces and the scaled Jacobian come from its JSON report; the scaled Jacobian is
    also recomputed from the written .vtu with the formula used for Gmsh below;
  * Gmsh, two runs, each in its own process (this script re-invoked with --gmsh-job) so
    that a crash or a hang of Gmsh costs one table cell, not the run:
      Blossom  - frontal-Delaunay (Mesh.Algorithm 6) + Blossom recombination of every
                 surface; it may leave triangles, which are counted;
      all-quad - the same, then Mesh.SubdivisionAlgorithm 1 (every element split into
                 quads), which halves the edges: its size is set to 2H so that the final
                 edges are about H, like the others.
    Two times per run: generate(2) alone, and the wall time of the whole child process
    (Python start, CAD import, meshing, extracting the mesh). The ratio columns set
    generate(2) alone against tquad's whole process, the comparison least favourable
    to TemplateQuad.

Scaled Jacobian of a quad p0..p3, the same code for both meshers: at corner i, with
e1 = p[i+1] - p[i], e2 = p[i-1] - p[i] and the quad's own normal n = (p2 - p0) x (p3 - p1),
s_i = dot(e1 x e2, n) / (|e1| |e2| |n|); the quad's value is the smallest s_i (1 for a
rectangle, <= 0 for an inverted or degenerate quad). Gmsh's triangles are left out of its
scaled Jacobian columns; `all_elements_min_sine` in the JSON is the smallest corner sine
over its quads and triangles together (a quad's scaled Jacobian is its smallest corner
sine, so the two compare; an equilateral triangle scores 0.866). Nothing here asserts anything; the numbers are printed as measured.
"""

import argparse
import datetime
import glob
import json
import math
import os
import platform
import signal
import subprocess
import sys
import tempfile
import time

import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TQUAD = os.path.join(REPO, "build", "bin", "tquad")
CAD_SUFFIXES = (".stp", ".step", ".brep")
GMSH_ROUTES = ("blossom", "allquad")


# ---------------------------------------------------------------- quality

def corner_scaled_jacobians(points, quads, normals=None):
    """Scaled Jacobian at every corner (see the module docstring): an (m, 4) array for
    points (n, 3) and quads (m, 4). `normals` is None for each quad's own normal
    (p2 - p0) x (p3 - p1), or an (m, 4, 3) array giving the normal at each corner. A corner
    with a zero-length edge or normal scores 0."""
    if len(quads) == 0:
        return np.zeros((0, 4))
    p = np.asarray(points, dtype=float)[np.asarray(quads)]          # (m, 4, 3)
    if normals is None:
        normal = np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 1])[:, None, :]   # (m, 1, 3)
    else:
        normal = np.asarray(normals, dtype=float)                    # (m, 4, 3)
    normal_len = np.linalg.norm(normal, axis=2)                      # (m, 1) or (m, 4)
    e1 = np.roll(p, -1, axis=1) - p                                  # p[i+1] - p[i]
    e2 = np.roll(p, 1, axis=1) - p                                   # p[i-1] - p[i]
    signed = np.einsum("mij,mij->mi", np.cross(e1, e2), np.broadcast_to(normal, p.shape))
    denom = np.linalg.norm(e1, axis=2) * np.linalg.norm(e2, axis=2) * normal_len
    corner = np.zeros_like(signed)
    np.divide(signed, denom, out=corner, where=denom > 0)             # degenerate -> 0
    return corner


def scaled_jacobian(points, quads):
    """Scaled Jacobian of each quad (see the module docstring); points (n, 3), quads (m, 4)."""
    if len(quads) == 0:
        return np.zeros(0)
    return corner_scaled_jacobians(points, quads).min(axis=1)


def triangle_corner_sines(points, triangles):
    """Smallest corner sine of each triangle (sin 60 = 0.866 for an equilateral one),
    comparable with a quad's scaled Jacobian, which is its smallest corner sine."""
    if len(triangles) == 0:
        return np.zeros(0)
    p = np.asarray(points, dtype=float)[np.asarray(triangles)]      # (m, 3, 3)
    e1 = np.roll(p, -1, axis=1) - p
    e2 = np.roll(p, 1, axis=1) - p
    cross = np.linalg.norm(np.cross(e1, e2), axis=2)
    denom = np.linalg.norm(e1, axis=2) * np.linalg.norm(e2, axis=2)
    sines = np.zeros_like(cross)
    np.divide(cross, denom, out=sines, where=denom > 0)
    return sines.min(axis=1)


def sj_stats(values):
    """Min and mean of the per-quad values, or None when there are no quads."""
    if len(values) == 0:
        return None
    return {"min": float(values.min()), "mean": float(values.mean()),
            "inverted": int((values <= 0).sum())}


# ---------------------------------------------------------------- gmsh child process

def gmsh_import(gmsh, path):
    gmsh.initialize([], False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.AbortOnError", 0)
    gmsh.model.add("part")
    gmsh.model.occ.importShapes(path)
    gmsh.model.occ.synchronize()


def gmsh_bbox_diagonal(path):
    import gmsh
    gmsh_import(gmsh, path)
    try:
        xmin, ymin, zmin, xmax, ymax, zmax = gmsh.model.getBoundingBox(-1, -1)
        faces = len(gmsh.model.getEntities(2))
        version = gmsh.__version__
    finally:
        gmsh.finalize()
    return {"diagonal": math.dist((xmin, ymin, zmin), (xmax, ymax, zmax)),
            "gmsh_faces": faces, "gmsh_version": version}


def set_size(gmsh, size):
    # 4.8 has the MeshSize* names; the CharacteristicLength* aliases are set too, harmlessly.
    for name in ("Mesh.MeshSizeMin", "Mesh.MeshSizeMax",
                 "Mesh.CharacteristicLengthMin", "Mesh.CharacteristicLengthMax"):
        try:
            gmsh.option.setNumber(name, size)
        except Exception:
            pass


def gmsh_surface_mesh(gmsh):
    """Node coordinates, quads and triangles of the 2D mesh, and surfaces left empty."""
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    index = np.zeros(int(node_tags.max()) + 1 if len(node_tags) else 1, dtype=np.int64)
    index[node_tags.astype(np.int64)] = np.arange(len(node_tags))
    points = coords.reshape(-1, 3)
    quads = np.zeros((0, 4), dtype=np.int64)
    triangles = np.zeros((0, 3), dtype=np.int64)
    types, _, nodes = gmsh.model.mesh.getElements(2)
    for etype, enodes in zip(types, nodes):
        if etype == 3:
            quads = np.vstack([quads, index[enodes.astype(np.int64)].reshape(-1, 4)])
        elif etype == 2:
            triangles = np.vstack([triangles, index[enodes.astype(np.int64)].reshape(-1, 3)])
    empty = sum(1 for _, tag in gmsh.model.getEntities(2)
                if not any(len(t) for t in gmsh.model.mesh.getElements(2, tag)[1]))
    return points, quads, triangles, empty


def gmsh_job(spec):
    """Meshes one part with one Gmsh route in this process and prints one JSON line."""
    if spec["route"] == "bbox":
        print(json.dumps(gmsh_bbox_diagonal(spec["path"])))
        return
    import gmsh
    gmsh_import(gmsh, spec["path"])
    result = {}
    try:
        gmsh.option.setNumber("Mesh.Algorithm", 6)              # frontal-Delaunay (8 crashes in 4.8)
        gmsh.option.setNumber("Mesh.RecombineAll", 1)
        gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)  # Blossom
        size = spec["size"]
        if spec["route"] == "allquad":
            # Subdivision splits every edge in two, so mesh at 2H to end with edges of about H.
            gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 1)
            size = 2 * size
        set_size(gmsh, size)
        start = time.perf_counter()
        try:
            gmsh.model.mesh.generate(2)
        except Exception as error:  # with AbortOnError 0 a failed surface is reported here
            result["error"] = str(error)[-300:]
        result["generate_s"] = time.perf_counter() - start
        points, quads, triangles, empty = gmsh_surface_mesh(gmsh)
    finally:
        gmsh.finalize()
    # The worst corner sine over all elements: a triangle left by recombination is
    # an element the solver sees too.
    sines = np.concatenate([scaled_jacobian(points, quads), triangle_corner_sines(points, triangles)])
    result.update({"quads": len(quads), "triangles": len(triangles), "empty_surfaces": empty,
                   "sj": sj_stats(scaled_jacobian(points, quads)),
                   "all_elements_min_sine": float(sines.min()) if len(sines) else None})
    print(json.dumps(result))


def run_gmsh(path, route, size, timeout):
    """Runs one Gmsh job in a child process; returns its result, or 'status' on failure."""
    spec = {"path": path, "route": route, "size": size}
    cmd = [sys.executable, os.path.abspath(__file__), "--gmsh-job", json.dumps(spec)]
    start = time.perf_counter()
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "process_s": time.perf_counter() - start}
    elapsed = time.perf_counter() - start
    lines = [line for line in out.stdout.splitlines() if line.startswith("{")]
    if out.returncode != 0 or not lines:
        return failure(out, elapsed)
    result = json.loads(lines[-1])
    result.update({"status": "ok", "process_s": elapsed})
    return result


def failure(out, elapsed):
    """Result of a child process that exited with an error or was killed by a signal."""
    status = "failed"
    if out.returncode < 0:
        try:
            status = "crashed (%s)" % signal.Signals(-out.returncode).name
        except ValueError:
            status = "crashed (signal %d)" % -out.returncode
    return {"status": status, "returncode": out.returncode, "process_s": elapsed,
            "stderr": out.stderr.strip()[-300:]}


def run_gmsh_command(path, size, timeout, workdir):
    """The Blossom route through Gmsh's own command (`gmsh PART -2 -o PART.msh`): the
    whole process a user waits for, to set beside tquad's whole process."""
    msh = os.path.join(workdir, os.path.splitext(os.path.basename(path))[0] + ".msh")
    cmd = ["gmsh", path, "-2", "-format", "msh41", "-o", msh, "-setnumber", "General.Terminal", "0",
           "-setnumber", "Mesh.Algorithm", "6", "-setnumber", "Mesh.RecombineAll", "1",
           "-setnumber", "Mesh.RecombinationAlgorithm", "1",
           "-setnumber", "Mesh.MeshSizeMin", repr(size), "-setnumber", "Mesh.MeshSizeMax", repr(size)]
    start = time.perf_counter()
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "process_s": time.perf_counter() - start}
    except OSError as error:
        return {"status": "failed", "returncode": -1, "process_s": 0.0, "stderr": str(error)}
    elapsed = time.perf_counter() - start
    if out.returncode != 0 or not os.path.exists(msh):
        return failure(out, elapsed)
    return {"status": "ok", "process_s": elapsed}


def gmsh_startup_seconds():
    """Wall time of a child that only starts Python and imports gmsh: the fixed part of
    every Gmsh process time."""
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", "import gmsh"], capture_output=True)
    return time.perf_counter() - start


# ---------------------------------------------------------------- tquad

def run_tquad(tquad, path, size, timeout, workdir):
    vtu = os.path.join(workdir, os.path.splitext(os.path.basename(path))[0] + ".vtu")
    cmd = [tquad, "mesh", path, "-o", vtu, "--keep-going", "--report", "json",
           "--size", repr(size)]
    start = time.perf_counter()
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "process_s": time.perf_counter() - start}
    except OSError as error:  # e.g. the binary is being relinked
        return {"status": "failed", "returncode": -1, "process_s": 0.0, "stderr": str(error)}
    elapsed = time.perf_counter() - start
    if out.returncode != 0 or not os.path.exists(vtu):
        return failure(out, elapsed)
    report = json.loads(out.stdout)
    result = {"status": "ok", "process_s": elapsed, "quads": report["quads"],
              "faces": len(report["faces"]) + len(report["refused_faces"]),
              "refused": len(report["refused_faces"]),
              "refused_faces": report["refused_faces"],
              "report_sj": {"min": report["quality"]["scaled_jacobian"]["min"],
                            "avg": report["quality"]["scaled_jacobian"]["avg"]},
              "report_inverted": report["quality"].get("inverted", 0),
              "stage_s": report.get("stage_seconds", {}),
              "face_s": report.get("face_seconds", {})}
    stages = result["stage_s"]
    # Everything tquad timed after the reader's child process returned the shape.
    result["after_read_s"] = sum(v for k, v in stages.items() if k != "read")
    result.update(vtu_quality(vtu))
    return result


def vtu_quality(vtu):
    import meshio
    mesh = meshio.read(vtu)
    quads = [block.data for block in mesh.cells if block.type == "quad"]
    quads = np.vstack(quads) if quads else np.zeros((0, 4), dtype=np.int64)
    points = mesh.points
    if points.shape[1] == 2:
        points = np.hstack([points, np.zeros((len(points), 1))])
    diagonal = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0))) if len(points) else 0.0
    return {"sj": sj_stats(scaled_jacobian(points, quads)), "mesh_diagonal": diagonal}


# ---------------------------------------------------------------- one part

def compare_part(path, args, workdir):
    name = os.path.basename(path)
    row = {"file": name}
    bbox = run_gmsh(path, "bbox", None, args.timeout)
    if bbox["status"] != "ok":
        row["error"] = "Gmsh could not import it (%s)" % bbox["status"]
        return row
    size = bbox["diagonal"] / args.divisor
    row.update({"diagonal": bbox["diagonal"], "size": size, "gmsh_faces": bbox["gmsh_faces"],
                "gmsh_version": bbox["gmsh_version"]})
    log("%s: H = %.6g, tquad ..." % (name, size))
    row["tquad"] = run_tquad(args.tquad, path, size, args.timeout, workdir)
    for route in GMSH_ROUTES:
        log("%s: gmsh %s ..." % (name, route))
        row[route] = run_gmsh(path, route, size, args.timeout)
    log("%s: gmsh command (Blossom) ..." % name)
    row["gmsh_command"] = run_gmsh_command(path, size, args.timeout, workdir)
    return row


def log(message):
    print(message, file=sys.stderr, flush=True)


# ---------------------------------------------------------------- output

def fmt_sj(sj):
    return "-" if not sj else "%.3f / %.3f" % (sj["min"], sj["mean"])


def fmt_time(seconds):
    return "%.2f" % seconds if seconds < 100 else "%.0f" % seconds


def tquad_cells(r):
    if r["status"] != "ok":
        return [r["status"], "-", "-", "-", fmt_time(r["process_s"])]
    report = "%.3f / %.3f" % (r["report_sj"]["min"], r["report_sj"]["avg"])
    return [str(r["quads"]), str(r["refused"]), fmt_sj(r["sj"]), report,
            fmt_time(r["process_s"])]


def gmsh_cells(r):
    if r["status"] != "ok":
        return [r["status"], "-", "-", "- / %s" % fmt_time(r["process_s"])]
    return [str(r["quads"]), str(r["triangles"]), fmt_sj(r["sj"]),
            "%s / %s" % (fmt_time(r["generate_s"]), fmt_time(r["process_s"]))]


def ratio(gmsh_run, tquad_run):
    """Gmsh's generate(2) alone over tquad's whole process (reading the file, meshing,
    checking, writing): the ratio least favourable to TemplateQuad, since Gmsh's child
    process also spends about 0.4 s starting Python and importing gmsh."""
    if tquad_run["status"] != "ok" or gmsh_run["status"] not in ("ok", "timeout"):
        return "-"
    if gmsh_run["status"] == "timeout":
        return ">%.1f" % (gmsh_run["process_s"] / tquad_run["process_s"])
    return "%.2f" % (gmsh_run["generate_s"] / tquad_run["process_s"])


def markdown_table(rows):
    header = ["file", "faces", "H",
              "TQ quads", "TQ refused", "TQ SJ min / mean", "TQ report SJ min / avg", "TQ s",
              "Blossom quads", "Blossom tris", "Blossom SJ min / mean", "Blossom s gen / proc",
              "all-quad quads", "all-quad tris", "all-quad SJ min / mean",
              "all-quad s gen / proc", "Blossom gen / TQ proc", "all-quad gen / TQ proc"]
    align = ["---"] + ["---:"] * (len(header) - 1)
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    for row in rows:
        if "error" in row:
            cells = [row["file"], row["error"]] + [""] * (len(header) - 2)
        else:
            tq = row["tquad"]
            faces = str(tq["faces"]) if tq["status"] == "ok" else "(%d)" % row["gmsh_faces"]
            cells = ([row["file"], faces, "%.4g" % row["size"]] + tquad_cells(tq)
                     + gmsh_cells(row["blossom"]) + gmsh_cells(row["allquad"])
                     + [ratio(row["blossom"], tq), ratio(row["allquad"], tq)])
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


STAGE_COLUMNS = ("read", "index", "assign intervals", "discretize edges", "mesh faces",
                 "assemble", "quality", "write")


def geometric_mean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def time_table(rows):
    """tquad's time split by stage beside Gmsh's, and the ratios the speed targets name:
    whole process against whole process (Gmsh's own command), and what follows reading
    against Gmsh's generate(2)."""
    header = (["file", "TQ whole"] + ["TQ " + s for s in STAGE_COLUMNS]
              + ["TQ faces: meshing / smoothing (summed over threads)", "TQ after reading",
                 "gmsh command whole", "Blossom generate(2)",
                 "gmsh whole / TQ whole", "generate(2) / TQ after reading"])
    lines = ["| " + " | ".join(header) + " |", "|---|" + "---:|" * (len(header) - 1)]
    whole_ratios, after_ratios = [], []
    for row in rows:
        if "error" in row or row["tquad"]["status"] != "ok":
            continue
        tq, cmd, blossom = row["tquad"], row["gmsh_command"], row["blossom"]
        stages = tq["stage_s"]
        cells = [row["file"], "%.3f" % tq["process_s"]]
        cells += ["%.3f" % stages[s] if s in stages else "-" for s in STAGE_COLUMNS]
        cells.append("%.3f / %.3f" % (tq["face_s"].get("meshing", 0), tq["face_s"].get("smoothing", 0)))
        cells.append("%.3f" % tq["after_read_s"])
        whole = after = "-"
        cells.append("%.3f" % cmd["process_s"] if cmd["status"] == "ok" else cmd["status"])
        cells.append("%.3f" % blossom["generate_s"] if blossom["status"] == "ok" else blossom["status"])
        if cmd["status"] == "ok":
            whole_ratios.append(cmd["process_s"] / tq["process_s"])
            whole = "%.2f" % whole_ratios[-1]
        if blossom["status"] == "ok" and tq["after_read_s"] > 0:
            after_ratios.append(blossom["generate_s"] / tq["after_read_s"])
            after = "%.1f" % after_ratios[-1]
        lines.append("| " + " | ".join(cells + [whole, after]) + " |")
    summary = ("Geometric means: gmsh command whole / TQ whole %.2f over %d parts; "
               "Blossom generate(2) / TQ after reading %.1f over %d parts."
               % (geometric_mean(whole_ratios), len(whole_ratios),
                  geometric_mean(after_ratios), len(after_ratios)))
    return "\n".join(lines), summary


def notes(rows, timeout):
    """One line per anomaly worth knowing when reading the table."""
    out = []
    for row in rows:
        if "error" in row:
            continue
        name, tq = row["file"], row["tquad"]
        if tq["status"] == "ok":
            if tq["refused"]:
                out.append("%s: tquad refused faces %s" % (
                    name, ", ".join("%d (%s)" % (f["face"], f.get("reason", "?"))
                                    for f in tq["refused_faces"])))
            if tq["sj"] and tq["sj"]["inverted"]:
                out.append("%s: tquad has %d quads with scaled Jacobian <= 0"
                           % (name, tq["sj"]["inverted"]))
            if not 2 / 3 < tq["mesh_diagonal"] / row["diagonal"] < 1.5:
                out.append("%s: tquad mesh diagonal %.4g vs Gmsh bounding box %.4g (units?)"
                           % (name, tq["mesh_diagonal"], row["diagonal"]))
            if tq["faces"] != row["gmsh_faces"]:
                out.append("%s: tquad reports %d faces, Gmsh imports %d surfaces"
                           % (name, tq["faces"], row["gmsh_faces"]))
        else:
            out.append("%s: tquad %s %s" % (name, tq["status"], tq.get("stderr", "")))
        for route in GMSH_ROUTES:
            r = row[route]
            if r["status"] == "timeout":
                out.append("%s: Gmsh %s stopped after %d s" % (name, route, timeout))
            elif r["status"] != "ok":
                out.append("%s: Gmsh %s %s, exit %d%s" % (
                    name, route, r["status"], r["returncode"],
                    ": " + r["stderr"] if r["stderr"] else ""))
            else:
                if r.get("empty_surfaces"):
                    out.append("%s: Gmsh %s left %d surfaces without elements"
                               % (name, route, r["empty_surfaces"]))
                if r.get("error"):
                    out.append("%s: Gmsh %s reported: %s" % (name, route, r["error"]))
                if r["sj"] and r["sj"]["inverted"]:
                    out.append("%s: Gmsh %s has %d quads with scaled Jacobian <= 0"
                               % (name, route, r["sj"]["inverted"]))
        if row["gmsh_command"]["status"] != "ok":
            out.append("%s: the gmsh command %s" % (name, row["gmsh_command"]["status"]))
    return out


def machine():
    def command(*cmd):
        try:
            return subprocess.run(cmd, capture_output=True, text=True).stdout.strip()
        except OSError:
            return "?"
    cpu = "?"
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next((line.split(":", 1)[1].strip() for line in f
                        if line.startswith("model name")), "?")
    except OSError:
        pass
    return {"uname": command("uname", "-srm"), "nproc": command("nproc"), "cpu": cpu,
            "python": platform.python_version(),
            "date": datetime.datetime.now().astimezone().isoformat(timespec="seconds")}


# ---------------------------------------------------------------- main

def find_parts(args):
    if args.files:
        return [os.path.join(args.cad_dir, f.strip()) for f in args.files.split(",") if f.strip()]
    return sorted((p for p in glob.glob(os.path.join(args.cad_dir, "*"))
                   if p.lower().endswith(CAD_SUFFIXES)), key=lambda p: os.path.basename(p).lower())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cad-dir", default=os.path.join(os.path.dirname(REPO), "shared",
                                                          "data", "cad"))
    parser.add_argument("--divisor", type=float, default=25.0,
                        help="H = bounding-box diagonal / divisor (default 25, as tquad)")
    parser.add_argument("--timeout", type=float, default=300.0,
                        help="seconds allowed to each tquad and Gmsh process (default 300)")
    parser.add_argument("--files", help="comma-separated file names inside --cad-dir")
    parser.add_argument("--json", help="also write the raw numbers to this file")
    parser.add_argument("--markdown", help="also append the report, as a markdown section, to this file")
    parser.add_argument("--tquad", default=TQUAD, help="tquad binary (default build/bin/tquad)")
    parser.add_argument("--gmsh-job", help=argparse.SUPPRESS)
    args = parser.parse_args()

    if args.gmsh_job:
        gmsh_job(json.loads(args.gmsh_job))
        return
    if not os.path.isdir(args.cad_dir):
        print("CAD directory not found: %s; nothing to compare." % args.cad_dir)
        return
    if not os.access(args.tquad, os.X_OK):
        sys.exit("tquad not found: %s (build it or pass --tquad)" % args.tquad)
    parts = find_parts(args)
    if not parts:
        print("No *.stp, *.step or *.brep file in %s; nothing to compare." % args.cad_dir)
        return

    start = time.perf_counter()
    startup = gmsh_startup_seconds()
    with tempfile.TemporaryDirectory(prefix="compare_parts_") as workdir:
        rows = [compare_part(os.path.abspath(p), args, workdir) for p in parts]
    total = time.perf_counter() - start
    info = machine()
    version = next((r["gmsh_version"] for r in rows if "gmsh_version" in r), "?")

    report = []

    def say(text=""):
        report.append(text)
        print(text)

    say("Whole CAD parts at H = bounding-box diagonal / %g (Gmsh's OCC bounding box), "
          "same H for both meshers.\n" % args.divisor)
    say(markdown_table(rows))
    say()
    say("- TQ: `tquad mesh --keep-going --size H` (default threads: all cores). SJ min / mean "
          "recomputed from its .vtu; 'report' is its own JSON report.")
    say("- Blossom: Gmsh %s, Mesh.Algorithm 6 + RecombineAll, Blossom; all-quad: the same "
          "+ SubdivisionAlgorithm 1 at size 2H. Gmsh default threads (General.NumThreads 1). "
          "SJ over quads only." % version)
    say("- Times in seconds, wall: TQ = whole process; Gmsh 'gen' = generate(2), 'proc' = "
          "whole child process (Python, CAD import, meshing, mesh extraction). Ratios = Gmsh "
          "generate(2) alone / TQ whole process. Time limit %g s per process. A child that only starts Python "
          "and imports gmsh takes %.2f s." % (args.timeout, startup))
    for line in notes(rows, args.timeout):
        say("- " + line)
    say()
    table, summary = time_table(rows)
    say("Time split (seconds, wall). TQ stages from its JSON report: 'read' is the reader's "
          "child process (file, shape check, transfer back); 'after reading' is the sum of the "
          "other stages (process start and exit not included). 'gmsh command' is Gmsh's own "
          "program, Blossom route, same size, writing .msh.\n")
    say(table)
    say()
    say(summary)
    say()
    say("Machine: %s, %s CPUs (nproc), %s. Date: %s. Total script time %.0f s."
          % (info["uname"], info["nproc"], info["cpu"], info["date"], total))

    if args.markdown:
        with open(args.markdown, "a") as f:
            f.write("## Whole parts at D/%g\n\nRegenerate: `/usr/bin/python3 bench/compare_parts.py --divisor %g "
                    "--markdown FILE` (appends a section like this one).\n\n" % (args.divisor, args.divisor))
            f.write("\n".join(report) + "\n\n")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"divisor": args.divisor, "timeout_s": args.timeout, "machine": info,
                       "gmsh_startup_s": startup, "total_s": total, "parts": rows}, f,
                      indent=1)


if __name__ == "__main__":
    main()
