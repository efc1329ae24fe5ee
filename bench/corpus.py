#!/usr/bin/python3
"""The real-part corpus judged in one command: tquad on every part and size, each written
quad measured independently, Gmsh 4.8 beside it.

Run with Debian's /usr/bin/python3 (gmsh, numpy, meshio, and FreeCAD's Part module from
/usr/lib/freecad-python3/lib):

    /usr/bin/python3 bench/corpus.py [--sets corpus,cad] [--files a.step,b.stp] [--slice N]
        [--divisors 25,50,100] [--gmsh-divisors 25] [--gmsh-routes blossom] [--no-gmsh]
        [--timeout 300] [--jobs 2] [--surface-check all|none|25,50] [--check]
        [--out-dir build/corpus] [--markdown bench/CORPUS.md | --no-markdown] [--json FILE]

Parts. `corpus`: the 119 STEP parts of REPO/../shared/data/corpus/freecad-library-119.tar.xz,
unpacked once into OUT_DIR/parts (the README and manifest.tsv beside the archive describe
them); `cad`: the parts (*.stp, *.step, *.brep) of REPO/../shared/data/cad. `--slice N`
takes the first N corpus parts in case-insensitive name order and nothing else. When the
corpus archive (or, for `--sets cad`, the CAD directory) is absent the script says so and
exits with 77, the code CTest takes for a skipped test.

Size. H = D / divisor, D the diagonal of the bounding box tquad itself takes (its default
size is D / 25): D/25 runs without --size, and D is 25 times the edge size its report gives
(a probe run at the default first when 25 is not among the divisors). FreeCAD's
Shape.BoundBox differs from it (no tolerance gap; a .brep's stored triangulation; the
report gives the largest difference met), and the manifest's diagonal is FreeCAD's, so
neither is used unless tquad reads no shape. The same H goes to tquad and to Gmsh.

Per part, in its own worker process (`--jobs` of them at once), for each divisor (Gmsh
runs one thread; tquad runs `--tquad-threads`, by default one when more than one worker
runs, so that each process has a core, and its own default of all cores with one worker):
  * `tquad mesh PART -o OUT.json --report json --size H --keep-going`, timed as the wall time
    of the whole process, killed with its process group after `--timeout` seconds. Recorded:
    exit status (0 meshed; 2 refused whole, with stderr's error line; anything else a crash),
    the report's quads, meshed and refused faces (code and reason), unsewn_edge_pairs, and
    its own scaled Jacobian;
  * every quad of OUT.json measured again here, corner by corner, with the scaled Jacobian
    s = dot(e1 x e2, n) / (|e1| |e2| |n|) (compare_parts.corner_scaled_jacobians) against
      own     - the quad's own normal n = (p2 - p0) x (p3 - p1);
      surface - the outer normal of the CAD face at that corner's node: the node projected
                on the face's surface (Surface.parameter), Face.normalAt there (FreeCAD
                orients it with the face, as tquad orients its quads: counter-clockwise seen
                from the outer normal, so a valid quad measures positive). Where the
                surface is singular (a partial derivative vanishing against the other, as
                at a pole or an apex, or the two within --singular-sine 0.01 of parallel,
                as at a collapsed corner of a Bezier patch) OpenCASCADE still returns a
                limit normal, which is noise there: the quad's own normal stands in. Face k
                of the JSON is Shape.Faces[k] (both TopExp::MapShapes order). A node
                farther than 1e-3 D from its face's surface is counted off the surface;
                when over 10 % of the nodes are, or tquad and FreeCAD count different
                faces, the part is marked "face order mismatch" and only the own measure
                is kept;
    a quad is "bad" when a corner is <= 1e-6 by either measure, or when it is collapsed:
    its smallest corner area |e1 x e2| under 1/1000 of its largest (the Jacobian ratio: a
    triangle in effect, whatever its angles); "worst" is the smaller of the two
    measures' minimum;
  * thin faces: a face whose width, 2 x its quads' area / its mesh's boundary length,
    is under THIN_FACE_WIDTH times the size; its quads are counted, and those under 0.2
    (a quad spans such a strip, and leans unless its two sides' nodes face each other);
  * the normals' agreement: every mesh edge two quads share is counted, and those the two
    quads run the same way (their normals disagree there: a shell element's top and
    bottom swap across it);
  * Gmsh (compare_parts' child processes, for the divisors in both --divisors and
    --gmsh-divisors): Blossom = Mesh.Algorithm 6 + Blossom recombination, all-quad = the
    same + subdivision at 2H; the wall time of the whole child process is set against
    tquad's whole process.
Once per part: the sharpest face corner, the smallest angle inside a face between
consecutive boundary edges at a vertex, measured in the face's tangent plane from the
edges' tangents (a tangent continuation is 180 degrees; seam and degenerate edges are
skipped, so a periodic face's seam is no corner; where the tangents coincide, a cusp of 0
or 360 degrees, chords to points just inside the edges tell which). A quad at a corner of
angle a < 90 degrees has a corner of at most a, so sin(a) bounds its scaled Jacobian; an
obtuse corner can be split, so a part whose corners are all 90 degrees or more has bound 1.
The summary counts the parts whose worst >= min(Blossom's worst, that bound) - 0.005, and
those whose mean (own normal, the formula Gmsh's quads get) >= Blossom's.

Output: bench/CORPUS.md (markdown; `--no-markdown` to skip), `--json FILE` the raw results,
a line per part on stderr. `--check` exits 1, naming part, size and face, when a written
quad has a corner <= 1e-6 by either measure, when a file FreeCAD reads is refused whole,
or when a tquad process crashed or ran out of time; it prints a one-line summary. Nothing
here asserts a speed: times are printed as measured.
"""

import argparse
import concurrent.futures
import datetime
import glob
import json
import math
import os
import shlex
import signal
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_parts  # noqa: E402  (bench/compare_parts.py: Gmsh child processes, quality)

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA_DIR = os.path.join(os.path.dirname(REPO), "shared", "data")
FREECAD_LIB = "/usr/lib/freecad-python3/lib"
CORPUS_ARCHIVE = "freecad-library-119.tar.xz"
TQUAD_DEFAULT_DIVISOR = 25.0  # tquad's size without --size: its bounding-box diagonal / 25
SKIP_EXIT = 77            # CTest's SKIP_RETURN_CODE for this script
BAD_CORNER = 1e-6         # a corner at or below this scaled Jacobian makes a quad bad
OFF_SURFACE = 1e-3        # a node farther than this times D from its face's surface is off it
SINGULAR_SINE = 1e-2      # Du, Dv closer to parallel than this sine: a singular point
VANISHING = 1e-9          # |Du| or |Dv| under this times the other: a singular point
MISMATCH_SHARE = 0.10     # more nodes off their faces than this: the face numbering differs
NEWTON_STEPS = 8          # Gauss-Newton steps of a projection from a neighbour's parameters
CUSP_DEGREES = 1.0        # tangents closer than this to one line: a cusp, told by chords
BOUND_MARGIN = 0.005      # slack of the "worst >= bound" comparison
THIN_FACE_WIDTH = 0.25    # a face narrower than this times the size (2 area / perimeter) is thin
REFUSAL_CODES = ("cannot_mesh", "inverted_quads", "too_coarse", "not_supported", "damaged",
                 "internal")


def log(message):
    print(message, file=sys.stderr, flush=True)


# ---------------------------------------------------------------- selecting parts

def read_manifest(path):
    """manifest.tsv as {filename: row}, numbers converted; {} when the file is absent."""
    if not os.path.exists(path):
        return {}
    rows = {}
    with open(path, encoding="utf-8") as f:
        header = f.readline().rstrip("\n").split("\t")
        for line in f:
            if not line.strip():
                continue
            row = dict(zip(header, line.rstrip("\n").split("\t")))
            for key in ("faces", "solids", "shells"):
                row[key] = int(row[key]) if row.get(key, "").isdigit() else None
            try:
                row["diagonal"] = float(row["diagonal"])
            except (KeyError, ValueError):
                row["diagonal"] = None
            rows[row["filename"]] = row
    return rows


def unpack_corpus(archive, out_dir, expected):
    """Unpacks the archive into out_dir (giving out_dir/parts) unless a previous run did so
    completely (a marker file is written last); returns the parts directory."""
    parts = os.path.join(out_dir, "parts")
    marker = os.path.join(out_dir, ".unpacked")
    if os.path.exists(marker) and len(cad_files(parts)) >= expected:
        return parts
    os.makedirs(out_dir, exist_ok=True)
    log("unpacking %s into %s ..." % (archive, out_dir))
    subprocess.run(["tar", "-xJf", archive, "-C", out_dir], check=True)
    with open(marker, "w") as f:
        f.write(archive + "\n")
    return parts


