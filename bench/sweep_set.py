#!/usr/bin/python3
"""The sweep set: solids built here from real faces and profiles, swept by tquad, Gmsh
and SMESH on the same solid and size.

    /usr/bin/python3 bench/sweep_set.py [--divisor 50] [--jobs 2] [--parts 30]
        [--markdown bench/SWEEP_SET.md] [--json raw.json] [--no-gmsh] [--no-smesh]

The set (built by FreeCAD's Part module in a child process, into build/sweep_set/):

* extrusion: the largest planar face with a hole of each of the first `--parts` parts
  (corpus and ../shared/data/cad, by name) that have one, extruded along its normal by
  a quarter of its diagonal; every third one obliquely (the vector tilted 30 degrees);
* revolution: the first 8 of those faces turned by 90, 180 and 360 degrees about an axis
  in their plane, a quarter of their diagonal clear of them;
* loft: profiles (square, rectangle, hexagon, circle, slot, the outer wires of the first
  6 real faces) lofted, ruled, to a copy scaled by 0.6 and turned by 0, 30 or 60
  degrees, half their diagonal away; and smooth lofts through three sections;
* stacked: the first 6 real faces extruded twice (one prism on the other, fused: every
  side face is two), lofts through three sections (ruled), plates with countersunk
  holes;
* pipe: profiles swept along a B-spline and along an arc.

Per solid, at H = D / divisor (D its bounding-box diagonal):

* tquad: `tquad sweep SOLID -o out.json --size H --report json --threads 1`, order 1 and
  order 2 (with --keep-going: a solid's refusal is the run's), whole processes timed. Its hexahedra are measured here: scaled Jacobian (the
  worst of the 8 corners), the share at or above 0.5, and the volume (order 1: six
  tetrahedra each; order 2: the twenty-node element's Jacobian at its 27 Gauss points)
  against the solid's: FreeCAD's (OpenCASCADE's), except where a face is a rational
  B-spline: there the divergence theorem over FreeCAD's triangulation at 1e-4 D
  (OpenCASCADE's volume was off by 0.4% on a loft between circles; the triangulation's
  own error is about 3e-4 of the volume);
* Gmsh 4.8, where tquad found an exact motion: its structured extrusion or revolution
  of the same source face with tquad's layers (bench/hex_sweep.py's gmsh_case);
* SMESH (FreeCAD 0.20's, bench/smesh_prism_case.py): Extrusion 3D (Prism_3D) at
  local length H; its compute time alone, its hexahedra measured the same way, and the
  prisms it leaves.

Writes bench/SWEEP_SET.md: per family the solids swept and refused, per solid the
figures side by side, and the summaries the sweep issue asks for (every extrusion and
revolution swept; the rest at 90%; worst at least each peer's minus 0.02; volume within
1% at order 1 and 0.1% at order 2; speed as ratios).
"""
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
import hex_sweep  # noqa: E402  (hexahedron measures, tquad and Gmsh runs)

REPO = os.path.dirname(HERE)
SET_DIR = os.path.join(REPO, "build", "sweep_set")
FREECAD_LIB = "/usr/lib/freecad/lib"


# ---------------------------------------------------------------- the set (FreeCAD)

