"""GUI commands of the TemplateQuad workbench.

TemplateQuad_Mesh: mesh the selected Part object (or only its selected faces) with a
new TemplateQuad mesh object, put it in the active FEM analysis if there is one, and
open its task panel. The work is factory.make_mesh; this module only adds the
selection, the transaction, the analysis and the panel.

TemplateQuad_Remesh: mesh the selected TemplateQuad mesh objects again (a recompute
only marks them OutOfDate when their part or settings change).
"""
import FreeCAD
import FreeCADGui

from . import paths

MESH_COMMAND = "TemplateQuad_Mesh"
REMESH_COMMAND = "TemplateQuad_Remesh"

#: Commands of the workbench's toolbar and menu, in order.
COMMANDS = [MESH_COMMAND, REMESH_COMMAND]


def _has_faces(obj) -> bool:
    """Whether obj carries a shape with faces (cheap: IsActive runs on every redraw)."""
    shape = getattr(obj, "Shape", None)
    if shape is None or not hasattr(shape, "countElement"):
        return False
    return not shape.isNull() and shape.countElement("Face") > 0


def split_selection(sub_names):
    """(faces, others): the selected sub-elements that are faces, and the others (edges,
    vertices), which a face mesh cannot be restricted to."""
    faces = [name for name in sub_names if name.startswith("Face")]
    return faces, [name for name in sub_names if not name.startswith("Face")]


def selection_note(label, faces, others) -> str:
    """What the report view says when the selection holds no face but other elements:
    the whole part is meshed ("" when there is nothing to say)."""
    if faces or not others:
        return ""
    return (f"{', '.join(others)} of {label} selected: not faces, so the whole of {label} is "
            f"meshed (select faces to mesh only them)")


def selected_source():
    """The object to mesh and the face names selected on it, or (None, [])."""
    for sel in FreeCADGui.Selection.getSelectionEx():
        if _has_faces(sel.Object):
            faces, others = split_selection(sel.SubElementNames)
            note = selection_note(sel.Object.Label, faces, others)
            if note:
                FreeCAD.Console.PrintMessage(f"TemplateQuad: {note}\n")
            return sel.Object, faces
    return None, []


def active_analysis(doc):
    """The active FEM analysis of doc, or None (also when the FEM GUI is missing)."""
    try:
        import FemGui
    except ImportError:
        return None
    analysis = FemGui.getActiveAnalysis()
    if analysis is not None and analysis.Document == doc:
        return analysis
    return None


class MeshCommand:
    """Template quad mesh of the selected part or faces."""

    def GetResources(self):
        return {
            "Pixmap": paths.icon("TemplateQuad_Mesh"),
            "MenuText": "Template quad mesh",
            "ToolTip": ("All-quadrilateral FEM mesh of the selected part or faces, by "
                        "hierarchical templates; added to the active analysis"),
        }

    def IsActive(self):
        if FreeCAD.ActiveDocument is None:
            return False
        return any(_has_faces(obj) for obj in FreeCADGui.Selection.getSelection())

    def Activated(self):
        from .factory import make_mesh

        doc = FreeCAD.ActiveDocument
        part, faces = selected_source()
        if part is None:
            return
        doc.openTransaction("Template quad mesh")
        try:
            # A click meshes what it can: faces that fail are left out, selected in the
            # 3D view and named in the panel, and the incomplete mesh cannot reach the
            # solver unnoticed (solver_guard). No raise: a failed mesh still gets its
            # object and task panel, where the user sees why.
            mesh = make_mesh(doc, part, faces=faces, keep_going=True, raise_on_error=False)
            if mesh is None:  # cancelled in the progress dialog: nothing was added
                doc.abortTransaction()
                return
            analysis = active_analysis(doc)
            if analysis is not None:
                analysis.addObject(mesh)
        except Exception:
            doc.abortTransaction()
            raise
        doc.commitTransaction()
        show_mesh_over_part(mesh, part)
        FreeCADGui.getDocument(doc).setEdit(mesh.Name)


def selected_meshes():
    """The TemplateQuad mesh objects among the selection."""
    from .solver_guard import is_templatequad_mesh
    return [obj for obj in FreeCADGui.Selection.getSelection() if is_templatequad_mesh(obj)]


class RemeshCommand:
    """Mesh the selected TemplateQuad meshes again."""

    def GetResources(self):
        return {
            "Pixmap": paths.icon("TemplateQuad_Mesh"),
            "MenuText": "Mesh again",
            "ToolTip": ("Mesh the selected TemplateQuad meshes again, with their part as it is "
                        "now (a change of the part or of a setting marks a mesh OutOfDate)"),
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and bool(selected_meshes())

    def Activated(self):
        for mesh in selected_meshes():
            doc = mesh.Document
            # Committed even when cancelled: the mesh then puts back the inputs of the
            # mesh it keeps (an abort would undo that and leave the new inputs).
            doc.openTransaction("Mesh again")
            mesh.Proxy.request_mesh(mesh)
            doc.commitTransaction()
            if mesh.Proxy.cancelled:
                return


def show_mesh_over_part(mesh, part) -> None:
    """Hide the part where the mesh covers it whole; else show which faces are missing.

    The mesh lies on the part's faces, so both visible is a muddle. When every face
    was meshed the part is hidden; when only some were (selected faces, or refused
    ones) the part stays, and the refused faces are selected so they stand out.
    """
    FreeCADGui.Selection.clearSelection()
    whole = not mesh.Faces and not mesh.Incomplete and not mesh.Proxy.last_error
    if whole:
        part.ViewObject.Visibility = False
    elif mesh.RefusedFaceNames:
        FreeCADGui.Selection.addSelection(part, list(mesh.RefusedFaceNames))


def register():
    """Add the commands to FreeCADGui (the workbench calls this in Initialize())."""
    FreeCADGui.addCommand(MESH_COMMAND, MeshCommand())
    FreeCADGui.addCommand(REMESH_COMMAND, RemeshCommand())
