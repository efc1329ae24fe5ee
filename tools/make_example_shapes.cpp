// make_example_shapes: writes the project's example CAD shapes (units mm), whose faces
// are good inputs for the 2/3/4-curve templates: faces bounded by one wire of 1 to 4
// edges, mostly.
//
//   make_example_shapes [DIR]      (DIR defaults to resources/shapes)
//
// Writes DIR/<name>.brep for each shape and DIR/plate_with_hole.step, and prints, for
// each shape, its faces with their wires and edges and whether it is valid and closed.
// Exit status 1 when a shape fails its checks or a file cannot be written.
#include <array>
#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepLib.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <StepData_StepModel.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax2.hxx>
#include <gp_Ax3.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace {

// Thrown by the builders below when OpenCASCADE reports failure without an exception.
struct BuildError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void require(bool ok, const std::string& what) {
  if (!ok) throw BuildError(what);
}

// ---------------------------------------------------------------------------------
// 1. Plate 100 x 60 with a central hole of diameter 20, as an open shell of four
//    faces. The cuts run from the hole to the rectangle's corners (along the
//    diagonals), so every face has one wire of 4 edges: rectangle side, cut, arc, cut.
//    Faces are built from shared TopoDS_Edges, so the shell is connected by
//    construction and no sewing (which could replace edges) is needed.
// ---------------------------------------------------------------------------------
TopoDS_Shape make_plate_with_hole() {
  const double length = 100.0, width = 60.0, radius = 10.0;
  const gp_Pnt centre(length / 2, width / 2, 0.0);

  // Rectangle corners, counter-clockwise from the origin: SW, SE, NE, NW.
  const std::array<gp_Pnt, 4> corner = {gp_Pnt(0, 0, 0), gp_Pnt(length, 0, 0),
                                        gp_Pnt(length, width, 0), gp_Pnt(0, width, 0)};
  std::array<TopoDS_Vertex, 4> corner_v, hole_v;
  for (int i = 0; i < 4; ++i) {
    corner_v[i] = BRepBuilderAPI_MakeVertex(corner[i]);
    // The hole point on the diagonal from the centre towards corner i.
    gp_Vec dir(centre, corner[i]);
    dir.Normalize();
    hole_v[i] = BRepBuilderAPI_MakeVertex(centre.Translated(dir * radius));
  }

  // side[i]: corner i -> corner i+1 (side i+1 of the rectangle, counter-clockwise);
  // cut[i]: corner i -> hole point i; arc[i]: hole point i -> hole point i+1 along
  // the circle, counter-clockwise.
  const gp_Circ circle(gp_Ax2(centre, gp::DZ()), radius);
  std::array<TopoDS_Edge, 4> side, cut, arc;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    BRepBuilderAPI_MakeEdge make_side(corner_v[i], corner_v[j]);
    BRepBuilderAPI_MakeEdge make_cut(corner_v[i], hole_v[i]);
    BRepBuilderAPI_MakeEdge make_arc(circle, hole_v[i], hole_v[j]);
    require(make_side.IsDone() && make_cut.IsDone() && make_arc.IsDone(),
            "plate_with_hole: edge construction failed");
    side[i] = make_side.Edge();
    cut[i] = make_cut.Edge();
    arc[i] = make_arc.Edge();
  }

  // Face i lies between diagonals i and i+1: its boundary, counter-clockwise seen
  // from +z, is side i, cut i+1, arc i reversed (the hole is passed clockwise), cut i
  // reversed. All faces have normal +z, so shared cuts are used in opposite senses.
  BRep_Builder builder;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    BRepBuilderAPI_MakeWire make_wire;
    make_wire.Add(side[i]);
    make_wire.Add(cut[j]);
    make_wire.Add(TopoDS::Edge(arc[i].Reversed()));
    make_wire.Add(TopoDS::Edge(cut[i].Reversed()));
    require(make_wire.IsDone(), "plate_with_hole: wire construction failed");
    BRepBuilderAPI_MakeFace make_face(gp_Pln(gp::XOY()), make_wire.Wire(), Standard_True);
    require(make_face.IsDone(), "plate_with_hole: face construction failed");
    TopoDS_Face face = make_face.Face();
    // Store the 2D curves explicitly, so readers need not compute them on the fly.
    TopTools_ListOfShape edges;
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) edges.Append(ex.Current());
    BRepLib::BuildPCurveForEdgesOnPlane(edges, face);
    builder.Add(shell, face);
  }
  shell.Closed(BRep_Tool::IsClosed(shell));
  return shell;
}