def make_set(out_dir, part_paths, parts_wanted):
    """Child process with FreeCAD: writes the solids and set.json into out_dir."""
    sys.path.append(FREECAD_LIB)
    import FreeCAD  # noqa: F401  (before Part)
    import Part
    from FreeCAD import Vector

    os.makedirs(out_dir, exist_ok=True)
    cases = []

    def save(name, family, shape, note):
        solids = shape.Solids
        if len(solids) != 1 or not solids[0].isValid() or solids[0].Volume <= 0:
            cases.append({"name": name, "family": family, "note": note, "build": "not one valid solid"})
            return
        solid = solids[0]
        path = os.path.join(out_dir, name + ".brep")
        solid.exportBrep(path)
        # OpenCASCADE's volume of rational B-spline faces (circles lofted) was off by
        # 0.4%: those solids' volume is taken from a fine triangulation (case_job).
        rational = any(type(f.Surface).__name__ == "BSplineSurface" and
                       (f.Surface.isURational() or f.Surface.isVRational()) for f in solid.Faces)
        cases.append({"name": name, "family": family, "note": note, "path": path, "volume": solid.Volume,
                      "reference": "triangulation" if rational else "OpenCASCADE",
                      "diagonal": solid.BoundBox.DiagonalLength, "faces": len(solid.Faces)})

    def attempt(name, family, note, build):
        try:
            save(name, family, build(), note)
        except Exception as error:  # a shape FreeCAD cannot build is that case's row
            cases.append({"name": name, "family": family, "note": note, "build": str(error)[:120]})

    # Real planar faces with holes, the largest of each part.
    faces = []
    for path in part_paths:
        if len(faces) >= parts_wanted:
            break
        try:
            shape = Part.read(path)
        except Exception:
            continue
        best = None
        for f in shape.Faces:
            if len(f.Wires) >= 2 and isinstance(f.Surface, Part.Plane) and f.isValid():
                if best is None or f.Area > best.Area:
                    best = f
        if best is not None:
            faces.append((os.path.splitext(os.path.basename(path))[0], best))

    def normal_of(f):
        u0, u1, v0, v1 = f.ParameterRange
        return f.normalAt((u0 + u1) / 2, (v0 + v1) / 2)

    for k, (part, f) in enumerate(faces):
        d = f.BoundBox.DiagonalLength
        n = normal_of(f)
        vector = n * (0.25 * d)
        note = part
        if k % 3 == 2:  # oblique: tilted 30 degrees toward a direction in the plane
            side = (f.Vertexes[0].Point - f.CenterOfMass)
            side = side - n * side.dot(n)
            if side.Length > 0:
                side.normalize()
                vector = (n * math.cos(math.radians(30)) + side * math.sin(math.radians(30))) * (0.25 * d)
                note += ", oblique"
        attempt("extrusion-%02d" % k, "extrusion", note, lambda f=f, v=vector: f.extrude(v))

    for k, (part, f) in enumerate(faces[:8]):
        box = f.BoundBox
        n = normal_of(f)
        # An axis in the face's plane, along its bounding box's longer side, clear of it.
        along = Vector(1, 0, 0) if box.XLength >= box.YLength else Vector(0, 1, 0)
        along = along - n * along.dot(n)
        if along.Length < 1e-9:
            along = Vector(0, 0, 1) - n * n.z
        along.normalize()
        across = n.cross(along)
        centre = f.CenterOfMass
        reach = max(abs((v.Point - centre).dot(across)) for v in f.Vertexes)
        base = centre + across * (reach + 0.25 * box.DiagonalLength)
        for angle in (90, 180, 360):
            attempt("revolution-%02d-%d" % (k, angle), "revolution", "%s, %d degrees" % (part, angle),
                    lambda f=f, b=base, a=along, angle=angle: f.revolve(b, a, angle))

    def polygon(points):
        return Part.makePolygon([Vector(*p) for p in points] + [Vector(*points[0])])

    profiles = [
        ("square", polygon([(-10, -10, 0), (10, -10, 0), (10, 10, 0), (-10, 10, 0)])),
        ("rectangle", polygon([(-15, -6, 0), (15, -6, 0), (15, 6, 0), (-15, 6, 0)])),
        ("hexagon", polygon([(10 * math.cos(a), 10 * math.sin(a), 0) for a in
                             [i * math.pi / 3 for i in range(6)]])),
        ("circle", Part.Wire(Part.makeCircle(10))),
    ]
    slot = Part.Wire([Part.LineSegment(Vector(-10, -5, 0), Vector(10, -5, 0)).toShape(),
                      Part.ArcOfCircle(Vector(10, -5, 0), Vector(15, 0, 0), Vector(10, 5, 0)).toShape(),
                      Part.LineSegment(Vector(10, 5, 0), Vector(-10, 5, 0)).toShape(),
                      Part.ArcOfCircle(Vector(-10, 5, 0), Vector(-15, 0, 0), Vector(-10, -5, 0)).toShape()])
    profiles.append(("slot", slot))
    for part, f in faces[:6]:
        wire = f.OuterWire.copy()
        wire.translate(-f.CenterOfMass)
        n = normal_of(f)
        rotation = FreeCAD.Rotation(n, Vector(0, 0, 1))
        wire.rotate(Vector(0, 0, 0), rotation.Axis, math.degrees(rotation.Angle))
        profiles.append(("outline of " + part, wire))

    def moved(wire, scale, turn, height):
        c = wire.copy()
        c.rotate(Vector(0, 0, 0), Vector(0, 0, 1), turn)
        c = c.transformGeometry(FreeCAD.Matrix(scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, scale, 0))
        c.translate(Vector(0, 0, height))
        return c

    for k, (name, wire) in enumerate(profiles):
        height = 0.5 * wire.BoundBox.DiagonalLength
        for turn in (0, 30, 60):
            attempt("loft-%02d-%d" % (k, turn), "loft", "%s, ruled, x0.6, %d degrees" % (name, turn),
                    lambda w=wire, t=turn, h=height: Part.makeLoft([w, moved(w, 0.6, t, h)], True, True))
        attempt("loft-%02d-smooth" % k, "loft", "%s, smooth through three sections" % name,
                lambda w=wire, h=height: Part.makeLoft([w, moved(w, 0.8, 15, h / 2), moved(w, 0.6, 30, h)],
                                                       True, False))
        attempt("stacked-loft-%02d" % k, "stacked", "%s, ruled through three sections" % name,
                lambda w=wire, h=height: Part.makeLoft([w, moved(w, 0.8, 15, h / 2), moved(w, 0.6, 30, h)],
                                                       True, True))

    for k, (part, f) in enumerate(faces[:6]):
        v = normal_of(f) * (0.15 * f.BoundBox.DiagonalLength)
        attempt("stacked-extrusion-%02d" % k, "stacked", part + ", two prisms fused",
                lambda f=f, v=v: f.extrude(v).fuse(f.translated(v).extrude(v)))

    for k, (r, depth) in enumerate(((4, 2), (3, 1.5), (6, 3))):
        def countersunk(r=r, depth=depth):
            plate = Part.makeBox(40, 30, 10, Vector(-20, -15, 0))
            bore = Part.makeCylinder(r, 12, Vector(0, 0, -1))
            sink = Part.makeCone(r, 2 * r, depth, Vector(0, 0, 10 - depth))
            return plate.cut(bore).cut(sink)
        attempt("stacked-countersunk-%02d" % k, "stacked", "plate, hole of radius %g countersunk %g deep" % (r, depth),
                countersunk)

    spline = Part.BSplineCurve()
    spline.interpolate([Vector(0, 0, 0), Vector(3, 0, 20), Vector(15, 4, 40), Vector(35, 4, 50)])
    spines = [("B-spline", Part.Wire(spline.toShape())),
              ("arc", Part.Wire(Part.ArcOfCircle(Vector(0, 0, 0), Vector(-12, 0, 29), Vector(-41, 0, 41)).toShape()))]
    for k, (name, wire) in enumerate(profiles[:3]):
        small = wire.copy().transformGeometry(FreeCAD.Matrix(0.3, 0, 0, 0, 0, 0.3, 0, 0, 0, 0, 0.3, 0))
        for spine_name, spine in spines:
            attempt("pipe-%02d-%s" % (k, spine_name.lower().replace("-", "")), "pipe",
                    "%s along a %s" % (name, spine_name),
                    lambda s=small, p=spine: p.makePipeShell([s], True, True))

    with open(os.path.join(out_dir, "set.json"), "w") as out:
        json.dump(cases, out, indent=1)


