#!/usr/bin/python3
"""Hexahedra by sweeping, on the corpus and the shared CAD parts, beside Gmsh.

    /usr/bin/python3 bench/hex_sweep.py [--sets corpus,cad] [--divisor 50] [--jobs 2]
        [--markdown bench/SWEEP.md] [--json raw.json] [--no-gmsh] [--files a.step,b.stp]

Per part (the corpus archive is unpacked into build/corpus as bench/corpus.py does):

* tquad: `tquad sweep PART -o out.json --keep-going --size H` with H = D / divisor (D: the
  part's bounding-box diagonal, from tquad's own default size, D / 25, in a first run). The
  whole process is timed. Every solid is swept or refused with its reason; the refusals
  are counted by reason.
* Each written hexahedron is measured here, not by tquad: its scaled Jacobian (the worst
  of its 8 corners, the determinant of the three unit edge vectors leaving the corner),
  and its volume (six tetrahedra).
* Gmsh 4.8 (python3-gmsh, one thread, a child process per part): for each solid tquad
  swept, the same profile built in Gmsh: the part imported, the face matching tquad's
  source cap (by its bounding box) kept and the rest removed, and that face extruded or
  revolved by tquad's motion with tquad's layer count and `recombine` (Gmsh's structured
  extrusion), its surface meshed at the same H with Blossom recombination
  (Mesh.RecombineAll, Mesh.Algorithm 6, Mesh.RecombinationAlgorithm 1). Its hexahedra
  are measured the same way; the prisms it leaves where its source mesh kept a triangle
  are counted.

Writes bench/SWEEP.md: the machine, the command, solids swept and refused (by reason),
per swept part the hexahedra, worst and mean scaled Jacobian beside Gmsh's, and times as
ratios (Gmsh's meshing time over tquad's whole process, and hexahedra per second).
"""
import argparse
import collections
import concurrent.futures
import datetime
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import corpus  # noqa: E402  (the corpus's unpacking and the machine line)

REPO = os.path.dirname(HERE)
CORNERS = [(1, 3, 4), (2, 0, 5), (3, 1, 6), (0, 2, 7), (7, 5, 0), (4, 6, 1), (5, 7, 2), (6, 4, 3)]
TETRAS = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]


def hex_measures(points, hexes):
    """(scaled Jacobian, volume) per hexahedron, both M arrays."""
    p = points[hexes]  # M x 8 x 3
    worst = np.ones(len(hexes))
    for i, (a, b, c) in enumerate(CORNERS):
        e = [p[:, j] - p[:, i] for j in (a, b, c)]
        det = np.einsum("ij,ij->i", np.cross(e[0], e[1]), e[2])
        lengths = np.prod([np.linalg.norm(v, axis=1) for v in e], axis=0)
        worst = np.minimum(worst, np.where(lengths > 0, det / np.where(lengths > 0, lengths, 1), -1.0))
    volume = np.zeros(len(hexes))
    for a, b, c, d in TETRAS:
        volume += np.einsum("ij,ij->i", np.cross(p[:, b] - p[:, a], p[:, c] - p[:, a]), p[:, d] - p[:, a]) / 6
    return worst, volume


def run_tquad(tquad, path, size, out_path, timeout, extra=()):
    cmd = [tquad, "sweep", path, "-o", out_path, "--keep-going", "--report", "json", "--threads", "1"] + list(extra)
    if size:
        cmd += ["--size", repr(size)]
    start = time.perf_counter()
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "seconds": timeout}
    seconds = time.perf_counter() - start
    if r.returncode != 0:
        return {"status": "refused" if r.returncode == 2 else "failed", "seconds": seconds,
                "error": (r.stderr.strip().splitlines() or [""])[-1][:2000]}
    return {"status": "ok", "seconds": seconds, "report": json.loads(r.stdout)}


