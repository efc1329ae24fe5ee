"""The work behind a TemplateQuad mesh object: shape -> tquad mesh -> Fem.FemMesh.

Pure functions of their arguments (no document objects, no GUI), so the mesh object's
execute() stays a few lines and everything here can be called from a script.

Indices: FreeCAD names sub-shapes from 1 ("Face3", "Vertex7"); the ``tquad`` module
numbers them from 0 in the same order (``Shape.Faces`` / ``Shape.Vertexes``). User-facing
strings use FreeCAD's names; the calls into ``tquad`` use 0-based indices.
"""
import os
import re
import sys
from typing import Dict, Iterable, List, Optional, Sequence

from . import paths

TQUAD_MISSING_MESSAGE = (
    "TemplateQuad: the Python module 'tquad' was not found or does not load ({error}). "
    "The Debian package templatequad installs it with the workbench; from a source "
    "tree, it is built by the project's CMake build (target tquad_python, into "
    "build/python/tquad) and copied into the add-on by freecad_workbench/install.sh; "
    "build it, then run install.sh again.\n")


class TquadMissing(ImportError):
    """The compiled ``tquad`` module cannot be imported."""


def load_tquad():
    """load_tquad(): import and return the ``tquad`` module.

    FreeCAD puts the workbench folder on sys.path when it loads the add-on, and
    install.sh copies the module there. When the package is imported some other way
    (a script that put freecad_workbench/ on sys.path), the folder is added here as a
    fallback.

    Raises:
        TquadMissing: with a message saying the module was not built or installed.
    """
    try:
        import tquad
        return tquad
    except ImportError as error:
        failure = error
    if paths.WORKBENCH_DIR not in sys.path and os.path.isdir(
            os.path.join(paths.WORKBENCH_DIR, "tquad")):
        sys.path.append(paths.WORKBENCH_DIR)
        try:
            import tquad
            return tquad
        except ImportError as error:
            failure = error
    raise TquadMissing(TQUAD_MISSING_MESSAGE.format(error=failure)) from failure


_FACE = re.compile(r"^(?:face)?(\d+)$", re.IGNORECASE)
_VERTEX = re.compile(r"^(?:vertex)?(\d+)$", re.IGNORECASE)


def _index(token: str, pattern, kind: str, entry: str) -> int:
    """One face or vertex reference: "Face4"/"Vertex4" are 1-based, "3" is 0-based."""
    match = pattern.match(token.strip())
    if not match:
        raise ValueError(f"Corners entry '{entry}': '{token.strip()}' is not a {kind} "
                         f"(write {kind.capitalize()}N, 1-based, or a 0-based index)")
    number = int(match.group(1))
    if token.strip()[0].isdigit():
        return number
    if number < 1:
        raise ValueError(f"Corners entry '{entry}': FreeCAD names count from "
                         f"{kind.capitalize()}1")
    return number - 1


def parse_corners(entries: Iterable[str]) -> Dict[int, List[int]]:
    """parse_corners(): the Corners property as tquad's {face: [vertex, ...]} (0-based).

    Each entry is ``FACE:V1,V2,...`` (2 to 4 vertices, where the face's boundary curves
    begin), written either with FreeCAD's names, ``Face4:Vertex1,Vertex5,Vertex8``
    (1-based, as the selection shows them), or with tquad's 0-based indices,
    ``3:0,4,7`` (as ``tquad mesh --corners``). Blank entries are ignored.

    Raises:
        ValueError: an entry that cannot be read; the message quotes it.
    """
    corners: Dict[int, List[int]] = {}
    for entry in entries:
        if not entry.strip():
            continue
        face_text, sep, vertex_text = entry.partition(":")
        if not sep:
            raise ValueError(f"Corners entry '{entry}': expected FACE:V1,V2,... "
                             "(e.g. Face4:Vertex1,Vertex5,Vertex8,Vertex3)")
        face = _index(face_text, _FACE, "face", entry)
        vertices = [_index(v, _VERTEX, "vertex", entry)
                    for v in vertex_text.split(",") if v.strip()]
        if not 2 <= len(vertices) <= 4:
            raise ValueError(f"Corners entry '{entry}': a face has 2, 3 or 4 corners, "
                             f"not {len(vertices)}")
        if face in corners:
            raise ValueError(f"Corners entry '{entry}': Face{face + 1} is given twice")
        corners[face] = vertices
    return corners