def triangulated_volume(path):
    """Child process with FreeCAD: the divergence theorem over the solid's triangulation
    at 1e-4 of its diagonal (its own error about 3e-4 of the volume); prints it."""
    sys.path.append(FREECAD_LIB)
    import FreeCAD  # noqa: F401  (before Part)
    import Part
    solid = Part.read(path)
    points, triangles = solid.tessellate(1e-4 * solid.BoundBox.DiagonalLength)
    p = np.array([[v.x, v.y, v.z] for v in points])
    t = np.array(triangles)
    print(float(np.einsum("ij,ij->i", p[t[:, 0]], np.cross(p[t[:, 1]], p[t[:, 2]])).sum() / 6))


def build_set(args):
    parts = [p["path"] for p in corpus.select_parts(args)]
    env = dict(os.environ, HOME=os.environ.get("HOME") if os.access(os.environ.get("HOME", "/"), os.W_OK)
               else tempfile.mkdtemp(prefix="tq_home_"))
    r = subprocess.run([sys.executable, os.path.abspath(__file__), "--make-set", SET_DIR, json.dumps(parts),
                        str(args.parts)], env=env, capture_output=True, text=True, timeout=1800)
    if r.returncode != 0:
        raise SystemExit("building the set failed:\n" + r.stderr[-3000:])
    with open(os.path.join(SET_DIR, "set.json")) as f:
        return json.load(f)


