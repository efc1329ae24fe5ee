"""The TemplateQuad FEM mesh object (App side; works in freecadcmd).

A ``Fem::FemMeshObjectPython`` whose proxy meshes its linked Part when asked
(``request_mesh``: the task panel's OK, the "Mesh again" command, ``make_mesh``), as
FreeCAD's Gmsh object does; a recompute for any other reason (the part or a setting
changed) leaves the mesh as it is and marks it ``OutOfDate``, which a solver's check
refuses (solver_guard). Being a Fem::FemMeshObject is what makes the FEM workbench take it as the
analysis mesh (femtools.membertools.get_mesh_to_solve looks for that type), and the
``Part`` link is the property name the CalculiX writer reads when it needs the
geometry behind the mesh (femmesh.meshsetsgetter: ``Shape``, else ``Part``); the
constraints themselves find their nodes geometrically (FemMesh.getNodesByEdge), which
works because the nodes lie on the CAD edges, in global coordinates.

Properties (group "TemplateQuad"; the size and order names are those of FreeCAD's
Gmsh mesh object, where they mean the same):
    Part                     link to the meshed Part feature (anything with a Shape)
    Faces                    FreeCAD face names to mesh ("Face3", ...); empty = all
    CharacteristicLengthMax  element size; 0 = automatic (bounding-box diagonal / 25)
    CharacteristicLengthMin  the element size never goes below it (0 = no floor)
    ElementOrder             "1st" (4-node quads) or "2nd" (8-node quads, their edge
                             middles on the curves and surfaces)
    Smooth                   optimize node positions on the surfaces
    BestCorners              search more corner choices per face (slower)
    Corners                  "FACE:V1,V2,..." entries overriding the automatic corners
    Sew                      join faces that touch without sharing their edge first
    MeshRegionList           FEM mesh regions: local sizes on faces, edges, vertices
    MeshGroupList            FEM mesh groups: named element and node sets of the mesh
    GroupsOfNodes            a group's faces (solids in 3D) give a node set too
    MeshSizeFromCurvature    the fewest element edges per full turn of a curved edge
    GrowthRate               the most neighbouring element edges differ in length
    KeepGoing                mesh the other faces when one is refused
    ElementDimension         "2D" (quads on the faces) or "3D" (hexahedra swept through
                             the solids that are extrusions or partial revolutions)
    Layers                   3D: hexahedra from source to target (0 = from the size)
    AcceptIncomplete         let the CalculiX solver run on a mesh with refused faces
    T4Ratio                  (advanced) the k of the T4 template test
Outputs (read-only, group "TemplateQuad results"):
    Quality (one summary line), ElementSizeUsed, ScaledJacobianMin and Mean,
    QualityHistogram, Incomplete, UnsewnEdges,
    RefusedFaceNames, RefusedFaces (with the reasons), TemplateTrees
"""
import FreeCAD

from .stateless_proxy import StatelessProxy
from . import meshing, solver_guard

GROUP = "TemplateQuad"
RESULT_GROUP = "TemplateQuad results"

# PropertyType flags of App::Property: read-only in the editor, and an output, i.e.
# setting it does not touch the object (else every recompute would leave it touched).
_OUTPUT = 1 | 8

