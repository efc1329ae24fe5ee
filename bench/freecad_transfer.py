#!/usr/bin/python3
"""How long FreeCAD takes to get a TemplateQuad mesh, by route, in one FreeCAD process.

    /usr/bin/python3 bench/freecad_transfer.py [--side 200] [--size 0.2] [--repeat 2]

A square plate (side x side mm, one face) is meshed by the tquad module at `size`
(200 mm at 0.2 mm: 1e6 quads), then turned into a Fem.FemMesh both ways the workbench
knows (freecad_workbench/freecad/templatequad/meshing.py): node by node (addNode /
addFace, one Python call each) and through a temporary VTK file (FemMesh.read), then
assigned to a Fem::FemMeshObjectPython (FreeCAD copies the mesh there). Measured
first: the whole make_mesh of the workbench (mesh object created and recomputed, in a
new document each time). Each step the least of --repeat runs. Needs freecadcmd and the build's Python module
(build/python/tquad). Prints the times and their ratios; asserts nothing.
"""

import argparse
import os
import sys

from freecad_script import run_in_freecad

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

INSIDE_FREECAD = r"""
import sys, time
sys.path[:0] = [{python!r}, {workbench!r}]
import FreeCAD, Part, tquad
from templatequad import meshing, factory

def least(repeat, work):
    best, value = None, None
    for _ in range(repeat):
        start = time.perf_counter()
        value = work()
        seconds = time.perf_counter() - start
        best = seconds if best is None else min(best, seconds)
    return best, value

shape = Part.makePlane({side}, {side})

def whole():
    # First, each time in a new document closed after: nothing else in memory.
    doc = FreeCAD.newDocument("Whole")
    part = doc.addObject("Part::Feature", "Plate")
    part.Shape = shape
    quads = factory.make_mesh(doc, part, size={size}).FemMesh.QuadrangleCount  # it recomputes
    FreeCAD.closeDocument(doc.Name)
    return quads
whole_seconds, whole_quads = least({repeat}, whole)
mesher, mesh = least({repeat}, lambda: meshing.mesh_shape(shape, size={size}))
by_node, _ = least({repeat}, lambda: meshing.femmesh_node_by_node(mesh))
by_file, femmesh = least({repeat}, lambda: meshing.femmesh_from_vtk_file(mesh))
if femmesh is None:
    raise SystemExit("this FreeCAD cannot read the VTK file: no file route to measure")
doc = FreeCAD.newDocument("Transfer")
target = doc.addObject("Fem::FemMeshObjectPython", "Target")
def assign():
    target.FemMesh = femmesh
assigned, _ = least({repeat}, assign)
print(f"quads {{len(mesh.quads)}}, nodes {{len(mesh.nodes)}}")
print(f"tquad.mesh_shape            {{mesher:7.2f}} s")
print(f"FemMesh node by node        {{by_node:7.2f}} s")
print(f"FemMesh from a VTK file     {{by_file:7.2f}} s  ({{by_node / by_file:.1f}}x faster)")
print(f"assigned to the mesh object {{assigned:7.2f}} s")
print(f"make_mesh + recompute       {{whole_seconds:7.2f}} s  (quads in the object: {{whole_quads}})")
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--side", type=float, default=200.0)
    parser.add_argument("--size", type=float, default=0.2)
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--python-dir", default=os.path.join(REPO, "build", "python"))
    args = parser.parse_args()
    if not os.path.isdir(os.path.join(args.python_dir, "tquad")):
        print(f"no tquad module under {args.python_dir}: build the project first", file=sys.stderr)
        return 2
    script = INSIDE_FREECAD.format(python=args.python_dir,
                                   workbench=os.path.join(REPO, "freecad_workbench", "freecad"),
                                   side=args.side, size=args.size, repeat=args.repeat)
    run = run_in_freecad(script)
    lines = [line for line in run.stdout.splitlines() if line.startswith(("quads", "tquad", "FemMesh", "assigned",
                                                                          "make_mesh"))]
    if run.returncode != 0 or not lines:
        print(run.stdout + run.stderr, file=sys.stderr)
        return 1
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
