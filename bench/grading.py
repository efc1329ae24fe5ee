#!/usr/bin/python3
"""Grading of local sizes on the real parts: neighbouring element edges along the CAD
edges, measured on every part with a mesh region; writes bench/GRADING.md.

Per part of the corpus and CAD sets (as bench/corpus.py selects them):
  1. `tquad mesh PART --keep-going` at its default size D/25 (D its diagonal, 25 times
     the report's edge size);
  2. the region: the smallest face of area at least (D/25)^2 (one element or more), sized
     D/250 (`--size-at faceK:D/250`), ten times finer than the rest, graded by the default
     growth rate 1.3; meshed again;
  3. measured on the written mesh: along each face's boundary (the mesh edges one quad of
     the face has), at every node that is not a CAD vertex (those of FreeCAD's reading of
     the part, to 1e-7 D), the ratio of the longer to the shorter of its two boundary
     edges. Where two faces share an edge its nodes are counted once.
On the mesh of step 1 the curvature sizing is measured too: every boundary segment
with both nodes on a circle of one of the part's circular edges (not both at CAD
vertices) spans at most 360/8 = 45 degrees of it, at the default 8 segments a turn.
The same grading is measured on the mesh of step 1, without a region: there, uneven neighbours
come from rules other than the sizes (nodes placed to face the vertices across a thin
face, finer ends at cusps), and a region's grading is judged by what it adds to them.
Reported: the nodes measured, the largest ratio and the nodes over 1.3 (to 1e-6), with
and without the region, per part where the region run has more such nodes. Nothing is
asserted.

Usage: /usr/bin/python3 bench/grading.py [--sets corpus,cad] [--files a.step,...]
       [--out bench/GRADING.md] [--timeout 300]
"""
import argparse
import datetime as dt
import os
import platform
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402  (the corpus bench's part selection, runner and readers)

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RATE = 1.3
FINER = 10.0
#: The default --curvature-segments (8 per full turn): at most 45 degrees a segment.
TURN_DEGREES = 360.0 / 8


def face_boundary(quads, face):
    """One face's boundary mesh edges: the node pairs (sorted) one of its quads has."""
    first, count = face["quads"]
    face_quads = quads[first:first + count]
    edges = np.sort(np.stack([face_quads, np.roll(face_quads, -1, axis=1)], axis=2).reshape(-1, 2), axis=1)
    unique, uses = np.unique(edges, axis=0, return_counts=True)
    return unique[uses == 1]


def boundary_ratios(points, quads, faces, vertices, tolerance):
    """{node: ratio} over the faces' boundaries (see the module's docstring)."""
    ratios = {}
    for face in faces:
        boundary = face_boundary(quads, face)
        neighbours = {}
        for a, b in boundary.tolist():
            neighbours.setdefault(a, []).append(b)
            neighbours.setdefault(b, []).append(a)
        for node, around in neighbours.items():
            if len(around) != 2 or node in ratios:
                continue
            p = points[node]
            if vertices.size and np.min(np.linalg.norm(vertices - p, axis=1)) <= tolerance:
                continue
            lengths = [np.linalg.norm(points[n] - p) for n in around]
            if min(lengths) > 0:
                ratios[node] = max(lengths) / min(lengths)
    return ratios


def boundary_segments(quads, faces):
    """The mesh edges (node pairs) on the faces' boundaries, each once."""
    found = set()
    for face in faces:
        found.update(map(tuple, face_boundary(quads, face).tolist()))
    return np.array(sorted(found), dtype=np.int64).reshape(-1, 2)


def circle_angles(points, segments, shape, vertex_nodes, tolerance):
    """The angle (degrees) each boundary segment spans on a circle of the part: both its
    nodes on one of the shape's circular edges' circles, not both CAD vertices (a
    one-segment straight edge between two points of a circle is a chord, not an arc)."""
    angles = []
    for edge in shape.Edges:
        try:
            curve = edge.Curve
        except (TypeError, RuntimeError):  # a curve type FreeCAD does not wrap: not a circle
            continue
        if curve.TypeId != "Part::GeomCircle":
            continue
        centre = np.array([curve.Center.x, curve.Center.y, curve.Center.z])
        axis = np.array([curve.Axis.x, curve.Axis.y, curve.Axis.z])
        d = points - centre
        along = d @ axis
        radial = np.linalg.norm(d - np.outer(along, axis), axis=1)
        on = (np.abs(along) <= tolerance) & (np.abs(radial - curve.Radius) <= tolerance)
        both = on[segments[:, 0]] & on[segments[:, 1]]
        both &= ~(vertex_nodes[segments[:, 0]] & vertex_nodes[segments[:, 1]])
        chords = np.linalg.norm(points[segments[both, 0]] - points[segments[both, 1]], axis=1)
        angles.extend(np.degrees(2 * np.arcsin(np.clip(chords / (2 * curve.Radius), 0, 1))).tolist())
    return np.array(angles)


def run(tquad, part, timeout, folder):
    """One part: the default run for D, then the region run, measured."""
    out = {"name": part["name"], "set": part["set"]}
    mesh_path = os.path.join(folder, "mesh.json")
    first = corpus.run_tquad(tquad, part["path"], 0, timeout, mesh_path)
    if first["status"] != "ok" or not first.get("edge_size"):
        out["error"] = "default run: " + first["status"]
        return out
    diagonal = 25.0 * first["edge_size"]
    try:
        shape = corpus.read_shape(part["path"])
    except Exception as error:  # FreeCAD's reader: a message in a dict
        out["error"] = "FreeCAD: " + corpus.exception_text(error)
        return out
    vertices = np.array([[v.Point.x, v.Point.y, v.Point.z] for v in shape.Vertexes]).reshape(-1, 3)
    points, quads, faces = corpus.read_mesh_json(mesh_path)
    plain = np.array(list(boundary_ratios(points, quads, faces, vertices, 1e-7 * diagonal).values()))
    out.update({"plain_nodes": int(plain.size), "plain_max": float(plain.max()) if plain.size else 1.0,
                "plain_over": int((plain > RATE * (1 + 1e-6)).sum())})
    tolerance = 1e-7 * diagonal
    vertex_nodes = np.zeros(len(points), dtype=bool)
    for v in vertices:
        vertex_nodes |= np.linalg.norm(points - v, axis=1) <= tolerance
    angles = circle_angles(points, boundary_segments(quads, faces), shape, vertex_nodes, tolerance)
    out.update({"arc_segments": int(angles.size), "arc_max": float(angles.max()) if angles.size else 0.0,
                "arc_over": int((angles > TURN_DEGREES * (1 + 1e-6)).sum())})
    large = [(f.Area, k) for k, f in enumerate(shape.Faces) if f.Area >= (diagonal / 25.0) ** 2]
    if not large:
        out["error"] = "no face of one element's area"
        return out
    face = min(large)[1]
    size = diagonal / 25.0 / FINER
    cmd = [tquad, "mesh", part["path"], "-o", mesh_path, "--keep-going", "--size-at", f"face{face}:{size!r}"]
    code, _, err, elapsed = corpus.run_process(cmd, timeout)
    if code != 0 or not os.path.exists(mesh_path):
        out["error"] = f"region run: exit {code}: {corpus.first_error_line(err)[:200]}"
        return out
    points, quads, faces = corpus.read_mesh_json(mesh_path)
    ratios = np.array(list(boundary_ratios(points, quads, faces, vertices, 1e-7 * diagonal).values()))
    out.update({"face": face, "region": size, "quads": len(quads), "seconds": elapsed,
                "nodes": int(ratios.size), "max": float(ratios.max()) if ratios.size else 1.0,
                "over": int((ratios > RATE * (1 + 1e-6)).sum())})
    return out


def markdown(rows, command, seconds):
    ok = [r for r in rows if "error" not in r]
    worse = sorted((r for r in ok if r["over"] > r["plain_over"]), key=lambda r: -r["max"])
    nodes = sum(r["nodes"] for r in ok)
    plain_nodes = sum(r["plain_nodes"] for r in ok)
    over = sum(r["over"] for r in ok)
    plain_over = sum(r["plain_over"] for r in ok)
    lines = ["# Grading of local sizes on the real parts", "",
             "Generated by `bench/grading.py` (its docstring defines what is measured). Command:", "",
             f"    {command}", "",
             f"Date {dt.datetime.now(dt.timezone.utc).isoformat(timespec='seconds')}; "
             f"{platform.machine()}, {os.cpu_count()} cores; {seconds:.0f} s in all.", "",
             f"Parts measured: {len(ok)} of {len(rows)}, each with a region ten times finer than the "
             f"rest on its smallest face of at least one element.", "",
             "| | boundary nodes | over the growth rate 1.3 | share | largest ratio |",
             "|---|---:|---:|---:|---:|",
             f"| with the region | {nodes:,} | {over:,} | {100.0 * over / max(nodes, 1):.3f}% | "
             f"{max((r['max'] for r in ok), default=1.0):.3f} |",
             f"| without (D/25 alone) | {plain_nodes:,} | {plain_over:,} | "
             f"{100.0 * plain_over / max(plain_nodes, 1):.3f}% | "
             f"{max((r['plain_max'] for r in ok), default=1.0):.3f} |", "",
             f"Parts where the region run has more nodes over 1.3 than the run without: {len(worse)}.", "",
             f"Curvature sizing (the runs without a region, default `--curvature-segments` 8): "
             f"{sum(r['arc_segments'] for r in ok):,} boundary segments on the parts' circles span at most "
             f"{max((r['arc_max'] for r in ok), default=0.0):.2f} degrees; "
             f"{sum(r['arc_over'] for r in ok)} span more than {TURN_DEGREES:g}.", ""]
    if worse:
        lines += ["| part | region face | quads | nodes | over 1.3 | largest ratio | without: over 1.3 "
                  "| largest |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
        lines += [f"| {r['name']} | {r['face']} | {r['quads']:,} | {r['nodes']:,} | {r['over']} | "
                  f"{r['max']:.3f} | {r['plain_over']} | {r['plain_max']:.3f} |" for r in worse]
        lines.append("")
    arcs = sorted((r for r in ok if r["arc_over"]), key=lambda r: -r["arc_max"])
    if arcs:
        lines += ["Parts with segments over 45 degrees on a circle:", "",
                  "| part | segments on circles | over 45 degrees | largest (degrees) |", "|---|---:|---:|---:|"]
        lines += [f"| {r['name']} | {r['arc_segments']:,} | {r['arc_over']} | {r['arc_max']:.2f} |" for r in arcs]
        lines.append("")
    failed = [r for r in rows if "error" in r]
    if failed:
        lines += ["Not measured:", ""] + [f"- {r['name']}: {r['error']}" for r in failed] + [""]
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sets", default="corpus,cad")
    parser.add_argument("--files", default="")
    parser.add_argument("--timeout", type=float, default=300)
    parser.add_argument("--out", default=os.path.join(REPO, "bench", "GRADING.md"))
    args = parser.parse_args(argv)
    corpus_args = corpus.parse_args(["--sets", args.sets] + (["--files", args.files] if args.files else []))
    parts = corpus.select_parts(corpus_args)
    tquad = os.path.join(REPO, "build", "bin", "tquad")
    start = dt.datetime.now()
    rows = []
    with tempfile.TemporaryDirectory(prefix="tq_grading_") as folder:
        for k, part in enumerate(parts, 1):
            try:
                rows.append(run(tquad, part, args.timeout, folder))
            except Exception as error:  # a fault of this script on one part: said, not fatal
                rows.append({"name": part["name"], "set": part["set"], "error": f"bench: {error!r}"})
            r = rows[-1]
            corpus.log(f"[{k}/{len(parts)}] {part['name']}: " +
                       (r["error"] if "error" in r else f"{r['nodes']} nodes, max {r['max']:.3f}, over {r['over']}"))
    seconds = (dt.datetime.now() - start).total_seconds()
    command = "/usr/bin/python3 bench/grading.py" + (f" --sets {args.sets}" if args.sets != "corpus,cad" else "") + (
        f" --files {args.files}" if args.files else "")
    text = markdown(rows, command, seconds)
    with open(args.out, "w") as out:
        out.write(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