def cad_files(directory):
    """The CAD files of a directory (*.stp, *.step, *.brep), in case-insensitive name order."""
    return sorted((p for p in glob.glob(os.path.join(directory, "*"))
                   if p.lower().endswith(compare_parts.CAD_SUFFIXES)),
                  key=lambda p: os.path.basename(p).lower())


def select_parts(args):
    """The parts to run: a list of {set, name, path, manifest}. Exits with SKIP_EXIT when the
    data a selected set needs is absent."""
    sets = [s.strip() for s in args.sets.split(",") if s.strip()]
    if args.slice is not None:
        sets = ["corpus"]
    unknown = set(sets) - {"corpus", "cad"}
    if unknown:
        sys.exit("unknown set(s): %s (corpus, cad)" % ", ".join(sorted(unknown)))
    parts = []
    if "corpus" in sets:
        if not os.path.exists(args.archive):
            print("corpus archive not found: %s; skipped (CI has it, most machines do not)."
                  % args.archive)
            sys.exit(SKIP_EXIT)
        manifest = read_manifest(args.manifest)
        directory = unpack_corpus(args.archive, args.out_dir, len(manifest))
        files = cad_files(directory)
        if args.slice is not None:
            files = files[:args.slice]
        parts += [{"set": "corpus", "name": os.path.basename(p), "path": os.path.abspath(p),
                   "manifest": manifest.get(os.path.basename(p))} for p in files]
    if "cad" in sets:
        if not os.path.isdir(args.cad_dir):
            if not parts:
                print("CAD directory not found: %s; skipped." % args.cad_dir)
                sys.exit(SKIP_EXIT)
            log("CAD directory not found: %s; the cad set is left out." % args.cad_dir)
        else:
            parts += [{"set": "cad", "name": os.path.basename(p), "path": os.path.abspath(p),
                       "manifest": None} for p in cad_files(args.cad_dir)]
    if args.files:
        wanted = {f.strip() for f in args.files.split(",") if f.strip()}
        missing = wanted - {p["name"] for p in parts}
        if missing:
            sys.exit("not found in the selected sets: %s" % ", ".join(sorted(missing)))
        parts = [p for p in parts if p["name"] in wanted]
    return parts


# ---------------------------------------------------------------- CAD geometry (worker)

def import_part_module():
    """FreeCAD's Part module. Imported in workers only: it cannot share a process with gmsh
    (both bring an OpenCASCADE), and Gmsh always runs in child processes."""
    if FREECAD_LIB not in sys.path:
        sys.path.append(FREECAD_LIB)
    import FreeCAD  # noqa: F401
    import Part
    return Part


def read_shape(path):
    """The shape of a CAD file as FreeCAD reads it, or raises with FreeCAD's message."""
    Part = import_part_module()
    shape = Part.Shape()
    shape.read(path)
    if shape.isNull():
        raise RuntimeError("FreeCAD read a null shape")
    return shape


def oriented_ends(edge):
    """(start point, start direction, end point, end direction, near start, near end) of
    an edge traversed in its orientation (a reversed edge runs from its curve's last
    parameter to its first). Directions are unit tangents; a tangent OpenCASCADE cannot give
    (a zero derivative) is taken as a short chord instead. The near points lie a thousandth
    of the parameter range inside the edge from each end."""
    first, last = edge.FirstParameter, edge.LastParameter
    step = 1e-3 * (last - first)

    def point(t):
        p = edge.valueAt(t)
        return np.array([p.x, p.y, p.z])

    def tangent(t, inward):
        try:
            v = edge.tangentAt(t)
            d = np.array([v.x, v.y, v.z])
        except Exception:
            d = inward * (point(t + inward * step) - point(t))
        n = np.linalg.norm(d)
        return d / n if n > 0 else d

    p_first, p_last = point(first), point(last)
    t_first, t_last = tangent(first, 1), tangent(last, -1)
    near_first, near_last = point(first + step), point(last - step)
    if edge.Orientation == "Reversed":
        return (p_last, -t_last, p_first, -t_first, near_last, near_first)
    return (p_first, t_first, p_last, t_last, near_first, near_last)


def face_normal_at(face, point):
    """The outer unit normal of a face at the surface point nearest `point`, or None where
    it is not defined (a pole, a failed projection)."""
    from FreeCAD import Vector
    try:
        u, v = face.Surface.parameter(Vector(*point))
        n = face.normalAt(u, v)
    except Exception:
        return None
    n = np.array([n.x, n.y, n.z])
    length = np.linalg.norm(n)
    return n / length if length > 0 else None


def angle_from_to(a, b, normal):
    """Angle in degrees (0 to 360) turning counter-clockwise about `normal` from direction a
    to direction b, both projected on the plane normal to it."""
    a = a - np.dot(a, normal) * normal
    b = b - np.dot(b, normal) * normal
    return math.degrees(math.atan2(np.dot(normal, np.cross(a, b)), np.dot(a, b))) % 360.0


def interior_angle(vertex, incoming, outgoing, normal):
    """Angle inside the face at a vertex, in degrees (0 to 360). `incoming` is the
    oriented_ends of the edge arriving at the vertex, `outgoing` of the one leaving it.
    OpenCASCADE keeps the face on the left of each oriented edge seen from the outer normal,
    so the face spans from the outgoing direction counter-clockwise to the incoming edge's
    reversed direction: a convex corner is under 180, a straight continuation 180, a reflex
    corner over. Where the tangents coincide (a cusp: 0 or 360, which they cannot tell
    apart) the chords to points just inside the two edges decide."""
    angle = angle_from_to(outgoing[1], -incoming[3], normal)
    if min(angle, 360.0 - angle) < CUSP_DEGREES:
        chord = angle_from_to(outgoing[4] - vertex, incoming[5] - vertex, normal)
        if (chord > 180.0) != (angle > 180.0):
            angle = 360.0 - angle
    return angle


def sharpest_corner(shape):
    """The smallest interior angle between consecutive boundary edges of any face of the
    shape: {"degrees", "sin", "face", "point"}, or None when no face has a measurable
    corner. Seam and degenerate edges are skipped and the wire closed over them (the
    edge that continues from the same vertex follows), so a cylinder's seam counts as no
    corner and a circle's own closing vertex as 180."""
    best = None
    for k, face in enumerate(shape.Faces):
        for wire in face.Wires:
            try:
                edges = [e for e in wire.OrderedEdges if not e.Degenerated and not e.isSeam(face)]
            except Exception:
                continue
            ends = [(e, oriented_ends(e)) for e in edges]
            for i, (edge, incoming) in enumerate(ends):
                end_vertex = edge.lastVertex(True)
                follower = None
                for j in range(1, len(ends) + 1):
                    other = ends[(i + j) % len(ends)]
                    if other[0].firstVertex(True).isSame(end_vertex):
                        follower = other
                        break
                if follower is None:
                    continue
                normal = face_normal_at(face, incoming[2])
                if normal is None:
                    continue
                angle = interior_angle(incoming[2], incoming, follower[1], normal)
                if best is None or angle < best["degrees"]:
                    best = {"degrees": angle, "face": k, "point": incoming[2].tolist()}
    if best is not None:
        sine = math.sin(math.radians(best["degrees"]))
        best["sin"] = sine if abs(sine) > 1e-12 else 0.0
    return best


def corner_bound(sharpest):
    """What the sharpest corner allows a scaled Jacobian: sin(angle) for an angle up to 90
    degrees (a quad there has a corner that sharp); 1 for a part whose corners are all 90
    degrees or more (an obtuse corner can be split, so its sine bounds nothing)."""
    if sharpest is None or sharpest["degrees"] >= 90.0:
        return 1.0
    return max(0.0, sharpest["sin"])


def singular(du, dv, singular_sine):
    """Whether the surface's normal is undefined, or no more than noise, where its partial
    derivatives are du and dv: one vanishes against the other (a sphere's pole, a cone's
    apex), or they are within `singular_sine` of parallel (a collapsed corner of a Bezier
    patch, where the normal turns by tens of degrees within a thousandth of the patch).
    OpenCASCADE still returns a limit normal at such points, and at an apex it depends on
    the direction it is approached from."""
    a, b = du.Length, dv.Length
    return min(a, b) <= VANISHING * max(a, b) or du.cross(dv).Length <= singular_sine * a * b