// ---------------------------------------------------------------------------------
// 2. L-shaped bracket: profile 40 x 40 outside, 8 thick, in the XZ plane, extruded
//    30 along +y, with a fillet of radius 5 on the inner corner edge.
// ---------------------------------------------------------------------------------
TopoDS_Shape make_filleted_bracket() {
  const double leg = 40.0, thick = 8.0, depth = 30.0, fillet_radius = 5.0;
  BRepBuilderAPI_MakePolygon profile;
  profile.Add(gp_Pnt(0, 0, 0));
  profile.Add(gp_Pnt(leg, 0, 0));
  profile.Add(gp_Pnt(leg, 0, thick));
  profile.Add(gp_Pnt(thick, 0, thick));
  profile.Add(gp_Pnt(thick, 0, leg));
  profile.Add(gp_Pnt(0, 0, leg));
  profile.Close();
  require(profile.IsDone(), "filleted_bracket: profile failed");
  BRepBuilderAPI_MakeFace profile_face(profile.Wire(), Standard_True);
  require(profile_face.IsDone(), "filleted_bracket: profile face failed");
  BRepPrimAPI_MakePrism prism(profile_face.Face(), gp_Vec(0, depth, 0));
  require(prism.IsDone(), "filleted_bracket: extrusion failed");

  // The inner corner edge is the one whose two vertices both have x = z = thick.
  BRepFilletAPI_MakeFillet fillet(prism.Shape());
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(prism.Shape(), TopAbs_EDGE, edges);
  int found = 0;
  for (int i = 1; i <= edges.Extent(); ++i) {
    TopoDS_Vertex a, b;
    TopExp::Vertices(TopoDS::Edge(edges(i)), a, b);
    const gp_Pnt pa = BRep_Tool::Pnt(a), pb = BRep_Tool::Pnt(b);
    auto at_corner = [&](const gp_Pnt& p) {
      return std::abs(p.X() - thick) < 1e-9 && std::abs(p.Z() - thick) < 1e-9;
    };
    if (at_corner(pa) && at_corner(pb)) {
      fillet.Add(fillet_radius, TopoDS::Edge(edges(i)));
      ++found;
    }
  }
  require(found == 1, "filleted_bracket: inner corner edge not found exactly once");
  fillet.Build();
  require(fillet.IsDone(), "filleted_bracket: fillet failed");
  return fillet.Shape();
}

// ---------------------------------------------------------------------------------
// 3. Cylinder radius 10, height 30: lateral face with a seam edge, two disk faces.
// ---------------------------------------------------------------------------------
TopoDS_Shape make_cylinder() {
  BRepPrimAPI_MakeCylinder cylinder(10.0, 30.0);
  cylinder.Build();
  require(cylinder.IsDone(), "cylinder: construction failed");
  return cylinder.Shape();
}

// ---------------------------------------------------------------------------------
// 4. One B-spline face interpolating z = 5 sin(x/20) cos(y/25) on a 5 x 5 grid over
//    [0,100] x [0,60], bounded by its four natural boundary edges.
// ---------------------------------------------------------------------------------
TopoDS_Shape make_bspline_patch() {
  TColgp_Array2OfPnt points(1, 5, 1, 5);
  for (int i = 1; i <= 5; ++i) {
    for (int j = 1; j <= 5; ++j) {
      const double x = 25.0 * (i - 1), y = 15.0 * (j - 1);
      points(i, j) = gp_Pnt(x, y, 5.0 * std::sin(x / 20.0) * std::cos(y / 25.0));
    }
  }
  GeomAPI_PointsToBSplineSurface fit;
  fit.Interpolate(points);  // degree 3, C2, through the points exactly
  require(fit.IsDone(), "bspline_patch: interpolation failed");
  BRepBuilderAPI_MakeFace make_face(fit.Surface(), 1e-7);
  require(make_face.IsDone(), "bspline_patch: face construction failed");
  return make_face.Face();
}

// ---------------------------------------------------------------------------------
// 5. Open box: the shell of a 40 x 30 x 20 box without its top face (z = 20); the
//    top face's four edges are free edges, the others are shared by two faces.
// ---------------------------------------------------------------------------------
TopoDS_Shape make_open_box() {
  BRepPrimAPI_MakeBox box(40.0, 30.0, 20.0);
  box.Build();
  require(box.IsDone(), "open_box: box construction failed");
  BRep_Builder builder;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  int kept = 0;
  for (TopExp_Explorer it(box.Shell(), TopAbs_FACE); it.More(); it.Next()) {
    BRepAdaptor_Surface surface(TopoDS::Face(it.Current()));
    const gp_Pln plane = surface.Plane();
    const bool top = plane.Axis().Direction().IsParallel(gp::DZ(), 1e-9) && std::abs(plane.Location().Z() - 20.0) < 1e-9;
    if (top) continue;
    builder.Add(shell, it.Current());
    ++kept;
  }
  require(kept == 5, "open_box: the top face was not found exactly once");
  return shell;
}

