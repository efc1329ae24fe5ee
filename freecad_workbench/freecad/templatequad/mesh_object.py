"""The TemplateQuad FEM mesh object (App side; works in freecadcmd).

A ``Fem::FemMeshObjectPython`` whose proxy re-meshes its linked Part on every
recompute. Being a Fem::FemMeshObject is what makes the FEM workbench take it as the
analysis mesh (femtools.membertools.get_mesh_to_solve looks for that type), and the
``Part`` link is the property name the CalculiX writer reads when it needs the
geometry behind the mesh (femmesh.meshsetsgetter: ``Shape``, else ``Part``); the
constraints themselves find their nodes geometrically (FemMesh.getNodesByEdge), which
works because the nodes lie on the CAD edges, in global coordinates.

Properties (group "TemplateQuad"):
    Part         link to the meshed Part feature (anything with a Shape)
    Faces        FreeCAD face names to mesh ("Face3", ...); empty = all faces
    Size         target edge length; 0 = automatic (bounding-box diagonal / 25)
    Corners      "FACE:V1,V2,..." entries overriding the automatic corners
    T4Ratio      the k of the T4 template test (k C <= A and k C <= B), >= 2
    KeepGoing    mesh the other faces when one is refused
Outputs (read-only, group "TemplateQuad results"):
    TemplateTrees, RefusedFaces, Quality
"""
import FreeCAD

from .stateless_proxy import StatelessProxy
from . import meshing

GROUP = "TemplateQuad"
RESULT_GROUP = "TemplateQuad results"

# PropertyType flags of App::Property: read-only in the editor, and an output, i.e.
# setting it does not touch the object (else every recompute would leave it touched).
_OUTPUT = 1 | 8

_INPUTS = (
    ("App::PropertyLink", "Part", "The Part feature (any object with a Shape) to mesh"),
    ("App::PropertyStringList", "Faces",
     "Faces to mesh, as FreeCAD names (Face1, Face3, ...); empty meshes all faces"),
    ("App::PropertyLength", "Size",
     "Target edge length; 0 = automatic (bounding-box diagonal / 25)"),
    ("App::PropertyStringList", "Corners",
     "Corner overrides, one per face: FACE:V1,V2,... with 2 to 4 vertices where the "
     "face's curves begin, as FreeCAD names (Face4:Vertex1,Vertex5,Vertex8) or 0-based "
     "tquad indices (3:0,4,7)"),
    ("App::PropertyInteger", "T4Ratio",
     "The k of the T4 template test k*C <= A and k*C <= B (at least 2)"),
    ("App::PropertyBool", "KeepGoing",
     "Mesh the other faces when one is refused (refused faces are listed in RefusedFaces)"),
    ("App::PropertyBool", "Smooth",
     "Move interior nodes on each face's surface to better-shaped quads (never lowering "
     "the worst corner around a node)"),
    ("App::PropertyBool", "BestCorners",
     "Try more corner sets (2, 3 or 4 curves) on every face without holes and without a "
     "Corners override, and keep the best worst, then mean, element quality (slower)"),
)
# Values of new properties, for new objects and for files saved before they existed
# (so those files mesh as they did).
_DEFAULTS = {"T4Ratio": 2, "Smooth": True, "BestCorners": False}
_OUTPUTS = (
    ("App::PropertyStringList", "TemplateTrees", "Template tree of each meshed face"),
    ("App::PropertyStringList", "RefusedFaces", "Faces not meshed, with the reason"),
    ("App::PropertyString", "Quality", "Element count and quality summary"),
)


def add_properties(obj) -> None:
    """add_properties(): add the properties obj lacks (new objects and older files)."""
    for prop_type, name, doc in _INPUTS:
        if not hasattr(obj, name):
            obj.addProperty(prop_type, name, GROUP, doc)
            if name in _DEFAULTS:
                setattr(obj, name, _DEFAULTS[name])
    for prop_type, name, doc in _OUTPUTS:
        if not hasattr(obj, name):
            obj.addProperty(prop_type, name, RESULT_GROUP, doc, _OUTPUT)


class TemplateQuadMesh(StatelessProxy):
    """Proxy of a Fem::FemMeshObjectPython that meshes obj.Part with tquad."""

    #: Read by FEM's femutils.type_of_obj; must not start with "Fem::" (those are FEM's).
    Type = "TemplateQuad::Mesh"

    def __init__(self, obj):
        obj.Proxy = self
        add_properties(obj)
        self.last_error = ""

    def onDocumentRestored(self, obj):
        add_properties(obj)

    def execute(self, obj):
        """Re-mesh: obj.Part's shape -> tquad -> obj.FemMesh, outputs, report view.

        On failure the mesh is emptied (a stale mesh must not reach a solver), the
        reason is printed and kept in ``last_error``, and the exception propagates so
        FreeCAD marks the object invalid.
        """
        self.last_error = ""
        try:
            shape = self._source_shape(obj)
            mesh = meshing.mesh_shape(shape, size=obj.Size.Value,
                                      faces=meshing.parse_faces(obj.Faces),
                                      corners=meshing.parse_corners(obj.Corners),
                                      t4_ratio=obj.T4Ratio, keep_going=obj.KeepGoing,
                                      smooth=obj.Smooth, best_corners=obj.BestCorners)
        except meshing.TquadMissing as error:
            self.last_error = str(error).strip()
            self._clear(obj)
            FreeCAD.Console.PrintError(self.last_error + "\n")
            raise
        except ValueError as error:
            self.last_error = meshing.explain_tquad_error(str(error).strip())
            self._clear(obj)
            FreeCAD.Console.PrintError(f"TemplateQuad: {obj.Label}: {self.last_error}\n")
            raise

        obj.FemMesh = meshing.to_femmesh(mesh)
        obj.TemplateTrees = meshing.template_tree_lines(mesh)
        obj.RefusedFaces = meshing.refused_face_lines(mesh)
        obj.Quality = meshing.quality_summary(mesh)
        for line in obj.RefusedFaces:
            FreeCAD.Console.PrintWarning(
                f"TemplateQuad: {obj.Label}: {obj.Part.Label} {line} (not meshed)\n")

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
        obj.Quality = ""