class FaceProjection:
    """Projects points on a face's surface, returning the parameters the face uses.

    An unbounded surface may pass through a point twice: a surface of revolution whose line
    lies in a plane across its axis covers that plane once at each sign of the line's
    parameter, with opposite normals, and the nearest-point projection may pick the other
    sheet. So a projection whose parameters fall outside the face's parameter box
    (BRepTools::UVBounds widened by a millionth, a periodic direction taken modulo its
    period) is made again on the surface trimmed to that box. The box is kept within a
    bounded direction's bounds and to one period of a periodic one: OpenCASCADE's
    constructor raises otherwise, and through FreeCAD that aborts the process."""

    def __init__(self, face):
        self.surface = face.Surface
        self.trimmed = None            # made on first need
        bounds = self.surface.bounds()
        u0, u1, v0, v1 = face.ParameterRange
        self.box, self.periods = [], []
        for lo, hi, low_bound, high_bound, periodic, period in (
                (u0, u1, bounds[0], bounds[1], self.surface.isUPeriodic(),
                 self.surface.UPeriod() if self.surface.isUPeriodic() else 0.0),
                (v0, v1, bounds[2], bounds[3], self.surface.isVPeriodic(),
                 self.surface.VPeriod() if self.surface.isVPeriodic() else 0.0)):
            margin = 1e-6 * (hi - lo)
            lo, hi = lo - margin, hi + margin
            if periodic:
                hi = min(hi, lo + period)
            else:
                lo, hi = max(lo, low_bound), min(hi, high_bound)
            self.box.append((lo, hi))
            self.periods.append(period)

    def inside(self, u, v):
        for x, (lo, hi), period in zip((u, v), self.box, self.periods):
            if period:
                x = lo + (x - lo) % period
            if not lo <= x <= hi:
                return False
        return True

    def from_guess(self, point, u, v, step_tolerance):
        """(u, v) of the point's projection by Gauss-Newton from a nearby guess (a
        neighbouring node's parameters): a few evaluations of the surface where the global
        projection samples it whole each time (milliseconds a point on a large B-spline).
        None when it does not settle within the face's box (the caller projects globally)."""
        surface = self.surface
        (u0, u1), (v0, v1) = self.box
        for _ in range(NEWTON_STEPS):
            r = point - surface.value(u, v)
            su, sv = surface.getDN(u, v, 1, 0), surface.getDN(u, v, 0, 1)
            a, b, c = su * su, su * sv, sv * sv
            det = a * c - b * b
            if not det > 1e-24 * a * c:
                return None           # singular: no tangent plane to step in
            ru, rv = su * r, sv * r
            du, dv = (c * ru - b * rv) / det, (a * rv - b * ru) / det
            u, v = u + du, v + dv
            if not self.periods[0]:
                u = min(max(u, u0), u1)
            if not self.periods[1]:
                v = min(max(v, v0), v1)
            if (su * du + sv * dv).Length <= step_tolerance:
                return (u, v) if self.inside(u, v) else None
        return None

    def parameters(self, point):
        """(u, v) of the point's projection within the face's box, or raises."""
        u, v = self.surface.parameter(point)
        if self.inside(u, v):
            return u, v
        if self.trimmed is None:
            (u0, u1), (v0, v1) = self.box
            self.trimmed = False
            if u0 < u1 and v0 < v1:
                Part = import_part_module()
                try:
                    self.trimmed = Part.RectangularTrimmedSurface(self.surface, u0, u1, v0, v1)
                except Exception:
                    pass
        return self.trimmed.parameter(point) if self.trimmed else (u, v)


def surface_normals(face, points, quads, tolerance, singular_sine):
    """Outer unit normals of a face at each point (k, 3) projected on its surface (within
    the face's parameter box), and how many points lie farther than `tolerance` from it.
    quads (m, 4) index `points`: the points are visited breadth-first along the quads'
    edges, each projected from a projected neighbour's parameters (FaceProjection.from_guess)
    and globally when that fails or lands off the surface. A singular point (see `singular`)
    or a failed projection gives a zero row: the caller falls back to the quad's own normal."""
    from FreeCAD import Vector
    projection = FaceProjection(face)
    surface = projection.surface
    count = len(points)
    normals = np.zeros((count, 3))
    pairs = np.concatenate([quads[:, [i, (i + 1) % 4]] for i in range(4)])
    pairs = np.unique(np.concatenate([pairs, pairs[:, ::-1]]), axis=0)
    starts = np.searchsorted(pairs[:, 0], np.arange(count + 1))
    uv = [None] * count
    off = 0
    seen = np.zeros(count, dtype=bool)
    for root in range(count):
        if seen[root]:
            continue
        seen[root] = True
        queue = [root]
        while queue:
            i = queue.pop()
            p = Vector(*points[i])
            neighbours = pairs[starts[i]:starts[i + 1], 1]
            guess = next((uv[j] for j in neighbours if uv[j] is not None), None)
            found = projection.from_guess(p, *guess, 1e-3 * tolerance) if guess else None
            try:
                if found is None or surface.value(*found).distanceToPoint(p) > tolerance:
                    found = projection.parameters(p)
            except Exception:  # no projection: off the surface
                found = None
            for j in neighbours:
                if not seen[j]:
                    seen[j] = True
                    queue.append(j)
            if found is None:
                off += 1
                continue
            uv[i] = found
            u, v = found
            if surface.value(u, v).distanceToPoint(p) > tolerance:
                off += 1
            try:
                du, dv = surface.getDN(u, v, 1, 0), surface.getDN(u, v, 0, 1)
                n = face.normalAt(u, v)
            except Exception:  # FreeCAD raises where OpenCASCADE finds no normal: singular
                continue
            if not singular(du, dv, singular_sine):
                normals[i] = (n.x, n.y, n.z)
    return normals, off


# ---------------------------------------------------------------- measuring a mesh

def read_mesh_json(path):
    """tquad's mesh JSON as (points (n, 3), quads (m, 4), faces [{face, quads: [first, count]}])."""
    with open(path) as f:
        mesh = json.load(f)
    points = np.asarray(mesh["nodes"], dtype=float).reshape(-1, 3)
    quads = np.asarray(mesh["quads"], dtype=np.int64).reshape(-1, 4)
    return points, quads, mesh["faces"]


COLLAPSED_AREA_RATIO = 1e-3


def collapsed_quads(points, quads):
    """Per quad, whether its smallest corner area |e_next x e_prev| is under
    COLLAPSED_AREA_RATIO of its largest (or all are zero)."""
    if not len(quads):
        return np.zeros(0, dtype=bool)
    p = points[quads]                                  # (m, 4, 3)
    areas = np.stack([np.linalg.norm(np.cross(p[:, (k + 1) % 4] - p[:, k], p[:, (k + 3) % 4] - p[:, k]), axis=1)
                      for k in range(4)], axis=1)
    low, high = areas.min(axis=1), areas.max(axis=1)
    return ~(low >= COLLAPSED_AREA_RATIO * high) | (high == 0)


def thin_face_quads(points, quads, quad_face, size):
    """Per quad, whether its face is thin: the face's width, taken as 2 x its quads'
    area / the length of its mesh's boundary (a strip's width, a disk's radius), under
    THIN_FACE_WIDTH times the size. Across a strip that thin a quad spans the strip,
    and leans unless the nodes of its two sides face each other."""
    if not len(quads) or not size:
        return np.zeros(len(quads), dtype=bool)
    p = points[quads]
    area = 0.5 * np.linalg.norm(np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 1]), axis=1)
    faces, face_of = np.unique(quad_face, return_inverse=True)
    face_area = np.bincount(face_of, weights=area, minlength=len(faces))
    a = quads.reshape(-1)
    b = np.roll(quads, -1, axis=1).reshape(-1)
    edge_face = np.repeat(face_of, 4)
    n = int(quads.max()) + 1
    keys = (edge_face * n + np.minimum(a, b)) * n + np.maximum(a, b)
    _, first, counts = np.unique(keys, return_index=True, return_counts=True)
    edge = first[counts == 1]                           # used once in its face: its boundary
    length = np.linalg.norm(points[a[edge]] - points[b[edge]], axis=1)
    perimeter = np.bincount(edge_face[edge], weights=length, minlength=len(faces))
    width = np.where(perimeter > 0, 2 * face_area / np.where(perimeter > 0, perimeter, 1), np.inf)
    return (width < THIN_FACE_WIDTH * size)[face_of]


def same_way_edges(quads):
    """(shared, same_way): mesh edges two or more quads share, and the quad edges that
    run along a shared edge the way another quad's already does."""
    if not len(quads):
        return 0, 0
    a = quads.reshape(-1)
    b = np.roll(quads, -1, axis=1).reshape(-1)
    n = int(quads.max()) + 1
    _, undirected = np.unique(np.minimum(a, b) * n + np.maximum(a, b), return_counts=True)
    _, directed = np.unique(a * n + b, return_counts=True)
    return int((undirected >= 2).sum()), int((directed - 1).sum())