# ---------------------------------------------------------------- measures

GAUSS = [(-math.sqrt(3 / 5), 5 / 9), (0.0, 8 / 9), (math.sqrt(3 / 5), 5 / 9)]
CORNER_SIGNS = np.array([(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                         (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)], dtype=float)
EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]


def hex20_volume(points, elements, chunk=50000):
    """The volume of twenty-node hexahedra (VTK / C3D20 order), 27-point Gauss rule."""
    if len(elements) > chunk:
        return sum(hex20_volume(points, elements[i:i + chunk], chunk) for i in range(0, len(elements), chunk))
    p = points[elements]  # M x 20 x 3
    total = 0.0
    for xi, wx in GAUSS:
        for eta, wy in GAUSS:
            for zeta, wz in GAUSS:
                g = np.zeros((20, 3))  # d N_i / d (xi, eta, zeta)
                local = (xi, eta, zeta)
                for i, s in enumerate(CORNER_SIGNS):
                    f = [1 + s[k] * local[k] for k in range(3)]
                    base = f[0] * f[1] * f[2] / 8
                    rest = s[0] * xi + s[1] * eta + s[2] * zeta - 2
                    for k in range(3):
                        others = np.prod([f[j] for j in range(3) if j != k]) / 8
                        g[i, k] = s[k] * others * rest + base * s[k]
                for m, (a, b) in enumerate(EDGES):
                    mid = (CORNER_SIGNS[a] + CORNER_SIGNS[b]) / 2  # one coordinate 0
                    zero = int(np.argmin(np.abs(mid)))
                    f = [1 + mid[k] * local[k] if k != zero else 1 - local[k] ** 2 for k in range(3)]
                    df = [mid[k] if k != zero else -2 * local[k] for k in range(3)]
                    for k in range(3):
                        g[8 + m, k] = df[k] * np.prod([f[j] for j in range(3) if j != k]) / 4
                jac = np.einsum("mnc,nk->mck", p, g)  # M x 3 (coords) x 3 (local)
                total += wx * wy * wz * np.linalg.det(jac).sum()
    return float(total)


def read_mesh(path, per):
    """The written .json mesh's nodes (N x 3) and elements (M x per)."""
    with open(path) as f:
        mesh = json.load(f)
    return mesh, np.array(mesh["nodes"], dtype=float).reshape(-1, 3), np.array(mesh["hexes"], dtype=np.int64).reshape(-1, per)


