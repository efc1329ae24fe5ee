#!/usr/bin/python3
"""First against second order on a plate with a hole in tension, solved by CalculiX
through FreeCAD, at several element sizes: how close each gets to the stress
concentration, and at what cost in nodes.

    /usr/bin/python3 bench/element_order_plate.py [--sizes 8,4,2,1]

The model is tests/freecad/test_fem_plate.py's: resources/shapes/plate_with_hole.brep
(100 x 60 mm, a hole of 20 mm at the middle, as four faces), 1 mm steel shell, the
x = 0 edge fixed, 1000 N along x on the x = 100 edge. Kt is the peak von Mises stress
on the hole's rim over the nominal net-section stress; Heywood's 2.296 is the
reference (an approximate formula: the converged value of the model is what both
orders approach). Needs freecadcmd, ccx and the build's Python module
(build/python/tquad). Prints a table; asserts nothing.
"""

import argparse
import os
import sys

from freecad_script import run_in_freecad

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

INSIDE_FREECAD = r"""
import math, os, shutil, sys, tempfile, time
sys.path[:0] = [{python!r}, {workbench!r}]
import FreeCAD, Part, ObjectsFem
from femtools import ccxtools
from templatequad import factory

shape = Part.Shape()
shape.read({plate!r})
for size in {sizes!r}:
    for order in ("1st", "2nd"):
        doc = FreeCAD.newDocument("Order")
        plate = doc.addObject("Part::Feature", "Plate")
        plate.Shape = shape
        doc.recompute()
        edge = lambda test: [f"Edge{{i + 1}}" for i, e in enumerate(plate.Shape.Edges) if test(e)][0]
        analysis = ObjectsFem.makeAnalysis(doc, "Analysis")
        solver = ObjectsFem.makeSolverCalculixCcxTools(doc, "CalculiX")
        solver.AnalysisType = "static"
        analysis.addObject(solver)
        analysis.addObject(ObjectsFem.makeElementGeometry2D(doc, 1.0, "Thickness"))
        material = ObjectsFem.makeMaterialSolid(doc, "Steel")
        values = material.Material
        values.update({{"Name": "Steel", "YoungsModulus": "210000 MPa", "PoissonRatio": "0.30"}})
        material.Material = values
        analysis.addObject(material)
        fixed = ObjectsFem.makeConstraintFixed(doc, "Fixed")
        fixed.References = [(plate, edge(lambda e: e.BoundBox.XMax < 1e-6))]
        analysis.addObject(fixed)
        force = ObjectsFem.makeConstraintForce(doc, "Pull")
        force.References = [(plate, edge(lambda e: e.BoundBox.XMin > 100 - 1e-6))]
        force.Force = 1000.0
        force.Direction = (plate, [edge(lambda e: e.BoundBox.YMax < 1e-6)])
        analysis.addObject(force)
        mesh = factory.make_mesh(doc, plate, size=size, element_order=order)
        analysis.addObject(mesh)
        doc.recompute()
        if force.DirectionVector.x < 0:
            force.Reversed = True
            doc.recompute()
        work = tempfile.mkdtemp(prefix="tq_order_")
        fea = ccxtools.FemToolsCcx(analysis, solver)
        fea.update_objects()
        fea.setup_working_dir(work)
        start = time.perf_counter()
        fea.run()
        seconds = time.perf_counter() - start
        result = [o for o in analysis.Group if o.isDerivedFrom("Fem::FemResultObject")][0]
        nodes = result.Mesh.FemMesh.Nodes
        rim = [s for n, s in zip(result.NodeNumbers, result.vonMises)
               if abs(math.hypot(nodes[n].x - 50, nodes[n].y - 30) - 10) < 1e-3]
        kt = max(rim) / 25.0
        print(f"ROW {{size}} | {{order}} | {{mesh.FemMesh.FaceCount}} | {{mesh.FemMesh.NodeCount}} | "
              f"{{kt:.3f}} | {{kt / 2.296:.3f}} | {{seconds:.2f}}")
        FreeCAD.closeDocument(doc.Name)
        shutil.rmtree(work, ignore_errors=True)
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="8,4,2,1", help="element sizes in mm, comma-separated")
    parser.add_argument("--python-dir", default=os.path.join(REPO, "build", "python"))
    args = parser.parse_args()
    sizes = [float(s) for s in args.sizes.split(",") if s.strip()]
    if not os.path.isdir(os.path.join(args.python_dir, "tquad")):
        print(f"no tquad module under {args.python_dir}: build the project first", file=sys.stderr)
        return 2
    script = INSIDE_FREECAD.format(python=args.python_dir,
                                   workbench=os.path.join(REPO, "freecad_workbench", "freecad"),
                                   plate=os.path.join(REPO, "resources", "shapes", "plate_with_hole.brep"),
                                   sizes=sizes)
    run = run_in_freecad(script)
    rows = [line[4:] for line in run.stdout.splitlines() if line.startswith("ROW ")]
    if run.returncode != 0 or not rows:
        print(run.stdout[-3000:] + run.stderr[-3000:], file=sys.stderr)
        return 1
    print("| size (mm) | order | quads | nodes | Kt | Kt / Heywood | FreeCAD's ccxtools run (s) |")
    print("|---:|---|---:|---:|---:|---:|---:|")
    for row in rows:
        print(f"| {row} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