def measure_mesh(path, shape, diagonal, surface_check, singular_sine, tquad_faces, size):
    """Measures every quad of a mesh JSON by both normals (the module docstring);
    tquad_faces is the number of faces tquad's report counts (meshed, refused and absorbed).

    Returns a dict: quads, bad, collapsed (counted in bad too), under_01, under_02,
    thin_quads and thin_under_02 (those in thin faces, thin_face_quads at `size`), worst_own / mean_own, worst_surface /
    mean_surface (None when not measured), worst, surface ("measured", "not asked",
    "face order mismatch", or why not), off_surface_nodes, off_surface_faces, bad_faces
    {face: count}, projected_nodes and seconds (reading, own, surface)."""
    start = time.perf_counter()
    points, quads, faces = read_mesh_json(path)
    read_s = time.perf_counter() - start
    quad_face = np.full(len(quads), -1, dtype=np.int64)
    for f in faces:
        first, count = f["quads"]
        quad_face[first:first + count] = f["face"]

    start = time.perf_counter()
    own = compare_parts.corner_scaled_jacobians(points, quads)              # (m, 4)
    own_s = time.perf_counter() - start
    result = {"quads": int(len(quads)), "nodes": int(len(points)), "surface": "not asked",
              "off_surface_nodes": 0, "off_surface_faces": {}, "projected_nodes": 0}

    surface = None
    start = time.perf_counter()
    if surface_check and shape is None:
        result["surface"] = "FreeCAD could not read the part"
    elif surface_check and len(quads):
        shape_faces = shape.Faces
        if tquad_faces != len(shape_faces) or max(f["face"] for f in faces) >= len(shape_faces):
            result["surface"] = "face order mismatch"
            result["mismatch"] = "tquad counts %d faces, FreeCAD %d" % (tquad_faces, len(shape_faces))
        else:
            tolerance = OFF_SURFACE * diagonal
            normals = np.zeros(quads.shape + (3,))
            for f in faces:
                first, count = f["quads"]
                if count == 0:
                    continue
                block = quads[first:first + count]
                # Each node once per face: shared-edge nodes get each face's own normal.
                nodes, inverse = np.unique(block, return_inverse=True)
                node_normals, off = surface_normals(shape_faces[f["face"]], points[nodes],
                                                     inverse.reshape(-1, 4), tolerance,
                                                     singular_sine)
                normals[first:first + count] = node_normals[inverse.reshape(-1)].reshape(count, 4, 3)
                result["projected_nodes"] += int(len(nodes))
                if off:
                    result["off_surface_nodes"] += off
                    result["off_surface_faces"][str(f["face"])] = off
            if result["off_surface_nodes"] > MISMATCH_SHARE * result["projected_nodes"]:
                result["surface"] = "face order mismatch"
                result["mismatch"] = "%d of %d nodes off their face's surface" % (
                    result["off_surface_nodes"], result["projected_nodes"])
            else:
                fallback = np.linalg.norm(normals, axis=2) == 0   # singular or unprojected
                if fallback.any():
                    p = points[quads]
                    quad_normal = np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 1])
                    normals[fallback] = np.broadcast_to(quad_normal[:, None, :], normals.shape)[fallback]
                result["singular_corners"] = int(fallback.sum())
                surface = compare_parts.corner_scaled_jacobians(points, quads, normals)
                result["surface"] = "measured"
    result["surface_s"] = time.perf_counter() - start

    own_min = own.min(axis=1) if len(quads) else np.zeros(0)
    both = own_min if surface is None else np.minimum(own_min, surface.min(axis=1))
    collapsed = collapsed_quads(points, quads)
    bad = (both <= BAD_CORNER) | collapsed
    result["shared_edges"], result["same_way_edges"] = same_way_edges(quads)
    thin = thin_face_quads(points, quads, quad_face, size)
    result["thin_quads"], result["thin_under_02"] = int(thin.sum()), int((thin & (both < 0.2)).sum())
    result.update({
        "bad": int(bad.sum()), "collapsed": int(collapsed.sum()), "under_01": int((both < 0.1).sum()), "under_02": int((both < 0.2).sum()),
        "worst_own": float(own_min.min()) if len(quads) else None,
        "mean_own": float(own_min.mean()) if len(quads) else None,
        "worst_surface": float(surface.min()) if surface is not None else None,
        "mean_surface": float(surface.min(axis=1).mean()) if surface is not None else None,
        "worst": float(both.min()) if len(quads) else None,
        "bad_faces": {str(int(k)): int(v) for k, v in zip(*np.unique(quad_face[bad], return_counts=True))},
        "read_s": read_s, "own_s": own_s})
    return result


# ---------------------------------------------------------------- tquad (worker)

def run_process(cmd, timeout):
    """Runs a command in its own process group; returns (returncode, stdout, stderr, wall
    seconds from start to exit), the returncode None on timeout and "not started" when the
    program could not be run. On timeout the whole group (tquad's reader child included) is
    killed."""
    start = time.perf_counter()
    try:
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                errors="replace", start_new_session=True)
    except OSError as error:  # e.g. the binary is being relinked
        return "not started", "", str(error), 0.0
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = proc.communicate()
        return None, out, err, time.perf_counter() - start
    return proc.returncode, out, err, time.perf_counter() - start


def first_error_line(stderr):
    """tquad's error line (it follows any warnings), else stderr's first line."""
    lines = [line for line in stderr.splitlines() if line.strip()]
    for line in lines:
        if line.startswith("tquad: error:"):
            return line
    return lines[0] if lines else ""


def run_tquad(tquad, path, size, timeout, mesh_path, threads=0):
    """One tquad run on a part. Returns {status: ok | refused | crashed | timeout, returncode,
    process_s, ...}: for ok the report's counts, for the others stderr's error line."""
    if os.path.exists(mesh_path):
        os.remove(mesh_path)
    cmd = [tquad, "mesh", path, "-o", mesh_path, "--report", "json", "--keep-going"]
    if threads:
        cmd += ["--threads", str(threads)]
    if size:
        cmd += ["--size", repr(size)]
    code, out, err, elapsed = run_process(cmd, timeout)
    result = {"returncode": code, "process_s": elapsed}
    if code is None:
        result["status"] = "timeout"
        return result
    if code == "not started":
        result.update({"status": "not started", "error": err})
        return result
    if code != 0 or not os.path.exists(mesh_path):
        result["status"] = "refused" if code == 2 else "crashed"
        if code is not None and code < 0:
            try:
                result["signal"] = signal.Signals(-code).name
            except ValueError:
                result["signal"] = str(-code)
        result["error"] = first_error_line(err)[:500]
        return result
    try:
        report = json.loads(out)
    except ValueError:
        result.update({"status": "crashed", "error": "unreadable report: " + out[:200]})
        return result
    quality = report.get("quality", {})
    result.update({
        "status": "ok", "quads": report["quads"], "meshed_faces": len(report["faces"]),
        "refused_faces": [{"face": f["face"], "code": f.get("code", "?"), "reason": f.get("reason", "")}
                          for f in report["refused_faces"]],
        "absorbed_faces": [f["face"] for f in report.get("absorbed_faces", [])],
        "unsewn_edge_pairs": len(report.get("unsewn_edge_pairs", [])),
        "edge_size": report.get("edge_size"),
        "report_sj_min": quality.get("scaled_jacobian", {}).get("min"),
        "report_sj_avg": quality.get("scaled_jacobian", {}).get("avg"),
        "report_inverted": quality.get("inverted"), "report_degenerate": quality.get("degenerate"),
        "off_surface_quads": report.get("off_surface_quads"),
        "warnings": len([line for line in err.splitlines() if line.startswith("tquad: warning")])})
    return result


def exception_text(error):
    """An exception's message; FreeCAD's carry a dict whose 'swhat' is the message."""
    detail = error.args[0] if error.args else error
    if isinstance(detail, dict):
        detail = detail.get("swhat") or detail
    return str(detail)[:300]


