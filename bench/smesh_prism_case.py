"""One solid meshed by SMESH's "Extrusion 3D" (StdMeshers_Prism_3D), through FreeCAD 0.20.

    SMESH_PRISM_SPEC='{"brep": "solid.brep", "size": H, "output": "mesh.unv",
                       "result": "result.json", "source": F, "target": F,
                       "timeout": 600}' \\
        HOME=/tmp/fakehome /usr/bin/python3 bench/smesh_prism_case.py

Reads the BREP, takes its first solid and meshes it as a SMESH user of Extrusion 3D
would at edge length H: Regular_1D + LocalLength(H) on the solid, Prism_3D on the
solid, and one of these 2D setups, tried in this order until one gives volumes:

  quad                 Quadrangle_2D + QuadranglePreference on the solid (every face).
  quad+mefisto_source  the same, but MEFISTO_2D (triangles) on the source cap, which
                       Quadrangle_2D cannot mesh when it has holes; Prism_3D sweeps the
                       triangles into prisms and projects them onto the target cap.
  mefisto_all          MEFISTO_2D on every face (Prism_3D still gives quadrangle walls).

`source` and `target` (optional) are indices into the solid's Faces. The binding's
ProjectionSource2D has no setters, so the pair cannot be imposed: Prism_3D finds it.
`source` is the cap given MEFISTO_2D in quad+mefisto_source; without it, the first
face other than `target` with an inner wire is taken, else the first whose outer wire
has other than four edges (a seam counted twice), else that setup is skipped.
`output` is written with FemMesh.write (the suffix picks the format: .unv, .vtu, .vtk,
.inp, .med, ...); `timeout` (seconds, default 600) bounds each setup. Optional fields
may be left out or null.

Each setup runs in a child process of this script: the binding attaches hypotheses
only to the second FemMesh of a process (so a throw-away FemMesh is made first and a
failed setup cannot be retried in the same process), and some failing computes end
the process (exit code 1, no message). The result file holds one JSON object:

  status               "ok" or "failed"; error: why, when failed
  setup                the setup that gave the mesh (null when failed)
  attempts             [{"setup", "error"}] for each setup that failed before it
  source_face          the cap picked for quad+mefisto_source (null: none found)
  size                 H; compute_s: seconds in mesh.compute() only (perf_counter)
  hexes, prisms, tetras, pyramids, volumes, nodes: element counts (volumes is the total)
  worst, mean          hexahedra's scaled Jacobian: per hex the worst of its 8 corners
                       (determinant of the 3 unit edge vectors leaving the corner, +1 on
                       a perfect cube), then worst and mean over hexes (null: no hexes)
  share_at_least_0_5   share of hexes with scaled Jacobian >= 0.5
  bad                  number of hexes with scaled Jacobian <= 1e-6
  written              whether `output` was written; write_error: why not
  freecad              FreeCAD's version

SMESH numbers a hexahedron's bottom face the other way round from the convention used
here (nodes 0-3 bottom, counterclockwise seen from the top 4-7, 4+i above i); the
nodes are reordered before measuring. The .vtu and .vtk files of FemMesh.write keep
SMESH's order, so a reader expecting VTK's order sees their hexahedra inverted.
"""

import json
import math
import os
import subprocess
import sys
import tempfile
import time

sys.path.append("/usr/lib/freecad/lib")
import FreeCAD  # noqa: E402  (must come before Part and Fem)
import Fem  # noqa: E402
import Part  # noqa: E402

SETUPS = ("quad", "quad+mefisto_source", "mefisto_all")
CHILD_ENV = "SMESH_PRISM_CHILD"
SMESH_TO_STANDARD = (0, 3, 2, 1, 4, 7, 6, 5)
CORNER_NEIGHBOURS = ((1, 3, 4), (2, 0, 5), (3, 1, 6), (0, 2, 7),
                     (7, 5, 0), (4, 6, 1), (5, 7, 2), (6, 4, 3))


def first_solid(path):
    shape = Part.Shape()
    shape.read(path)
    if not shape.Solids:
        raise ValueError("no solid in %s" % path)
    return shape.Solids[0]


def pick_source(solid, spec):
    if spec.get("source") is not None:
        return int(spec["source"])
    others = [i for i in range(len(solid.Faces)) if i != spec.get("target")]
    for test in (lambda f: len(f.Wires) > 1,  # seam edges count twice below
                 lambda f: len(f.OuterWire.OrderedEdges) != 4):
        for i in others:
            if test(solid.Faces[i]):
                return i
    return None


def scaled_jacobian(points):
    """Worst corner of one hexahedron given in the standard order."""
    worst = math.inf
    for corner, (a, b, c) in enumerate(CORNER_NEIGHBOURS):
        p = points[corner]
        edges = [points[n] - p for n in (a, b, c)]
        lengths = [e.Length for e in edges]
        if min(lengths) <= 0.0:
            return 0.0
        u, v, w = (e * (1.0 / n) for e, n in zip(edges, lengths))
        worst = min(worst, u.dot(v.cross(w)))
    return worst


def hex_quality(mesh):
    nodes = mesh.Nodes
    values = []
    for volume in mesh.Volumes:
        ids = mesh.getElementNodes(volume)
        if len(ids) == 8:
            values.append(scaled_jacobian([nodes[ids[k]] for k in SMESH_TO_STANDARD]))
    if not values:
        return {"worst": None, "mean": None, "share_at_least_0_5": None, "bad": 0}
    return {"worst": min(values), "mean": sum(values) / len(values),
            "share_at_least_0_5": sum(v >= 0.5 for v in values) / len(values),
            "bad": sum(v <= 1e-6 for v in values)}


