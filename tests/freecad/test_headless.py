"""Headless tests of the TemplateQuad add-on, run inside freecadcmd.

The add-on is the copy run_freecad_tests.sh installed into a temporary
FREECAD_USER_HOME, so these also check that FreeCAD finds it the way a user's FreeCAD
would. The reference for counts is the tquad module itself on the same BREP text.
"""
import ast
import math
import os
import shutil
import sys
import tempfile
import unittest

import FreeCAD
import Part

from refused_face import drilled_cone_face


def _add_part(doc, shape, name):
    """A Part feature holding `shape`, recomputed."""
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = shape
    doc.recompute()
    return obj


def _tquad():
    import tquad
    return tquad


class AddonInstallTest(unittest.TestCase):
    """FreeCAD loads the installed add-on and its metadata."""

    def test_package_imports_from_the_user_mod_directory(self):
        import freecad.templatequad as addon
        mod_dir = os.path.join(FreeCAD.getUserAppDataDir(), "Mod", "TemplateQuad")
        self.assertTrue(os.path.realpath(addon.__file__).startswith(os.path.realpath(mod_dir)),
                        f"freecad.templatequad came from {addon.__file__}, not {mod_dir}")
        self.assertTrue(callable(addon.make_mesh), "make_mesh is not exported")
        self.assertTrue(os.path.realpath(_tquad().__file__).startswith(os.path.realpath(mod_dir)),
                        "tquad is not the copy install.sh put into the add-on")

    def test_package_xml_is_read_by_freecad(self):
        path = os.path.join(FreeCAD.getUserAppDataDir(), "Mod", "TemplateQuad", "package.xml")
        meta = FreeCAD.Metadata(path)
        self.assertEqual(meta.Name, "TemplateQuad", "package name")
        self.assertEqual(meta.Version, "0.1.0", "package version")
        self.assertEqual([m["name"] for m in meta.Maintainer], ["TemplateQuad contributors"], "maintainer")
        self.assertEqual([l["name"] for l in meta.License], ["LGPL-2.1-or-later"], "SPDX licence")
        self.assertTrue(os.path.isfile(os.path.join(os.path.dirname(path), "LICENSE")), "licence file installed")
        workbenches = meta.Content.get("workbench", [])
        self.assertEqual([w.Classname for w in workbenches], ["TemplateQuadWorkbench"],
                         "one workbench entry with the workbench class name")
        icon = os.path.join(os.path.dirname(path), workbenches[0].Icon)
        self.assertTrue(os.path.isfile(icon), f"workbench icon {icon} missing")
        self.assertTrue(os.path.isfile(os.path.join(os.path.dirname(path), meta.Icon)), "package icon")
        self.assertEqual(workbenches[0].Subdirectory, "freecad_workbench", "the workbench folder")
        self.assertIn("FEM", [d["package"] for d in workbenches[0].Depend], "depends on FEM")
        repo_xml = os.path.join(os.environ["TQ_TEST_DIR"], os.pardir, os.pardir, "package.xml")
        self.assertTrue(os.path.isfile(repo_xml), "package.xml sits at the repository root")


class CornerParsingTest(unittest.TestCase):
    """The Corners property's two spellings mean the same thing."""

    def test_freecad_names_and_tquad_indices(self):
        from freecad.templatequad import meshing
        self.assertEqual(meshing.parse_corners(["Face4:Vertex1,Vertex5,Vertex8", "0:1,2"]),
                         {3: [0, 4, 7], 0: [1, 2]}, "FreeCAD names are 1-based, digits 0-based")
        self.assertEqual(meshing.parse_faces(["Face3", "Face1"]), [0, 2], "face names")
        self.assertIsNone(meshing.parse_faces([]), "no faces means all faces")
        for bad in ["Face1", "Face1:Vertex1", "Face0:Vertex1,Vertex2", "Edge1:1,2",
                    "Face1:1,2", "Face1:1,2,3,4,5"]:
            entries = [bad, "Face1:1,2"] if bad == "Face1:1,2" else [bad]
            with self.assertRaises(ValueError, msg=f"'{bad}' should be refused"):
                meshing.parse_corners(entries)


class QualityColoursTest(unittest.TestCase):
    """The colour map's scale: red at 0.2 and below, yellow at 0.6, green at 1."""

    def test_scale_and_element_ids(self):
        from freecad.templatequad import quality_colours as qc
        self.assertEqual(qc.quality_colour(-0.3), qc.INVERTED)
        self.assertEqual(qc.quality_colour(0.0), qc.quality_colour(0.2), "red below 0.2")
        red, yellow, green = qc.quality_colour(0.2), qc.quality_colour(0.6), qc.quality_colour(1.0)
        self.assertGreater(red[0], 0.8)
        self.assertLess(red[1], 0.1)
        self.assertGreater(min(yellow[:2]), 0.8)
        self.assertGreater(green[1], 0.5)
        self.assertLess(green[0], 0.1)
        greens = [qc.quality_colour(v / 100)[1] for v in range(20, 61)]
        self.assertEqual(greens, sorted(greens), "red to yellow: green rises")
        colours = qc.element_colours([1.0, 0.1])
        self.assertEqual(sorted(colours), [1, 2], "FemMesh element ids start at 1")
        self.assertEqual(colours[2], red)
        self.assertEqual(qc.histogram_band_colour(0), qc.INVERTED, "band 0: below 0")
        for got, want in zip(qc.histogram_band_colour(10), qc.quality_colour(0.95)):
            self.assertAlmostEqual(got, want, 12, msg="band 10: [0.9, 1], at 0.95")


class WorstElementsTest(unittest.TestCase):
    """Which elements are the worst, on which face, and when the panel warns."""

    def test_worst_first_ties_by_id_and_their_faces(self):
        import random
        from freecad.templatequad import worst_elements as we
        rng = random.Random(7)
        for _ in range(200):
            values = [round(rng.random(), 2) for _ in range(rng.randint(1, 60))]
            count = rng.randint(1, 70)
            want = sorted(((v, j + 1) for j, v in enumerate(values)))[:count]
            self.assertEqual(we.worst_elements(values, count), [(j, v) for v, j in want])
            # Faces in any order, each a run of elements: every element finds its own.
            sizes = [rng.randint(1, 9) for _ in range(rng.randint(1, 8))]
            faces = rng.sample(range(100), len(sizes))
            owners, first, truth = [], 0, {}
            for face, n in zip(faces, sizes):
                owners += [face, first, n]
                truth.update({first + k + 1: face for k in range(n)})
                first += n
            for element in range(1, first + 2):
                self.assertEqual(we.owner_of(element, owners), truth.get(element, -1))
        self.assertEqual(we.worst_lines([(5, 0.0412)], [3, 0, 10], "Face"),
                         ["element 5 on Face4: scaled Jacobian 0.041"])
        self.assertEqual(we.quality_warning(0.5, "Face4", 0.1), "")
        self.assertIn("Face4 has a scaled Jacobian of 0.041, under 0.1", we.quality_warning(0.0412, "Face4", 0.1))