def gmsh_case(path, cases, size):
    """Child process: Gmsh's extrusion or revolution of each source face; prints JSON."""
    import gmsh
    gmsh.initialize(["", "-nt", "1"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.AbortOnError", 0)
    results = []
    for case in cases:
        gmsh.clear()
        if "skip" in case:
            results.append({"status": case["skip"]})
            continue
        try:
            gmsh.model.occ.importShapes(path)
            gmsh.model.occ.synchronize()
            box = case["source_box"]
            best = None
            for _, tag in gmsh.model.getEntities(2):
                b = gmsh.model.getBoundingBox(2, tag)
                error = max(abs(b[i] - box[i]) for i in range(6))
                if best is None or error < best[0]:
                    best = (error, tag)
            if best is None or best[0] > 0.1 * size:
                results.append({"status": "no matching face"})
                continue
            # The part without its solids and its other faces: the source face alone (a
            # copy of it instead makes Gmsh 4.8 mesh the copy as "extruded" and fail).
            source = [(2, best[1])]
            gmsh.model.occ.remove(gmsh.model.getEntities(3), recursive=False)
            gmsh.model.occ.remove([e for e in gmsh.model.getEntities(2) if e != source[0]], recursive=True)
            if "rotation" in case:
                r = case["rotation"]
                gmsh.model.occ.revolve(source, *r["point"], *r["direction"], r["angle"],
                                       numElements=[case["layers"]], recombine=True)
            else:
                gmsh.model.occ.extrude(source, *case["translation"], numElements=[case["layers"]], recombine=True)
            gmsh.model.occ.synchronize()
            gmsh.option.setNumber("Mesh.MeshSizeMin", size)
            gmsh.option.setNumber("Mesh.MeshSizeMax", size)
            gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
            gmsh.option.setNumber("Mesh.RecombineAll", 1)
            gmsh.option.setNumber("Mesh.Algorithm", 6)  # frontal-Delaunay (8 crashes in 4.8)
            gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)
            start = time.perf_counter()
            gmsh.model.mesh.generate(3)
            seconds = time.perf_counter() - start
            tags, coords, _ = gmsh.model.mesh.getNodes()
            index = np.zeros(int(tags.max()) + 1, dtype=np.int64)
            index[tags.astype(np.int64)] = np.arange(len(tags))
            points = coords.reshape(-1, 3)
            hexes = np.zeros((0, 8), dtype=np.int64)
            prisms = 0
            for etype, _, nodes in zip(*gmsh.model.mesh.getElements(3)):
                if etype == 5:
                    hexes = index[nodes.astype(np.int64)].reshape(-1, 8)
                elif etype == 6:
                    prisms += len(nodes) // 6
            sj, _ = hex_measures(points, hexes) if len(hexes) else (np.zeros(0), None)
            results.append({"status": "ok", "hexes": int(len(hexes)), "prisms": prisms, "seconds": seconds,
                            "min": float(sj.min()) if len(sj) else None,
                            "mean": float(sj.mean()) if len(sj) else None})
        except Exception as error:  # one solid's failure is that solid's row
            results.append({"status": "failed", "error": str(error)[:200]})
    gmsh.finalize()
    print(json.dumps(results))


def run_gmsh(path, cases, size, timeout):
    try:
        r = subprocess.run([sys.executable, os.path.abspath(__file__), "--gmsh-case", path, json.dumps(cases),
                            repr(size)], capture_output=True, text=True, timeout=timeout)
        return json.loads(r.stdout.strip().splitlines()[-1])
    except (subprocess.TimeoutExpired, IndexError, json.JSONDecodeError):
        return [{"status": "failed"} for _ in cases]


def part_job(part, args, work):
    name = part["name"]
    first = run_tquad(args.tquad, part["path"], None, os.path.join(work, name + ".d25.json"), args.timeout)
    diagonal = None
    if first["status"] == "ok":
        diagonal = first["report"]["edge_size"] * 25
    elif first["status"] == "refused" and "no solid" not in first.get("error", ""):
        diagonal = None
    row = {"set": part["set"], "name": name, "first": {k: v for k, v in first.items() if k != "report"}}
    if diagonal is None:
        row["tquad"] = first if first["status"] != "ok" else None
        row["refusals"] = refusal_reasons(first)
        return row
    size = diagonal / args.divisor
    out = os.path.join(work, name + ".json")
    tq = run_tquad(args.tquad, part["path"], size, out, args.timeout)
    row["size"] = size
    row["tquad"] = {k: v for k, v in tq.items() if k != "report"}
    row["refusals"] = refusal_reasons(tq)
    if tq["status"] != "ok":
        return row
    report = tq["report"]
    with open(out) as f:
        mesh = json.load(f)
    points = np.array(mesh["nodes"], dtype=float).reshape(-1, 3)
    hexes = np.array(mesh["hexes"], dtype=np.int64).reshape(-1, 8)
    sj, volume = hex_measures(points, hexes)
    row["hexes"] = int(len(hexes))
    row["solids"] = len(report["solids"])
    row["refused_solids"] = len(report["refused_solids"])
    row["min"] = float(sj.min())
    row["mean"] = float(sj.mean())
    row["layer_seconds"] = report.get("seconds", {}).get("layers")
    row["bad"] = int((sj <= 1e-6).sum())
    row["volume"] = float(volume.sum())
    cases = []
    for s in mesh["solids"]:
        if s["source"] < 0 or "projection" in s:
            # A full revolution's source is a section, not a face of the part; a
            # one-to-one sweep has no exact motion for Gmsh's extrusion.
            cases.append({"skip": "a full revolution" if s["source"] < 0 else "a one-to-one sweep"})
            s["min"] = float(sj[s["first_hex"]:s["first_hex"] + s["hex_count"]].min())
            continue
        nodes = np.array(mesh["face_nodes"][str(s["source"])], dtype=np.int64)
        box = list(points[nodes].min(axis=0)) + list(points[nodes].max(axis=0))
        case = {"source_box": [float(v) for v in box], "layers": s["layers"]}
        if "rotation" in s:
            case["rotation"] = s["rotation"]
        else:
            case["translation"] = s["translation"]
        cases.append(case)
        first_hex, count = s["first_hex"], s["hex_count"]
        s["min"] = float(sj[first_hex:first_hex + count].min())
    row["per_solid"] = [{"solid": s["solid"], "layers": s["layers"], "hexes": s["hex_count"], "min": s["min"],
                         "motion": motion_of(s)} for s in mesh["solids"]]
    if not args.no_gmsh and cases:
        row["gmsh"] = run_gmsh(part["path"], cases, size, args.timeout)
    os.remove(out)
    return row


def motion_of(solid):
    if "projection" in solid:
        return "one-to-one projection"
    if "rotation" in solid:
        return "full revolution" if solid["source"] < 0 else "rotation"
    return "translation"


def refusal_reasons(run):
    if run.get("status") == "ok":
        return [r["reason"] for r in run["report"]["refused_solids"]]
    return [run.get("error", run.get("status", "?"))]


def reason_class(reason):
    """A refusal's reason without its face and edge numbers: why no exact motion was
    found, why it is not a full revolution, and why not a one-to-one sweep."""
    parts = reason.split("; nor ")
    labels = [caps_class(parts[0])]
    for part in parts[1:]:
        route, _, why = part.partition(": ")
        labels.append("not " + route + ": " + caps_class(why))
    return "; ".join(labels)


def caps_class(reason):
    text = reason.split(": ", 1)[-1] if reason.startswith("/") or reason.startswith(REPO) else reason
    for key, label in (("no solid to sweep", "no solid (faces or shells only)"),
                       ("touches the axis", "a revolution's profile touches its axis"),
                       ("split along the sweep", "side faces split along the sweep"),
                       ("is not a straight segment", "a side edge is not a straight segment equal to the sweep"),
                       ("is not an arc about the axis", "a side edge is not an arc about the axis"),
                       ("moved along one vector or turned", "no pair of planar faces is moved or turned"),
                       ("numbers of vertices", "no pair of planar faces has as many vertices"),
                       ("is not planar", "no two planar faces"),
                       ("no two planar faces", "no two planar faces"),
                       ("source face was not meshed", "the source face was refused"),
                       ("inverted or degenerate", "hexahedra would be inverted"),
                       ("does not turn about the axis", "a face does not turn about the axis"),
                       ("no circular edge gives an axis", "no circular edge"),
                       ("section by a half-plane", "its half-plane section is not one face"),
                       ("that are not four-sided", "over two faces are not four-sided"),
                       ("is not four-sided along the sweep", "a side is not four-sided"),
                       ("does not run from an edge", "a side does not reach the target (stacked sides)"),
                       ("share edge", "the caps share an edge"),
                       ("different numbers of edges", "the caps' edge counts differ"),
                       ("have no side face", "a source edge has no side face"),
                       ("lies on none of its edges", "a source boundary node off its edges")):
        if key in text:
            return label
    return text[:80]


def markdown(rows, args, info, total_seconds):
    out = ["# Hexahedra by sweeping: tquad sweep on the corpus and the shared parts, beside Gmsh", "",
           "Generated by `bench/hex_sweep.py` (its docstring defines every column). Command:", "",
           "    /usr/bin/python3 bench/hex_sweep.py " + " ".join(sys.argv[1:]), "",
           "Date %s. Machine: %s. tquad: %s. Gmsh %s. Total run time %.0f s, %d parts, %d at once; "
           "tquad with --threads 1, Gmsh with one thread." % (
               datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"), info["cpu"],
               info["tquad"], info.get("gmsh", "?"), total_seconds, len(rows), args.jobs), ""]
    swept = sum(r.get("solids", 0) for r in rows)
    refused = collections.Counter()
    for r in rows:
        for reason in r.get("refusals", []):
            refused[reason_class(reason)] += 1
    parts_swept = sum(1 for r in rows if r.get("solids"))
    hexes = sum(r.get("hexes", 0) for r in rows)
    bad = sum(r.get("bad", 0) for r in rows)
    motions = collections.Counter(s["motion"] for r in rows for s in r.get("per_solid", []))
    out += ["## Summary", "",
            "- H = D / %g. Parts with a solid swept: %d of %d; solids swept: %d (%s); hexahedra %d, with a "
            "corner at or below 1e-6: %d." % (args.divisor, parts_swept, len(rows), swept,
                                               ", ".join("%d by %s" % (v, k) for k, v in sorted(motions.items())),
                                               hexes, bad), ""]
    out += ["Refused (a solid each, or a whole part where none was swept), by reason:", "",
            "| reason | count |", "|---|---:|"]
    out += ["| %s | %d |" % (k, v) for k, v in refused.most_common()]
    out += [""]
    compared = [(r, s, g) for r in rows for s, g in zip(r.get("per_solid", []), r.get("gmsh", []) or [])
                if g.get("status") == "ok" and g.get("hexes")]
    if compared:
        at_least = sum(1 for _, s, g in compared if s["min"] >= g["min"] - 0.02)
        out += ["Per solid against Gmsh's extrusion of the same profile (same H, same layers): tquad's worst "
                "scaled Jacobian at least Gmsh's minus 0.02 on %d of %d solids; Gmsh left prisms (a triangle in "
                "its source mesh) in %d of them." % (
                    at_least, len(compared), sum(1 for _, _, g in compared if g["prisms"])), ""]
    out += ["## Parts with a solid swept", "",
            "| set | part | solids swept / refused | hexahedra | worst / mean | Gmsh worst / mean (hexes, prisms) "
            "| tquad s | hexahedra / s | hexahedra / s of the layers | Gmsh s / tquad s |",
            "|---|---|---:|---:|---|---|---:|---:|---:|---:|"]
    for r in rows:
        if not r.get("solids"):
            continue
        g = [x for x in r.get("gmsh", []) or [] if x.get("status") == "ok" and x.get("hexes")]
        gmsh_text = "-"
        ratio = "-"
        if g:
            gmin = min(x["min"] for x in g)
            gmean = sum(x["mean"] * x["hexes"] for x in g) / sum(x["hexes"] for x in g)
            gmsh_text = "%.3f / %.3f (%d, %d)" % (gmin, gmean, sum(x["hexes"] for x in g), sum(x["prisms"] for x in g))
            ratio = "%.2f" % (sum(x["seconds"] for x in g) / r["tquad"]["seconds"])
        layers = r.get("layer_seconds")
        out.append("| %s | %s | %d / %d | %d | %.3f / %.3f | %s | %.2f | %.0f | %s | %s |" % (
            r["set"], r["name"], r["solids"], r["refused_solids"], r["hexes"], r["min"], r["mean"], gmsh_text,
            r["tquad"]["seconds"], r["hexes"] / r["tquad"]["seconds"],
            "%.0f" % (r["hexes"] / layers) if layers else "-", ratio))
    out += ["", "Gmsh s / tquad s sets Gmsh's meshing call alone (no reading) against tquad's whole "
            "process (reading in a child process, meshing the source, sweeping, writing JSON). Hexahedra per "
            "second of the layers: tquad's own timing of its layers stage (placing the layers, building and "
            "measuring the hexahedra; the report's `seconds.layers`).", ""]
    return "\n".join(out) + "\n"


def write_results(args, rows, text, summary_ends):
    """The raw rows to --json (if given), the page to --markdown; the summary printed."""
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    with open(args.markdown, "w") as f:
        f.write(text)
    print(text.split(summary_ends)[0])


def parse_args(argv, doc, markdown, more=lambda parser: None):
    """The sweep benches' command line (`more` adds a bench's own options), and where
    the corpus and the shared parts are."""
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("--data-dir", default=corpus.DATA_DIR)
    parser.add_argument("--sets", default="corpus,cad")
    parser.add_argument("--files")
    parser.add_argument("--divisor", type=float, default=50.0)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--timeout", type=float, default=300.0)
    parser.add_argument("--no-gmsh", action="store_true")
    parser.add_argument("--markdown", default=os.path.join(REPO, "bench", markdown))
    parser.add_argument("--json")
    parser.add_argument("--tquad", default=os.path.join(REPO, "build", "bin", "tquad"))
    more(parser)
    args = parser.parse_args(argv[1:])
    args.archive = os.path.join(args.data_dir, "corpus", corpus.CORPUS_ARCHIVE)
    args.manifest = os.path.join(os.path.dirname(args.archive), "manifest.tsv")
    args.cad_dir = os.path.join(args.data_dir, "cad")
    args.out_dir = os.path.join(REPO, "build", "corpus")
    args.slice = None
    return args


def main(argv):
    if len(argv) > 1 and argv[1] == "--gmsh-case":
        gmsh_case(argv[2], json.loads(argv[3]), float(argv[4]))
        return 0
    args = parse_args(argv, __doc__, "SWEEP.md")
    parts = corpus.select_parts(args)
    stamp = corpus.engine_stamp(args.tquad)
    start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="tq_sweep_") as work:
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            rows = list(pool.map(lambda p: part_job(p, args, work), parts))
    total = time.perf_counter() - start
    info = corpus.machine_info(args.tquad, stamp)
    try:
        info["gmsh"] = subprocess.run([sys.executable, "-c", "import gmsh; print(gmsh.__version__)"],
                                      capture_output=True, text=True).stdout.strip() or "?"
    except OSError:
        info["gmsh"] = "?"
    write_results(args, rows, markdown(rows, args, info, total), "## Parts")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