def part_job(spec):
    """Everything about one part, in a worker process (crashes and hangs of FreeCAD stay
    there): reads the shape, finds its sharpest corner, then for each divisor runs tquad,
    measures its mesh and runs the Gmsh routes. Returns the part's result dict.

    D is tquad's own bounding-box diagonal: TQUAD_DEFAULT_DIVISOR times the edge size its
    report gives for a run without --size. That run is the D/25 run itself when 25 is among
    the divisors, otherwise a probe run first. Only when tquad reads no shape does FreeCAD's
    box stand in (it leaves out the tolerance gap and, from a .brep holding a triangulation,
    bounds the triangulation)."""
    part = {"set": spec["set"], "name": spec["name"], "path": spec["path"], "runs": {}}
    start = time.perf_counter()
    shape = None
    try:
        shape = read_shape(spec["path"])
        bbox = shape.BoundBox
        part.update({"freecad": "read", "faces": len(shape.Faces), "solids": len(shape.Solids),
                     "freecad_diagonal": bbox.DiagonalLength if bbox.isValid() else None})
    except Exception as error:
        part.update({"freecad": "not read: %s" % exception_text(error), "faces": None, "freecad_diagonal": None})
    part["read_s"] = time.perf_counter() - start
    if shape is not None and part["faces"]:
        start = time.perf_counter()
        try:
            part["sharpest"] = sharpest_corner(shape)
        except Exception as error:
            part["sharpest"] = None
            part["sharpest_error"] = exception_text(error)
        part["sharpest_s"] = time.perf_counter() - start

    stem = "%s__%s" % (spec["set"], os.path.splitext(spec["name"])[0])
    mesh_path = lambda divisor: os.path.join(spec["mesh_dir"], "%s.d%g.json" % (stem, divisor))  # noqa: E731
    divisors = list(spec["divisors"])
    default_run = None
    if TQUAD_DEFAULT_DIVISOR in divisors:
        divisors.remove(TQUAD_DEFAULT_DIVISOR)
        divisors.insert(0, TQUAD_DEFAULT_DIVISOR)
        default_run = run_tquad(spec["tquad"], spec["path"], None, spec["timeout"], mesh_path(TQUAD_DEFAULT_DIVISOR),
                                spec["threads"])
    else:
        default_run = run_tquad(spec["tquad"], spec["path"], None, spec["timeout"], mesh_path(0), spec["threads"])
        part["probe"] = {k: default_run.get(k) for k in ("status", "process_s", "edge_size", "error")}
        if os.path.exists(mesh_path(0)):
            os.remove(mesh_path(0))
    if default_run["status"] == "ok" and default_run.get("edge_size"):
        part.update({"diagonal": TQUAD_DEFAULT_DIVISOR * default_run["edge_size"], "diagonal_from": "tquad"})
    else:
        part.update({"diagonal": part["freecad_diagonal"], "diagonal_from": "FreeCAD"})
    if not part["freecad_diagonal"]:
        shape = None  # nothing to measure against

    for divisor in divisors:
        size = part["diagonal"] / divisor if part["diagonal"] else None
        run = {"divisor": divisor, "size": size}
        if divisor == TQUAD_DEFAULT_DIVISOR:
            run["tquad"] = tq = default_run   # tquad's own default size, which is D / 25
        else:
            run["tquad"] = tq = run_tquad(spec["tquad"], spec["path"], size, spec["timeout"], mesh_path(divisor),
                                               spec["threads"])
        if tq["status"] == "ok":
            check = spec["surface_check"] is None or divisor in spec["surface_check"]
            try:
                run["measure"] = measure_mesh(mesh_path(divisor), shape, part["diagonal"], check,
                                              spec["singular_sine"],
                                              faces_of(tq), size)
            except Exception as error:
                run["measure"] = {"error": "%s: %s" % (type(error).__name__, str(error)[:300])}
            if not spec["keep_meshes"]:
                os.remove(mesh_path(divisor))
        if size and divisor in spec["gmsh_divisors"]:
            for route in spec["gmsh_routes"]:
                run[route] = compare_parts.run_gmsh(spec["path"], route, size, spec["timeout"])
        part["runs"]["%g" % divisor] = run
    return part


# ---------------------------------------------------------------- driving the workers

def tquad_threads(args):
    """tquad's --threads: as asked, else 1 when several workers share the cores (each
    process then has one, as Gmsh's single thread has), else 0 (tquad's default)."""
    if args.tquad_threads is not None:
        return max(0, args.tquad_threads)
    return 1 if args.jobs > 1 else 0


def run_worker(part, settings, args):
    """Runs part_job for one part in a child process (this script with --part-job) and
    returns its result; a worker that dies or overruns gives a part marked 'worker'."""
    spec = dict(settings, set=part["set"], name=part["name"], path=part["path"])
    result_path = os.path.join(settings["result_dir"], "%s__%s.json" % (part["set"], part["name"]))
    if os.path.exists(result_path):
        os.remove(result_path)
    cmd = [sys.executable, os.path.abspath(__file__), "--part-job", json.dumps(spec), result_path]
    runs = len(settings["divisors"]) * (1 + len(settings["gmsh_routes"]))
    code, out, err, elapsed = run_process(cmd, runs * args.timeout + 600)
    if code == 0 and os.path.exists(result_path):
        with open(result_path) as f:
            result = json.load(f)
    else:
        result = {"set": part["set"], "name": part["name"], "path": part["path"], "runs": {},
                  "worker": "timed out" if code is None else "exit %s: %s" % (code, err.strip()[-300:])}
    result["manifest"] = part["manifest"]
    result["worker_s"] = elapsed
    return result


def run_all(parts, settings, args):
    """All parts through `args.jobs` workers at once, larger files first (they take longest);
    results in the parts' order."""
    order = sorted(range(len(parts)), key=lambda i: -os.path.getsize(parts[i]["path"]))
    results = [None] * len(parts)
    done = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {pool.submit(run_worker, parts[i], settings, args): i for i in order}
        for future in concurrent.futures.as_completed(futures):
            i = futures[future]
            results[i] = future.result()
            done += 1
            log("[%d/%d] %s" % (done, len(parts), progress_line(results[i])))
    return results


def progress_line(part):
    """One line about a finished part, for stderr."""
    if "worker" in part:
        return "%s: worker %s" % (part["name"], part["worker"])
    cells = []
    for key, run in part["runs"].items():
        tq = run["tquad"]
        text = "D/%s %s" % (key, tq["status"])
        if tq["status"] == "ok":
            m = run.get("measure", {})
            text += " %d quads, %d refused, bad %s, worst %s, %.2f s" % (
                tq["quads"], len(tq["refused_faces"]), m.get("bad", "?"), fmt(m.get("worst")), tq["process_s"])
        elif tq.get("error"):
            text += " (%s)" % tq["error"][:100]
        if "blossom" in run:
            text += ", Blossom %s %.2f s" % (run["blossom"]["status"], run["blossom"]["process_s"])
        cells.append(text)
    return "%s: %s" % (part["name"], "; ".join(cells))


# ---------------------------------------------------------------- judging

def fmt(value, digits=3):
    return "-" if value is None else "%.*f" % (digits, value)


def tquad_ok(run):
    return run is not None and run["tquad"]["status"] == "ok" and "error" not in run.get("measure", {})


def failures(results):
    """What --check fails on, one message per finding (part, size, face where it applies)."""
    out = []
    for part in results:
        name = "%s/%s" % (part["set"], part["name"])
        if "worker" in part:
            out.append("%s: the measuring worker failed (%s)" % (name, part["worker"]))
            continue
        for key, run in part["runs"].items():
            tq = run["tquad"]
            where = "%s at D/%s (H = %s)" % (name, key, "%.6g" % run["size"] if run["size"] else "default")
            if tq["status"] == "timeout":
                out.append("%s: tquad timed out after %.1f s" % (where, tq["process_s"]))
            elif tq["status"] == "not started":
                out.append("%s: tquad could not be started: %s" % (where, tq["error"]))
            elif tq["status"] == "crashed":
                out.append("%s: tquad crashed (exit %s%s): %s" % (
                    where, tq["returncode"], ", " + tq["signal"] if "signal" in tq else "", tq.get("error", "")))
            elif tq["status"] == "refused" and part.get("freecad") == "read":
                out.append("%s: refused whole although FreeCAD reads it: %s" % (where, tq.get("error", "")))
            elif tq["status"] == "ok":
                m = run.get("measure", {})
                if "error" in m:
                    out.append("%s: the mesh could not be measured: %s" % (where, m["error"]))
                for face, count in sorted(m.get("bad_faces", {}).items(), key=lambda kv: int(kv[0])):
                    out.append("%s face %s: %d quad(s) with a corner <= %g (own worst %s, surface worst %s)"
                               % (where, face, count, BAD_CORNER, fmt(m["worst_own"]), fmt(m["worst_surface"])))
    return out


def size_keys(results):
    keys = {k for part in results for k in part["runs"]}
    return sorted(keys, key=float)


def faces_of(tq):
    """The faces tquad counts in a part: meshed, refused and absorbed (strips narrower than
    0.004 of the size, with no quads of their own)."""
    return tq["meshed_faces"] + len(tq["refused_faces"]) + len(tq.get("absorbed_faces", []))


def face_totals(results, key):
    """Per size: faces of all parts (FreeCAD's count), meshed, refused by code, absorbed,
    and faces of files tquad did not mesh at all."""
    totals = {"faces": 0, "meshed": 0, "refused": 0, "absorbed": 0, "codes": {}, "in_unmeshed_files": 0}
    for part in results:
        run = part["runs"].get(key)
        if run is None:
            continue
        tq = run["tquad"]
        faces = part.get("faces") or (part["manifest"] or {}).get("faces") or 0
        if tq["status"] == "ok":
            faces = faces_of(tq)
            totals["meshed"] += tq["meshed_faces"]
            totals["absorbed"] += len(tq.get("absorbed_faces", []))
            totals["refused"] += len(tq["refused_faces"])
            for f in tq["refused_faces"]:
                totals["codes"][f["code"]] = totals["codes"].get(f["code"], 0) + 1
        else:
            totals["in_unmeshed_files"] += faces
        totals["faces"] += faces
    return totals


