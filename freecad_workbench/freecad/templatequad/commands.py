"""GUI commands of the TemplateQuad workbench.

TemplateQuad_Mesh: mesh the selected Part object (or only its selected faces) with a
new TemplateQuad mesh object, put it in the active FEM analysis if there is one, and
open its task panel. The work is factory.make_mesh; this module only adds the
selection, the transaction, the analysis and the panel.

TemplateQuad_Remesh: mesh the selected TemplateQuad mesh objects again (a recompute
only marks them OutOfDate when their part or settings change).

TemplateQuad_MeshRegion, TemplateQuad_MeshGroup: FreeCAD's own FEM mesh region and
mesh group (ObjectsFem.makeMeshRegion, makeMeshGroup, with FreeCAD's task panels) on
the selected TemplateQuad mesh; FEM's commands of the same names are only active on
a Gmsh mesh.

TemplateQuad_ShowWorst: highlight the selected mesh's worst elements, zoom onto them
and list them with their faces in the report view.

TemplateQuad_ExportGroups: write the selected mesh with its mesh groups as *ELSET and
*NSET to an .inp file (FreeCAD's File > Export leaves groups out).
"""
import FreeCAD
import FreeCADGui

from . import paths

MESH_COMMAND = "TemplateQuad_Mesh"
REMESH_COMMAND = "TemplateQuad_Remesh"
REGION_COMMAND = "TemplateQuad_MeshRegion"
GROUP_COMMAND = "TemplateQuad_MeshGroup"
EXPORT_COMMAND = "TemplateQuad_ExportGroups"
WORST_COMMAND = "TemplateQuad_ShowWorst"

#: Commands of the workbench's toolbar and menu, in order.
COMMANDS = [MESH_COMMAND, REMESH_COMMAND, WORST_COMMAND, REGION_COMMAND, GROUP_COMMAND, EXPORT_COMMAND]


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


class OneMeshCommand:
    """A command on the one selected TemplateQuad mesh: its name, tip and icon, and
    active while exactly one mesh is selected."""

    def __init__(self, menu: str, tip: str, icon: str = ""):
        self.menu, self.tip, self.icon = menu, tip, icon or paths.icon("TemplateQuad_Mesh")

    def GetResources(self):
        return {"Pixmap": self.icon, "MenuText": self.menu, "ToolTip": self.tip}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and len(selected_meshes()) == 1


class AddToMeshCommand(OneMeshCommand):
    """A FEM mesh region or mesh group on the one selected TemplateQuad mesh."""

    def __init__(self, kind: str, menu: str, tip: str, icon: str):
        super().__init__(menu, tip, icon)
        self.kind = kind

    def GetResources(self):
        try:
            import FemGui  # noqa: F401  (registers FEM's icons, these among them)
        except ImportError:
            pass
        return super().GetResources()

    def Activated(self):
        mesh = selected_meshes()[0]
        doc = mesh.Document
        doc.openTransaction(self.menu)
        import ObjectsFem
        made = getattr(ObjectsFem, "make" + self.kind)(doc, mesh)
        doc.commitTransaction()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.getDocument(doc).setEdit(made.Name)


def show_worst_elements(mesh) -> list:
    """Highlight and zoom onto mesh's worst elements (the WorstElements preference), and
    list them in the report view; returns their lines."""
    from . import worst_elements as worst_module
    from .view_provider import show_worst

    count, _ = worst_module.preferences()
    worst = show_worst(mesh.ViewObject, count)
    if not worst:
        FreeCAD.Console.PrintWarning(f"TemplateQuad: {mesh.Label}: no element qualities; mesh it again\n")
        return []
    kind = "Solid" if mesh.FemMesh.VolumeCount else "Face"
    lines = worst_module.worst_lines(worst, list(mesh.ElementOwners), kind)
    FreeCAD.Console.PrintMessage(f"TemplateQuad: {mesh.Label}: the {len(lines)} worst element(s), highlighted: "
                                 + "; ".join(lines) + "\n")
    return lines


class ShowWorstCommand(OneMeshCommand):
    """The selected mesh's worst elements, highlighted and zoomed to."""

    def __init__(self):
        super().__init__("Show worst elements",
                         "Highlight the worst elements (lowest scaled Jacobian) of the selected TemplateQuad "
                         "mesh, zoom onto them and list them with their faces")

    def Activated(self):
        show_worst_elements(selected_meshes()[0])


def export_with_groups(mesh, path: str) -> None:
    """export_with_groups(): mesh's FemMesh with its groups as an Abaqus/CalculiX .inp
    (FemMesh.writeABAQUS: the highest-order elements, groups as *ELSET and *NSET),
    written beside `path` and renamed onto it, so a failure leaves no partial file.

    Raises:
        ValueError: the mesh is empty (not meshed yet, or its meshing failed).
    """
    import os
    import tempfile

    femmesh = mesh.FemMesh
    if femmesh.NodeCount == 0:
        raise ValueError(f"{mesh.Label} has no mesh to export; mesh it first")
    folder = os.path.dirname(os.path.abspath(path))
    handle, temporary = tempfile.mkstemp(prefix=".templatequad-", suffix=".inp", dir=folder)
    os.close(handle)
    try:
        femmesh.writeABAQUS(temporary, 1, True)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


class ExportGroupsCommand(OneMeshCommand):
    """The selected mesh and its groups to an .inp file."""

    def __init__(self):
        super().__init__("Export mesh with groups (.inp)",
                         "Write the selected TemplateQuad mesh to an Abaqus/CalculiX .inp file with its mesh "
                         "groups as element and node sets")

    def Activated(self):
        from PySide import QtGui

        mesh = selected_meshes()[0]
        path, _ = QtGui.QFileDialog.getSaveFileName(
            FreeCADGui.getMainWindow(), "Export mesh with groups", mesh.Label + ".inp",
            "Abaqus/CalculiX input (*.inp)")
        if not path:
            return
        try:
            export_with_groups(mesh, path)
        except (ValueError, OSError) as error:
            FreeCAD.Console.PrintError(f"TemplateQuad: {mesh.Label}: {error}\n")
            return
        FreeCAD.Console.PrintMessage(f"TemplateQuad: {mesh.Label} written to {path} with "
                                     f"{mesh.FemMesh.GroupCount} group(s)\n")


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
    FreeCADGui.addCommand(REGION_COMMAND, AddToMeshCommand(
        "MeshRegion", "Mesh region", "A FEM mesh region on the selected TemplateQuad mesh: its element "
        "size on the faces, edges and vertices it references", "FEM_MeshRegion"))
    FreeCADGui.addCommand(GROUP_COMMAND, AddToMeshCommand(
        "MeshGroup", "Mesh group", "A FEM mesh group on the selected TemplateQuad mesh: the elements "
        "and nodes of the faces, edges and vertices it references, as a named set",
        "FEM_MeshGroup"))
    FreeCADGui.addCommand(EXPORT_COMMAND, ExportGroupsCommand())
    FreeCADGui.addCommand(WORST_COMMAND, ShowWorstCommand())