_INPUTS = (
    ("App::PropertyLink", "Part", "The Part feature (any object with a Shape) to mesh"),
    ("App::PropertyStringList", "Faces",
     "Faces to mesh, as FreeCAD names (Face1, Face3, ...); empty meshes all faces"),
    ("App::PropertyLength", "CharacteristicLengthMax",
     "Element size: the target edge length; 0 = automatic (bounding-box diagonal / 25)"),
    ("App::PropertyLength", "CharacteristicLengthMin",
     "The element size never goes below this (0 = no floor); short or strongly curved "
     "edges may still get shorter elements"),
    ("App::PropertyEnumeration", "ElementOrder",
     "Element order: 1st (4-node quadrilaterals, S4 shells in CalculiX) or 2nd (8-node "
     "quadrilaterals, a node in the middle of each edge on the part's curves and surfaces)"),
    ("App::PropertyBool", "Smooth",
     "Move interior nodes on each face's surface to better-shaped quads (never lowering "
     "the worst corner around a node)"),
    ("App::PropertyBool", "BestCorners",
     "Try more corner sets (2, 3 or 4 curves) on every face without a Corners override "
     "(the face's own when it has no holes, and each poor patch's of its decomposition), "
     "and keep the best worst, then mean, element quality (slower)"),
    ("App::PropertyStringList", "Corners",
     "Corner overrides, one per face: FACE:V1,V2,... with 2 to 4 vertices where the "
     "face's curves begin, as FreeCAD names (Face4:Vertex1,Vertex5,Vertex8) or 0-based "
     "tquad indices (3:0,4,7)"),
    ("App::PropertyBool", "Sew",
     "Join faces that touch without sharing their edge (an IGES import of trimmed "
     "surfaces) before meshing, so the mesh is connected there; off, such faces are "
     "meshed each on its own edge"),
    ("App::PropertyBool", "KeepGoing",
     "Mesh the other faces when one is refused (refused faces are listed in RefusedFaces "
     "and the mesh is marked Incomplete)"),
    ("App::PropertyBool", "AcceptIncomplete",
     "Let the CalculiX solver run on this mesh although faces were refused (it has holes "
     "there); off, the solver's check stops with the refused faces' names"),
    ("App::PropertyInteger", "T4Ratio",
     "Advanced: the k of the T4 template test k*C <= A and k*C <= B (at least 2)"),
    ("App::PropertyEnumeration", "ElementDimension",
     "2D: quadrilateral shells on the part's faces; 3D: hexahedra, each solid that is an "
     "extrusion or a partial revolution swept from a face (C3D8, or C3D20 at 2nd order)"),
    ("App::PropertyInteger", "Layers",
     "3D: hexahedra through each solid from its source face to its target (0 = from the "
     "element size)"),
    ("App::PropertyLinkList", "MeshRegionList",
     "FEM mesh regions (FEM > Mesh region): each one's CharacteristicLength on the faces, "
     "edges and vertices of the part it references"),
    ("App::PropertyLinkList", "MeshGroupList",
     "FEM mesh groups (FEM > Mesh group): each one's faces (solids in 3D) become an element "
     "group named after it, its edges and vertices a node group, written as *ELSET and *NSET "
     "(TemplateQuad > Export mesh with groups)"),
    ("App::PropertyBool", "GroupsOfNodes",
     "Mesh groups of faces (solids in 3D) get a node group of their nodes too"),
    ("App::PropertyInteger", "MeshSizeFromCurvature",
     "The fewest element edges a curved edge gets per full turn of its curve (8 to 1000; "
     "8 is one per 45 degrees)"),
    ("App::PropertyFloat", "GrowthRate",
     "The most one element edge may be longer than its neighbour where mesh regions make "
     "sizes differ (over 1, at most 10)"),
)
#: The dimensions ElementDimension offers (FreeCAD's Gmsh object has the same names).
ELEMENT_DIMENSIONS = ["2D", "3D"]
#: The orders ElementOrder offers (FreeCAD's Gmsh object spells them the same way).
ELEMENT_ORDERS = ["1st", "2nd"]
# Values of new properties, for new objects and for files saved before they existed
# (so those files mesh as they did).
_DEFAULTS = {"GroupsOfNodes": False, "T4Ratio": 2, "Smooth": True, "BestCorners": False, "Sew": False, "Layers": 0, "GrowthRate": 1.3,
             "MeshSizeFromCurvature": 8}