// ---------------------------------------------------------------------------------
// 6. Three fins: three 40 x 20 planar faces on one edge (0,0,0)-(40,0,0), at 0, 90
//    and 225 degrees around it, in one shell: the edge is shared by three faces (a
//    non-manifold shell, as stiffeners on a plate make).
// ---------------------------------------------------------------------------------
TopoDS_Shape make_three_fins() {
  const TopoDS_Vertex a = BRepBuilderAPI_MakeVertex(gp_Pnt(0, 0, 0));
  const TopoDS_Vertex b = BRepBuilderAPI_MakeVertex(gp_Pnt(40, 0, 0));
  const TopoDS_Edge spine = BRepBuilderAPI_MakeEdge(a, b);
  BRep_Builder builder;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  for (const double degrees : {0.0, 90.0, 225.0}) {
    const double t = degrees * M_PI / 180.0;
    const gp_Vec out(0, 20 * std::cos(t), 20 * std::sin(t));
    const TopoDS_Vertex c = BRepBuilderAPI_MakeVertex(gp_Pnt(40, 0, 0).Translated(out));
    const TopoDS_Vertex d = BRepBuilderAPI_MakeVertex(gp_Pnt(0, 0, 0).Translated(out));
    BRepBuilderAPI_MakeWire wire(spine, BRepBuilderAPI_MakeEdge(b, c), BRepBuilderAPI_MakeEdge(c, d),
                                 BRepBuilderAPI_MakeEdge(d, a));
    require(wire.IsDone(), "three_fins: wire construction failed");
    const gp_Pln plane(gp_Ax3(gp_Pnt(0, 0, 0), gp_Dir(gp_Vec(1, 0, 0).Crossed(out)), gp::DX()));
    BRepBuilderAPI_MakeFace face(plane, wire.Wire());
    require(face.IsDone(), "three_fins: face construction failed");
    builder.Add(shell, face.Face());
  }
  return shell;
}

// ---------------------------------------------------------------------------------
// Reporting and checks.
// ---------------------------------------------------------------------------------
const char* surface_name(GeomAbs_SurfaceType type) {
  switch (type) {
    case GeomAbs_Plane: return "plane";
    case GeomAbs_Cylinder: return "cylinder";
    case GeomAbs_Cone: return "cone";
    case GeomAbs_Sphere: return "sphere";
    case GeomAbs_Torus: return "torus";
    case GeomAbs_BezierSurface: return "bezier";
    case GeomAbs_BSplineSurface: return "bspline";
    default: return "other";
  }
}

const char* curve_name(const TopoDS_Edge& edge) {
  if (BRep_Tool::Degenerated(edge)) return "degenerated";
  switch (BRepAdaptor_Curve(edge).GetType()) {
    case GeomAbs_Line: return "line";
    case GeomAbs_Circle: return "circle";
    case GeomAbs_Ellipse: return "ellipse";
    case GeomAbs_BezierCurve: return "bezier";
    case GeomAbs_BSplineCurve: return "bspline";
    default: return "other";
  }
}

struct ShapeSummary {
  std::vector<std::vector<int>> edges_per_wire;  // per face, per wire
  int free_edges = 0;    // edges of one face only
  int shared_edges = 0;  // edges of two faces
  int other_edges = 0;   // edges of more than two faces (non-manifold)
  bool valid = false;
};