def run_smesh(path, size, timeout):
    script = os.path.join(HERE, "smesh_prism_case.py")
    with tempfile.TemporaryDirectory(prefix="tq_smesh_") as work:
        result = os.path.join(work, "result.json")
        spec = {"brep": path, "size": size, "output": os.path.join(work, "mesh.unv"), "result": result}
        env = dict(os.environ, SMESH_PRISM_SPEC=json.dumps(spec), HOME=work)
        start = time.perf_counter()
        try:
            subprocess.run([sys.executable, script], env=env, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return {"status": "timeout"}
        wall = time.perf_counter() - start
        try:
            with open(result) as f:
                out = json.load(f)
        except (OSError, json.JSONDecodeError):
            return {"status": "failed", "error": "no result"}
        out["wall_s"] = wall
        return out


def case_job(case, args, work):
    row = dict(case)
    if "path" not in case:
        return row
    size = case["diagonal"] / args.divisor
    row["size"] = size
    if case["reference"] == "triangulation":
        r = subprocess.run([sys.executable, os.path.abspath(__file__), "--volume", case["path"]], capture_output=True,
                           text=True, timeout=1800, env=dict(os.environ, HOME=work))
        row["volume"] = case["volume"] = float(r.stdout.strip().splitlines()[-1])
    out = os.path.join(work, case["name"] + ".json")
    first = hex_sweep.run_tquad(args.tquad, case["path"], size, out, args.timeout, ["--order", "1"])
    row["tquad"] = {k: v for k, v in first.items() if k != "report"}
    if first["status"] == "ok":
        mesh, points, hexes = read_mesh(out, 8)
        sj, volume = hex_sweep.hex_measures(points, hexes)
        solid = first["report"]["solids"][0]
        row.update({"hexes": int(len(hexes)), "min": float(sj.min()), "mean": float(sj.mean()),
                    "good": float((sj >= 0.5).mean()), "bad": int((sj <= 1e-6).sum()),
                    "volume_error": float(volume.sum() / case["volume"] - 1), "layers": solid["layers"],
                    "motion": hex_sweep.motion_of(solid),
                    "layer_seconds": first["report"].get("seconds", {}).get("layers"),
                    "stage_seconds": first["report"].get("seconds", {})})
        if not args.no_gmsh and row["motion"] in ("translation", "rotation"):
            nodes = np.array(mesh["face_nodes"][str(solid["source"])], dtype=np.int64)
            box = list(points[nodes].min(axis=0)) + list(points[nodes].max(axis=0))
            gcase = {"source_box": [float(v) for v in box], "layers": solid["layers"]}
            gcase.update({k: solid[k] for k in ("rotation", "translation") if k in solid})
            row["gmsh"] = hex_sweep.run_gmsh(case["path"], [gcase], size, args.timeout)[0]
        os.remove(out)
        second = hex_sweep.run_tquad(args.tquad, case["path"], size, out, args.timeout, ["--order", "2"])
        row["tquad2"] = {k: v for k, v in second.items() if k != "report"}
        if second["status"] == "ok":
            _, points, elements = read_mesh(out, 20)
            row["volume_error2"] = hex20_volume(points, elements) / case["volume"] - 1
            os.remove(out)
    if not args.no_smesh:
        row["smesh"] = run_smesh(case["path"], size, args.timeout)
    return row


# ---------------------------------------------------------------- report

def fmt(value, pattern="%.3f"):
    return "-" if value is None else pattern % value


def markdown(rows, args, info, total_seconds):
    out = ["# The sweep set: solids built from real faces and profiles, swept by tquad, Gmsh and SMESH", "",
           "Generated by `bench/sweep_set.py` (its docstring defines the set and every column). Command:", "",
           "    /usr/bin/python3 bench/sweep_set.py " + " ".join(sys.argv[1:]), "",
           "Date %s. Machine: %s. tquad: %s. Gmsh %s; SMESH of FreeCAD %s. Total run time %.0f s, %d solids, %d "
           "at once; tquad with --threads 1, Gmsh with one thread." % (
               datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"), info["cpu"],
               info["tquad"], info.get("gmsh", "?"), info.get("freecad", "?"), total_seconds, len(rows), args.jobs),
           ""]
    built = [r for r in rows if "path" in r]
    swept = [r for r in built if r.get("hexes")]
    out += ["## Summary", "", "H = D / %g, D each solid's bounding-box diagonal." % args.divisor, "",
            "| family | built | swept | refused | hexahedra | at or below 1e-6 | worst | volume error o1 max | "
            "volume error o2 max |", "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    families = []
    for r in rows:
        if r["family"] not in families:
            families.append(r["family"])
    for fam in families:
        b = [r for r in built if r["family"] == fam]
        s = [r for r in b if r.get("hexes")]
        e1 = [abs(r["volume_error"]) for r in s]
        e2 = [abs(r["volume_error2"]) for r in s if "volume_error2" in r]
        out.append("| %s | %d | %d | %d | %d | %d | %s | %s | %s |" % (
            fam, len(b), len(s), len(b) - len(s), sum(r["hexes"] for r in s), sum(r["bad"] for r in s),
            fmt(min((r["min"] for r in s), default=None)), fmt(max(e1, default=None), "%.2e"),
            fmt(max(e2, default=None), "%.2e")))
    exact = [r for r in built if r["family"] in ("extrusion", "revolution")]
    rest = [r for r in built if r["family"] not in ("extrusion", "revolution")]
    out += ["", "- Extrusions and revolutions swept: %d of %d; the rest (lofts, stacked, pipes): %d of %d (%.0f%%)." % (
        sum(1 for r in exact if r.get("hexes")), len(exact), sum(1 for r in rest if r.get("hexes")), len(rest),
        100.0 * sum(1 for r in rest if r.get("hexes")) / max(1, len(rest)))]
    not_built = [r for r in rows if "path" not in r]
    if not_built:
        out.append("- Not built by FreeCAD (no row below): %d (%s)." % (
            len(not_built), "; ".join("%s: %s" % (r["name"], r["build"]) for r in not_built[:6])))
    for peer in ("gmsh", "smesh"):
        pairs = [(r, r[peer]) for r in swept if isinstance(r.get(peer), dict) and r[peer].get("status") == "ok"
                 and r[peer].get("hexes")]
        if pairs:
            at_least = sum(1 for r, p in pairs if r["min"] >= p["worst" if peer == "smesh" else "min"] - 0.02)
            out.append("- Against %s on the %d solids where it made hexahedra: tquad's worst at least its worst "
                       "minus 0.02 on %d; it left prisms in %d." % (
                           "Gmsh's structured extrusion" if peer == "gmsh" else "SMESH's Extrusion 3D", len(pairs),
                           at_least, sum(1 for _, p in pairs if p.get("prisms"))))
    smesh_times = [(r, r["smesh"]) for r in swept if isinstance(r.get("smesh"), dict)
                   and r["smesh"].get("status") == "ok" and r["smesh"].get("compute_s")]
    if smesh_times:
        ratios = [p["compute_s"] / r["tquad"]["seconds"] for r, p in smesh_times]
        out.append("- SMESH's compute alone over tquad's whole process: geometric mean %.2f (min %.2f, max %.2f) "
                   "on %d solids." % (math.exp(sum(math.log(x) for x in ratios) / len(ratios)), min(ratios),
                                      max(ratios), len(ratios)))
        computes = [(p["compute_s"], sum(r["stage_seconds"].get(k, 0) for k in ("source", "layers", "node_sets")))
                    for r, p in smesh_times if r.get("stage_seconds")]
        computes = [a / b for a, b in computes if b > 0]
        if computes:
            out.append("- SMESH's compute over tquad's own (meshing the source, the layers and the node sets, as "
                       "its report times them; no reading, writing or process start): geometric mean %.2f (min "
                       "%.2f, max %.2f) on %d solids." % (
                           math.exp(sum(math.log(x) for x in computes) / len(computes)), min(computes),
                           max(computes), len(computes)))
    big = [r for r in swept if r["motion"] == "translation" and r["hexes"] >= 1e5]
    if big:
        out.append("- Extrusions of at least 1e5 hexahedra, hexahedra per second: %s (whole process / the layers "
                   "stage alone)." % ", ".join("%.0f / %.0f" % (r["hexes"] / r["tquad"]["seconds"],
                                                                r["hexes"] / r["layer_seconds"]) for r in big))
    out += ["", "## Per solid", "",
            "| solid | family | what | faces | tquad route | layers | hexahedra | worst / mean | >= 0.5 | "
            "volume error o1 / o2 | tquad s | Gmsh worst / mean (hexes, prisms) | SMESH worst / mean (hexes, prisms) "
            "| SMESH compute s / tquad s |",
            "|---|---|---|---:|---|---:|---:|---|---:|---|---:|---|---|---:|"]
    for r in built:
        if not r.get("hexes"):
            out.append("| %s | %s | %s | %d | refused: %s | | | | | | %s | | %s | |" % (
                r["name"], r["family"], r["note"], r["faces"], (r.get("tquad") or {}).get("error", "?")[:160],
                fmt((r.get("tquad") or {}).get("seconds"), "%.2f"), smesh_text(r.get("smesh"))))
            continue
        g = r.get("gmsh") or {}
        gtext = ("%.3f / %.3f (%d, %d)" % (g["min"], g["mean"], g["hexes"], g["prisms"])
                 if g.get("status") == "ok" and g.get("hexes") else g.get("status", "-"))
        s = r.get("smesh") or {}
        ratio = (s["compute_s"] / r["tquad"]["seconds"]) if s.get("status") == "ok" and s.get("compute_s") else None
        out.append("| %s | %s | %s | %d | %s | %d | %d | %.3f / %.3f | %.0f%% | %s / %s | %.2f | %s | %s | %s |" % (
            r["name"], r["family"], r["note"], r["faces"], r["motion"], r["layers"], r["hexes"], r["min"], r["mean"],
            100 * r["good"], fmt(r["volume_error"], "%.1e"), fmt(r.get("volume_error2"), "%.1e"),
            r["tquad"]["seconds"], gtext, smesh_text(s), fmt(ratio, "%.2f")))
    out += ["", "Times: tquad's whole process (reading, meshing the source, sweeping, writing JSON); Gmsh's and "
            "SMESH's meshing calls alone, without reading.", ""]
    return "\n".join(out) + "\n"


def smesh_text(s):
    if not s:
        return "-"
    if s.get("status") != "ok":
        return "failed" if s.get("status") == "failed" else s.get("status", "-")
    if not s.get("hexes"):
        return "no hexahedra (%d prisms, %d tetrahedra)" % (s.get("prisms", 0), s.get("tetras", 0))
    return "%.3f / %.3f (%d, %d)" % (s["worst"], s["mean"], s["hexes"], s.get("prisms", 0))


def main(argv):
    if len(argv) > 1 and argv[1] == "--make-set":
        make_set(argv[2], json.loads(argv[3]), int(argv[4]))
        return 0
    if len(argv) > 1 and argv[1] == "--volume":
        triangulated_volume(argv[2])
        return 0
    if len(argv) > 1 and argv[1] == "--gmsh-case":
        hex_sweep.gmsh_case(argv[2], json.loads(argv[3]), float(argv[4]))
        return 0

    def more(parser):
        parser.add_argument("--parts", type=int, default=30)
        parser.add_argument("--no-smesh", action="store_true")

    args = hex_sweep.parse_args(argv, __doc__, "SWEEP_SET.md", more)
    stamp = corpus.engine_stamp(args.tquad)
    start = time.perf_counter()
    cases = build_set(args)
    with tempfile.TemporaryDirectory(prefix="tq_sweep_set_") as work:
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            rows = list(pool.map(lambda c: case_job(c, args, work), cases))
    total = time.perf_counter() - start
    info = corpus.machine_info(args.tquad, stamp)
    for key, code in (("gmsh", "import gmsh; print(gmsh.__version__)"),
                      ("freecad", "import sys; sys.path.append(%r); import FreeCAD; "
                                  "print('.'.join(FreeCAD.Version()[:3]))" % FREECAD_LIB)):
        try:
            info[key] = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                       env=dict(os.environ, HOME=tempfile.gettempdir())).stdout.strip() or "?"
        except OSError:
            info[key] = "?"
    hex_sweep.write_results(args, rows, markdown(rows, args, info, total), "## Per solid")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