def add_hypotheses(mesh, solid, setup, size, source):
    """The setup's hypotheses; returned, as they must stay alive until compute()."""
    hypotheses = []

    def add(name, shape, configure=None):
        hypothesis = getattr(Fem, "StdMeshers_" + name)(len(hypotheses) + 1, mesh)
        if configure:
            configure(hypothesis)
        mesh.addHypothesis(hypothesis, shape)
        hypotheses.append(hypothesis)

    add("Regular_1D", solid)
    add("LocalLength", solid, lambda h: h.setLength(size))
    if setup == "mefisto_all":
        add("MEFISTO_2D", solid)
    else:
        add("Quadrangle_2D", solid)
        add("QuadranglePreference", solid)
        if setup == "quad+mefisto_source":
            add("MEFISTO_2D", solid.Faces[source])
    add("Prism_3D", solid)
    return hypotheses


def write_json(path, data):
    with open(path, "w") as f:
        json.dump(data, f, indent=1)


def child(spec):
    """One setup, in this process; writes its own result to spec["child_result"]."""
    path = spec["child_result"]
    solid = first_solid(spec["brep"])
    Fem.FemMesh()  # throw-away: the binding's hypotheses attach to the second FemMesh
    mesh = Fem.FemMesh()
    mesh.setShape(solid)
    hypotheses = add_hypotheses(mesh, solid, spec["setup"], float(spec["size"]), spec["source_face"])
    write_json(path, {"status": "failed", "error": "the process ended inside mesh.compute()"})
    start = time.perf_counter()
    try:
        mesh.compute()
    except Exception as error:  # the binding raises Base.FreeCADError, among others
        write_json(path, {"status": "failed", "error": "compute() raised %s: %s"
                          % (type(error).__name__, error)})
        return
    compute_s = time.perf_counter() - start
    del hypotheses
    write_json(path, {"status": "failed", "error": "the process ended after compute()"})
    result = {"status": "ok", "compute_s": compute_s, "hexes": mesh.HexaCount,
              "prisms": mesh.PrismCount, "tetras": mesh.TetraCount,
              "pyramids": mesh.PyramidCount, "volumes": mesh.VolumeCount,
              "nodes": mesh.NodeCount}
    if mesh.VolumeCount == 0:
        write_json(path, {"status": "failed", "compute_s": compute_s, "error":
                          "compute() gave no volumes (%d quadrangles, %d triangles on faces)"
                          % (mesh.QuadrangleCount, mesh.TriangleCount)})
        return
    result["written"], result["write_error"] = False, None
    if spec.get("output"):
        try:
            mesh.write(spec["output"])
            result["written"] = os.path.exists(spec["output"])
        except Exception as error:
            result["write_error"] = "%s: %s" % (type(error).__name__, error)
    result.update(hex_quality(mesh))
    write_json(path, result)


def run_setup(spec, setup, source):
    """Runs one setup in a child process; returns its result dictionary."""
    with tempfile.TemporaryDirectory() as scratch:
        child_spec = dict(spec, setup=setup, source_face=source,
                          child_result=os.path.join(scratch, "child.json"))
        env = dict(os.environ, **{CHILD_ENV: json.dumps(child_spec)})
        try:
            run = subprocess.run([sys.executable, os.path.abspath(__file__)], env=env,
                                 capture_output=True, text=True,
                                 timeout=float(spec.get("timeout") or 600))
        except subprocess.TimeoutExpired:
            return {"status": "failed", "error": "timed out after %s s" % (spec.get("timeout") or 600)}
        if not os.path.exists(child_spec["child_result"]):
            tail = (run.stderr or run.stdout).strip().splitlines()[-3:]
            return {"status": "failed", "error": "exit code %d before compute: %s"
                    % (run.returncode, " | ".join(tail))}
        with open(child_spec["child_result"]) as f:
            result = json.load(f)
        if result["status"] != "ok" and run.returncode != 0:
            result["error"] += " (exit code %d)" % run.returncode
        return result


def main():
    spec = json.loads(os.environ["SMESH_PRISM_SPEC"])
    final = {"status": "failed", "error": None, "setup": None, "attempts": [],
             "source_face": None, "size": spec["size"],
             "freecad": ".".join(FreeCAD.Version()[:3])}
    try:
        source = pick_source(first_solid(spec["brep"]), spec)
    except Exception as error:
        final["error"] = "cannot read the solid: %s: %s" % (type(error).__name__, error)
        write_json(spec["result"], final)
        return
    final["source_face"] = source
    for setup in SETUPS:
        if setup == "quad+mefisto_source" and source is None:
            final["attempts"].append({"setup": setup, "error": "no source face found"})
            continue
        result = run_setup(spec, setup, source)
        if result["status"] == "ok":
            final.update(result, setup=setup, error=None)
            break
        final["attempts"].append({"setup": setup, "error": result["error"]})
    else:
        final["error"] = "; ".join("%s: %s" % (a["setup"], a["error"]) for a in final["attempts"])
    write_json(spec["result"], final)


if __name__ == "__main__":
    if CHILD_ENV in os.environ:
        child(json.loads(os.environ[CHILD_ENV]))
    else:
        main()
    sys.exit(0)
