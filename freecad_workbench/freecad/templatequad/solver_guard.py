"""Keep an incomplete or out-of-date TemplateQuad mesh from reaching a solver unnoticed.

A mesh made before its part or settings changed (OutOfDate) is not the model's. A
mesh whose part had refused faces has holes where those faces are. A solver would
solve it without complaint, and a constraint on a refused face would quietly act on
the nodes around its rim. install() hooks FEM's checks at two places, each naming
every incomplete TemplateQuad mesh of the analysis unless the mesh's
AcceptIncomplete is set:

- ``femtools.checksanalysis.check_member_for_solver_calculix``, which CalculiX's
  checks (ccxtools' check_prerequisites and the CalculiX solver object's "Check"
  task) call and stop on any message it returns;
- ``femsolver.run.Check.check_mesh_exists``, which the "Check" task of every solver
  object of FreeCAD 0.20 calls first (CalculiX, Z88, Mystran, Elmer): there the
  task fails with the message as its report's error (CalculiX's own task is left
  to the first hook, so it reports the message once).

Installed lazily, by the mesh object itself (created or restored), so FreeCAD's
start-up never imports the FEM modules for it.
"""
from typing import List

import FreeCAD

#: The proxy Type of TemplateQuad mesh objects (mesh_object.TemplateQuadMesh.Type).
MESH_TYPE = "TemplateQuad::Mesh"

_WRAPPED_MARK = "_templatequad_guarded"


def is_templatequad_mesh(obj) -> bool:
    return getattr(getattr(obj, "Proxy", None), "Type", None) == MESH_TYPE


def refused_face_names(mesh_obj) -> List[str]:
    """The FreeCAD names of the faces the mesh left out ("Face28"), from its records."""
    return list(getattr(mesh_obj, "RefusedFaceNames", []) or [])


def incomplete_mesh_message(mesh_obj) -> str:
    """The solver check's message for one mesh: empty when it may be solved."""
    if not is_templatequad_mesh(mesh_obj):
        return ""
    if getattr(mesh_obj, "OutOfDate", False):
        part = getattr(mesh_obj, "Part", None)
        return (f"The mesh {mesh_obj.Label} is out of date: "
                f"{part.Label if part is not None else 'its part'} or a setting changed since it "
                "was made. Mesh it again (double-click it and press OK, or TemplateQuad > Mesh "
                "again).\n")
    if not getattr(mesh_obj, "Incomplete", False):
        return ""
    part = getattr(mesh_obj, "Part", None)
    part_label = part.Label if part is not None else "its part"
    faces = ", ".join(refused_face_names(mesh_obj)) or "some faces"
    if getattr(mesh_obj, "AcceptIncomplete", False):
        FreeCAD.Console.PrintWarning(
            f"TemplateQuad: {mesh_obj.Label} leaves {faces} of {part_label} unmeshed; "
            "solving anyway (AcceptIncomplete is set).\n")
        return ""
    return (f"The mesh {mesh_obj.Label} is incomplete: {faces} of {part_label} "
            "could not be meshed, so the model has holes there and loads or supports on "
            "those faces would act on their edges only. Mesh them (a smaller element "
            "size, or other corners), or set the mesh's AcceptIncomplete property to "
            "solve anyway.\n")


def analysis_messages(analysis, mesh) -> str:
    """Messages for every incomplete TemplateQuad mesh of the analysis (and ``mesh``)."""
    meshes = [obj for obj in getattr(analysis, "Group", []) if is_templatequad_mesh(obj)]
    if mesh is not None and is_templatequad_mesh(mesh) and mesh not in meshes:
        meshes.append(mesh)
    return "".join(incomplete_mesh_message(m) for m in meshes)


def install() -> bool:
    """install(): hook FEM's solver checks once; False when FEM is missing."""
    try:
        from femtools import checksanalysis
    except ImportError:
        return False
    _guard_calculix_member_check(checksanalysis)
    try:
        from femsolver import run
    except ImportError:  # a FEM without the solver framework still has ccxtools
        return True
    _guard_solver_check_task(run.Check)
    return True


def _guard_calculix_member_check(checksanalysis) -> None:
    original = checksanalysis.check_member_for_solver_calculix
    if getattr(original, _WRAPPED_MARK, False):
        return

    def check_member_for_solver_calculix(analysis, solver, mesh, member):
        return original(analysis, solver, mesh, member) + analysis_messages(analysis, mesh)

    setattr(check_member_for_solver_calculix, _WRAPPED_MARK, True)
    check_member_for_solver_calculix.__doc__ = original.__doc__
    checksanalysis.check_member_for_solver_calculix = check_member_for_solver_calculix


def _guard_solver_check_task(check_class) -> None:
    original = check_class.check_mesh_exists
    if getattr(original, _WRAPPED_MARK, False):
        return

    def check_mesh_exists(task):
        if not original(task):
            return False
        if type(task).__module__.startswith("femsolver.calculix"):
            return True  # its member check names the incomplete meshes
        message = analysis_messages(task.analysis, None)
        if message:
            task.report.error(message)
            task.fail()
            return False
        return True

    setattr(check_mesh_exists, _WRAPPED_MARK, True)
    check_mesh_exists.__doc__ = original.__doc__
    check_class.check_mesh_exists = check_mesh_exists