ELEMENT_QUALITY = "ElementQuality"
_OUTPUTS = (
    ("App::PropertyString", "Quality", "Element count and quality, one line"),
    ("App::PropertyLength", "ElementSizeUsed",
     "The element size the mesh was made with (the automatic one when the size is 0)"),
    ("App::PropertyFloat", "ScaledJacobianMin", "The worst quad's scaled Jacobian (1 = a square)"),
    ("App::PropertyFloat", "ScaledJacobianMean", "The mean scaled Jacobian of the quads"),
    ("App::PropertyIntegerList", "QualityHistogram",
     "Quads per scaled Jacobian band: below 0, then [0, 0.1) ... [0.9, 1]"),
    ("App::PropertyBool", "Incomplete", "Faces were refused: the mesh has holes there"),
    ("App::PropertyBool", "OutOfDate",
     "The part or a setting changed since the mesh was made: mesh again (double-click the "
     "mesh and press OK, or TemplateQuad > Mesh again)"),
    ("App::PropertyInteger", "UnsewnEdges",
     "Pairs of edges where faces touch without sharing the edge: the mesh is not "
     "connected along them (Sew joins them)"),
    ("App::PropertyStringList", "RefusedFaceNames", "The refused faces (Face28, ...)"),
    ("App::PropertyStringList", "RefusedFaces", "Faces not meshed, with the reason"),
    ("App::PropertyStringList", "TemplateTrees", "Template tree of each meshed face"),
    ("App::PropertyFloatList", ELEMENT_QUALITY,
     "Scaled Jacobian of each quad, in element order: the quality colour map's values"),
    ("App::PropertyIntegerList", "ElementOwners",
     "(face, first element, count) per meshed face, or per swept solid in 3D, flat and 0-based"),
)
#: A million values are no list to show in the property editor: saved, not shown.
_HIDDEN_OUTPUTS = (ELEMENT_QUALITY, "ElementOwners")


def _owners(records, owner: str, first: str, count: str):
    """ElementOwners from tquad's face or solid records, in element order."""
    rows = sorted((r[first], r[owner], r[count]) for r in records)
    return [int(v) for start, index, n in rows for v in (index, start, n)]


def _face_names_problem(obj):
    """Faces: a name that is not a face, or a face the part does not have."""
    faces = meshing.parse_faces(obj.Faces) or []
    count = len(obj.Part.Shape.Faces) if obj.Part is not None and hasattr(obj.Part, "Shape") else None
    for f in faces:
        if count is not None and f >= count:
            return f"Faces: Face{f + 1} does not exist; the part has Face1..Face{count}"
    return None


def _corner_problem(obj):
    meshing.parse_corners(obj.Corners)
    return None


_SIZES = ("CharacteristicLengthMax", "CharacteristicLengthMin")

# Inputs checked as they are set (onChanged): each gives the reason a value is wrong,
# or None; a wrong value is put back to the one before it.
_CHECKS = {
    "T4Ratio": lambda obj: (None if obj.T4Ratio >= 2 else
                            f"T4Ratio {obj.T4Ratio}: the k of the T4 template test k*C <= A and "
                            f"k*C <= B must be at least 2"),
    "Layers": lambda obj: None if obj.Layers >= 0 else
    f"Layers {obj.Layers}: 0 (layers from the element size) or more",
    "MeshSizeFromCurvature": lambda obj: None if 8 <= obj.MeshSizeFromCurvature <= 1000 else
    f"MeshSizeFromCurvature {obj.MeshSizeFromCurvature}: 8 (one element edge per 45 degrees) to 1000",
    "GrowthRate": lambda obj: None if 1.0 < obj.GrowthRate <= 10.0 else
    f"GrowthRate {obj.GrowthRate:g}: over 1 and at most 10",
    "Faces": _face_names_problem,
    "Corners": _corner_problem,
}


def _migrate_size(obj) -> None:
    """Files saved before the Gmsh-style names had a "Size" property: keep its value."""
    if "Size" in obj.PropertiesList and "CharacteristicLengthMax" in obj.PropertiesList:
        obj.CharacteristicLengthMax = obj.Size
        obj.removeProperty("Size")


def _offer_every_dimension(obj) -> None:
    """Keep ElementDimension's choices those of this version, keeping the value."""
    if list(obj.getEnumerationsOfProperty("ElementDimension")) != ELEMENT_DIMENSIONS:
        value = obj.ElementDimension
        obj.ElementDimension = ELEMENT_DIMENSIONS
        obj.ElementDimension = value if value in ELEMENT_DIMENSIONS else ELEMENT_DIMENSIONS[0]