def parse_faces(names: Iterable[str]) -> Optional[List[int]]:
    """parse_faces(): the Faces property ("Face3", ...) as 0-based indices; None = all."""
    indices = [_index(name, _FACE, "face", name) for name in names if name.strip()]
    return sorted(set(indices)) if indices else None


def mesh_shape(shape, size: float = 0.0, faces: Optional[Sequence[int]] = None,
               corners: Optional[Dict[int, List[int]]] = None, t4_ratio: int = 2,
               keep_going: bool = False, smooth: bool = True, best_corners: bool = False,
               min_size: float = 0.0, order: int = 1, sew: bool = False, progress=None,
               sizes: Optional[Dict[str, float]] = None, curvature_segments: int = 8,
               growth_rate: float = 1.3):
    """mesh_shape(): mesh a Part.Shape with tquad; returns the tquad.Mesh.

    The shape goes over as BREP text (``exportBrepToString``), which keeps its
    placement, so the nodes are in global coordinates. Arguments as tquad.mesh_shape.

    Raises:
        TquadMissing: the module is not installed.
        ValueError: tquad refused the shape, a face or the sizes (message from tquad).
        tquad.Cancelled: the progress callable asked to stop.
    """
    tquad = load_tquad()
    return tquad.mesh_shape(shape.exportBrepToString(), size=float(size), faces=faces,
                            corners=corners or None, keep_going=bool(keep_going),
                            t4_ratio=int(t4_ratio), smooth=bool(smooth),
                            best_corners=bool(best_corners), min_size=float(min_size),
                            order=int(order), sew=bool(sew), progress=progress,
                            sizes=sizes, curvature_segments=int(curvature_segments),
                            growth_rate=float(growth_rate))


def run_plain(work, title: str = ""):
    """run_plain(): work(None): meshing without a progress display (headless)."""
    return work(None)


def return_memory() -> None:
    """Give the memory a finished, failed or cancelled run freed back to the system.

    The C allocator keeps freed blocks for reuse, so after a multi-gigabyte run the
    process would stay that large; malloc_trim(0) releases them (glibc only; elsewhere
    nothing happens)."""
    import ctypes
    import gc

    gc.collect()
    try:
        ctypes.CDLL("libc.so.6").malloc_trim(0)
    except (OSError, AttributeError):
        pass


def element_nodes(mesh):
    """element_nodes(): the elements' node indices (0-based), M x 4, or M x 8 for a
    second-order mesh: corners, then the middles of edges 0-1, 1-2, 2-3 and 3-0, the
    order of VTK's quadratic quad and of FreeCAD's (SMESH's) 8-node quadrangle."""
    import numpy

    quads = numpy.asarray(mesh.quads).reshape(-1, 4)
    mids = mesh.mid_nodes
    return quads if mids is None else numpy.hstack([quads, numpy.asarray(mids).reshape(-1, 4)])


def to_femmesh(mesh):
    """to_femmesh(): a Fem.FemMesh of the tquad mesh's quads (node and element ids from 1).

    Node i (0-based in tquad) becomes node i + 1; quad j becomes face element j + 1 with
    the same counter-clockwise node order, so the shell normals follow the CAD faces'
    outer normals; a second-order quad has its four edge middles after its corners.
    The mesh goes through a temporary legacy VTK file that FemMesh.read takes in one
    C++ call (femmesh_from_vtk_file); where that FreeCAD cannot read it (built
    without VTK) or reads something else, node by node (femmesh_node_by_node).
    Measured by bench/freecad_transfer.py: see docs/freecad.md.
    """
    femmesh = femmesh_from_vtk_file(mesh)
    return femmesh if femmesh is not None else femmesh_node_by_node(mesh)


