"""Keep an incomplete TemplateQuad mesh from reaching the CalculiX solver unnoticed.

A mesh whose part had refused faces has holes where those faces are. CalculiX would
solve it without complaint, and a constraint on a refused face would quietly act on
the nodes around its rim. FEM's CalculiX checks (the solver object's "Check" task and
ccxtools' check_prerequisites) both call
``femtools.checksanalysis.check_member_for_solver_calculix`` and stop on any message
it returns; install() wraps that function so it also names every incomplete
TemplateQuad mesh of the analysis, unless the mesh's AcceptIncomplete is set.

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
    if not is_templatequad_mesh(mesh_obj) or not getattr(mesh_obj, "Incomplete", False):
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
    """install(): wrap FEM's CalculiX member check once; False when FEM is missing."""
    try:
        from femtools import checksanalysis
    except ImportError:
        return False
    original = checksanalysis.check_member_for_solver_calculix
    if getattr(original, _WRAPPED_MARK, False):
        return True

    def check_member_for_solver_calculix(analysis, solver, mesh, member):
        return original(analysis, solver, mesh, member) + analysis_messages(analysis, mesh)

    setattr(check_member_for_solver_calculix, _WRAPPED_MARK, True)
    check_member_for_solver_calculix.__doc__ = original.__doc__
    checksanalysis.check_member_for_solver_calculix = check_member_for_solver_calculix
    return True