def share(numerator, denominator):
    return "%.1f%%" % (100.0 * numerator / denominator) if denominator else "-"


def comparisons(results, key):
    """At one size, against Gmsh Blossom: parts whose worst reaches min(Blossom worst, the
    sharpest corner's bound) - BOUND_MARGIN, parts whose mean (own normal, the formula
    Gmsh's quads are measured with) reaches Blossom's, and the whole-process time ratios."""
    reach, mean_ok, ratios, compared, below = [], [], [], [], []
    for part in results:
        run = part["runs"].get(key)
        if not tquad_ok(run) or "blossom" not in run or run["blossom"]["status"] != "ok":
            continue
        blossom, m = run["blossom"], run["measure"]
        if not blossom.get("sj") or m["worst"] is None:
            continue
        compared.append(part["name"])
        bound = min(blossom["sj"]["min"], corner_bound(part.get("sharpest")))
        if m["worst"] >= bound - BOUND_MARGIN:
            reach.append(part["name"])
        else:
            below.append((part["name"], m["worst"], bound))
        if m["mean_own"] >= blossom["sj"]["mean"]:
            mean_ok.append(part["name"])
        ratios.append(blossom["process_s"] / run["tquad"]["process_s"])
    return {"compared": compared, "reach": reach, "mean_ok": mean_ok, "ratios": ratios, "below": below}


def notes(results):
    """Findings worth a line: refused faces are in the tables, these are the rest."""
    out = []
    for part in results:
        name = part["name"]
        if "worker" in part:
            out.append("%s: worker %s" % (name, part["worker"]))
            continue
        if part.get("freecad") != "read":
            out.append("%s: FreeCAD %s" % (name, part.get("freecad")))
        manifest = part.get("manifest") or {}
        if manifest.get("faces") and part.get("faces") and manifest["faces"] != part["faces"]:
            out.append("%s: FreeCAD reads %d faces, the manifest lists %d" % (name, part["faces"], manifest["faces"]))
        for key, run in part["runs"].items():
            tq, where = run["tquad"], "%s D/%s" % (name, key)
            if tq["status"] != "ok":
                continue
            m = run.get("measure", {})
            if faces_of(tq) != part.get("faces"):
                out.append("%s: tquad counts %d faces, FreeCAD %s" % (where, faces_of(tq), part.get("faces")))
            if tq["unsewn_edge_pairs"]:
                out.append("%s: %d unsewn edge pair(s) (faces touching without a shared edge)"
                           % (where, tq["unsewn_edge_pairs"]))
            if m.get("surface") == "face order mismatch":
                out.append("%s: face order mismatch (%s); surface measure left out"
                           % (where, m.get("mismatch", "")))
            elif m.get("off_surface_nodes"):
                faces = sorted(m["off_surface_faces"].items(), key=lambda kv: -kv[1])
                out.append("%s: %d of %d nodes farther than %g D from their face's surface (faces %s)" % (
                    where, m["off_surface_nodes"], m["projected_nodes"], OFF_SURFACE,
                    ", ".join("%s: %d" % kv for kv in faces[:6]) + (" ..." if len(faces) > 6 else "")))
            if m.get("worst_surface") is not None and tq.get("report_sj_min") is not None \
                    and abs(m["worst_surface"] - tq["report_sj_min"]) > 0.05:
                out.append("%s: surface-measured worst %.3f, tquad's report %.3f"
                           % (where, m["worst_surface"], tq["report_sj_min"]))
            for route in ("blossom", "allquad"):
                r = run.get(route)
                if r and r["status"] != "ok":
                    out.append("%s: Gmsh %s %s" % (where, route, r["status"]))
    return out


# ---------------------------------------------------------------- markdown

def table(header, rows, align=None):
    align = align or ["---"] + ["---:"] * (len(header) - 1)
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def files_section(results):
    """Files read / refused whole / crashed / timed out per set, at the first size."""
    rows, refused = [], []
    for set_name in ("corpus", "cad"):
        parts = [p for p in results if p["set"] == set_name]
        if not parts:
            continue
        counts = {"ok": 0, "refused": 0, "crashed": 0, "timeout": 0, "worker": 0, "not started": 0}
        for part in parts:
            if "worker" in part or not part["runs"]:
                counts["worker"] += 1
                continue
            first = part["runs"][size_keys([part])[0]]["tquad"]
            counts[first["status"]] += 1
            if first["status"] != "ok":
                refused.append("%s/%s: %s%s (FreeCAD %s)" % (
                    set_name, part["name"], first["status"],
                    ": " + first["error"] if first.get("error") else "",
                    "reads it" if part.get("freecad") == "read" else part.get("freecad")))
        freecad = sum(1 for p in parts if p.get("freecad") == "read")
        rows.append([set_name, len(parts), freecad, counts["ok"], counts["refused"], counts["crashed"],
                     counts["timeout"], counts["worker"] + counts["not started"]])
    text = table(["set", "files", "FreeCAD reads", "tquad meshed", "refused whole", "crashed",
                  "timed out", "not run (worker or binary failed)"], rows)
    return text, refused


def faces_section(results, keys):
    rows = []
    for key in keys:
        t = face_totals(results, key)
        codes = ", ".join("%s %d" % (c, t["codes"][c]) for c in REFUSAL_CODES if c in t["codes"])
        codes += "".join(", %s %d" % (c, n) for c, n in t["codes"].items() if c not in REFUSAL_CODES)
        read = t["meshed"] + t["refused"] + t["absorbed"]
        rows.append(["D/" + key, t["faces"], t["meshed"], t["absorbed"], t["refused"], codes.strip(", ") or "-",
                     t["in_unmeshed_files"], share(t["meshed"], read), share(t["meshed"] + t["absorbed"], t["faces"]),
                     share(t["meshed"], t["faces"])])
    return table(["size", "faces", "meshed", "absorbed", "refused", "refused by code", "in files not meshed",
                  "meshed / faces of meshed files", "meshed or absorbed / all faces", "meshed / all faces"], rows)


def refused_section(results, keys):
    """One line per part and size with refused faces: face (code): reason."""
    out = []
    for part in sorted(results, key=lambda p: (p["set"] != "corpus", p["name"].lower())):
        for key in keys:
            run = part["runs"].get(key)
            if run is None or run["tquad"]["status"] != "ok" or not run["tquad"]["refused_faces"]:
                continue
            out.append("%s D/%s: %s" % (part["name"], key, "; ".join(
                "face %d (%s): %s" % (f["face"], f["code"], " ".join(f["reason"].split())[:160])
                for f in run["tquad"]["refused_faces"])))
    return out


def bad_section(results, keys):
    rows = []
    for key in keys:
        quads = bad = 0
        parts = []
        for part in results:
            run = part["runs"].get(key)
            if not tquad_ok(run):
                continue
            m = run["measure"]
            quads += m["quads"]
            bad += m["bad"]
            if m["bad"]:
                parts.append("%s (%d; faces %s)" % (part["name"], m["bad"], ", ".join(sorted(m["bad_faces"], key=int))))
        rows.append(["D/" + key, quads, bad, "; ".join(parts) or "-"])
    return table(["size", "quads written", "corner <= 1e-6 by either normal", "parts with them"], rows,
                 ["---", "---:", "---:", "---"])


def part_rows(results, keys):
    header = ["set", "file", "size", "faces", "refused", "quads", "bad", "<0.1", "<0.2",
              "worst own / surface", "mean own / surface", "sharpest corner deg (sin)",
              "Blossom worst / mean / tris", "tquad s", "Blossom s", "Blossom / tquad"]
    rows = []
    for part in sorted(results, key=lambda p: (p["set"] != "corpus", p["name"].lower())):
        sharp = part.get("sharpest")
        sharp_cell = "%.1f (%.3f)" % (sharp["degrees"], sharp["sin"]) if sharp else "-"
        if "worker" in part:
            rows.append([part["set"], part["name"], "-", "worker " + part["worker"][:80]] + [""] * 12)
            continue
        for key in keys:
            run = part["runs"].get(key)
            if run is None:
                continue
            tq = run["tquad"]
            cells = [part["set"], part["name"], "D/" + key]
            if tq["status"] != "ok":
                cells += [part.get("faces") or "-", tq["status"]] + ["-"] * 6 + [sharp_cell]
            else:
                m = run.get("measure", {})
                if "error" in m:
                    m = {}
                cells += [faces_of(tq), len(tq["refused_faces"]),
                          tq["quads"], m.get("bad", "-"), m.get("under_01", "-"), m.get("under_02", "-"),
                          "%s / %s" % (fmt(m.get("worst_own")), surface_cell(m, "worst_surface")),
                          "%s / %s" % (fmt(m.get("mean_own")), surface_cell(m, "mean_surface")), sharp_cell]
            blossom = run.get("blossom")
            if blossom is None:
                cells += ["-"]
            elif blossom["status"] != "ok" or not blossom.get("sj"):
                cells += [blossom["status"]]
            else:
                cells += ["%.3f / %.3f / %d" % (blossom["sj"]["min"], blossom["sj"]["mean"], blossom["triangles"])]
            cells.append("%.2f" % tq["process_s"] if tq["status"] != "timeout" else "timeout")
            cells.append("%.2f" % blossom["process_s"] if blossom else "-")
            if blossom and blossom["status"] in ("ok", "timeout") and tq["status"] == "ok":
                ratio = blossom["process_s"] / tq["process_s"]
                cells.append((">%.2f" if blossom["status"] == "timeout" else "%.2f") % ratio)
            else:
                cells.append("-")
            rows.append(cells)
    return table(header, rows, ["---", "---"] + ["---:"] * (len(header) - 2))