def write_legacy_vtk(path: str, nodes, elements, hexahedra: bool = False) -> None:
    """write_legacy_vtk(): nodes (n x 3 floats) and elements (element_nodes: m x 4
    quads or m x 8 quadratic quads, 0-based; with hexahedra, m x 8 or m x 20) as a
    binary legacy VTK unstructured grid (big-endian, as that format asks; cell type
    9 = quad, 23 = quadratic quad, 12 = hexahedron, 25 = quadratic hexahedron)."""
    import numpy

    nodes = numpy.asarray(nodes, dtype=float).reshape(-1, 3)
    per = elements.shape[1]
    cells = numpy.empty((len(elements), per + 1), dtype=">i4")
    cells[:, 0] = per
    cells[:, 1:] = elements
    with open(path, "wb") as out:
        out.write(b"# vtk DataFile Version 3.0\nTemplateQuad mesh\nBINARY\nDATASET UNSTRUCTURED_GRID\n")
        out.write(b"POINTS %d double\n" % len(nodes))
        out.write(nodes.astype(">f8").tobytes())
        out.write(b"\nCELLS %d %d\n" % (len(elements), (per + 1) * len(elements)))
        out.write(cells.tobytes())
        out.write(b"\nCELL_TYPES %d\n" % len(elements))
        cell_type = {4: 9, 8: 23, 20: 25}[per] if per != 8 or not hexahedra else 12
        out.write(numpy.full(len(elements), cell_type, dtype=">i4").tobytes())
        out.write(b"\n")


def femmesh_from_vtk_file(mesh):
    """femmesh_from_vtk_file(): the Fem.FemMesh read back from a temporary VTK file, or
    None where FreeCAD cannot read it or what it read is not this mesh (counts, the
    first and last node's position and quad's nodes)."""
    import tempfile

    import Fem

    if len(mesh.quads) == 0:
        return None
    femmesh = Fem.FemMesh()
    with tempfile.TemporaryDirectory(prefix="templatequad-") as folder:
        path = os.path.join(folder, "mesh.vtk")
        write_legacy_vtk(path, mesh.nodes, element_nodes(mesh))
        try:
            femmesh.read(path)
        except Exception:  # FreeCAD without VTK raises here; any failure means fall back
            return None
    nodes = mesh.nodes
    if femmesh.NodeCount != len(nodes) or femmesh.QuadrangleCount != len(mesh.quads) \
            or femmesh.FaceCount != len(mesh.quads):
        return None
    for node_id in (1, len(nodes)):
        if tuple(femmesh.getNodeById(node_id)) != tuple(float(c) for c in nodes[node_id - 1]):
            return None
    elements = element_nodes(mesh)
    for quad_id in (1, len(elements)):
        if tuple(femmesh.getElementNodes(quad_id)) != tuple(int(n) + 1 for n in elements[quad_id - 1]):
            return None
    return femmesh


def femmesh_node_by_node(mesh):
    """femmesh_node_by_node(): the same Fem.FemMesh built with addNode/addFace, one Python
    call per node and per quad (the fallback of to_femmesh)."""
    import Fem  # here, not at module level: importing this package stays cheap

    femmesh = Fem.FemMesh()
    add_node = femmesh.addNode
    for node_id, (x, y, z) in enumerate(mesh.nodes.tolist(), start=1):
        add_node(x, y, z, node_id)
    add_face = femmesh.addFace
    for quad_id, quad in enumerate((element_nodes(mesh) + 1).tolist(), start=1):
        add_face(quad, quad_id)
    return femmesh


#: The swept hexahedra's node order as FreeCAD's FemMesh (SMESH) takes them, from
#: tquad's (VTK's and CalculiX's): SMESH's bottom face runs the other way round, so
#: FreeCAD's CalculiX writer, which reorders SMESH's hexahedra, gives positive C3D8
#: and C3D20 (tests/freecad/test_headless.py checks the written order).
SMESH_HEXA8 = (0, 3, 2, 1, 4, 7, 6, 5)
SMESH_HEXA20 = SMESH_HEXA8 + (11, 10, 9, 8, 15, 14, 13, 12, 16, 19, 18, 17)


def sweep_shape(shape, size: float = 0.0, min_size: float = 0.0, layers: int = 0,
                smooth: bool = True, order: int = 1):
    """sweep_shape(): the solids of a Part.Shape swept into hexahedra by tquad
    (tquad.sweep_shape, keep_going on: refused solids come back as records)."""
    tquad = load_tquad()
    return tquad.sweep_shape(shape.exportBrepToString(), size=float(size), min_size=float(min_size),
                             layers=int(layers), keep_going=True, smooth=bool(smooth), order=int(order))