def _offer_every_order(obj) -> None:
    """Files saved when only "1st" was offered: offer "2nd" too, keeping the value."""
    if list(obj.getEnumerationsOfProperty("ElementOrder")) != ELEMENT_ORDERS:
        value = obj.ElementOrder
        obj.ElementOrder = ELEMENT_ORDERS
        obj.ElementOrder = value if value in ELEMENT_ORDERS else ELEMENT_ORDERS[0]


def _order_number(value: str) -> int:
    """An ElementOrder value as tquad's order (1 or 2)."""
    return 2 if value == "2nd" else 1


def _length(value) -> float:
    """A length property's value in mm (a Quantity, or a number in scripts)."""
    return float(getattr(value, "Value", value))


#: Each keyword of tquad.mesh_shape the object offers: the property it comes from
#: (the options schema's "freecad" column, tquad.mesh_option_schema()) and how its
#: value becomes the keyword's. The one place the mesh object's inputs meet the
#: module's options; tests/freecad/test_headless.py checks this table against the
#: schema, the object's defaults against the schema's, and that this,
#: OPTIONS_NOT_OFFERED and FREECAD_ONLY_PROPERTIES cover every keyword and input.
OPTION_PROPERTIES = {
    "size": ("CharacteristicLengthMax", _length),
    "min_size": ("CharacteristicLengthMin", _length),
    "faces": ("Faces", meshing.parse_faces),
    "corners": ("Corners", meshing.parse_corners),
    "t4_ratio": ("T4Ratio", int),
    "smooth": ("Smooth", bool),
    "best_corners": ("BestCorners", bool),
    "order": ("ElementOrder", _order_number),
    "sew": ("Sew", bool),
    "sizes": ("MeshRegionList", meshing.region_sizes),
    "curvature_segments": ("MeshSizeFromCurvature", int),
    "growth_rate": ("GrowthRate", float),
}

#: Input properties of the object that are not options of tquad.mesh_shape, and why.
FREECAD_ONLY_PROPERTIES = {
    "Part": "what is meshed: its Shape goes to tquad as BREP text",
    "ElementDimension": "2D meshes the faces (tquad.mesh_shape), 3D sweeps the solids (tquad.sweep_shape)",
    "Layers": "tquad.sweep_shape's layers",
    "KeepGoing": "whether refused faces fail the recompute or leave an Incomplete mesh",
    "AcceptIncomplete": "whether a solver may run on an Incomplete mesh",
    "MeshGroupList": "named sets of the finished mesh's elements and nodes (FemMesh groups)",
    "GroupsOfNodes": "whether a mesh group's faces or solids give a node set too",
}

#: The keywords of tquad.mesh_shape the object does not offer as properties, and why.
OPTIONS_NOT_OFFERED = {
    "brep_text_or_path": "the linked Part's shape, sent as BREP text",
    "keep_going": "always on: refused faces come back as records and KeepGoing decides",
    "allow_inverted": "a FEM mesh never takes inverted, degenerate, folded or collapsed quads",
    "threads": "all cores",
    "t5_cut_edges": "chosen per region from its geometry",
    "max_quads": "the module's limit",
    "progress": "the progress dialog and its Cancel button",
    "read_timeout": "the module's default, scaled to the shape",
}


def mesh_options(obj) -> dict:
    """The keywords of tquad.mesh_shape from the object's properties (OPTION_PROPERTIES)."""
    return {keyword: convert(getattr(obj, name)) for keyword, (name, convert) in OPTION_PROPERTIES.items()}