def surface_cell(m, key):
    if m.get(key) is not None:
        return fmt(m[key])
    return {"not asked": "n/a", "face order mismatch": "mismatch"}.get(m.get("surface"), "-")


def summary_lines(results, keys, gmsh_keys):
    out = []
    spread = [(abs(p["diagonal"] / p["freecad_diagonal"] - 1), p["name"]) for p in results
              if p.get("diagonal_from") == "tquad" and p.get("freecad_diagonal")]
    if spread:
        worst = max(spread)
        out.append("D from tquad's own box for %d of %d parts; FreeCAD's Shape.BoundBox differs by up to %.1f%% (%s)."
                   % (len(spread), len(results), 100 * worst[0], worst[1]))
    for key in keys:
        t = face_totals(results, key)
        quads = sum(p["runs"][key]["measure"]["quads"] for p in results if tquad_ok(p["runs"].get(key)))
        bad = sum(p["runs"][key]["measure"]["bad"] for p in results if tquad_ok(p["runs"].get(key)))
        out.append("D/%s: faces meshed %d of %d (%s), %d more absorbed (%s meshed or absorbed); quads %d, "
                   "bad (a corner <= 1e-6, or collapsed) %d."
                   % (key, t["meshed"], t["faces"], share(t["meshed"], t["faces"]), t["absorbed"],
                      share(t["meshed"] + t["absorbed"], t["faces"]), quads, bad))
        runs = [p for p in results if tquad_ok(p["runs"].get(key)) and "shared_edges" in p["runs"][key]["measure"]]
        same = [(p["name"], p["runs"][key]["measure"]["same_way_edges"]) for p in runs
                if p["runs"][key]["measure"]["same_way_edges"]]
        thin = sum(p["runs"][key]["measure"].get("thin_quads", 0) for p in results if tquad_ok(p["runs"].get(key)))
        poor = sum(p["runs"][key]["measure"].get("under_02", 0) for p in results if tquad_ok(p["runs"].get(key)))
        thin_poor = sum(p["runs"][key]["measure"].get("thin_under_02", 0) for p in results
                        if tquad_ok(p["runs"].get(key)))
        out.append("D/%s thin faces (2 x area / perimeter under %g of the size): %d quads (%s of all), %d of the "
                   "%d quads under 0.2 (%s)."
                   % (key, THIN_FACE_WIDTH, thin, share(thin, quads), thin_poor, poor, share(thin_poor, poor)))
        out.append("D/%s normals: %d shared mesh edges in %d parts, %d run the same way by two quads "
                   "(normals that disagree)%s."
                   % (key, sum(p["runs"][key]["measure"]["shared_edges"] for p in runs), len(runs),
                      sum(n for _, n in same), (": " + ", ".join("%s %d" % s for s in same)) if same else ""))
    for key in keys:
        runs = [p["runs"][key]["measure"] for p in results if tquad_ok(p["runs"].get(key))]
        nodes = sum(m["projected_nodes"] for m in runs)
        surface_s = sum(m["surface_s"] for m in runs)
        if nodes:
            out.append("D/%s measuring cost (in the workers): %d nodes projected on their faces in %.1f s "
                       "(%.0f us a node), mesh JSON read in %.1f s, own-normal measure %.2f s."
                       % (key, nodes, surface_s, 1e6 * surface_s / nodes, sum(m["read_s"] for m in runs),
                          sum(m["own_s"] for m in runs)))
    for key in gmsh_keys:
        c = comparisons(results, key)
        n = len(c["compared"])
        if not n:
            continue
        out.append("D/%s, %d parts meshed by both: worst >= min(Blossom worst, corner bound) - %g in %d (%s); "
                   "mean >= Blossom's mean in %d (%s); Blossom whole process / tquad whole process, "
                   "geometric mean %.2f (min %.2f, max %.2f)."
                   % (key, n, BOUND_MARGIN, len(c["reach"]), share(len(c["reach"]), n), len(c["mean_ok"]),
                      share(len(c["mean_ok"]), n), compare_parts.geometric_mean(c["ratios"]),
                      min(c["ratios"]), max(c["ratios"])))
        if c["below"]:
            out.append("D/%s, worst below the bound (worst < bound): %s." % (key, ", ".join(
                "%s (%.3f < %.3f)" % row for row in sorted(c["below"], key=lambda row: row[0].lower()))))
    return out


def markdown(results, args, info, total_s, command):
    keys = size_keys(results)
    gmsh_keys = [k for k in keys if not args.no_gmsh and float(k) in args.gmsh_divisors]
    files, refused = files_section(results)
    surface_note = ("the surface measure at every size" if args.surface_check is None else
                    "the surface measure only at D/%s (`--surface-check`); 'n/a' elsewhere"
                    % ", D/".join("%g" % d for d in args.surface_check) if args.surface_check else
                    "no surface measure (`--surface-check none`)")
    lines = [
        "# The real-part corpus: tquad per part and size, measured independently, beside Gmsh",
        "",
        "Generated by `bench/corpus.py` (its docstring defines every column). Command:",
        "",
        "    " + command,
        "",
        "Date %s. Machine: %s, %s cores (nproc), %s RAM, %s. tquad: %s. Gmsh %s. Total run time %.0f s, "
        "%d parts through %d worker(s) at once; tquad with %s, Gmsh with one thread."
        % (info["date"], info["cpu"], info["nproc"], info["ram"], info["uname"], info["tquad"],
           info.get("gmsh", "?"), total_s, len(results), args.jobs,
           "--threads %d" % tquad_threads(args) if tquad_threads(args) else "its default threads (all cores)"),
        "",
        "## Summary",
        "",
    ]
    lines += ["- " + line for line in summary_lines(results, keys, gmsh_keys)]
    lines += ["", "## Files", "", files, ""]
    lines += ["- " + line for line in refused] or ["- No file refused whole."]
    lines += ["", "## Faces", "", faces_section(results, keys), ""]
    lines += ["- " + line for line in refused_section(results, keys)] or ["- No face refused."]
    lines += ["",
              "## Bad quads: a corner <= 1e-6 (by the quad's own normal or the surface's), or collapsed", "",
              bad_section(results, keys), "",
              "## Per part", "",
              "H = D / divisor, D the shape's bounding-box diagonal as tquad takes it (D/25 is its default). bad = quads with a corner "
              "<= 1e-6 by either normal, or collapsed (its smallest corner area |e1 x e2| under 1/1000 of its largest); <0.1, <0.2 = quads whose smaller measure is under that; worst and mean "
              "by the quad's own normal / by the surface's outer normal (%s). Sharpest corner: the smallest "
              "angle between boundary edges inside a face, on the CAD. Blossom: Gmsh %s, Mesh.Algorithm 6 + "
              "Blossom recombination, scaled Jacobian of its quads (own normal), triangles it left. Times: wall "
              "seconds of each whole process (start to exit, file reading included), while %d part(s) ran at "
              "once; ratio = Blossom / tquad." % (surface_note, info.get("gmsh", "?"), args.jobs), "",
              part_rows(results, keys), ""]
    if "allquad" in args.gmsh_routes and not args.no_gmsh:
        lines += ["## Gmsh all-quad (subdivision at 2H)", "", allquad_rows(results, gmsh_keys), ""]
    lines += ["## Notes", ""]
    lines += ["- " + line for line in notes(results)] or ["- None."]
    return "\n".join(lines) + "\n"


def allquad_rows(results, keys):
    rows = []
    for part in sorted(results, key=lambda p: (p["set"] != "corpus", p["name"].lower())):
        for key in keys:
            run = part["runs"].get(key) or {}
            r = run.get("allquad")
            if r is None:
                continue
            tq = run["tquad"]
            if r["status"] == "ok" and r.get("sj"):
                cells = ["%.3f / %.3f" % (r["sj"]["min"], r["sj"]["mean"]), r["quads"], r["triangles"]]
            else:
                cells = [r["status"], "-", "-"]
            ratio = "%.2f" % (r["process_s"] / tq["process_s"]) if tq["status"] == "ok" and r["status"] == "ok" else "-"
            rows.append([part["set"], part["name"], "D/" + key] + cells + ["%.2f" % r["process_s"], ratio])
    return table(["set", "file", "size", "worst / mean", "quads", "triangles", "all-quad s", "all-quad / tquad"],
                 rows, ["---", "---"] + ["---:"] * 6)