def to_femmesh_volumes(swept):
    """to_femmesh_volumes(): a Fem.FemMesh of the swept hexahedra (ids from 1), through
    a temporary legacy VTK file as to_femmesh does, in SMESH's node order."""
    import tempfile

    import numpy

    import Fem

    hexes = numpy.asarray(swept.hexes)
    order = SMESH_HEXA20 if hexes.shape[1] == 20 else SMESH_HEXA8
    elements = hexes[:, list(order)]
    femmesh = Fem.FemMesh()
    with tempfile.TemporaryDirectory(prefix="templatequad-") as folder:
        path = os.path.join(folder, "mesh.vtk")
        write_legacy_vtk(path, swept.nodes, elements, hexahedra=True)
        femmesh.read(path)
    if femmesh.NodeCount != len(swept.nodes) or femmesh.VolumeCount != len(hexes):
        raise RuntimeError("FreeCAD read back %d nodes and %d volumes of %d and %d" % (
            femmesh.NodeCount, femmesh.VolumeCount, len(swept.nodes), len(hexes)))
    return femmesh


def swept_summary(swept) -> str:
    """swept_summary(): one line: hexahedra, nodes, solids and the scaled Jacobian."""
    sj = swept.scaled_jacobian
    line = (f"{len(swept.hexes)} hexahedra, {len(swept.nodes)} nodes; {len(swept.solids)} solid(s) swept; "
            f"scaled Jacobian min {float(sj.min()):.3f} avg {float(sj.mean()):.3f}")
    line += f"; {len(swept.refused_solids)} solid(s) not swept" if swept.refused_solids else ""
    unshared = getattr(swept, "unshared_faces", [])
    return line + ("; not conforming across " + ", ".join("Face%d" % (f + 1) for f in unshared) if unshared else "")


def swept_solid_line(s) -> str:
    """swept_solid_line(): how one solid was swept, in FreeCAD's 1-based names."""
    if s["source"] < 0:
        how = "its profile turned a full turn"
    else:
        how = "Face%d to Face%d" % (s["source"] + 1, s["target"] + 1)
        if "projection" in s:
            how += " (least-squares projection)"
    return "Solid%d: %s, %d layers, %d hexahedra" % (s["solid"] + 1, how, s["layers"], s["hex_count"])


def refused_solid_lines(swept) -> List[str]:
    """refused_solid_lines(): "SolidN: <why>" per solid tquad did not sweep (FreeCAD's
    1-based names; the faces in the reason become FaceN too)."""
    return ["Solid%d: %s" % (r["solid"] + 1, freecad_wording(r["reason"].split(": ", 1)[-1]))
            for r in swept.refused_solids]


def quality_summary(mesh) -> str:
    """quality_summary(): one line: counts, scaled Jacobian and Lee-Lo min/avg, bad and
    collapsed quads."""
    q = mesh.quality
    sj, ll = q["scaled_jacobian"], q["lee_lo"]
    return (f"{len(mesh.quads)} quads, {len(mesh.nodes)} nodes; "
            f"scaled Jacobian min {sj['min']:.3f} avg {sj['avg']:.3f}; "
            f"Lee-Lo min {ll['min']:.3f} avg {ll['avg']:.3f}; "
            f"inverted {q['inverted']}, degenerate {q['degenerate']}, collapsed {q.get('collapsed', 0)}")


def unsewn_warning(pairs: int, sew: bool) -> str:
    """unsewn_warning(): what a user reads about edges where faces touch without sharing
    the edge ("" for none): the mesh falls apart there, and a solver takes the pieces
    as unconnected shells."""
    if pairs == 0:
        return ""
    advice = "" if sew else "; turn on Sew to join them"
    return (f"{pairs} pair(s) of edges lie on each other without being shared (the faces "
            f"are not sewn there): the mesh is not connected along them{advice}")


_REGION_ELEMENT = re.compile(r"^(Face|Edge|Vertex)(\d+)$")


def region_sizes(regions):
    """region_sizes(): tquad's ``sizes`` from FEM mesh regions (``Fem::MeshRegion``
    objects, ObjectsFem.makeMeshRegion): each one's CharacteristicLength on the faces,
    edges and vertices its References name, as "face2" and so on (0-based; the least
    size where regions overlap). The References are taken to name the meshed part's
    elements, as FreeCAD's own mesh regions do. None when no region sets a size.

    Raises:
        ValueError: a region of length 0 or less, or a reference to a solid or a shell.
    """
    sizes = {}
    for region in regions or []:
        length = float(getattr(region.CharacteristicLength, "Value", region.CharacteristicLength))
        if not length > 0:
            raise ValueError(f"{region.Label}: its CharacteristicLength must be over 0")
        for _, names in region.References:
            for name in names:
                match = _REGION_ELEMENT.match(name)
                if not match:
                    raise ValueError(f"{region.Label}: {name} is not a face, edge or vertex; a mesh "
                                     "region of TemplateQuad sizes faces, edges and vertices")
                key = f"{match.group(1).lower()}{int(match.group(2)) - 1}"
                sizes[key] = min(sizes.get(key, length), length)
    return sizes or None