def add_properties(obj) -> None:
    """add_properties(): add the properties obj lacks (new objects and older files)."""
    for prop_type, name, doc in _INPUTS:
        if not hasattr(obj, name):
            obj.addProperty(prop_type, name, GROUP, doc)
            if name == "ElementOrder":
                obj.ElementOrder = ELEMENT_ORDERS
            if name == "ElementDimension":
                obj.ElementDimension = ELEMENT_DIMENSIONS
            if name in _DEFAULTS:
                setattr(obj, name, _DEFAULTS[name])
    _migrate_size(obj)
    _offer_every_order(obj)
    _offer_every_dimension(obj)
    for prop_type, name, doc in _OUTPUTS:
        if not hasattr(obj, name):
            obj.addProperty(prop_type, name, RESULT_GROUP, doc, _OUTPUT)
    for name in _HIDDEN_OUTPUTS:
        obj.setEditorMode(name, 2)  # hidden (the editor mode is not saved: set on restore too)


#: Above this many elements a new mesh is handed to FreeCAD's view hidden (_set_femmesh).
_HIDE_WHILE_BUILDING = 100_000


class _NoDialog:
    """HandOver without a GUI: every step goes on."""

    @staticmethod
    def step(what: str) -> bool:
        return True

    @staticmethod
    def close():
        pass


def _hand_over(obj, quads: int):
    """The hand-over's steps: beside a dialog in the GUI (progress_dialog.HandOver)."""
    if not FreeCAD.GuiUp:
        return _NoDialog()
    from .progress_dialog import HandOver
    return HandOver(f"{obj.Part.Label}: handing {quads:,} quads to FreeCAD", quads, 2)


