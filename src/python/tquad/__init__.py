"""TemplateQuad: all-quadrilateral meshes by hierarchical templates.

    >>> import tquad
    >>> m = tquad.mesh_boundary(points, corners=[0, 10, 20, 30])
    >>> m.nodes.shape, m.quads.shape, m.template_trees
    >>> s = tquad.mesh_shape("part.step", size=2.0, keep_going=True)

Wrong input raises ValueError with the message the command line would print; the
message names the face, edge, vertex, point or curve at fault.
"""
import numbers
import textwrap
from typing import Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core

#: Raised when mesh_shape's progress callback asks to stop.
Cancelled = _core.Cancelled

#: A ValueError raised by mesh_shape without keep_going when faces are refused; its
#: ``refused_faces`` attribute lists them as Mesh.refused_faces would.
FacesRefused = _core.FacesRefused

#: The ``code`` of a refused face, and what it means.
REFUSAL_CODES = {
    "cannot_mesh": "no meshing route gave a valid mesh (the reason says what failed)",
    "inverted_quads": "every mesh found keeps inverted, degenerate, folded or collapsed quads",
    "too_coarse": "too few boundary segments; a smaller element size gives it more",
    "not_supported": "a kind of face the mesher does not handle yet",
    "damaged": "the face's geometry is invalid",
    "internal": "the mesher itself failed (a bug)",
}

__all__ = ["Cancelled", "FacesRefused", "Mesh", "REFUSAL_CODES", "SweptMesh", "mesh_boundary",
           "mesh_option_schema", "mesh_shape", "sweep_shape"]

_MAX_QUADS = 100_000_000