_GROUP_ELEMENT = re.compile(r"^(Solid|Face|Edge|Vertex)(\d+)$")


def mesh_groups(groups):
    """mesh_groups(): FEM mesh groups (``Fem::MeshGroup``, ObjectsFem.makeMeshGroup) as
    (name, {"Solid"|"Face"|"Edge"|"Vertex": [0-based indices]}) pairs, in their order.
    The name is the group's Label with UseLabel on, else its Name (as FreeCAD's Gmsh
    mesh names them). The References name the meshed part's elements, as for regions.

    Raises:
        ValueError: a group without references, a reference that is not a solid, face,
            edge or vertex, or two groups of one name.
    """
    named = []
    for group in groups or []:
        name = group.Label if getattr(group, "UseLabel", False) else group.Name
        if any(name == other for other, _ in named):
            raise ValueError(f"{group.Label}: another mesh group is named {name!r} too; "
                             "a name is one set in the written mesh")
        kinds = {}
        for _, names in group.References:
            for element in names:
                match = _GROUP_ELEMENT.match(element)
                if not match:
                    raise ValueError(f"{group.Label}: {element} is not a solid, face, edge or vertex")
                kinds.setdefault(match.group(1), []).append(int(match.group(2)) - 1)
        if not kinds:
            raise ValueError(f"{group.Label}: the mesh group references nothing; "
                             "add faces, edges or vertices of the part to it")
        named.append((name, {kind: sorted(set(ids)) for kind, ids in kinds.items()}))
    return named


def add_mesh_groups(femmesh, shape, groups, nodes_too: bool, owner: str, ranges, elements) -> List[str]:
    """add_mesh_groups(): the mesh groups (mesh_groups) added to a FemMesh whose
    element j + 1 is row j of `elements` (0-based nodes; node i is FemMesh node i + 1).

    `owner` is the shape element that owns elements: "Face" for quads (to_femmesh),
    "Solid" for hexahedra (to_femmesh_volumes); `ranges` maps an owner's 0-based index
    to (first element, count). A group's owners become an element group ("Face" or
    "Volume") and, with nodes_too (FreeCAD's GroupsOfNodes), a "Node" group of their
    nodes; its other references (edges, vertices; faces of a 3D mesh) become a "Node"
    group of the nodes on them, found on the CAD shapes as FreeCAD's constraints find
    theirs. FemMesh.writeABAQUS(path, 1, True) writes them as *ELSET and *NSET.
    Returns one warning per owner the mesh lacks (a refused face or solid).

    Raises:
        ValueError: a group naming a solid of a 2D mesh (it has no volume elements) or
            an element the part does not have.
    """
    import numpy

    shapes = {"Solid": shape.Solids, "Face": shape.Faces, "Edge": shape.Edges, "Vertex": shape.Vertexes}
    by_nodes = {"Face": "getNodesByFace", "Edge": "getNodesByEdge", "Vertex": "getNodesByVertex"}
    warnings = []
    for name, kinds in groups:
        if "Solid" in kinds and owner != "Solid":
            raise ValueError(f"mesh group {name}: Solid{kinds['Solid'][0] + 1} has no elements in a "
                             "2D mesh; group its faces, or mesh with ElementDimension 3D")
        for kind, ids in kinds.items():
            if ids[-1] >= len(shapes[kind]):
                raise ValueError(f"mesh group {name}: {kind}{ids[-1] + 1} does not exist; the part "
                                 f"has {kind}1..{kind}{len(shapes[kind])}")
        owned = []
        for index in kinds.get(owner, []):
            if index not in ranges:
                warnings.append(f"mesh group {name}: {owner}{index + 1} is not meshed, so not in the group")
                continue
            first, count = ranges[index]
            owned.append(numpy.arange(first, first + count))
        owned = numpy.concatenate(owned) if owned else numpy.zeros(0, dtype=int)
        if len(owned):
            group = femmesh.addGroup(name, "Face" if owner == "Face" else "Volume")
            femmesh.addGroupElements(group, (owned + 1).tolist())
        nodes = set()
        if nodes_too and len(owned):
            nodes.update((numpy.unique(elements[owned]) + 1).tolist())
        for kind, ids in kinds.items():
            if kind != owner:
                find = getattr(femmesh, by_nodes[kind])
                for index in ids:
                    nodes.update(find(shapes[kind][index]))
        if nodes:
            group = femmesh.addGroup(name, "Node")
            femmesh.addGroupElements(group, sorted(nodes))
    return warnings