class TemplateQuadMesh(StatelessProxy):
    """Proxy of a Fem::FemMeshObjectPython that meshes obj.Part with tquad."""

    #: Read by FEM's femutils.type_of_obj; must not start with "Fem::" (those are FEM's).
    Type = solver_guard.MESH_TYPE

    def __init__(self, obj):
        obj.Proxy = self
        add_properties(obj)
        self._reset_runtime_state()
        solver_guard.install()

    def onDocumentRestored(self, obj):
        add_properties(obj)
        self._reset_runtime_state()
        self._remember_meshed_inputs(obj)  # the saved mesh was made with the saved inputs
        solver_guard.install()

    def _reset_runtime_state(self):
        """What the proxy knows between recomputes and never saves (StatelessProxy)."""
        self.last_error = ""
        self.cancelled = False
        self.meshed_inputs = None  # the inputs the current mesh was made with
        self.mesh_requested = False  # set by request_mesh for the recompute it starts

    def onBeforeChange(self, obj, prop):
        if prop in _CHECKS:
            self._value_before = (prop, getattr(obj, prop, None))

    def onChanged(self, obj, prop):
        """A wrong input is said when it is set, in one line, and put back; the sizes'
        order (minimum over maximum) is only warned about, since a script may set the
        other next."""
        if getattr(obj.Document, "Restoring", False) or prop not in _CHECKS and prop not in _SIZES:
            return
        if prop in _SIZES:
            high, low = obj.CharacteristicLengthMax.Value, obj.CharacteristicLengthMin.Value
            if high > 0 and low > high:
                FreeCAD.Console.PrintWarning(
                    f"TemplateQuad: {obj.Label}: the minimum element size ({low:g} mm) is larger than "
                    f"the element size ({high:g} mm): meshing will refuse it\n")
            return
        try:
            reason = _CHECKS[prop](obj)
        except ValueError as error:
            reason = str(error)
        if reason is None:
            return
        self.last_error = reason
        before = getattr(self, "_value_before", None)
        self._value_before = None
        if before is not None and before[0] == prop and before[1] is not None:
            setattr(obj, prop, before[1])
            reason += f"; kept {before[1]!r}"
        FreeCAD.Console.PrintError(f"TemplateQuad: {obj.Label}: {reason}\n")

    def request_mesh(self, obj):
        """Mesh obj now (a recompute of its document); the outcome is in the object
        (its mesh and outputs) and in ``last_error`` and ``cancelled``."""
        self.mesh_requested = True
        try:
            obj.touch()
            obj.Document.recompute()
        finally:
            self.mesh_requested = False

    def execute(self, obj):
        """Mesh when asked (request_mesh); any other recompute marks the mesh out of date.

        Meshing: obj.Part's shape -> tquad -> obj.FemMesh, outputs, report view.

        On a user's error (a refused part, a bad setting, tquad missing) the mesh is
        emptied (a stale mesh must not reach a solver), the reason is printed once, as
        one line naming FreeCAD's objects, and kept in ``last_error`` and the Quality
        property; nothing is raised, since FreeCAD prints a raised error's whole Python
        traceback (``make_mesh`` and the GUI commands read ``last_error``). Anything
        else is a fault of the add-on and propagates with its traceback. Cancelled by
        the user (GUI), everything is left as it was and ``cancelled`` is set; the
        caller restores the inputs.
        """
        if not getattr(self, "mesh_requested", False):
            self._mark_out_of_date(obj)
            return
        self.mesh_requested = False  # one mesh per request, whatever recomputes follow
        try:
            self._execute(obj)
        finally:
            meshing.return_memory()

    def _execute(self, obj):
        """execute()'s meshing, once asked."""
        self.last_error = ""
        self.cancelled = False
        if getattr(obj, "ElementDimension", "2D") == "3D":
            self._sweep(obj)
            return
        try:
            groups = meshing.mesh_groups(obj.MeshGroupList)
            mesh = self._mesh(obj)
            if mesh is None:  # the user cancelled: the mesh and its inputs stay as they were
                self._cancel(obj)
                return
            if mesh.refused_faces and not obj.KeepGoing:
                raise ValueError(meshing.refusal_error(mesh))
            hand = _hand_over(obj, len(mesh.quads))
            try:
                if not hand.step("reading the mesh"):
                    self._cancel(obj)
                    return
                femmesh = meshing.to_femmesh(mesh)
                group_warnings = meshing.add_face_mesh_groups(femmesh, mesh, obj.Part.Shape, groups,
                                                              obj.GroupsOfNodes)
                if not hand.step("copying it into the object and building its view"):
                    self._cancel(obj)
                    return
                self._set_femmesh(obj, femmesh, len(mesh.quads))
            finally:
                hand.close()
        except (meshing.TquadMissing, ValueError) as error:
            self._fail(obj, error)
            return

        obj.TemplateTrees = meshing.template_tree_lines(mesh)
        obj.RefusedFaces = meshing.refused_face_lines(mesh)
        obj.RefusedFaceNames = meshing.refused_face_names(mesh)
        obj.Incomplete = bool(mesh.refused_faces)
        obj.OutOfDate = False
        obj.UnsewnEdges = len(mesh.unsewn_edge_pairs)
        obj.Quality = meshing.quality_summary(mesh)
        obj.ScaledJacobianMin = float(mesh.quality["scaled_jacobian"]["min"])
        obj.ScaledJacobianMean = float(mesh.quality["scaled_jacobian"]["avg"])
        obj.QualityHistogram = [int(n) for n in mesh.quality["jacobian_histogram"]]
        obj.ElementSizeUsed = float(mesh.edge_size or 0.0)
        obj.ElementQuality = mesh.scaled_jacobian.tolist()  # a numpy array
        obj.ElementOwners = _owners(mesh.faces, "face", "first_quad", "quad_count")
        self._remember_meshed_inputs(obj)
        for line in obj.RefusedFaces:
            FreeCAD.Console.PrintWarning(
                f"TemplateQuad: {obj.Label}: {obj.Part.Label} {line} (not meshed)\n")
        unsewn = meshing.unsewn_warning(obj.UnsewnEdges, obj.Sew)
        if unsewn:
            FreeCAD.Console.PrintWarning(f"TemplateQuad: {obj.Label}: {obj.Part.Label}: {unsewn}\n")
        oversized = meshing.size_warning(mesh)
        if oversized:
            FreeCAD.Console.PrintWarning(f"TemplateQuad: {obj.Label}: {obj.Part.Label}: {oversized}\n")
        turned, disagreeing = meshing.orientation_messages(mesh)
        if turned:
            FreeCAD.Console.PrintMessage(f"TemplateQuad: {obj.Label}: {obj.Part.Label}: {turned}\n")
        if disagreeing:
            FreeCAD.Console.PrintWarning(f"TemplateQuad: {obj.Label}: {obj.Part.Label}: {disagreeing}\n")
        absorbed = meshing.absorbed_message(mesh)
        if absorbed:
            FreeCAD.Console.PrintMessage(f"TemplateQuad: {obj.Label}: {obj.Part.Label}: {absorbed}\n")
        for line in group_warnings:
            FreeCAD.Console.PrintWarning(f"TemplateQuad: {obj.Label}: {line}\n")

    def _cancel(self, obj):
        """The user cancelled: the mesh kept, and the inputs it was made with put back."""
        self.cancelled = True
        self._restore_meshed_inputs(obj)

    @staticmethod
    def _set_femmesh(obj, femmesh, elements: int):
        """obj.FemMesh = femmesh. A large mesh is hidden while FreeCAD's view provider
        rebuilds its view: shown, the view is drawn again during the rebuild, which
        takes about half as long again (bench/GUI_CANCEL.md)."""
        vobj = getattr(obj, "ViewObject", None) if FreeCAD.GuiUp else None
        shown = vobj is not None and vobj.Visibility and elements > _HIDE_WHILE_BUILDING
        if shown:
            vobj.Visibility = False
        try:
            obj.FemMesh = femmesh
        finally:
            if shown:
                vobj.Visibility = True

    def _sweep(self, obj):
        """ElementDimension 3D: the part's solids swept into hexahedra -> obj.FemMesh.

        Solids tquad cannot sweep are listed in RefusedFaces ("Solid2: ...") and make
        the mesh Incomplete; without KeepGoing they fail the recompute. Errors as
        execute's."""
        try:
            groups = meshing.mesh_groups(obj.MeshGroupList)
            shape = self._source_shape(obj)
            swept = meshing.sweep_shape(shape, size=obj.CharacteristicLengthMax.Value,
                                        min_size=obj.CharacteristicLengthMin.Value, layers=obj.Layers,
                                        smooth=obj.Smooth, order=2 if obj.ElementOrder == "2nd" else 1)
            if swept.refused_solids and not obj.KeepGoing:
                raise ValueError("%d solid(s) not swept: %s. Turn on 'Mesh the other faces' (KeepGoing) "
                                 "to sweep the rest." % (len(swept.refused_solids),
                                                         "; ".join(meshing.refused_solid_lines(swept))))
            femmesh = meshing.to_femmesh_volumes(swept)
            group_warnings = meshing.add_solid_mesh_groups(femmesh, swept, shape, groups, obj.GroupsOfNodes)
        except (meshing.TquadMissing, ValueError) as error:
            self._fail(obj, error)
            return
        self._set_femmesh(obj, femmesh, len(swept.hexes))
        for line in group_warnings:
            FreeCAD.Console.PrintWarning(f"TemplateQuad: {obj.Label}: {line}\n")
        obj.TemplateTrees = [meshing.swept_solid_line(s) for s in swept.solids]
        for face in getattr(swept, "unshared_faces", []):
            FreeCAD.Console.PrintWarning(
                f"TemplateQuad: {obj.Label}: Face{face + 1} is shared by two swept solids whose nodes there "
                "differ: the mesh does not conform across it\n")
        obj.RefusedFaces = meshing.refused_solid_lines(swept)
        obj.RefusedFaceNames = []
        obj.Incomplete = bool(swept.refused_solids)
        obj.OutOfDate = False
        obj.UnsewnEdges = 0
        obj.Quality = meshing.swept_summary(swept)
        sj = swept.scaled_jacobian
        obj.ScaledJacobianMin = float(sj.min())
        obj.ScaledJacobianMean = float(sj.mean())
        import numpy
        bands, _ = numpy.histogram(numpy.clip(sj[sj >= 0], 0, 1), bins=numpy.linspace(0, 1, 11))
        obj.QualityHistogram = [int((sj < 0).sum())] + [int(n) for n in bands]
        obj.ElementSizeUsed = float(swept.edge_size)
        obj.ElementQuality = sj.tolist()
        obj.ElementOwners = _owners(swept.solids, "solid", "first_hex", "hex_count")
        self._remember_meshed_inputs(obj)
        for line in obj.RefusedFaces:
            FreeCAD.Console.PrintWarning(f"TemplateQuad: {obj.Label}: {obj.Part.Label} {line} (not swept)\n")

    def _fail(self, obj, error):
        """A user's error (tquad's ValueError, or the module missing): the mesh emptied,
        the reason kept (``last_error``, Quality) and printed once as one line."""
        text = str(error).strip()
        reason = text if isinstance(error, meshing.TquadMissing) else meshing.explain_tquad_error(text)
        self.last_error = reason
        self._clear(obj)
        self.meshed_inputs = None
        obj.Quality = f"not meshed: {reason}"
        FreeCAD.Console.PrintError(f"TemplateQuad: {obj.Label}: {reason}\n")

    def _mark_out_of_date(self, obj):
        """A recompute nobody asked to mesh: the part or a setting changed. The mesh
        stays (a large one is not thrown away for a touch) and is marked, once in the
        report view; the solver checks refuse it until it is meshed again."""
        if obj.OutOfDate:
            return
        obj.OutOfDate = True
        part = obj.Part.Label if obj.Part is not None else "its part"
        FreeCAD.Console.PrintWarning(
            f"TemplateQuad: {obj.Label}: {part} or a setting changed; the mesh is out of date. "
            "Mesh again: double-click the mesh and press OK, or TemplateQuad > Mesh again.\n")

    def _remember_meshed_inputs(self, obj):
        """The inputs the current mesh was made with (restored by a cancelled re-mesh)."""
        self.meshed_inputs = {name: getattr(obj, name) for _, name, _ in _INPUTS}

    def _restore_meshed_inputs(self, obj):
        """A cancelled re-mesh (from the panel, the property editor or a script) puts
        back the inputs of the mesh kept, so the object never shows inputs its mesh was
        not made with. A new object has none: its creator removes it."""
        for name, value in (getattr(self, "meshed_inputs", None) or {}).items():
            if getattr(obj, name) != value:
                setattr(obj, name, value)

    def _mesh(self, obj):
        """The tquad mesh of the linked part (None when the user cancelled it).

        Refused faces come back as records whatever KeepGoing says; execute() decides.
        In the GUI the work runs beside a progress dialog with a Cancel button.
        """
        shape = self._source_shape(obj)
        run = meshing.run_plain
        if FreeCAD.GuiUp:
            from .progress_dialog import confirm_large_run, run_with_progress
            # A run above the preference's estimate asks first; No is a cancel.
            quads, memory = meshing.estimated_run(shape, obj.CharacteristicLengthMax.Value)
            if not confirm_large_run(obj.Part.Label, quads, memory):
                return None
            run = run_with_progress
        options = mesh_options(obj)
        return run(lambda progress: meshing.mesh_shape(shape, keep_going=True, progress=progress, **options),
                   f"Meshing {obj.Part.Label}")

    @staticmethod
    def _source_shape(obj):
        """The shape to mesh; ValueError with a user message when there is none."""
        part = obj.Part
        if part is None:
            raise ValueError("no Part is linked; set the Part property")
        shape = getattr(part, "Shape", None)
        if shape is None or shape.isNull() or not shape.Faces:
            raise ValueError(f"{part.Label} has no faces to mesh")
        return shape

    @staticmethod
    def _clear(obj):
        import Fem
        obj.FemMesh = Fem.FemMesh()
        obj.TemplateTrees = []
        obj.RefusedFaces = []
        obj.RefusedFaceNames = []
        obj.Incomplete = False
        obj.OutOfDate = False
        obj.UnsewnEdges = 0
        obj.Quality = ""
        obj.QualityHistogram = []
        obj.ElementQuality = []
        obj.ElementOwners = []
        obj.ScaledJacobianMin = obj.ScaledJacobianMean = 0.0
        obj.ElementSizeUsed = 0.0