// Prints the face/wire/edge table of one shape and returns its counts. Faces are
// listed in TopExp::MapShapes order (the order FreeCAD's shape.Faces uses too).
ShapeSummary describe(const std::string& name, const TopoDS_Shape& shape) {
  ShapeSummary summary;
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  std::cout << name << ": " << faces.Extent() << " face(s)\n";
  for (int f = 1; f <= faces.Extent(); ++f) {
    const TopoDS_Face face = TopoDS::Face(faces(f));
    std::vector<int> wires;
    std::ostringstream line;
    line << "  face " << f << " (" << surface_name(BRepAdaptor_Surface(face).GetType())
         << ")";
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    for (TopoDS_Iterator w(face); w.More(); w.Next()) {
      if (w.Value().ShapeType() != TopAbs_WIRE) continue;
      int count = 0;
      std::ostringstream types;
      // TopoDS_Iterator lists a seam edge twice (once per orientation), as a loop
      // around the face does.
      for (TopoDS_Iterator e(w.Value()); e.More(); e.Next()) {
        types << (count ? " " : "") << curve_name(TopoDS::Edge(e.Value()));
        ++count;
      }
      wires.push_back(count);
      line << (wires.size() == 1 ? ": " : "; ") << (w.Value().IsSame(outer) ? "outer" : "inner")
           << " wire " << count << " edge(s) [" << types.str() << "]";
    }
    line << " -> " << wires.size() << " wire(s)";
    std::cout << line.str() << "\n";
    summary.edges_per_wire.push_back(wires);
  }

  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    if (BRep_Tool::Degenerated(TopoDS::Edge(edge_faces.FindKey(i)))) continue;
    // A seam edge appears twice in its face's ancestor list: count distinct faces.
    TopTools_IndexedMapOfShape distinct;
    for (const TopoDS_Shape& s : edge_faces(i)) distinct.Add(s);
    const int n = distinct.Extent();
    if (n == 1 && BRep_Tool::IsClosed(TopoDS::Edge(edge_faces.FindKey(i)),
                                      TopoDS::Face(distinct(1)))) {
      ++summary.shared_edges;  // a seam joins its face to itself
    } else if (n <= 1) {
      ++summary.free_edges;
    } else if (n == 2) {
      ++summary.shared_edges;
    } else {
      ++summary.other_edges;
    }
  }

  summary.valid = BRepCheck_Analyzer(shape).IsValid();
  TopTools_IndexedMapOfShape shells, solids;
  TopExp::MapShapes(shape, TopAbs_SHELL, shells);
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  std::cout << "  " << edge_faces.Extent() << " edge(s): " << summary.shared_edges
            << " shared by two faces (or seam), " << summary.free_edges << " free, "
            << summary.other_edges << " non-manifold\n";
  std::cout << "  solids " << solids.Extent() << ", shells " << shells.Extent();
  for (int s = 1; s <= shells.Extent(); ++s) {
    std::cout << (s == 1 ? " (" : ", ")
              << (BRep_Tool::IsClosed(shells(s)) ? "closed" : "open");
    if (s == shells.Extent()) std::cout << ")";
  }
  std::cout << "; BRepCheck_Analyzer " << (summary.valid ? "valid" : "INVALID") << "\n";
  return summary;
}

// The plate must be one connected shell whose four faces each have one wire of 4
// edges; the four cuts are shared by two faces, the 4 sides and 4 arcs by one.
bool check_plate(const TopoDS_Shape& plate, const ShapeSummary& summary) {
  bool ok = summary.valid && summary.edges_per_wire.size() == 4;
  for (const auto& wires : summary.edges_per_wire)
    ok = ok && wires.size() == 1 && wires[0] == 4;
  ok = ok && summary.shared_edges == 4 && summary.free_edges == 8 && summary.other_edges == 0;

  // Connectivity: walk from face 1 across shared edges.
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(plate, TopAbs_FACE, faces);
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(plate, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  std::vector<bool> reached(faces.Extent() + 1, false);
  std::vector<int> stack = {1};
  reached[1] = true;
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    for (TopExp_Explorer ex(faces(f), TopAbs_EDGE); ex.More(); ex.Next()) {
      for (const TopoDS_Shape& g : edge_faces.FindFromKey(ex.Current())) {
        const int k = faces.FindIndex(g);
        if (k > 0 && !reached[k]) {
          reached[k] = true;
          stack.push_back(k);
        }
      }
    }
  }
  int connected = 0;
  for (int f = 1; f <= faces.Extent(); ++f) connected += reached[f] ? 1 : 0;
  std::cout << "  check: " << connected << " of " << faces.Extent()
            << " faces connected through shared edges\n";
  return ok && connected == faces.Extent();
}

int count(const TopoDS_Shape& shape, TopAbs_ShapeEnum type) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, type, map);
  return map.Extent();
}

// Reading a file back must give as many faces and edges as were written.
bool same_counts(const TopoDS_Shape& written, const TopoDS_Shape& read) {
  return !read.IsNull() && count(read, TopAbs_FACE) == count(written, TopAbs_FACE) &&
         count(read, TopAbs_EDGE) == count(written, TopAbs_EDGE);
}

bool write_brep(const TopoDS_Shape& shape, const std::filesystem::path& path) {
  // Format version 1 without triangles: readable by any OpenCASCADE 7.x.
  bool ok = BRepTools::Write(shape, path.string().c_str(), Standard_False, Standard_False,
                             TopTools_FormatVersion_VERSION_1);
  TopoDS_Shape read;
  ok = ok && BRepTools::Read(read, path.string().c_str(), BRep_Builder()) &&
       same_counts(shape, read);
  std::cout << "  wrote " << path.string() << (ok ? " (read back)" : " FAILED") << "\n";
  return ok;
}