def _integer(value, what: str, low: Optional[int] = None, high: Optional[int] = None) -> int:
    """`value` as an int when it is an integer (Python's or numpy's) within [low, high];
    ValueError naming `what` otherwise. A float (4.5, or 4.0), a string ('4') or a bool
    is refused, as the command line refuses it, rather than silently converted."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise ValueError("%s must be an integer, not %r" % (what, value))
    number = int(value)
    if (low is not None and number < low) or (high is not None and number > high):
        bounds = ("at least %d" % low if high is None else
                  "at most %d" % high if low is None else "between %d and %d" % (low, high))
        raise ValueError("%s must be %s, not %d" % (what, bounds, number))
    return number


def _template_integers(t4_ratio, t5_cut_edges, max_quads) -> Tuple[int, int, int]:
    """The template options as integers; the mesher checks their ranges (the T4
    ratio's message cites the paper), max_quads's lower bound is checked here."""
    return (_integer(t4_ratio, "t4_ratio"), _integer(t5_cut_edges, "t5_cut_edges"),
            _integer(max_quads, "max_quads", 1))


class Mesh:
    """A quad mesh of one boundary region (face 0) or of the faces of a shape.

    Attributes:
        nodes: float64 array, N x 3, node positions. For a boundary input the
            boundary points come first, bit-exact.
        quads: int32 array, M x 4, 0-based node indices, counter-clockwise seen from
            the face's outer normal (for a boundary, in the loop's orientation).
        faces: one dict per meshed face: ``face`` (index in the shape),
            ``template_tree`` (e.g. ``"T2[T0,T0,T1[T0,T0,T0,T0]]"``), ``first_quad``
            and ``quad_count`` (the face's quads are a contiguous range).
        refused_faces: one dict per face not meshed: ``face`` (0-based), ``code``
            (a key of REFUSAL_CODES, to act on without reading the message),
            ``reason`` (a message naming the face, 0-based) and ``vertices`` (the
            shape vertices on the face's outer wire, in order, 0-based).
        quality: ``lee_lo`` and ``scaled_jacobian`` (each ``min``, ``avg``,
            ``max``, ``std``), the ``inverted``, ``degenerate`` and ``collapsed``
            quad counts, and ``jacobian_histogram``: 11 counts, the quads below 0,
            then per tenth of the scaled Jacobian from [0, 0.1) to [0.9, 1].
        scaled_jacobian, lee_lo: float64 arrays, one value per quad (on a CAD
            face, the scaled Jacobian's corners are measured against the surface's
            outer normal).
        mid_nodes: second order (``order=2``) only, else None: int32 array, M x 4,
            the node in the middle of each quad's edges 0-1, 1-2, 2-3 and 3-0;
            ``quads`` then ``mid_nodes`` side by side are the 8-node quads in the
            order of VTK's quadratic quad and CalculiX's S8.
        edge_size: for a shape, the target edge length used.
        shape_diagonal: for a shape, its bounding-box diagonal (the automatic size
            is a 25th of it; a size above it gives each edge its fewest segments).
        changed_edges: for a shape, the edges whose counts changed by one so that
            every face's total is even: dicts ``edge``, ``from``, ``to``.
        unsewn_edge_pairs: for a shape, pairs of edges that lie on each other
            without being one edge (the file's faces are not sewn there): the mesh
            is not connected along them (``sew=True`` joins them).
        sewn_edges: for a shape meshed with ``sew=True``, the edges merged into
            their neighbours; else 0.
        turned_faces: for a shape, faces outside solids whose quads were turned so
            that faces meeting at an edge agree on their normals (outward on a
            closed shell, else the larger area's side).
        orientation_conflicts: for a shape, pairs of faces meeting with normals
            that cannot agree (a one-sided shell, or solids' faces that disagree).
        read_warnings: for a shape file, what the reader read past without losing
            any of the shape (an entity's name written as ``$``), a line each.
        contracted_edges: for a shape, the edges far shorter than the size (under
            0.004 of it) whose two ends were made one node: a quad beside such an
            edge would be a triangle in effect.
        absorbed_faces: for a shape, the faces narrower than that everywhere (a
            strip: two long sides, short ends), which get no quads of their own:
            their ends are contracted and their two long sides share one row of
            nodes, so the faces beside them meet; dicts ``face``, ``width``,
            ``kept_edge``, ``merged_edge``.
        bad_quad_faces: for a shape meshed with ``allow_inverted=True``, the faces
            kept with inverted, degenerate, folded or collapsed quads (a corner's
            scaled Jacobian at or below 1e-6 against the surface normal or the
            quad's own, or a corner's Jacobian under 1/1000 of another's): dicts
            ``face``, ``quads``. Without it such faces are refused.
        collapsed_quad_faces: for a shape meshed with ``allow_inverted=True``, the
            faces kept with collapsed quads (a corner's Jacobian under 1/1000 of
            another corner's, its corners' angles sound: a triangle in effect),
            dicts ``face``, ``quads``; they are in ``bad_quad_faces`` too.
    """

    def __init__(self, data: dict):
        self.nodes: np.ndarray = data["nodes"]
        self.quads: np.ndarray = data["quads"]
        self.faces: List[dict] = data["faces"]
        self.refused_faces: List[dict] = data["refused_faces"]
        self.quality: dict = data["quality"]
        self.edge_size: Optional[float] = data.get("edge_size")
        self.shape_diagonal: Optional[float] = data.get("shape_diagonal")
        self.changed_edges: List[dict] = data.get("changed_edges", [])
        self.unsewn_edge_pairs: List[Tuple[int, int]] = data.get("unsewn_edge_pairs", [])
        self.sewn_edges: int = data.get("sewn_edges", 0)
        self.turned_faces: List[int] = data.get("turned_faces", [])
        self.orientation_conflicts: List[Tuple[int, int]] = data.get("orientation_conflicts", [])
        self.contracted_edges: List[int] = data.get("contracted_edges", [])
        self.absorbed_faces: List[dict] = data.get("absorbed_faces", [])
        self.bad_quad_faces: List[dict] = data.get("bad_quad_faces", [])
        self.collapsed_quad_faces: List[dict] = data.get("collapsed_quad_faces", [])
        self.read_warnings: List[str] = data.get("read_warnings", [])
        self.scaled_jacobian: np.ndarray = data["scaled_jacobian"]
        self.lee_lo: np.ndarray = data["lee_lo"]
        self.mid_nodes: Optional[np.ndarray] = data.get("mid_nodes")

    @property
    def template_trees(self) -> List[str]:
        """The template tree of each meshed face, in face order."""
        return [f["template_tree"] for f in self.faces]

    @property
    def template_tree(self) -> str:
        """The template tree of a one-face mesh (a boundary input)."""
        if len(self.faces) != 1:
            raise ValueError(f"the mesh has {len(self.faces)} faces; use template_trees")
        return self.faces[0]["template_tree"]

    def face_quads(self, face: int) -> np.ndarray:
        """The quads of one face of the shape (by its index in the shape)."""
        for f in self.faces:
            if f["face"] == face:
                return self.quads[f["first_quad"]:f["first_quad"] + f["quad_count"]]
        raise ValueError(f"face {face} is not in the mesh")

    def __repr__(self) -> str:
        return (f"Mesh({len(self.nodes)} nodes, {len(self.quads)} quads, "
                f"{len(self.faces)} faces, {len(self.refused_faces)} refused)")


def mesh_boundary(points, corners: Sequence[int], *, t4_ratio: int = 2,
                  t5_cut_edges: int = 0, max_quads: int = _MAX_QUADS, smooth: bool = True,
                  best_corners: bool = False) -> Mesh:
    """Mesh the region inside a closed boundary loop.

    Args:
        points: N x 3 (or N x 2) coordinates in order around the region; the loop
            closes itself (do not repeat the first point). N must be even.
        corners: 2, 3 or 4 indices into points, one per curve; curve k runs from
            corner k to corner k + 1.
        t4_ratio: the k of the T4 test k C <= A and k C <= B (at least 2).
        t5_cut_edges: edges on the cut of a two-curve region; 0 from the geometry.
        max_quads: refuse a mesh larger than this.
        smooth: smooth the interior nodes (doublets merged, no node's worst
            corner lowered): a planar region's in its plane, a curved 3D loop's on
            the surface its templates' mesh spans (fitted around each node). The
            boundary points are kept bit for bit either way.
        best_corners: also try other corner sets (2, 3 or 4 curves, from the given
            corners and the points where the loop turns) and keep the best worst,
            then mean, scaled Jacobian; ``faces[0]["corner_search"]`` gives the
            given corners' figures beside the chosen ones (the CLI's --corners best).
            Without it, the search runs anyway where the given corners leave an
            inverted quad, and its mesh is kept if it has fewer
            (``corner_search["reason"]`` is then ``"inverted"``).

    Raises:
        ValueError: the boundary cannot be meshed (the message says why and where).
    """
    array = np.asarray(points, dtype=np.float64)
    corner_list = [_integer(c, "corner") for c in corners]
    return Mesh(_core.mesh_boundary(array, corner_list, *_template_integers(t4_ratio, t5_cut_edges, max_quads),
                                    bool(smooth), bool(best_corners)))


def mesh_shape(brep_text_or_path: str, *, size: float = 0.0,
               faces: Optional[Iterable[int]] = None,
               corners: Optional[Mapping[int, Sequence[int]]] = None,
               keep_going: bool = False, allow_inverted: bool = False, threads: int = 0,
               t4_ratio: int = 2, t5_cut_edges: int = 0,
               max_quads: int = _MAX_QUADS, smooth: bool = True,
               progress: Optional[Callable[[str, int, int], Optional[bool]]] = None,
               read_timeout: Optional[float] = None, best_corners: bool = False,
               min_size: float = 0.0, order: int = 1, sew: bool = False,
               sizes: Optional[Dict[str, float]] = None, curvature_segments: int = 8,
               growth_rate: float = 1.3) -> Mesh:
    """Mesh the faces of a CAD shape, conforming across shared edges.

    Args:
        brep_text_or_path: BREP text (FreeCAD's ``Shape.exportBrepToString()``) or
            the path of a .step/.stp, .iges/.igs or .brep file.
        {options}

    The options are the command line's (``docs/cli.md``), declared once in the
    schema ``mesh_option_schema()`` lists. In Python: a refused face without
    ``keep_going`` raises ``FacesRefused``; ``progress`` is called as
    ``progress(stage, done, total)`` at each stage ("index", "assign intervals",
    "discretize edges", "mesh faces", "assemble") and after each face, and
    returning True (or raising) cancels; ``read_timeout`` None takes the default;
    with ``order`` 2 the middle nodes are in ``mid_nodes``; with ``sew`` the
    edges merged are counted in ``sewn_edges``; ``sizes`` maps "face3", "edge7" or
    "vertex1" (0-based) to a local size, e.g. ``sizes={"face3": 0.5}``.

    Raises:
        Cancelled: the progress callback asked to stop (nothing is returned).
        FacesRefused: faces refused without keep_going (a ValueError; its
            ``refused_faces`` lists them).
        ValueError: unreadable shape or bad options.
    """
    face_list = [_integer(f, "face") for f in faces] if faces is not None else []
    corner_map: Dict[int, List[int]] = {
        _integer(k, "corners' face"): [_integer(v, "corner of face %s" % k) for v in vs]
        for k, vs in (corners or {}).items()}
    if sizes is not None and not isinstance(sizes, Mapping):
        raise ValueError("sizes must map 'face3', 'edge7' or 'vertex1' to a size, not %r" % (sizes,))
    size_entries = []
    for entity, value in (sizes or {}).items():
        if not isinstance(entity, str) or isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ValueError("sizes entry %r: %r: expected 'face3', 'edge7' or 'vertex1' and a number"
                             % (entity, value))
        size_entries.append("%s:%r" % (entity, float(value)))
    return Mesh(_core.mesh_shape(str(brep_text_or_path), float(size), face_list, corner_map,
                                 bool(keep_going), bool(allow_inverted), _integer(threads, "threads", 0, 1024),
                                 *_template_integers(t4_ratio, t5_cut_edges, max_quads), bool(smooth),
                                 progress, 0.0 if read_timeout is None else float(read_timeout),
                                 bool(best_corners), float(min_size), _integer(order, "order", 1, 2), bool(sew),
                                 size_entries, _integer(curvature_segments, "curvature_segments", 8, 1000),
                                 float(growth_rate)))


def mesh_option_schema() -> List[dict]:
    """The options of mesh_shape as every front end knows them, in keyword order:
    ``name`` (the keyword), ``flag`` (``tquad mesh``'s), ``freecad`` (the FreeCAD mesh
    object's property, "" when FreeCAD sets it itself), ``type`` and ``default`` (as
    Python writes them) and ``help``."""
    return [dict(row) for row in _core.mesh_option_schema()]


def _document_options(doc: str) -> str:
    """doc with its "{options}" line replaced by each option's help, as Args lines."""
    lines = []
    for row in mesh_option_schema():
        lines += textwrap.wrap(row["help"], 76, initial_indent="        %s: " % row["name"],
                               subsequent_indent="            ")
    return doc.replace("        {options}", "\n".join(lines))


mesh_shape.__doc__ = _document_options(mesh_shape.__doc__ or "")


class SweptMesh:
    """Hexahedra swept from quads (sweep_shape).

    Attributes:
        nodes: N x 3 float64.
        hexes: M x 8 int32, 0-based, in VTK's hexahedron and CalculiX's C3D8 order (the
            bottom face 0-3, node i + 4 above node i); at order 2 M x 20, the 12 edge
            middles after the corners (VTK's type 25, C3D20).
        jacobian_ratio: at order 2, each hexahedron's smallest Jacobian determinant at
            its 27 integration points over the largest; None at order 1.
        scaled_jacobian: M float64, each hexahedron's worst corner (1: a cube).
        solids: per swept solid, ``solid``, ``source`` and ``target`` (face indices),
            ``layers``, ``height`` (the longest path), ``first_hex``, ``hex_count``, and
            ``translation`` (x, y, z), ``rotation`` {``point``, ``direction``,
            ``angle`` in radians} or ``projection`` ("least squares").
        refused_solids: with keep_going, ``{"solid", "reason"}`` per solid not swept.
        unshared_faces: faces two swept solids share whose nodes there differ (the mesh
            does not conform across them); a cap one solid swept is the next one's
            source, so shared caps share their nodes.
        face_nodes: per CAD face of a swept solid (0-based), its node indices (int32).
        edge_size: the target edge length used.
        read_warnings: what the reader let through with a warning.
    """

    def __init__(self, data: dict) -> None:
        self.nodes = data["nodes"]
        self.hexes = data["hexes"]
        self.scaled_jacobian = data["scaled_jacobian"]
        self.jacobian_ratio = data["jacobian_ratio"]
        self.solids = list(data["solids"])
        self.refused_solids = list(data["refused_solids"])
        self.unshared_faces = list(data["unshared_faces"])
        self.face_nodes = dict(data["face_nodes"])
        self.edge_size = float(data["edge_size"])
        self.read_warnings = list(data["read_warnings"])

    def __repr__(self) -> str:
        return (f"SweptMesh({len(self.nodes)} nodes, {len(self.hexes)} hexahedra, "
                f"{len(self.solids)} solids, {len(self.refused_solids)} refused)")


def sweep_shape(brep_text_or_path: str, *, size: float = 0.0, min_size: float = 0.0, layers: int = 0,
                source: Optional[int] = None, target: Optional[int] = None, keep_going: bool = False,
                smooth: bool = True, threads: int = 0, read_timeout: Optional[float] = None,
                order: int = 1) -> SweptMesh:
    """Sweep the solids of a CAD shape into hexahedra (as ``tquad sweep``).

    A solid is swept when it is an extrusion or a revolution (planar caps that are the
    same face moved or turned, the profile clear of the axis; or a full turn), or a
    one-to-one sweep: two caps joined by four-sided side faces, stacked or not (lofts,
    pipes along curves). The source cap is meshed as mesh_shape meshes a face; the
    target gets the same quads moved; the layers are the exact translation or rotation,
    or else placed by least-squares projection. Other solids are refused.

    Args:
        brep_text_or_path: BREP text or the path of a .step/.stp, .iges/.igs or .brep file.
        size, min_size, smooth, threads, read_timeout: as for mesh_shape (the source faces).
        layers: hexahedra through each solid; 0 takes round(height / size), at least 1.
        source, target: the caps (face indices, 0-based), both or neither; None finds
            them per solid.
        keep_going: sweep the other solids when one is refused (listed in
            ``refused_solids``); otherwise a refused solid raises ValueError.
        order: 1 for eight-node hexahedra; 2 for twenty-node ones (``hexes`` M x 20,
            the edge middles on the CAD curves and surfaces or on their node's path).

    Raises:
        ValueError: unreadable shape, no solid, a solid that is not sweepable (without
            keep_going), given caps that are not a sweep's, or bad options.
    """
    if (source is None) != (target is None):
        raise ValueError("give both source and target, or neither")
    return SweptMesh(_core.sweep_shape(
        str(brep_text_or_path), float(size), float(min_size), _integer(layers, "layers", 0, 1_000_000),
        -1 if source is None else _integer(source, "source", 0),
        -1 if target is None else _integer(target, "target", 0), bool(keep_going), bool(smooth),
        _integer(threads, "threads", 0, 1024), 0.0 if read_timeout is None else float(read_timeout),
        _integer(order, "order", 1, 2)))
