"""One SMESH case of bench/sweep.py, run inside FreeCAD 0.20's freecadcmd.

    SWEEP_SMESH_SPEC='{"counts": [...], "width": W, "height": H,
                       "output": "mesh.vtu", "result": "result.json"}' \\
        freecadcmd -c "exec(open('bench/smesh_case.py').read())"

Builds the planar W x H rectangle as a FreeCAD face, gives each of its four edges a
Regular_1D + NumberOfSegments hypothesis with its count (bottom, right, top, left, as
in sweep.py), the face Quadrangle_2D + QuadranglePreference, times compute(), writes
the mesh to `output` (as a user would save it) and writes one JSON object to `result`:
compute seconds, quadrangle and triangle counts, the segments found on each side and
FreeCAD's version. The process's wall time and peak memory are measured by sweep.py,
and so is the quality, from the written file.

A quirk of the 0.20 binding: hypotheses attach only to the second FemMesh created in
a process, so a throw-away FemMesh is created first, and each case runs in its own
process.
"""

import json
import os
import sys
import time

import FreeCAD
import Fem
import Part


def rectangle_face(width, height):
    corners = [FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(width, 0, 0),
               FreeCAD.Vector(width, height, 0), FreeCAD.Vector(0, height, 0)]
    edges = [Part.LineSegment(corners[i], corners[(i + 1) % 4]).toShape() for i in range(4)]
    return Part.Face(Part.Wire(edges))


def side_of(edge, width, height):
    """0 bottom, 1 right, 2 top, 3 left: the side an edge of the rectangle lies on."""
    mid = edge.CenterOfMass
    distances = [abs(mid.y), abs(mid.x - width), abs(mid.y - height), abs(mid.x)]
    return distances.index(min(distances))


def add_hypotheses(mesh, face, counts, width, height):
    """Per-edge segment counts and the face's quadrangle algorithm; returns the hypotheses
    (they must stay alive until compute())."""
    hypotheses = []
    next_id = iter(range(1, 100))
    for edge in face.Edges:
        regular = Fem.StdMeshers_Regular_1D(next(next_id), mesh)
        segments = Fem.StdMeshers_NumberOfSegments(next(next_id), mesh)
        segments.setNumberOfSegments(counts[side_of(edge, width, height)])
        mesh.addHypothesis(regular, edge)
        mesh.addHypothesis(segments, edge)
        hypotheses += [regular, segments]
    quadrangle = Fem.StdMeshers_Quadrangle_2D(next(next_id), mesh)
    preference = Fem.StdMeshers_QuadranglePreference(next(next_id), mesh)
    mesh.addHypothesis(quadrangle, face)
    mesh.addHypothesis(preference, face)
    return hypotheses + [quadrangle, preference]


def segments_per_side(mesh, face, width, height):
    found = [0, 0, 0, 0]
    for edge in face.Edges:
        found[side_of(edge, width, height)] += len(mesh.getEdgesByEdge(edge))
    return found


def main():
    spec = json.loads(os.environ["SWEEP_SMESH_SPEC"])
    width, height = spec["width"], spec["height"]
    Fem.FemMesh()  # throw-away: the binding's hypotheses attach to the second FemMesh
    mesh = Fem.FemMesh()
    face = rectangle_face(width, height)
    mesh.setShape(face)
    hypotheses = add_hypotheses(mesh, face, spec["counts"], width, height)
    start = time.perf_counter()
    mesh.compute()
    compute_s = time.perf_counter() - start
    mesh.write(spec["output"])
    result = {"compute_s": compute_s, "quads": mesh.QuadrangleCount, "triangles": mesh.TriangleCount,
              "boundary_segments": segments_per_side(mesh, face, width, height),
              "hypotheses": len(hypotheses), "freecad": ".".join(FreeCAD.Version()[:3])}
    with open(spec["result"], "w") as f:
        json.dump(result, f)


main()
sys.exit(0)