bool write_step(const TopoDS_Shape& shape, const std::filesystem::path& path,
                const std::string& product) {
  STEPControl_Writer writer;  // its constructor initialises the STEP controller
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  Interface_Static::SetCVal("write.step.unit", "MM");
  Interface_Static::SetCVal("write.step.product.name", product.c_str());
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone) {
    std::cout << "  STEP transfer of " << product << " FAILED\n";
    return false;
  }
  // Fixed header fields instead of the current time and full path, so that repeated
  // runs give the same bytes.
  APIHeaderSection_MakeHeader header(writer.Model());
  header.SetName(new TCollection_HAsciiString(path.filename().string().c_str()));
  header.SetTimeStamp(new TCollection_HAsciiString("2000-01-01T00:00:00"));
  bool ok = writer.Write(path.string().c_str()) == IFSelect_RetDone;
  STEPControl_Reader reader;
  ok = ok && reader.ReadFile(path.string().c_str()) == IFSelect_RetDone &&
       reader.TransferRoots() > 0 && same_counts(shape, reader.OneShape());
  std::cout << "  wrote " << path.string() << (ok ? " (read back)" : " FAILED") << "\n";
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "resources/shapes";
  // The STEP translator reports its statistics as info messages on stdout; keep
  // warnings and errors only, so the output is this program's table.
  for (const Handle(Message_Printer)& printer : Message::DefaultMessenger()->Printers())
    printer->SetTraceLevel(Message_Warning);
  try {
    std::filesystem::create_directories(dir);
    bool ok = true;

    const TopoDS_Shape plate = make_plate_with_hole();
    const ShapeSummary plate_summary = describe("plate_with_hole", plate);
    const bool plate_ok = check_plate(plate, plate_summary);
    std::cout << "  check: " << (plate_ok ? "passed" : "FAILED") << "\n";
    ok = plate_ok && ok;
    ok = write_brep(plate, dir / "plate_with_hole.brep") && ok;
    ok = write_step(plate, dir / "plate_with_hole.step", "plate_with_hole") && ok;

    struct Solid {
      const char* name;
      TopoDS_Shape (*make)();
      int faces;
    };
    // Expected face counts: bracket 8 prism faces + 1 fillet face; cylinder lateral +
    // two disks; patch one face.
    const Solid others[] = {{"filleted_bracket", make_filleted_bracket, 9},
                            {"cylinder", make_cylinder, 3},
                            {"bspline_patch", make_bspline_patch, 1}};
    for (const Solid& s : others) {
      const TopoDS_Shape shape = s.make();
      const ShapeSummary summary = describe(s.name, shape);
      bool shape_ok = summary.valid && int(summary.edges_per_wire.size()) == s.faces &&
                      summary.other_edges == 0;
      // The two solids must be closed; the patch is one face with 4 free edges.
      if (shape.ShapeType() == TopAbs_SOLID) {
        shape_ok = shape_ok && summary.free_edges == 0;
      } else {
        shape_ok = shape_ok && summary.edges_per_wire[0] == std::vector<int>{4};
      }
      std::cout << "  check: " << (shape_ok ? "passed" : "FAILED") << "\n";
      ok = shape_ok && ok;
      ok = write_brep(shape, dir / (std::string(s.name) + ".brep")) && ok;
    }
    // Open and non-manifold shells: faces valid one by one, edges free or shared by
    // three faces.
    struct Shell {
      const char* name;
      TopoDS_Shape (*make)();
      int faces, free_edges;
    };
    const Shell shells[] = {{"open_box", make_open_box, 5, 4}, {"three_fins", make_three_fins, 3, 9}};
    for (const Shell& s : shells) {
      const TopoDS_Shape shape = s.make();
      const ShapeSummary summary = describe(s.name, shape);
      bool faces_ok = int(summary.edges_per_wire.size()) == s.faces && summary.free_edges == s.free_edges;
      for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
        faces_ok = faces_ok && BRepCheck_Analyzer(it.Current()).IsValid();
      }
      std::cout << "  check: " << (faces_ok ? "passed" : "FAILED") << "\n";
      ok = faces_ok && ok;
      ok = write_brep(shape, dir / (std::string(s.name) + ".brep")) && ok;
    }
    return ok ? 0 : 1;
  } catch (const Standard_Failure& e) {
    std::cerr << "make_example_shapes: OpenCASCADE error: " << e.GetMessageString() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "make_example_shapes: " << e.what() << "\n";
  }
  return 1;
}