class MeshObjectTest(unittest.TestCase):
    """make_mesh on Part shapes: all quads, same mesh as tquad, re-meshes on change."""

    def setUp(self):
        self.doc = FreeCAD.newDocument("TemplateQuadHeadless")

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def _part(self, shape, name):
        return _add_part(self.doc, shape, name)

    def _filleted_box(self):
        box = Part.makeBox(40, 30, 20)
        vertical = [e for e in box.Edges
                    if abs(e.Vertexes[0].Point.z - e.Vertexes[1].Point.z) > 1e-9]
        return box.makeFillet(5, vertical[:2])

    def _assert_same_as_tquad(self, mesh_obj, shape, size, **options):
        femmesh = mesh_obj.FemMesh
        reference = _tquad().mesh_shape(shape.exportBrepToString(), size=size, **options)
        self.assertFalse(reference.refused_faces, "tquad refused a face of the test shape")
        self.assertEqual(femmesh.NodeCount, len(reference.nodes), "node count vs tquad")
        self.assertEqual(femmesh.FaceCount, len(reference.quads), "element count vs tquad")
        self.assertEqual(femmesh.QuadrangleCount, femmesh.FaceCount, "not all quadrilaterals")
        self.assertEqual(femmesh.TriangleCount, 0, "triangles in the mesh")
        self.assertEqual(femmesh.VolumeCount, 0, "volume elements in a surface mesh")
        self.assertEqual(len(mesh_obj.TemplateTrees), len(shape.Faces), "one tree per face")
        self.assertEqual(list(mesh_obj.RefusedFaces), [], "refused faces")
        self.assertTrue(mesh_obj.Quality.startswith(f"{len(reference.quads)} quads"),
                        f"quality summary: {mesh_obj.Quality}")
        self.assertEqual(mesh_obj.Proxy.last_error, "", "error after a good mesh")

    def test_mesh_equals_the_cli_on_the_same_shape(self):
        """The FEM mesh is node for node and quad for quad the `tquad mesh` CLI's."""
        import json
        import subprocess
        from freecad.templatequad import make_mesh
        cli = os.environ.get("TQ_CLI", "")
        if not os.path.exists(cli):
            self.skipTest(f"no tquad executable at TQ_CLI={cli!r}")
        part = self._part(self._filleted_box(), "FilletedBoxCli")
        mesh = make_mesh(self.doc, part, size=3.0)
        with tempfile.TemporaryDirectory() as folder:
            brep, out = os.path.join(folder, "part.brep"), os.path.join(folder, "mesh.json")
            part.Shape.exportBrep(brep)
            run = subprocess.run([cli, "mesh", brep, "-o", out, "--size", "3.0"],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, f"tquad mesh failed: {run.stderr}")
            with open(out) as f:
                reference = json.load(f)
        femmesh = mesh.FemMesh
        self.assertEqual(femmesh.NodeCount, len(reference["nodes"]), "node count vs the CLI")
        self.assertEqual(femmesh.FaceCount, len(reference["quads"]), "quad count vs the CLI")
        for i, (x, y, z) in enumerate(reference["nodes"], start=1):
            p = femmesh.getNodeById(i)
            self.assertEqual((p.x, p.y, p.z), (x, y, z), f"node {i} differs from the CLI's")
        for j, quad in enumerate(reference["quads"], start=1):
            self.assertEqual(list(femmesh.getElementNodes(j)), [n + 1 for n in quad],
                             f"quad {j} differs from the CLI's")

    def test_the_vtk_file_route_is_taken_and_equals_node_by_node(self):
        """to_femmesh reads a temporary VTK file on this FreeCAD (not the slow fallback),
        and that gives the same nodes and quads as addNode/addFace."""
        from freecad.templatequad import meshing
        mesh = meshing.mesh_shape(self._filleted_box(), size=3.0)
        by_file = meshing.femmesh_from_vtk_file(mesh)
        self.assertIsNotNone(by_file, "FreeCAD did not read the VTK file back as this mesh")
        by_node = meshing.femmesh_node_by_node(mesh)
        self.assertEqual(by_file.NodeCount, by_node.NodeCount)
        self.assertEqual(by_file.QuadrangleCount, by_node.QuadrangleCount)
        for i in range(1, by_node.NodeCount + 1):
            self.assertEqual(tuple(by_file.getNodeById(i)), tuple(by_node.getNodeById(i)), f"node {i}")
        for j in range(1, by_node.QuadrangleCount + 1):
            self.assertEqual(by_file.getElementNodes(j), by_node.getElementNodes(j), f"quad {j}")

    def test_no_collapsed_quad_reaches_freecad(self):
        """A box with one edge chamfered 1e-4 (a strip far narrower than the size): the
        strip is absorbed (no elements of its own, its ends contracted, the faces beside
        it sharing its nodes), so no face keeps a collapsed quad (a triangle in effect;
        FreeCAD offers no way to allow bad quads): none reaches the FEM mesh, and the
        user reads which face was absorbed, in FreeCAD's names."""
        from freecad.templatequad import meshing
        box = Part.makeBox(10, 10, 10)
        shape = box.makeChamfer(1e-4, [box.Edges[0]])
        strip = [i for i, f in enumerate(shape.Faces) if f.Area < 0.01]
        self.assertEqual(len(strip), 1)
        mesh = meshing.mesh_shape(shape, size=2.0, keep_going=True)
        self.assertEqual(mesh.refused_faces, [])
        self.assertEqual([a["face"] for a in mesh.absorbed_faces], strip)
        self.assertEqual(len(mesh.faces), len(shape.Faces) - 1)
        self.assertEqual(mesh.quality["collapsed"], 0)
        self.assertIn("collapsed 0", meshing.quality_summary(mesh))
        self.assertTrue(meshing.absorbed_message(mesh).startswith(f"Face{strip[0] + 1} narrower"),
                        meshing.absorbed_message(mesh))
        self.assertEqual(meshing.absorbed_message(meshing.mesh_shape(box, size=2.0)), "")

    def test_box_is_all_quads_and_equals_tquad(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        mesh = make_mesh(self.doc, part, size=2.5)
        self.assertTrue(mesh.isDerivedFrom("Fem::FemMeshObject"), "not a FEM mesh object")
        self.assertIs(mesh.Part, part, "Part link (the CalculiX writer reads it)")
        self._assert_same_as_tquad(mesh, part.Shape, 2.5)

    def test_a_twisted_loft_is_swept_into_the_same_hexahedra_as_tquad(self):
        from freecad.templatequad import make_mesh

        def square(side, z, degrees):
            a = math.radians(degrees)
            corners = [(-1, -1), (1, -1), (1, 1), (-1, 1), (-1, -1)]
            return Part.makePolygon([FreeCAD.Vector(side / 2 * (x * math.cos(a) - y * math.sin(a)),
                                                    side / 2 * (x * math.sin(a) + y * math.cos(a)), z)
                                     for x, y in corners])

        loft = Part.makeLoft([square(20, 0, 0), square(12, 20, 30)], True, True)
        part = self._part(loft, "Loft")
        mesh = make_mesh(self.doc, part, size=2.0, element_dimension="3D")
        reference = _tquad().sweep_shape(loft.exportBrepToString(), size=2.0)
        self.assertEqual(mesh.Proxy.last_error, "", "error after a good sweep")
        self.assertEqual(list(mesh.RefusedFaces), [], "refused solids")
        self.assertIn("projection", reference.solids[0], "not the one-to-one route")
        self.assertEqual(mesh.FemMesh.HexaCount, len(reference.hexes), "hexahedra vs tquad")
        self.assertEqual(mesh.FemMesh.VolumeCount, mesh.FemMesh.HexaCount, "hexahedra only")
        self.assertEqual(mesh.FemMesh.NodeCount, len(reference.nodes), "nodes vs tquad")
        self.assertIn("least-squares projection", mesh.TemplateTrees[0], "how the solid was swept")

    def test_filleted_box_is_all_quads_and_equals_tquad(self):
        from freecad.templatequad import make_mesh
        part = self._part(self._filleted_box(), "FilletedBox")
        mesh = make_mesh(self.doc, part, size=3.0)
        self._assert_same_as_tquad(mesh, part.Shape, 3.0)

    def test_quads_turn_counter_clockwise_around_the_outer_normal(self):
        # Shell normals decide the sign of pressure loads: the 1-based FemMesh must
        # keep tquad's orientation. On a box centred at c, outward means away from c.
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        femmesh = make_mesh(self.doc, part, size=5.0).FemMesh
        centre = FreeCAD.Vector(5, 10, 15)
        for element in femmesh.Faces:
            a, b, c, d = (femmesh.getNodeById(n) for n in femmesh.getElementNodes(element))
            normal = (c - a).cross(d - b)
            outward = (a + b + c + d) * 0.25 - centre
            self.assertGreater(normal.dot(outward), 0, f"element {element} faces inwards")

    def test_every_mesh_shape_keyword_is_a_property_or_named_as_not_offered(self):
        """One table maps the module's options to the object's properties: a keyword
        added to tquad.mesh_shape and not to the table, or a property the object lacks,
        fails here."""
        import inspect
        from freecad.templatequad import make_mesh, mesh_object
        keywords = set(inspect.signature(_tquad().mesh_shape).parameters)
        offered, not_offered = set(mesh_object.OPTION_PROPERTIES), set(mesh_object.OPTIONS_NOT_OFFERED)
        self.assertFalse(offered & not_offered, "a keyword both offered and not")
        self.assertEqual(offered | not_offered, keywords, "keywords of tquad.mesh_shape not in the table")
        mesh = make_mesh(self.doc, self._part(Part.makeBox(10, 10, 10), "OptionsBox"), size=5.0)
        for keyword, (name, _) in mesh_object.OPTION_PROPERTIES.items():
            self.assertIn(name, mesh.PropertiesList, f"the property for {keyword}")
        # The table follows the options schema: its property per option, and the
        # object's defaults are the schema's.
        schema = {row["name"]: row for row in _tquad().mesh_option_schema()}
        self.assertEqual({keyword: name for keyword, (name, _) in mesh_object.OPTION_PROPERTIES.items()},
                         {name: row["freecad"] for name, row in schema.items() if row["freecad"]})
        fresh = make_mesh(self.doc, self._part(Part.makeBox(10, 10, 10), "DefaultsBox"))
        for keyword, (name, convert) in mesh_object.OPTION_PROPERTIES.items():
            with self.subTest(option=keyword):
                value = convert(getattr(fresh, name))  # no faces or corners given: None in Python
                self.assertEqual(value or None if keyword in ("faces", "corners") else value,
                                 ast.literal_eval(schema[keyword]["default"]))
        inputs = {name for _, name, _ in mesh_object._INPUTS}
        self.assertEqual(inputs - set(mesh_object.OPTION_PROPERTIES[k][0] for k in mesh_object.OPTION_PROPERTIES),
                         set(mesh_object.FREECAD_ONLY_PROPERTIES))
        mesh.Sew, mesh.ElementOrder, mesh.Corners = True, "2nd", ["Face1:Vertex1,Vertex3,Vertex7,Vertex5"]
        options = mesh_object.mesh_options(mesh)
        self.assertEqual((options["size"], options["sew"], options["order"]), (5.0, True, 2))
        self.assertEqual(options["corners"], {0: [0, 2, 6, 4]})

    def test_smooth_and_best_corners_reach_tquad(self):
        from freecad.templatequad import make_mesh
        part = self._part(self._filleted_box(), "FilletedBoxOptions")
        mesh = make_mesh(self.doc, part, size=3.0)
        self.assertTrue(mesh.Smooth, "smoothing is on by default")
        self.assertFalse(mesh.BestCorners, "the corner search is off by default")
        smoothed = [tuple(mesh.FemMesh.getNodeById(i)) for i in range(1, mesh.FemMesh.NodeCount + 1)]
        mesh.Smooth = False
        mesh.Proxy.request_mesh(mesh)
        self._assert_same_as_tquad(mesh, part.Shape, 3.0, smooth=False)
        raw = [tuple(mesh.FemMesh.getNodeById(i)) for i in range(1, mesh.FemMesh.NodeCount + 1)]
        self.assertNotEqual(raw, smoothed, "Smooth off left the nodes where smoothing put them")
        mesh.Smooth = True
        mesh.BestCorners = True
        mesh.Proxy.request_mesh(mesh)
        self._assert_same_as_tquad(mesh, part.Shape, 3.0, best_corners=True)

    def test_sew_joins_faces_that_do_not_share_their_edges(self):
        # A box's faces copied one by one share no edge (as an IGES import of trimmed
        # surfaces): meshed apart, each face on its own edges; with Sew, the box's mesh.
        from freecad.templatequad import make_mesh
        box = Part.makeBox(10, 20, 30)
        whole = make_mesh(self.doc, self._part(box, "WholeBox"), size=5.0)
        apart_part = self._part(Part.Compound([face.copy() for face in box.Faces]), "BoxFacesApart")
        warnings = []
        print_warning = FreeCAD.Console.PrintWarning
        FreeCAD.Console.PrintWarning = lambda text: warnings.append(str(text))
        try:
            apart = make_mesh(self.doc, apart_part, size=5.0)
        finally:
            FreeCAD.Console.PrintWarning = print_warning
        self.assertFalse(apart.Sew, "sewing is off by default")
        self.assertGreater(apart.FemMesh.NodeCount, whole.FemMesh.NodeCount, "faces meshed apart")
        self.assertEqual(whole.UnsewnEdges, 0)
        self.assertEqual(apart.UnsewnEdges, 12, "each of the box's 12 edges is two edges apart")
        self.assertTrue(any("BoxFacesApart: 12 pair(s) of edges" in w and "turn on Sew" in w
                            for w in warnings), f"the report view says so: {warnings}")
        apart.Sew = True
        apart.Proxy.request_mesh(apart)
        self.assertEqual(apart.UnsewnEdges, 0, "sewn: none left")
        self.assertEqual(apart.FemMesh.NodeCount, whole.FemMesh.NodeCount, "sewn: the box's nodes")
        self.assertEqual(apart.FemMesh.FaceCount, whole.FemMesh.FaceCount, "sewn: the box's quads")
        self._assert_same_as_tquad(apart, apart_part.Shape, 5.0, sew=True)

    def test_sewn_faces_of_mixed_orientation_all_face_outward(self):
        # Face copies, every other one reversed (as trimmed surfaces of an IGES file
        # come): once sewn, every element faces away from the box's centre, and the
        # report view names the faces whose elements were turned.
        from freecad.templatequad import make_mesh
        box = Part.makeBox(10, 20, 30)
        faces = [f.copy() if i % 2 == 0 else f.copy().reversed() for i, f in enumerate(box.Faces)]
        part = self._part(Part.Compound(faces), "MixedFaces")
        messages = []
        print_message = FreeCAD.Console.PrintMessage
        FreeCAD.Console.PrintMessage = lambda text: messages.append(str(text))
        try:
            obj = make_mesh(self.doc, part, size=5.0, sew=True)
        finally:
            FreeCAD.Console.PrintMessage = print_message
        femmesh = obj.FemMesh
        centre = FreeCAD.Vector(5, 10, 15)
        for element in femmesh.Faces:
            a, b, c, d = (femmesh.getNodeById(n) for n in femmesh.getElementNodes(element))
            normal = (c - a).cross(d - b)
            outward = (a + b + c + d) * 0.25 - centre
            self.assertGreater(normal.dot(outward), 0, f"element {element} faces inwards")
        self.assertTrue(any("Face2, Face4, Face6: elements turned" in m for m in messages), messages)

    def test_changing_size_marks_the_mesh_out_of_date_until_meshed_again(self):
        from freecad.templatequad import make_mesh
        part = self._part(self._filleted_box(), "FilletedBox")
        mesh = make_mesh(self.doc, part, size=4.0)
        self.assertFalse(mesh.OutOfDate)
        coarse = mesh.FemMesh.FaceCount
        mesh.CharacteristicLengthMax = 2.0
        self.doc.recompute()  # FreeCAD's Gmsh object too meshes only when asked
        self.assertTrue(mesh.OutOfDate, "a recompute marks the mesh out of date")
        self.assertEqual(mesh.FemMesh.FaceCount, coarse, "and does not mesh again")
        mesh.Proxy.request_mesh(mesh)
        self.assertFalse(mesh.OutOfDate)
        fine = mesh.FemMesh.FaceCount
        self.assertGreater(fine, coarse, "a smaller size must give more elements")
        self.assertAlmostEqual(mesh.ElementSizeUsed.Value, 2.0, 9, "the size used is shown")
        self._assert_same_as_tquad(mesh, part.Shape, 2.0)

    def test_part_change_propagates(self):
        from freecad.templatequad import make_mesh
        box = self.doc.addObject("Part::Box", "Box")
        self.doc.recompute()
        mesh = make_mesh(self.doc, box, size=2.0)
        before = mesh.FemMesh.FaceCount
        box.Length = 30
        warnings = []
        print_warning = FreeCAD.Console.PrintWarning
        FreeCAD.Console.PrintWarning = lambda text: warnings.append(str(text))
        try:
            self.doc.recompute()
            self.doc.recompute()
        finally:
            FreeCAD.Console.PrintWarning = print_warning
        self.assertTrue(mesh.OutOfDate, "the part changed: the mesh is out of date")
        self.assertEqual(mesh.FemMesh.FaceCount, before, "kept until meshed again")
        self.assertEqual(len([w for w in warnings if "out of date" in w]), 1, f"said once: {warnings}")
        from freecad.templatequad import solver_guard
        self.assertIn("is out of date", solver_guard.incomplete_mesh_message(mesh), "a solver check stops")
        mesh.Proxy.request_mesh(mesh)
        self.assertGreater(mesh.FemMesh.FaceCount, before, "meshed again, the mesh follows its Part")
        self.assertEqual(solver_guard.incomplete_mesh_message(mesh), "")

    def test_faces_subset(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        mesh = make_mesh(self.doc, part, size=2.0, faces=["Face2"])
        reference = _tquad().mesh_shape(part.Shape.exportBrepToString(), size=2.0, faces=[1])
        self.assertEqual(mesh.FemMesh.FaceCount, len(reference.quads), "one face's quads")
        self.assertEqual(len(mesh.TemplateTrees), 1, "one face meshed")
        self.assertTrue(mesh.TemplateTrees[0].startswith("Face2:"), mesh.TemplateTrees[0])

    def test_fem_lookups_find_the_nodes_of_each_face_and_edge(self):
        # FEM constraints, materials and thicknesses find their nodes geometrically
        # (FemMesh.getNodesBy*), so every node must lie on its CAD face and edges.
        from freecad.templatequad import make_mesh
        shape = Part.Shape()
        shape.read(os.path.join(os.environ["TQ_TEST_DIR"], os.pardir, os.pardir,
                                "resources", "shapes", "plate_with_hole.brep"))
        part = self._part(shape, "Plate")
        femmesh = make_mesh(self.doc, part, size=3.0).FemMesh
        reference = _tquad().mesh_shape(shape.exportBrepToString(), size=3.0)
        for k, face in enumerate(shape.Faces):
            expected = len(set(reference.face_quads(k).flatten().tolist()))
            self.assertEqual(len(femmesh.getNodesByFace(face)), expected,
                             f"nodes found on Face{k + 1}")
        for k, edge in enumerate(shape.Edges):
            self.assertGreaterEqual(len(femmesh.getNodesByEdge(edge)), 2,
                                    f"nodes found on Edge{k + 1}")

    def test_refused_face_is_reported_and_keep_going_meshes_the_rest(self):
        from freecad.templatequad import make_mesh
        cone = drilled_cone_face()  # a pole and a hole: refused
        square = Part.makePlane(20, 20, FreeCAD.Vector(200, 0, 0))
        part = self._part(Part.makeCompound([cone, square]), "ConeAndSquare")
        with self.assertRaises(ValueError, msg="a refused face without KeepGoing") as caught:
            make_mesh(self.doc, part, size=5.0)
        error = str(caught.exception)
        self.assertIn("Face1", error, "the error maps tquad's face 0")
        self.assertIn("not supported", error, "the refusal's code is worded")
        self.assertIn("KeepGoing", error, "says which property meshes the rest")
        self.assertNotIn("--", error, "no command-line option in a FreeCAD message")
        warnings = []
        print_warning = FreeCAD.Console.PrintWarning
        FreeCAD.Console.PrintWarning = lambda text: warnings.append(str(text))
        try:
            mesh = make_mesh(self.doc, part, size=5.0, keep_going=True)
        finally:
            FreeCAD.Console.PrintWarning = print_warning
        self.assertTrue(any("ConeAndSquare Face1: " in w and "(not meshed)" in w for w in warnings),
                        f"the refused face is reported in the report view: {warnings}")
        self.assertEqual(list(mesh.RefusedFaceNames), ["Face1"], "the refused face, by name")
        self.assertTrue(mesh.Incomplete, "a mesh with a refused face is incomplete")
        self.assertEqual(len(mesh.RefusedFaces), 1, "one refused face")
        self.assertTrue(mesh.RefusedFaces[0].startswith("Face1: this kind of face is not supported"),
                        mesh.RefusedFaces[0])
        self.assertNotIn("face 0", mesh.RefusedFaces[0], "tquad's 0-based name is not shown")
        self.assertEqual([t.split(":")[0] for t in mesh.TemplateTrees], ["Face2"],
                         "the other face is meshed")
        self.assertEqual(mesh.FemMesh.FaceCount, 16, "20 x 20 square at size 5")
        mesh.Faces = ["Face2"]
        mesh.Proxy.request_mesh(mesh)
        self.assertFalse(mesh.Incomplete, "only the meshable face asked for: complete")
        self.assertEqual(list(mesh.RefusedFaceNames), [])

    def test_freecad_wording_of_tquad_messages(self):
        from freecad.templatequad import meshing
        cases = {
            "face 27: vertices 41, 42 and 7 are not on it; use a smaller --size":
                "Face28: Vertex42, Vertex43 and Vertex8 are not on it; use a smaller element size",
            "--corners: vertex 4 is not on the outer wire of face 2":
                "Corners: Vertex5 is not on the outer wire of Face3",
            "at least 5 quads, over the limit of 100 (--max-quads); use a larger --size":
                "at least 5 quads, over the limit of 100; use a larger element size",
            "edge 0: failed (a damaged curve?); node 5":
                "Edge1: failed (a damaged curve?); node 5",
            "1 face(s) refused: face 3: x (--keep-going meshes the other faces)":
                "1 face(s) refused: Face4: x",
            "--corners for face 998: the shape has faces 0..48":
                "Corners for Face999: the shape has Face1..Face49",
            "vertices 0..7 and edges 2..11":
                "Vertex1..Vertex8 and Edge3..Edge12",
        }
        for tquad_text, freecad_text in cases.items():
            self.assertEqual(meshing.freecad_wording(tquad_text), freecad_text)

    def test_second_order_quads_share_their_edge_middles(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeCylinder(5, 10), "Cylinder")
        first = make_mesh(self.doc, part, size=2.0)
        second = make_mesh(self.doc, part, size=2.0, element_order="2nd")
        quads = first.FemMesh.QuadrangleCount
        self.assertEqual(second.FemMesh.QuadrangleCount, quads)
        self.assertEqual(second.FemMesh.FaceCount, quads, "quads only")
        self.assertEqual(len(second.FemMesh.getElementNodes(1)), 8, "8-node quads")
        # A closed surface: 2 q edges, each with one middle node shared by its two quads.
        self.assertEqual(second.FemMesh.NodeCount, first.FemMesh.NodeCount + 2 * quads)
        self.assertEqual(second.ElementOrder, "2nd")
        second.ElementOrder = "1st"
        second.Proxy.request_mesh(second)
        self.assertEqual(second.FemMesh.NodeCount, first.FemMesh.NodeCount, "back to 4-node quads")
        with self.assertRaises(ValueError):
            make_mesh(self.doc, part, element_order="3rd")

    def test_size_floor_and_element_order(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        mesh = make_mesh(self.doc, part, min_size=8.0)
        self.assertAlmostEqual(mesh.ElementSizeUsed.Value, 8.0, 9,
                               "the automatic size (diagonal / 25 = 1.5) is raised to the minimum")
        self._assert_same_as_tquad(mesh, part.Shape, 8.0)
        self.assertEqual(mesh.ElementOrder, "1st")
        self.assertEqual(list(mesh.getEnumerationsOfProperty("ElementOrder")), ["1st", "2nd"])
        with self.assertRaises(ValueError) as caught:
            make_mesh(self.doc, part, size=2.0, min_size=3.0)
        self.assertIn("minimum element size (3) is larger than the element size (2)",
                      str(caught.exception))

    def test_files_saved_with_the_old_size_property_keep_their_size(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        mesh = make_mesh(self.doc, part, size=2.0)
        mesh.addProperty("App::PropertyLength", "Size", "TemplateQuad", "the old name")
        mesh.Size = 3.5
        mesh.CharacteristicLengthMax = 0.0
        mesh.Proxy.onDocumentRestored(mesh)
        self.assertNotIn("Size", mesh.PropertiesList, "the old property is removed")
        self.assertEqual(mesh.CharacteristicLengthMax.Value, 3.5, "its value is kept")

    def test_files_saved_when_only_first_order_was_offered_offer_second_order(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        mesh = make_mesh(self.doc, part, size=5.0)
        mesh.ElementOrder = ["1st"]  # as such a file has it
        mesh.Proxy.onDocumentRestored(mesh)
        self.assertEqual(list(mesh.getEnumerationsOfProperty("ElementOrder")), ["1st", "2nd"])
        self.assertEqual(mesh.ElementOrder, "1st", "its value is kept")

    def test_bad_corners_fail_loudly_and_leave_no_stale_mesh(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        mesh = make_mesh(self.doc, part, size=2.0)
        mesh.Corners = ["Face1:Vertex1,Vertex99"]  # well formed; the part has 8 vertices
        printed = []
        print_error = FreeCAD.Console.PrintError
        FreeCAD.Console.PrintError = lambda text: printed.append(str(text))
        try:
            mesh.Proxy.request_mesh(mesh)
        finally:
            FreeCAD.Console.PrintError = print_error
        # A user's error raises nothing into FreeCAD's recompute (which would print the
        # whole Python traceback): one line in the report view, the reason in Quality.
        self.assertNotIn("Invalid", mesh.State, "no exception reached the recompute")
        self.assertEqual(len(printed), 1, printed)
        self.assertIn("Face1", printed[0])
        self.assertIn("does not exist", printed[0])
        self.assertEqual(printed[0].count("\n"), 1, "one line")
        self.assertTrue(mesh.Quality.startswith("not meshed: "), mesh.Quality)
        self.assertEqual(mesh.FemMesh.FaceCount, 0, "a failed mesh must not keep old elements")
        self.assertIn("does not exist", mesh.Proxy.last_error, mesh.Proxy.last_error)
        # Later recomputes do not mesh it again, nor print its error again.
        errors = []
        print_error = FreeCAD.Console.PrintError
        FreeCAD.Console.PrintError = lambda text: errors.append(str(text))
        try:
            for _ in range(3):
                mesh.touch()
                self.doc.recompute()
        finally:
            FreeCAD.Console.PrintError = print_error
        self.assertEqual(errors, [], "the error is not printed again")
        self.assertTrue(mesh.OutOfDate)
        self.assertIn("does not exist", mesh.Proxy.last_error, "the reason is still there")
        with self.assertRaises(ValueError, msg="make_mesh raises by default"):
            make_mesh(self.doc, part, corners=["Face1:Vertex1"])

    def test_a_mesh_region_on_a_hole_refines_it_and_grades_out(self):
        # FEM's own Mesh region (ObjectsFem.makeMeshRegion) on a TemplateQuad mesh: the
        # hole of a 100 x 60 x 5 plate at 0.5 under a global 5 gets about 2 pi 8 / 0.5
        # segments on each rim, and the mesh stays under a fifth of a uniform 0.5 mesh.
        import ObjectsFem
        from freecad.templatequad import make_mesh, meshing
        plate = Part.makeBox(100, 60, 5).cut(
            Part.makeCylinder(8, 7, FreeCAD.Vector(50, 30, -1), FreeCAD.Vector(0, 0, 1)))
        part = self._part(plate, "HoledPlate")
        mesh = make_mesh(self.doc, part, size=5.0)
        coarse = mesh.FemMesh.FaceCount
        hole = next(i for i, f in enumerate(plate.Faces) if f.Surface.TypeId == "Part::GeomCylinder")
        region = ObjectsFem.makeMeshRegion(self.doc, mesh, 0.5)
        region.References = [(part, (f"Face{hole + 1}",))]
        self.assertEqual(meshing.region_sizes(mesh.MeshRegionList), {f"face{hole}": 0.5})
        mesh.Proxy.request_mesh(mesh)
        self.assertEqual(mesh.Proxy.last_error, "")
        fem = mesh.FemMesh
        for edge in plate.Faces[hole].Edges:
            if edge.Curve.TypeId != "Part::GeomCircle":
                continue
            on_rim = len(fem.getNodesByEdge(edge))
            self.assertAlmostEqual(on_rim, 2 * math.pi * 8 / 0.5, delta=4, msg="rim nodes")
        uniform = make_mesh(self.doc, part, size=0.5)
        self.assertGreater(fem.FaceCount, 2 * coarse, "the hole is finer")
        self.assertLess(5 * fem.FaceCount, uniform.FemMesh.FaceCount, "far under a uniform fine mesh")

    def test_element_owners_name_each_quads_face(self):
        from freecad.templatequad import make_mesh, worst_elements as we
        shape = self._filleted_box()
        part = self._part(shape, "Filleted")
        mesh = make_mesh(self.doc, part, size=4.0)
        reference = _tquad().mesh_shape(shape.exportBrepToString(), size=4.0)
        owners = list(mesh.ElementOwners)
        self.assertEqual(len(owners), 3 * len(shape.Faces))
        for record in reference.faces:
            for element in (record["first_quad"] + 1, record["first_quad"] + record["quad_count"]):
                self.assertEqual(we.owner_of(element, owners), record["face"])
        worst = we.worst_elements(list(mesh.ElementQuality), 3)
        self.assertAlmostEqual(worst[0][1], mesh.ScaledJacobianMin, places=9)

    def _groups(self, mesh):
        fem = mesh.FemMesh
        return {(fem.getGroupName(g), fem.getGroupElementType(g)): set(fem.getGroupElements(g))
                for g in fem.Groups}

    def test_mesh_groups_become_element_and_node_sets(self):
        # FEM's own Mesh group (ObjectsFem.makeMeshGroup) on a TemplateQuad mesh: a
        # group of faces is exactly their quads (and, with GroupsOfNodes, their nodes),
        # a group of edges and vertices the nodes on them; they survive save and reopen
        # and the export writes them as *ELSET and *NSET.
        import ObjectsFem
        from freecad.templatequad import commands, make_mesh
        plate = Part.makeBox(100, 60, 5).cut(
            Part.makeCylinder(8, 7, FreeCAD.Vector(50, 30, -1), FreeCAD.Vector(0, 0, 1)))
        part = self._part(plate, "HoledPlate")
        mesh = make_mesh(self.doc, part, size=5.0)
        hole = next(i for i, f in enumerate(plate.Faces) if f.Surface.TypeId == "Part::GeomCylinder")
        top = next(i for i, f in enumerate(plate.Faces) if f.BoundBox.ZMin > 5 - 1e-9)
        faces = ObjectsFem.makeMeshGroup(self.doc, mesh, True, "Faces")
        faces.Label = "HoleAndTop"
        faces.References = [(part, (f"Face{hole + 1}", f"Face{top + 1}"))]
        rim = next(i for i, e in enumerate(plate.Edges) if e.Curve.TypeId == "Part::GeomCircle")
        edges = ObjectsFem.makeMeshGroup(self.doc, mesh, False, "RimAndCorner")
        edges.References = [(part, (f"Edge{rim + 1}", "Vertex1"))]
        mesh.GroupsOfNodes = True
        mesh.Proxy.request_mesh(mesh)
        self.assertEqual(mesh.Proxy.last_error, "")
        reference = _tquad().mesh_shape(plate.exportBrepToString(), size=5.0)
        quads = set()
        for f in (hole, top):
            record = next(r for r in reference.faces if r["face"] == f)
            quads.update(range(record["first_quad"] + 1, record["first_quad"] + record["quad_count"] + 1))
        fem = mesh.FemMesh
        on_faces = set(fem.getNodesByFace(plate.Faces[hole])) | set(fem.getNodesByFace(plate.Faces[top]))
        on_rim = set(fem.getNodesByEdge(plate.Edges[rim])) | set(fem.getNodesByVertex(plate.Vertexes[0]))
        want = {("HoleAndTop", "Face"): quads, ("HoleAndTop", "Node"): on_faces,
                ("RimAndCorner", "Node"): on_rim}
        self.assertEqual(self._groups(mesh), want)
        self.assertGreater(len(quads), 20)
        self.assertGreater(len(on_rim), 10)

        folder = tempfile.mkdtemp(prefix="tq_groups_")
        try:
            written = os.path.join(folder, "plate.inp")
            commands.export_with_groups(mesh, written)
            text = open(written).read()
            for name, kind in (("HoleAndTop", "ELSET"), ("HoleAndTop", "NSET"), ("RimAndCorner", "NSET")):
                block = text.split(f"*{kind}, {kind}={name}\n")[1].split("\n\n")[0]
                ids = {int(n) for n in block.replace(",", " ").split()}
                self.assertEqual(ids, want[(name, "Face" if kind == "ELSET" else "Node")], (name, kind))
            self.assertEqual(os.listdir(folder), ["plate.inp"], "no temporary file left")
            saved = os.path.join(folder, "groups.FCStd")
            name = mesh.Name
            self.doc.saveAs(saved)
            FreeCAD.closeDocument(self.doc.Name)
            self.doc = FreeCAD.openDocument(saved)
            self.assertEqual(self._groups(self.doc.getObject(name)), want, "groups after reopening")
        finally:
            shutil.rmtree(folder, ignore_errors=True)

    def test_mesh_groups_of_a_swept_solid_and_wrong_groups(self):
        import ObjectsFem
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(20, 10, 5), "Block")
        mesh = make_mesh(self.doc, part, size=2.5, element_dimension="3D")
        solid = ObjectsFem.makeMeshGroup(self.doc, mesh, True, "All")
        solid.References = [(part, ("Solid1", "Face1"))]
        mesh.Proxy.request_mesh(mesh)
        self.assertEqual(mesh.Proxy.last_error, "")
        groups = self._groups(mesh)
        self.assertEqual(groups[("All", "Volume")], set(range(1, mesh.FemMesh.VolumeCount + 1)))
        self.assertEqual(groups[("All", "Node")], set(mesh.FemMesh.getNodesByFace(part.Shape.Faces[0])))

        mesh.ElementDimension = "2D"
        for references, needle in ((("Solid1",), "Solid1 has no elements in a 2D mesh"),
                                   (("Face9",), "Face9 does not exist; the part has Face1..Face6"),
                                   ((), "references nothing")):
            solid.References = [(part, references)] if references else []
            mesh.Proxy.request_mesh(mesh)
            self.assertIn(needle, mesh.Proxy.last_error)
            self.assertNotIn("\n", mesh.Proxy.last_error)
            self.assertEqual(mesh.FemMesh.NodeCount, 0, "no mesh kept on a wrong group")
        # FreeCAD keeps labels unique, unless its DuplicateLabels preference is on.
        from freecad.templatequad import meshing

        class Group:
            UseLabel, References = True, [(part, ("Face1",))]

            def __init__(self, label):
                self.Label = self.Name = label
        with self.assertRaisesRegex(ValueError, "another mesh group is named 'Twin' too"):
            meshing.mesh_groups([Group("Twin"), Group("Twin")])

    def test_a_size_larger_than_the_part_says_so(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        warnings = []
        print_warning = FreeCAD.Console.PrintWarning
        FreeCAD.Console.PrintWarning = lambda text: warnings.append(str(text))
        try:
            make_mesh(self.doc, part, size=1e6)
        finally:
            FreeCAD.Console.PrintWarning = print_warning
        self.assertTrue(any("the element size 1e+06 mm is larger than the part (37.42 mm across)" in w
                            for w in warnings), warnings)
        warnings.clear()
        FreeCAD.Console.PrintWarning = lambda text: warnings.append(str(text))
        try:
            make_mesh(self.doc, part, size=5.0)
        finally:
            FreeCAD.Console.PrintWarning = print_warning
        self.assertFalse(any("larger than the part" in w for w in warnings), warnings)

    def test_a_selection_of_edges_says_the_whole_part_is_meshed(self):
        from freecad.templatequad import commands
        self.assertEqual(commands.split_selection(["Face2", "Edge3", "Face5", "Vertex1"]),
                         (["Face2", "Face5"], ["Edge3", "Vertex1"]))
        self.assertEqual(commands.selection_note("Box", [], ["Edge3", "Vertex1"]),
                         "Edge3, Vertex1 of Box selected: not faces, so the whole of Box is meshed "
                         "(select faces to mesh only them)")
        self.assertEqual(commands.selection_note("Box", ["Face2"], ["Edge3"]), "", "faces are meshed")
        self.assertEqual(commands.selection_note("Box", [], []), "", "the part itself")

    def test_wrong_inputs_are_said_when_set_and_put_back(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        mesh = make_mesh(self.doc, part, size=5.0)
        cases = [("T4Ratio", 0, 2, "must be at least 2"),
                 ("Layers", -3, 0, "0 (layers from the element size) or more"),
                 ("MeshSizeFromCurvature", 4, 8, "8 (one element edge per 45 degrees) to 1000"),
                 ("GrowthRate", 0.5, 1.3, "over 1 and at most 10"),
                 ("Faces", ["Face99"], [], "Face99 does not exist; the part has Face1..Face6"),
                 ("Corners", ["Face1:Vertex1"], [], "2, 3 or 4 corners")]
        for prop, wrong, kept, reason in cases:
            with self.subTest(prop):
                printed = []
                print_error = FreeCAD.Console.PrintError
                FreeCAD.Console.PrintError = lambda text: printed.append(str(text))
                try:
                    setattr(mesh, prop, wrong)
                finally:
                    FreeCAD.Console.PrintError = print_error
                self.assertEqual(getattr(mesh, prop), kept, "put back")
                self.assertEqual(len(printed), 1, printed)
                self.assertIn(prop, printed[0])
                self.assertIn(reason, printed[0])
        # A right value is taken silently.
        mesh.T4Ratio = 3
        self.assertEqual(mesh.T4Ratio, 3)

    def test_corner_override_reaches_tquad(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        face = part.Shape.Faces[0]
        corners = [next(i for i, v in enumerate(part.Shape.Vertexes) if v.isSame(fv))
                   for fv in face.Vertexes][:3]  # 3 curves instead of the automatic 4
        entry = "Face1:" + ",".join(f"Vertex{i + 1}" for i in corners)
        mesh = make_mesh(self.doc, part, size=2.0, corners=[entry])
        reference = _tquad().mesh_shape(part.Shape.exportBrepToString(), size=2.0,
                                        corners={0: corners})
        self.assertEqual(mesh.TemplateTrees[0].split(" ")[1], reference.template_trees[0],
                         "the Corners property must reach tquad as 0-based vertex indices")
        self.assertEqual(mesh.FemMesh.FaceCount, len(reference.quads), "element count")

    def test_missing_tquad_module_is_reported(self):
        from freecad.templatequad import make_mesh
        part = self._part(Part.makeBox(10, 20, 30), "Box")
        saved = sys.modules.get("tquad")
        sys.modules["tquad"] = None  # makes "import tquad" raise ImportError
        try:
            with self.assertRaises(ValueError) as caught:
                make_mesh(self.doc, part)
        finally:
            sys.modules["tquad"] = saved
        self.assertIn("'tquad' was not found", str(caught.exception), "the user's message")
        self.assertIn("install.sh", str(caught.exception), "says how to fix it")

    def test_saved_document_reopens_and_remeshes(self):
        from freecad.templatequad import make_mesh
        part = self._part(self._filleted_box(), "FilletedBox")
        mesh = make_mesh(self.doc, part, size=4.0, t4_ratio=3, keep_going=True)
        count, name = mesh.FemMesh.FaceCount, mesh.Name
        quality = list(mesh.ElementQuality)
        self.assertEqual(len(quality), count, "one scaled Jacobian per quad")
        self.assertAlmostEqual(min(quality), mesh.ScaledJacobianMin, 12)
        self.assertIn("Hidden", mesh.getEditorMode("ElementQuality"), "not a list in the editor")
        path = os.path.join(tempfile.mkdtemp(), "tq.FCStd")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        mesh = self.doc.getObject(name)
        self.assertEqual(mesh.Proxy.Type, "TemplateQuad::Mesh", "proxy restored")
        self.assertEqual((mesh.T4Ratio, mesh.KeepGoing, mesh.CharacteristicLengthMax.Value), (3, True, 4.0),
                         "inputs restored")
        self.assertEqual(mesh.FemMesh.FaceCount, count, "saved mesh restored")
        self.assertEqual(list(mesh.ElementQuality), quality, "its quality too (the colour map)")
        self.assertIn("Hidden", mesh.getEditorMode("ElementQuality"))
        mesh.Proxy.request_mesh(mesh)
        self.assertEqual(mesh.FemMesh.FaceCount, count, "re-mesh after reopening")



class BadInputInFreeCadTest(unittest.TestCase):
    """Bad shapes and parameters given to the mesh object inside FreeCAD: make_mesh
    raises ValueError, the document keeps exactly the objects it had (the Part
    untouched), and the message goes to the report view (FreeCAD.Console.PrintError).
    Open and non-manifold shells are meshed. The same inputs through the CLI and the
    module: tests/python/bad_input_matrix.py."""

    SHAPES = os.path.normpath(os.path.join(os.environ.get("TQ_TEST_DIR", "."), os.pardir, os.pardir,
                                           "resources", "shapes"))

    def setUp(self):
        self.doc = FreeCAD.newDocument("TemplateQuadBadInput")
        self.printed = []
        self._print_error = FreeCAD.Console.PrintError
        FreeCAD.Console.PrintError = lambda text: self.printed.append(str(text))

    def tearDown(self):
        FreeCAD.Console.PrintError = self._print_error
        FreeCAD.closeDocument(self.doc.Name)

    def _part(self, shape, name):
        return _add_part(self.doc, shape, name)

    def _refused(self, part, expect, **options):
        from freecad.templatequad import make_mesh
        names = sorted(o.Name for o in self.doc.Objects)
        shape_before = part.Shape.exportBrepToString()
        self.printed.clear()
        with self.assertRaises(ValueError) as caught:
            make_mesh(self.doc, part, **options)
        message = str(caught.exception)
        for text in expect:
            self.assertIn(text, message)
        self.assertEqual(sorted(o.Name for o in self.doc.Objects), names, "the document's objects")
        self.assertEqual(part.Shape.exportBrepToString(), shape_before, "the Part's shape")
        self.assertTrue(any(message in line for line in self.printed),
                        f"'{message}' not in the report view: {self.printed}")
        # Once, as one line: no traceback, nothing printed twice.
        self.assertEqual(len(self.printed), 1, self.printed)
        self.assertEqual(self.printed[0].rstrip("\n").count("\n"), 0, self.printed[0])

    def test_bad_shapes_and_parameters_leave_the_document_as_it_was(self):
        box = self._part(Part.makeBox(100, 60, 10), "Box")
        wire = self._part(Part.Wire(Part.makeCircle(10)), "Circle")
        cone = self._part(drilled_cone_face(), "DrilledCone")  # its one face is refused
        cases = [
            ("a Part with no face", wire, ["has no faces to mesh"], {}),
            ("size 1e-7 on a 100 mm box", box, ["segments", "the size is too small"], {"size": 1e-7}),
            ("negative size", box, ["size must be"], {"size": -1.0}),
            ("NaN size", box, ["size must be"], {"size": float("nan")}),
            ("a face that does not exist", box, ["does not exist"], {"faces": ["Face99"]}),
            ("a corner vertex that does not exist", box, ["does not exist"], {"corners": ["Face1:Vertex99,Vertex1"]}),
            ("one corner", box, ["2, 3 or 4 corners"], {"corners": ["Face1:Vertex1"]}),
            ("every face refused, keep going", cone, ["no face"], {"keep_going": True}),
        ]
        for name, part, expect, options in cases:
            with self.subTest(name):
                self._refused(part, expect, **options)

    def test_open_and_non_manifold_shells_are_meshed_like_the_module_meshes_them(self):
        from freecad.templatequad import make_mesh
        for name in ("open_box", "three_fins"):
            with self.subTest(name):
                path = os.path.join(self.SHAPES, name + ".brep")
                part = self._part(Part.read(path), name)
                mesh = make_mesh(self.doc, part, size=4.0)
                reference = _tquad().mesh_shape(part.Shape.exportBrepToString(), size=4.0)
                self.assertEqual(mesh.FemMesh.QuadrangleCount, len(reference.quads))
                self.assertEqual(mesh.FemMesh.NodeCount, len(reference.nodes))
                self.assertEqual(list(mesh.RefusedFaces), [])


if __name__ == "__main__":
    unittest.main()