def add_face_mesh_groups(femmesh, mesh, shape, groups, nodes_too: bool) -> List[str]:
    """add_face_mesh_groups(): add_mesh_groups for a quad mesh (to_femmesh)."""
    ranges = {f["face"]: (f["first_quad"], f["quad_count"]) for f in mesh.faces}
    return add_mesh_groups(femmesh, shape, groups, nodes_too, "Face", ranges, element_nodes(mesh))


def add_solid_mesh_groups(femmesh, swept, shape, groups, nodes_too: bool) -> List[str]:
    """add_solid_mesh_groups(): add_mesh_groups for swept hexahedra (to_femmesh_volumes)."""
    import numpy

    ranges = {s["solid"]: (s["first_hex"], s["hex_count"]) for s in swept.solids}
    return add_mesh_groups(femmesh, shape, groups, nodes_too, "Solid", ranges, numpy.asarray(swept.hexes))


#: Peak memory per quad while faces of millions of quads are meshed (as measured on
#: such runs): what the estimate before a large run shows.
PEAK_BYTES_PER_QUAD = 700


def estimated_run(shape, size: float):
    """estimated_run(): (quads, bytes) that meshing `shape` at `size` (0: automatic, the
    bounding-box diagonal / 25) takes about: its faces' area over the size squared (a
    square grid of that size), and PEAK_BYTES_PER_QUAD each. Curved and short edges
    and local sizes add quads the estimate does not count."""
    h = size if size > 0 else shape.BoundBox.DiagonalLength / 25.0
    quads = int(round(shape.Area / (h * h))) if h > 0 else 0
    return quads, quads * PEAK_BYTES_PER_QUAD


def size_warning(mesh) -> str:
    """size_warning(): "" unless the element size exceeds the part, which then gets the
    fewest elements its edges' curvature and faces allow (the size has no say)."""
    diagonal, size = getattr(mesh, "shape_diagonal", None), getattr(mesh, "edge_size", None)
    if not diagonal or not size or size <= diagonal:
        return ""
    return (f"the element size {size:g} mm is larger than the part ({diagonal:.4g} mm across): each "
            f"edge gets the fewest elements its curvature and faces allow")


def orientation_messages(mesh):
    """orientation_messages(): (message, warning), each "" for none. The message names
    the faces outside solids whose elements were turned so that neighbouring faces
    agree on their normals (a shell's top and bottom, a pressure's side); the warning
    names faces that meet with normals that cannot agree (a one-sided shell)."""
    turned = [f"Face{f + 1}" for f in getattr(mesh, "turned_faces", [])]
    conflicts = [f"Face{a + 1} and Face{b + 1}" for a, b in getattr(mesh, "orientation_conflicts", [])]
    message = (f"{', '.join(turned)}: elements turned to agree with their neighbours' normals"
               if turned else "")
    warning = (f"normals cannot agree where {'; '.join(conflicts)} meet (a one-sided shell, or "
               f"solids whose faces disagree): a shell element's top and bottom swap there"
               if conflicts else "")
    return message, warning


def absorbed_message(mesh) -> str:
    """absorbed_message(): what a user reads about faces absorbed as strips ("" for
    none): they have no elements of their own, so a constraint on them alone finds
    no nodes, and their neighbours meet across them."""
    faces = [f"Face{a['face'] + 1}" for a in getattr(mesh, "absorbed_faces", [])]
    if not faces:
        return ""
    return (f"{', '.join(faces)} narrower than 0.004 of the element size everywhere: absorbed "
            f"with no elements of their own (the faces beside them share their nodes)")


def template_tree_lines(mesh) -> List[str]:
    """template_tree_lines(): "FaceN: <tree> (<count> quads)" per meshed face."""
    return [f"Face{f['face'] + 1}: {f['template_tree']} ({f['quad_count']} quads)"
            for f in mesh.faces]