# ---------------------------------------------------------------- main

def engine_stamp(tquad):
    """Modification time of the newest file of the engine: the tquad binary and the plugin
    libraries it loads (lib/templatequad/*.so beside bin/). None when the binary is absent."""
    files = [tquad] + glob.glob(os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(tquad))),
                                             "lib", "templatequad", "*.so"))
    try:
        return max(os.path.getmtime(f) for f in files)
    except OSError:
        return None


def iso_time(stamp):
    return "?" if stamp is None else \
        datetime.datetime.fromtimestamp(stamp).astimezone().isoformat(timespec="seconds")


def machine_info(tquad, stamp_before):
    """compare_parts.machine() plus RAM, the engine's build time (before the run; a
    rebuild during it is reported) and the repository's commit."""
    info = compare_parts.machine()
    try:
        with open("/proc/meminfo") as f:
            kb = next(int(line.split()[1]) for line in f if line.startswith("MemTotal"))
        info["ram"] = "%.1f GiB" % (kb / 2 ** 20)
    except (OSError, StopIteration):
        info["ram"] = "?"
    stamp_after = engine_stamp(tquad)
    info["engine_changed"] = stamp_after != stamp_before
    stamp = iso_time(stamp_before)
    if info["engine_changed"]:
        stamp += " (REBUILT DURING THE RUN, at %s: the results mix builds)" % iso_time(stamp_after)
    commit = subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip() or "?"
    dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    info["gmsh"] = "not run"
    info["tquad"] = "%s built %s, work tree at commit %s%s" % (
        os.path.relpath(tquad, REPO), stamp, commit, " with local changes" if dirty else "")
    return info


def number_list(text):
    return [float(x) for x in text.split(",") if x.strip()]


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data-dir", default=DATA_DIR,
                        help="holds corpus/ and cad/ (default REPO/../shared/data)")
    parser.add_argument("--archive", help="corpus archive (default DATA_DIR/corpus/%s)" % CORPUS_ARCHIVE)
    parser.add_argument("--manifest", help="corpus manifest (default beside the archive)")
    parser.add_argument("--cad-dir", help="the cad set's directory (default DATA_DIR/cad)")
    parser.add_argument("--sets", default="corpus,cad", help="comma-separated: corpus, cad (default both)")
    parser.add_argument("--files", help="comma-separated file names within the selected sets")
    parser.add_argument("--slice", type=int, help="only the first N corpus parts in name order")
    parser.add_argument("--divisors", type=number_list, default=[25.0, 50.0, 100.0],
                        help="H = D / divisor for each (default 25,50,100)")
    parser.add_argument("--gmsh-divisors", type=number_list, default=[25.0],
                        help="divisors (among --divisors) Gmsh also runs at (default 25)")
    parser.add_argument("--gmsh-routes", default="blossom", help="blossom, allquad (default blossom)")
    parser.add_argument("--no-gmsh", action="store_true", help="run no Gmsh")
    parser.add_argument("--surface-check", default="all",
                        help="divisors measured against the surface normal: all (default), none, or a list")
    parser.add_argument("--singular-sine", type=float, default=SINGULAR_SINE,
                        help="a surface point whose partial derivatives are closer to parallel than "
                             "this sine is singular: its corners use the quad's own normal (default %g)"
                             % SINGULAR_SINE)
    parser.add_argument("--timeout", type=float, default=300.0,
                        help="seconds allowed to each tquad and Gmsh process (default 300)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="parts run at once (default: the number of CPUs)")
    parser.add_argument("--tquad-threads", type=int, default=None,
                        help="tquad's --threads (default: 1 when --jobs is over 1, as Gmsh runs one "
                             "thread; otherwise tquad's own default, all cores)")
    parser.add_argument("--out-dir", default=os.path.join(REPO, "build", "corpus"),
                        help="unpacked parts, meshes and per-part results (default build/corpus)")
    parser.add_argument("--keep-meshes", action="store_true", help="keep tquad's mesh JSON files")
    parser.add_argument("--markdown", default=os.path.join(REPO, "bench", "CORPUS.md"),
                        help="markdown report (default bench/CORPUS.md)")
    parser.add_argument("--no-markdown", action="store_true", help="write no markdown")
    parser.add_argument("--json", help="write the raw results to this file")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 on a bad quad, a readable file refused whole, a crash or a timeout")
    parser.add_argument("--tquad", default=compare_parts.TQUAD, help="tquad binary (default build/bin/tquad)")
    parser.add_argument("--part-job", nargs=2, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    args.archive = args.archive or os.path.join(args.data_dir, "corpus", CORPUS_ARCHIVE)
    args.manifest = args.manifest or os.path.join(os.path.dirname(args.archive), "manifest.tsv")
    args.cad_dir = args.cad_dir or os.path.join(args.data_dir, "cad")
    args.gmsh_routes = [r.strip() for r in args.gmsh_routes.split(",") if r.strip()]
    if set(args.gmsh_routes) - set(compare_parts.GMSH_ROUTES):
        parser.error("--gmsh-routes: blossom, allquad")
    if args.surface_check == "all":
        args.surface_check = None          # every size
    elif args.surface_check == "none":
        args.surface_check = []
    else:
        args.surface_check = number_list(args.surface_check)
    return args


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if args.part_job:
        spec, result_path = args.part_job
        result = part_job(json.loads(spec))
        with open(result_path + ".tmp", "w") as f:
            json.dump(result, f)
        os.replace(result_path + ".tmp", result_path)
        return 0

    command = " ".join(shlex.quote(a) for a in ["/usr/bin/python3", os.path.relpath(os.path.abspath(__file__), REPO)]
                       + sys.argv[1:])
    parts = select_parts(args)
    if not parts:
        print("no parts selected")
        return 0
    if not os.access(args.tquad, os.X_OK):
        print("tquad not found: %s (build it or pass --tquad)" % args.tquad, file=sys.stderr)
        return 1
    mesh_dir = os.path.join(args.out_dir, "meshes")
    result_dir = os.path.join(args.out_dir, "results")
    os.makedirs(mesh_dir, exist_ok=True)
    os.makedirs(result_dir, exist_ok=True)
    gmsh_divisors = [] if args.no_gmsh else [d for d in args.gmsh_divisors if d in args.divisors]
    settings = {"tquad": os.path.abspath(args.tquad), "divisors": args.divisors, "gmsh_divisors": gmsh_divisors,
                "gmsh_routes": args.gmsh_routes if gmsh_divisors else [], "timeout": args.timeout,
                "surface_check": args.surface_check, "mesh_dir": mesh_dir, "result_dir": result_dir,
                "keep_meshes": args.keep_meshes, "singular_sine": args.singular_sine,
                "threads": tquad_threads(args)}

    start = time.perf_counter()
    stamp = engine_stamp(args.tquad)
    results = run_all(parts, settings, args)
    total_s = time.perf_counter() - start
    info = machine_info(args.tquad, stamp)
    if info["engine_changed"]:
        log("warning: the tquad binary or its libraries changed during the run; the results mix builds")
    if gmsh_divisors:
        info["gmsh"] = subprocess.run([sys.executable, "-c", "import gmsh; print(gmsh.__version__)"],
                                      capture_output=True, text=True).stdout.strip() or "?"

    if not args.no_markdown:
        with open(args.markdown, "w") as f:
            f.write(markdown(results, args, info, total_s, command))
        log("wrote %s" % args.markdown)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"command": command, "machine": info, "total_s": total_s,
                       "settings": settings, "parts": results}, f, indent=1)

    found = failures(results)
    keys = size_keys(results)
    faces = [face_totals(results, k) for k in keys]
    bad = sum(p["runs"][k]["measure"]["bad"] for k in keys for p in results if tquad_ok(p["runs"].get(k)))
    mismatches = sum(1 for p in results for r in p["runs"].values()
                     if tquad_ok(r) and r["measure"].get("surface") == "face order mismatch")
    print("corpus: %d parts at D/%s in %.0f s; faces meshed %s; bad quads %d; face order mismatches %d; %s"
          % (len(parts), ",".join(keys), total_s,
             ", ".join("%d/%d (%s)" % (t["meshed"], t["faces"], share(t["meshed"], t["faces"])) for t in faces),
             bad, mismatches, "%d finding(s)" % len(found) if found else "no finding"))
    if args.check:
        for line in found:
            print("FAIL " + line)
        return 1 if found else 0
    for line in found:
        log("finding: " + line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