#: What a FreeCAD user can do about a refused face, per tquad refusal code.
REFUSAL_ADVICE = {
    "too_coarse": "too few elements along its edges; lower the maximum element size",
    "inverted_quads": "every mesh found folds over on its surface; try other corners or "
                      "a smaller element size",
    "not_supported": "this kind of face is not supported yet",
    "damaged": "its geometry is invalid; Part > Check geometry shows why",
    "cannot_mesh": "no mesh found; try other corners or a smaller element size",
    "internal": "the mesher failed on it; please report it with the part",
}

# tquad's 0-based sub-shape numbers, as FreeCAD names them (1-based, capitalized).
_NUMBERED = re.compile(r"\b(face|edge|vertex)(?:es)?( \d+(?:(?:, | and )\d+)*)\b")
_VERTICES = re.compile(r"\bvertices( \d+(?:(?:, | and )\d+)*)\b")
# "faces 0..48": a range of 0-based indices.
_RANGE = re.compile(r"\b(face|edge|verti|solid)(?:s|ces) (\d+)\.\.(\d+)\b")
_RANGE_KIND = {"face": "Face", "edge": "Edge", "verti": "Vertex", "solid": "Solid"}
# Command-line words in tquad's messages, as the FreeCAD object calls them.
_CLI_WORDS = (
    (re.compile(r"\s*\(--keep-going meshes the other faces\)"), ""),
    (re.compile(r"a (larger|smaller) --size"), r"a \1 element size"),
    (re.compile(r" \(--max-quads\)"), ""),
    (re.compile(r"--size"), "the element size"),
    (re.compile(r"--corners"), "Corners"),
    (re.compile(r"--faces"), "Faces"),
)


def _rename(kind: str, numbers: str) -> str:
    names = [f"{kind}{int(n) + 1}" for n in re.findall(r"\d+", numbers)]
    return " and ".join([", ".join(names[:-1]), names[-1]]) if len(names) > 1 else names[0]


def freecad_wording(message: str) -> str:
    """freecad_wording(): a tquad message in a FreeCAD user's terms.

    tquad counts faces, edges and vertices from 0 and speaks of command-line options;
    FreeCAD names them Face1, Edge1, Vertex1 and the object has properties. Only the
    wording changes: decisions are taken on tquad's records (codes, indices), never on
    its messages.
    """
    text = _RANGE.sub(lambda m: f"{_RANGE_KIND[m.group(1)]}{int(m.group(2)) + 1}.."
                               f"{_RANGE_KIND[m.group(1)]}{int(m.group(3)) + 1}", message)
    text = _VERTICES.sub(lambda m: _rename("Vertex", m.group(1)), text)
    text = _NUMBERED.sub(lambda m: _rename(m.group(1).capitalize(), m.group(2)), text)
    for pattern, replacement in _CLI_WORDS:
        text = pattern.sub(replacement, text)
    return text


def refused_face_names(mesh) -> List[str]:
    """refused_face_names(): "FaceN" of each face tquad did not mesh (1-based)."""
    return [f"Face{r['face'] + 1}" for r in mesh.refused_faces]


def refused_face_lines(mesh) -> List[str]:
    """refused_face_lines(): "FaceN: <advice> (<what failed>)" per refused face.

    The advice follows the refusal's code; the detail is tquad's reason without its
    leading "face k", in FreeCAD's names.
    """
    lines = []
    for r in mesh.refused_faces:
        detail = freecad_wording(re.sub(rf"^face {r['face']}\b:?\s*", "", r["reason"]))
        advice = REFUSAL_ADVICE.get(r.get("code"), REFUSAL_ADVICE["cannot_mesh"])
        lines.append(f"Face{r['face'] + 1}: {advice} ({detail})")
    return lines


def refusal_error(mesh) -> str:
    """refusal_error(): the error when faces are refused and the user did not let the
    other faces be meshed (KeepGoing off)."""
    names = refused_face_names(mesh)
    first = refused_face_lines(mesh)[0]
    more = f" ({len(names) - 1} more: {', '.join(names[1:])})" if len(names) > 1 else ""
    return (f"{len(names)} face(s) not meshed: {first}{more}. Turn on 'Mesh the other "
            "faces' (KeepGoing) to mesh the rest.")


def explain_tquad_error(message: str) -> str:
    """explain_tquad_error(): a tquad error message in a FreeCAD user's terms."""
    return freecad_wording(message)
