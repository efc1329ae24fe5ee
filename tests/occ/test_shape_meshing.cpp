// Meshes every face of the example shapes (resources/shapes) and of the real CAD parts
// in ../shared/data/cad (skipped when that folder is absent) and checks each mesh:
// all quads and conforming; watertight where the shape's topology is closed; every
// node on its face; no quad corner inverted against the face's outer normal at its
// node; every refused face with a reason. Prints a table of faces meshed and refused per file.
#include <gtest/gtest.h>

#include "../case_stride.h"

#include <stdexcept>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Circ.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <GeomAbs_SurfaceType.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_Plane.hxx>
#include <TopLoc_Location.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <gp_Elips.hxx>
#include <gp_Ax1.hxx>
#include <BRepTools.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pln.hxx>
#include <Bnd_Box.hxx>
#include <ShapeAnalysis_Surface.hxx>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <set>

#include "core/input_error.h"
#include "generated_parts.h"
#include "core/mesh/quadratic_quad.h"
#include "core/mesh/quality.h"
#include "occ/face/face_mesher.h"
#include "occ/model/shape_index.h"
#include "occ/model/edge_contraction.h"
#include "occ/shape_mesher.h"
#include "occ/read/shape_reader.h"

namespace tquad {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> shape_files(const fs::path& dir) {
  std::vector<std::string> files;
  if (!fs::is_directory(dir)) return files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (is_shape_path(entry.path().string())) files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Every non-degenerate edge bounds two faces or is a seam: a closed shell.
bool topology_is_closed(const ShapeIndex& index) {
  for (int e = 0; e < index.edge_count(); ++e) {
    if (BRep_Tool::Degenerated(index.edge(e))) continue;
    const auto& faces = index.faces_of_edge(e);
    if (faces.size() == 2) continue;
    if (faces.size() == 1 && BRep_Tool::IsClosed(index.edge(e), index.face(faces[0]))) continue;
    return false;
  }
  return true;
}

double diagonal(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  return std::sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0) + (z1 - z0) * (z1 - z0));
}

struct FileReport {
  int faces = 0, meshed = 0, refused = 0;
  long long quads = 0;
  bool closed = false;
};

// The most faces that share one edge of the shape (at least 2).
int most_faces_on_one_edge(const TopoDS_Shape& shape) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  int most = 2;
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    TopTools_MapOfShape distinct;
    for (const TopoDS_Shape& face : edge_faces(i)) distinct.Add(face);
    most = std::max(most, distinct.Extent());
  }
  return most;
}

FileReport check_file(const std::string& path) {
  FileReport report;
  const TopoDS_Shape shape = read_shape(path);
  const ShapeIndex index(shape);
  ShapeMeshOptions options;
  options.keep_going = true;
  options.order = 2;  // the same quads as at first order, with their edge middles checked too
  const ShapeMeshResult result = mesh_shape(shape, options);
  const ShapeMesh& mesh = result.mesh;
  report.faces = index.face_count();
  report.meshed = static_cast<int>(mesh.faces.size());
  report.refused = static_cast<int>(mesh.refused_faces.size());
  report.quads = static_cast<long long>(mesh.quads.size());
  report.closed = topology_is_closed(index);
  EXPECT_EQ(report.meshed + report.refused, report.faces) << path;
  for (const RefusedFace& r : mesh.refused_faces) {
    EXPECT_FALSE(r.reason.empty()) << path << " face " << r.face;
  }

  // Conforming everywhere (a mesh edge in at most as many quads as faces share a
  // shape edge: 2, or more on a non-manifold shell); watertight when the shape is
  // closed and nothing refused.
  const int faces_per_edge = most_faces_on_one_edge(shape);
  std::map<std::pair<NodeId, NodeId>, int> uses;
  for (const Quad& q : mesh.quads) {
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < i; ++j) EXPECT_NE(q[i], q[j]) << path << ": a quad repeats a node";
      const NodeId a = q[i], b = q[(i + 1) % 4];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  // One middle per mesh edge, shared by its quads, and no quad folded by its middles.
  EXPECT_EQ(mesh.mid_nodes.size(), mesh.quads.size()) << path;
  if (mesh.mid_nodes.size() != mesh.quads.size()) return report;
  std::map<std::pair<NodeId, NodeId>, NodeId> middle_of;
  for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
    for (int i = 0; i < 4; ++i) {
      const NodeId m = mesh.mid_nodes[k][i];
      const auto [it, added] = middle_of.emplace(std::minmax(mesh.quads[k][i], mesh.quads[k][(i + 1) % 4]), m);
      EXPECT_EQ(it->second, m) << path << ": quad " << k << " edge " << i << " has another middle than its neighbour";
    }
    EXPECT_GT(quadratic_quad_min_scaled_jacobian(element_positions(mesh, k)), 0.0) << path << ": quad " << k << " folds";
  }
  EXPECT_EQ(mesh.nodes.size(), uses.size() + std::set<NodeId>([&] {
                                 std::set<NodeId> corners;
                                 for (const Quad& q : mesh.quads) corners.insert(q.begin(), q.end());
                                 return corners;
                               }()).size())
      << path << ": nodes are the corners and one middle per edge";
  const bool watertight_expected = report.closed && report.refused == 0;
  for (const auto& [edge, count] : uses) {
    EXPECT_LE(count, faces_per_edge) << path << ": mesh edge " << edge.first << "-" << edge.second << " in " << count << " quads";
    if (watertight_expected) EXPECT_EQ(count, 2) << path << ": open mesh edge " << edge.first << "-" << edge.second;
  }

  // Nodes on their faces; quads facing the outer normal. A contracted edge's node
  // stands for both its vertices (edge_contraction.h): off the faces at the other
  // vertex by up to the edge's length.
  const double tolerance = 1e-6 * diagonal(shape);
  std::vector<gp_Pnt> joined;
  for (int e : result.contracted_edges) {
    TopoDS_Vertex first, last;
    TopExp::Vertices(index.edge(e), first, last);
    joined.push_back(BRep_Tool::Pnt(first));
    joined.push_back(BRep_Tool::Pnt(last));
  }
  const double contracted = kContractedEdgeRatio * result.size;
  const auto at_joined_vertex = [&](const Vec3& p) {
    for (const gp_Pnt& v : joined) if (v.Distance(gp_Pnt(p.x, p.y, p.z)) <= contracted) return true;
    return false;
  };
  for (const FaceMesh& f : mesh.faces) {
    const TopoDS_Face& face = index.face(f.face);
    TopLoc_Location location;
    ShapeAnalysis_Surface surface(BRep_Tool::Surface(face, location));
    const gp_Trsf to_local = location.Transformation().Inverted();
    // Boundary nodes lie on edges, which may be off the surface by their tolerance.
    const double face_tolerance =
        std::max(tolerance, 2 * std::max(BRep_Tool::MaxTolerance(face, TopAbs_EDGE),
                                         BRep_Tool::MaxTolerance(face, TopAbs_VERTEX)));
    const BRepAdaptor_Surface adaptor(face);
    for (std::int64_t k = f.first_quad; k < f.first_quad + f.quad_count; ++k) {
      const Quad& q = mesh.quads[k];
      // The outer normal where a point projects on the surface (zero at a pole).
      auto normal_at = [&](const Vec3& x) {
        const gp_Pnt2d uv = surface.ValueOfUV(gp_Pnt(x.x, x.y, x.z).Transformed(to_local), face_tolerance);
        gp_Pnt p;
        gp_Vec du, dv;
        adaptor.D1(uv.X(), uv.Y(), p, du, dv);
        gp_Vec outer = du.Crossed(dv);  // the adaptor includes the location
        if (singular_normal(du, dv)) return Vec3{};
        if (face.Orientation() == TopAbs_REVERSED) outer.Reverse();
        return Vec3{outer.X(), outer.Y(), outer.Z()};
      };
      Vec3 centre;
      for (NodeId n : q) {
        const Vec3& p = mesh.nodes[n];
        centre += 0.25 * p;
        surface.ValueOfUV(gp_Pnt(p.x, p.y, p.z).Transformed(to_local), face_tolerance);
        EXPECT_LE(surface.Gap(), at_joined_vertex(p) ? std::max(face_tolerance, contracted) : face_tolerance)
            << path << " face " << f.face << " node " << n;
      }
      // Middles on the surface, or on their chords where they were straightened.
      for (int i = 0; i < 4; ++i) {
        const Vec3& m = mesh.nodes[mesh.mid_nodes[k][i]];
        if (m == 0.5 * (mesh.nodes[q[i]] + mesh.nodes[q[(i + 1) % 4]])) continue;
        surface.ValueOfUV(gp_Pnt(m.x, m.y, m.z).Transformed(to_local), face_tolerance);
        EXPECT_LE(surface.Gap(), face_tolerance) << path << " face " << f.face << ": middle of quad " << k << " edge " << i;
      }
      // Each corner against the surface normal at its node (at the centre for a pole).
      for (int i = 0; i < 4; ++i) {
        Vec3 n = normal_at(mesh.nodes[q[i]]);
        if (norm(n) == 0) n = normal_at(centre);
        if (norm(n) == 0) continue;  // singular all over this quad: nothing to judge by
        const Vec3 a = mesh.nodes[q[(i + 1) % 4]] - mesh.nodes[q[i]];
        const Vec3 b = mesh.nodes[q[(i + 3) % 4]] - mesh.nodes[q[i]];
        const double s = dot(cross(a, b), n) / (norm(a) * norm(b) * norm(n));
        EXPECT_GE(s, -kSurfaceInvertedBelow) << path << " face " << f.face << ": quad " << k << " inverted at corner " << i;
      }
    }
  }
  return report;
}

void check_folder(const fs::path& dir) {
  const auto files = shape_files(dir);
  ASSERT_FALSE(files.empty()) << "no shape files in " << dir;
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    check_file(path);
  }
}

// Primitives with poles, written to a temporary BREP and checked like the others.
FileReport check_primitive(const TopoDS_Shape& shape, const std::string& name) {
  const std::string path = (fs::temp_directory_path() / (name + ".brep")).string();
  BRepTools::Write(shape, path.c_str());
  const FileReport r = check_file(path);
  fs::remove(path);
  return r;
}

TEST(ShapeMeshing, PolesAndSeams) {
  // A hemisphere: a cap with a pole and a seam, closed by a disk.
  FileReport r = check_primitive(BRepPrimAPI_MakeSphere(10.0, 0.0, M_PI / 2).Shape(), "hemisphere");
  EXPECT_EQ(r.refused, 0);
  EXPECT_TRUE(r.closed);
  // A pointed cone: its side has the apex (a degenerate edge) and a seam.
  r = check_primitive(BRepPrimAPI_MakeCone(10.0, 0.0, 20.0).Shape(), "cone");
  EXPECT_EQ(r.refused, 0);
  EXPECT_TRUE(r.closed);
  // A whole sphere (no edge but its seam and two poles): the cube sphere.
  r = check_primitive(BRepPrimAPI_MakeSphere(10.0).Shape(), "sphere");
  EXPECT_EQ(r.refused, 0);
  EXPECT_TRUE(r.closed);
  // A refused face with no other face: nothing is meshed, which is an error even
  // with keep_going (never an empty mesh).
  ShapeMeshOptions options;
  options.keep_going = true;
  const TopoDS_Shape cone = drilled_cone(0, 0, 0);
  TopoDS_Shape side;
  for (TopExp_Explorer it(cone, TopAbs_FACE); it.More() && side.IsNull(); it.Next()) {
    if (BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType() == GeomAbs_Cone) side = it.Current();
  }
  ASSERT_FALSE(side.IsNull());
  try {
    mesh_shape(side, options);
    ADD_FAILURE() << "a drilled cone's side gave a mesh";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no face could be meshed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("has a hole and a pole"), std::string::npos) << e.what();
  }
}

// Surfaces closed around two poles at sizes from coarse to fine: a sphere, a prolate
// and an oblate ellipsoid of revolution (a half ellipse revolved), each one face of a
// seam and two poles. Every quad's corners stay well above 0 against the surface
// normal and against the quad's own normal, and the mesh is closed.
TEST(ShapeMeshing, SurfacesClosedAroundTwoPolesGetTheCubeSphere) {
  const auto revolved_ellipse = [](double along_axis, double across) {
    const gp_Ax2 frame(gp_Pnt(0, 0, 0), gp_Dir(0, 1, 0), gp_Dir(0, 0, 1));
    const Handle(Geom_TrimmedCurve) half =
        along_axis >= across ? new Geom_TrimmedCurve(new Geom_Ellipse(gp_Elips(frame, along_axis, across)), 0, M_PI)
                             : new Geom_TrimmedCurve(new Geom_Ellipse(gp_Elips(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 1, 0),
                                                                                        gp_Dir(1, 0, 0)),
                                                                                  across, along_axis)),
                                                     -M_PI / 2, M_PI / 2);
    return BRepPrimAPI_MakeRevol(BRepBuilderAPI_MakeEdge(half).Edge(), gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)))
        .Shape();
  };
  const std::vector<std::pair<std::string, TopoDS_Shape>> shapes{
      {"sphere", BRepPrimAPI_MakeSphere(10.0).Shape()},
      {"prolate", revolved_ellipse(15.0, 6.0)},
      {"oblate", revolved_ellipse(5.0, 12.0)}};
  for (const auto& [name, shape] : shapes) {
    const ShapeIndex index(shape);
    ASSERT_EQ(index.face_count(), 1) << name;
    for (const double divisor : {4.0, 10.0, 25.0, 60.0}) {
      ShapeMeshOptions options;
      options.size = diagonal(shape) / divisor;
      const ShapeMesh mesh = mesh_shape(shape, options).mesh;
      ASSERT_EQ(mesh.faces.size(), 1u) << name;
      EXPECT_EQ(mesh.faces[0].template_tree, "C6[T0,T0,T0,T0,T0,T0]") << name;
      std::map<std::pair<NodeId, NodeId>, int> uses;
      for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
        const Quad& q = mesh.quads[k];
        const std::array<Vec3, 4> p{mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]], mesh.nodes[q[3]]};
        EXPECT_GT(own_scaled_jacobian(p), 0.2) << name << " D/" << divisor << " quad " << k;
        EXPECT_GT(mesh.scaled_jacobian[k], 0.2) << name << " D/" << divisor << " quad " << k;
        for (int i = 0; i < 4; ++i) ++uses[std::minmax(q[i], q[(i + 1) % 4])];
      }
      for (const auto& [edge, count] : uses) EXPECT_EQ(count, 2) << name << " D/" << divisor << ": open mesh edge";
    }
  }
}

// Lunes (two meridians between the poles, 30 to 330 degrees wide) and zones (between
// two parallels, or from a pole to a parallel) of a sphere, as solids: every face
// meshed, the mesh closed, and every corner of every quad well above 0 against the
// surface normal and the quad's own normal. A lune wider than about 150 degrees
// has a smooth rim through its poles, where a template corner is a 180-degree quad.
TEST(ShapeMeshing, LunesAndZonesOfASphereHaveNoFlatCornerAtTheirPoles) {
  struct Piece {
    std::string name;
    TopoDS_Shape shape;
    double bound;  // the sine of the sharpest corner, or what a sphere's disk allows
  };
  std::vector<Piece> pieces;
  for (const double degrees : {30.0, 90.0, 180.0, 270.0, 330.0}) {
    pieces.push_back({"lune " + std::to_string(static_cast<int>(degrees)),
                      BRepPrimAPI_MakeSphere(10.0, -M_PI / 2, M_PI / 2, degrees * M_PI / 180).Shape(),
                      std::min(std::sin(degrees * M_PI / 180), 0.5)});
  }
  pieces.push_back({"zone", BRepPrimAPI_MakeSphere(10.0, -M_PI / 6, M_PI / 3).Shape(), 0.5});
  pieces.push_back({"cap to a parallel", BRepPrimAPI_MakeSphere(10.0, -M_PI / 2, M_PI / 3).Shape(), 0.5});
  for (const Piece& piece : pieces) {
    for (const double divisor : {10.0, 25.0, 60.0}) {
      ShapeMeshOptions options;
      options.size = diagonal(piece.shape) / divisor;
      const ShapeMeshResult result = mesh_shape(piece.shape, options);
      const ShapeMesh& mesh = result.mesh;
      EXPECT_TRUE(mesh.refused_faces.empty()) << piece.name;
      std::map<std::pair<NodeId, NodeId>, int> uses;
      for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
        const Quad& q = mesh.quads[k];
        const std::array<Vec3, 4> p{mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]], mesh.nodes[q[3]]};
        EXPECT_GT(own_scaled_jacobian(p), 0.9 * piece.bound) << piece.name << " D/" << divisor << " quad " << k;
        EXPECT_GT(mesh.scaled_jacobian[k], 0.9 * piece.bound) << piece.name << " D/" << divisor << " quad " << k;
        for (int i = 0; i < 4; ++i) ++uses[std::minmax(q[i], q[(i + 1) % 4])];
      }
      for (const auto& [edge, count] : uses) EXPECT_EQ(count, 2) << piece.name << " D/" << divisor << ": open edge";
    }
  }
}

// A 10 x 6 rectangle of the plane z = 0 drilled twice, with, when `point_edge`, a degenerate edge
// at its corner (10, 0) whose pcurve runs 1e-6 up from there: an edge shorter than
// its vertex tolerance, as exporters write, marked degenerate though the plane does
// not collapse anywhere.
TopoDS_Face rectangle_with_point_edge(bool point_edge) {
  const Handle(Geom_Plane) plane = new Geom_Plane(gp_Pln());
  BRep_Builder builder;
  const gp_Pnt corners[4] = {gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0), gp_Pnt(10, 6, 0), gp_Pnt(0, 6, 0)};
  TopoDS_Vertex v[4];
  for (int i = 0; i < 4; ++i) builder.MakeVertex(v[i], corners[i], 1e-5);
  TopoDS_Wire wire;
  builder.MakeWire(wire);
  for (int i = 0; i < 4; ++i) {
    builder.Add(wire, BRepBuilderAPI_MakeEdge(v[i], v[(i + 1) % 4]).Edge());
    if (i == 0 && point_edge) {
      TopoDS_Edge point;
      builder.MakeEdge(point);
      const Handle(Geom2d_Line) up = new Geom2d_Line(gp_Pnt2d(10, 0), gp_Dir2d(0, 1));
      builder.UpdateEdge(point, up, plane, TopLoc_Location(), 1e-5);
      builder.Range(point, 0.0, 1e-6);
      builder.Degenerated(point, Standard_True);
      builder.Add(point, v[1].Oriented(TopAbs_FORWARD));
      builder.Add(point, v[1].Oriented(TopAbs_REVERSED));
      builder.Add(wire, point);
    }
  }
  BRepBuilderAPI_MakeFace face(plane, wire, Standard_True);
  // Two holes: the face is decomposed into patches.
  for (const double x : {3.0, 7.0}) {
    const TopoDS_Edge circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(x, 3, 0), gp_Dir(0, 0, 1)), 1.0)).Edge();
    face.Add(TopoDS::Wire(BRepBuilderAPI_MakeWire(circle).Wire().Reversed()));
  }
  return face.Face();
}

TEST(ShapeMeshing, ADegenerateEdgeThatIsAPointOfTheChartIsNoPole) {
  // The face is the same drilled rectangle with the point edge or without it: the same
  // decomposition and the same quads. Taken for a pole, the point edge had the face
  // refused ("a hole and a pole").
  ShapeMeshOptions options;
  options.size = 1.0;
  const ShapeMesh plain = mesh_shape(rectangle_with_point_edge(false), options).mesh;
  const ShapeMesh pointed = mesh_shape(rectangle_with_point_edge(true), options).mesh;
  ASSERT_EQ(plain.faces.size(), 1u);
  ASSERT_EQ(pointed.faces.size(), 1u);
  EXPECT_EQ(pointed.faces[0].template_tree, plain.faces[0].template_tree);
  EXPECT_EQ(pointed.quads.size(), plain.quads.size());
  EXPECT_GT(pointed.quads.size(), 0u);
  ASSERT_EQ(pointed.scaled_jacobian.size(), plain.scaled_jacobian.size());
  for (std::size_t k = 0; k < pointed.scaled_jacobian.size(); ++k) {
    EXPECT_NEAR(pointed.scaled_jacobian[k], plain.scaled_jacobian[k], 1e-6) << "quad " << k;
  }
}

// A 10 x 6 rectangle of the plane z = 0 with a hole through the vertex (5, 0) of its
// bottom side: a circle of radius 2 tangent to the side there, or a triangle
// (5, 0), (6, 2), (4, 2), whose sides leave the bottom side at 63.4 degrees.
TopoDS_Face rectangle_with_touching_hole(bool circle) {
  const Handle(Geom_Plane) plane = new Geom_Plane(gp_Pln());
  BRep_Builder builder;
  const gp_Pnt corners[5] = {gp_Pnt(0, 0, 0), gp_Pnt(5, 0, 0), gp_Pnt(10, 0, 0), gp_Pnt(10, 6, 0), gp_Pnt(0, 6, 0)};
  TopoDS_Vertex v[5];
  for (int i = 0; i < 5; ++i) builder.MakeVertex(v[i], corners[i], 1e-7);
  TopoDS_Wire outer;
  builder.MakeWire(outer);
  for (int i = 0; i < 5; ++i) builder.Add(outer, BRepBuilderAPI_MakeEdge(v[i], v[(i + 1) % 5]).Edge());
  TopoDS_Wire hole;
  builder.MakeWire(hole);
  if (circle) {
    const gp_Circ round(gp_Ax2(gp_Pnt(5, 2, 0), gp_Dir(0, 0, 1), gp_Dir(0, -1, 0)), 2.0);
    builder.Add(hole, BRepBuilderAPI_MakeEdge(round, v[1], v[1]).Edge());
  } else {
    TopoDS_Vertex t[2];
    builder.MakeVertex(t[0], gp_Pnt(6, 2, 0), 1e-7);
    builder.MakeVertex(t[1], gp_Pnt(4, 2, 0), 1e-7);
    builder.Add(hole, BRepBuilderAPI_MakeEdge(v[1], t[0]).Edge());
    builder.Add(hole, BRepBuilderAPI_MakeEdge(t[0], t[1]).Edge());
    builder.Add(hole, BRepBuilderAPI_MakeEdge(t[1], v[1]).Edge());
  }
  BRepBuilderAPI_MakeFace face(plane, outer, Standard_True);
  face.Add(TopoDS::Wire(circle ? hole.Reversed() : hole));
  return face.Face();
}

TEST(ShapeMeshing, AHoleThroughAVertexOfTheOuterLoopIsSplicedIntoIt) {
  // The region around a hole that touches the outer loop at a shared vertex is still
  // one region, bounded by one walk through that vertex twice (core/decomposition/touching_loops.h).
  // Refused before ("the boundary touches itself"). Both wedges at the vertex get
  // quads there, meeting at its one node; no refinement round is spent.
  for (const bool circle : {false, true}) {
    SCOPED_TRACE(circle ? "tangent circle" : "triangle");
    ShapeMeshOptions options;
    options.size = 1.0;
    const ShapeMeshResult result = mesh_shape(rectangle_with_touching_hole(circle), options);
    ASSERT_TRUE(result.mesh.refused_faces.empty());
    EXPECT_EQ(result.refinement_rounds, 0);
    const ShapeMesh& mesh = result.mesh;
    ASSERT_GT(mesh.quads.size(), 0u);
    int touching = -1;
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
      if (distance(mesh.nodes[i], Vec3{5, 0, 0}) < 1e-9) touching = static_cast<int>(i);
    }
    ASSERT_GE(touching, 0);
    // The quads at the vertex lie on both sides of the hole: x below and above 5.
    bool left = false, right = false;
    double worst = 1;
    for (std::size_t q = 0; q < mesh.quads.size(); ++q) {
      const std::array<Vec3, 4> corners = {mesh.nodes[mesh.quads[q][0]], mesh.nodes[mesh.quads[q][1]],
                                           mesh.nodes[mesh.quads[q][2]], mesh.nodes[mesh.quads[q][3]]};
      EXPECT_FALSE(is_bad_quad(corners, mesh.scaled_jacobian[q])) << "quad " << q;
      worst = std::min(worst, mesh.scaled_jacobian[q]);
      if (std::find(mesh.quads[q].begin(), mesh.quads[q].end(), touching) == mesh.quads[q].end()) continue;
      const Vec3 middle = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
      (middle.x < 5 ? left : right) = true;
    }
    EXPECT_TRUE(left && right);
    // The triangle's wedges are 63.4 degrees (sin 0.89); the circle's are cusps.
    if (!circle) EXPECT_GT(worst, 0.3);
  }
}

TEST(ShapeMeshing, ConeApexIsAMeshNode) {
  // A pointed cone of height 20 along z: its side's pole is the apex (0, 0, 20); a
  // quad spanning it would cut the tip off.
  const ShapeMeshResult result = mesh_shape(BRepPrimAPI_MakeCone(10.0, 0.0, 20.0).Shape(), ShapeMeshOptions{});
  double nearest = INFINITY;
  for (const Vec3& p : result.mesh.nodes) nearest = std::min(nearest, distance(p, Vec3{0, 0, 20}));
  EXPECT_LT(nearest, 1e-9);
}

TEST(ShapeMeshing, SharpConeTipsAreMetByTwoQuads) {
  // Pointed cones of height 20 and half-angle a. A quad's corner at the tip, between
  // chords along generators, is at most 2a with two quads there (the tip's sector in
  // halves, pole_sector_mesh.h) and 2 asin(sin a sin 45 deg) with four (the disk
  // around the pole). On sharp tips the sector wins; from about 30 degrees its
  // halves (quarter disks and wider, one long arc against two short sides) mesh
  // worse than the disk, which then stays. Each mesh is checked like the other
  // shapes (valid on the surface, closed); the corner at the tip is printed and
  // must come near the bound of the layout chosen.
  for (double degrees : {10.0, 18.4, 30.0, 45.0, 60.0}) {
    SCOPED_TRACE(degrees);
    const double a = degrees * M_PI / 180;
    const TopoDS_Shape cone = BRepPrimAPI_MakeCone(20.0 * std::tan(a), 0.0, 20.0).Shape();
    const FileReport r = check_primitive(cone, "cone_tip");
    EXPECT_EQ(r.refused, 0);
    EXPECT_TRUE(r.closed);
    const ShapeMesh mesh = mesh_shape(cone, ShapeMeshOptions{}).mesh;
    NodeId tip = 0;
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
      if (distance(mesh.nodes[i], Vec3{0, 0, 20}) < distance(mesh.nodes[tip], Vec3{0, 0, 20})) tip = static_cast<NodeId>(i);
    }
    ASSERT_LT(distance(mesh.nodes[tip], Vec3{0, 0, 20}), 1e-9);
    int around = 0;
    double worst = 1.0;
    for (const Quad& q : mesh.quads) {
      const auto at = std::find(q.begin(), q.end(), tip);
      if (at == q.end()) continue;
      ++around;
      const std::array<Vec3, 4> p{mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]], mesh.nodes[q[3]]};
      const Vec3 own = cross(p[2] - p[0], p[3] - p[1]);
      worst = std::min(worst, corner_scaled_jacobian(p, static_cast<int>(at - q.begin()), own));
    }
    const double best_two = std::sin(2 * a), best_four = std::sin(2 * std::asin(std::sin(a) * std::sqrt(0.5)));
    if (degrees < 20) EXPECT_EQ(around, 2);
    ASSERT_TRUE(around == 2 || around == 4) << around;
    // Near the bound of the layout chosen. Four alike need the pole on a grid node of
    // the disk's middle square, so a rim count that is a multiple of 4
    // (pole_rims.h): the 60-degree cone's tip was 0.80 of 0.97 without it.
    EXPECT_GT(worst, 0.9 * (around == 2 ? best_two : best_four));
  }
}

// `shape` checked like the parts (check_primitive), closed and nothing refused, and its
// mesh at `size`.
ShapeMeshResult checked_and_meshed(const TopoDS_Shape& shape, const std::string& name, double size) {
  const FileReport r = check_primitive(shape, name);
  EXPECT_EQ(r.refused, 0);
  EXPECT_TRUE(r.closed);
  ShapeMeshOptions options;
  options.size = size;
  return mesh_shape(shape, options);
}

// The lowest scaled Jacobian (each corner against the surface normal) of face f's quads.
double face_worst(const ShapeMesh& mesh, const FaceMesh& f) {
  double worst = 1.0;
  for (std::int64_t k = f.first_quad; k < f.first_quad + f.quad_count; ++k) worst = std::min(worst, mesh.scaled_jacobian[k]);
  return worst;
}

TEST(ShapeMeshing, SphereCapsGetTheDiskOGridConvexOrConcave) {
  // Caps of a sphere of radius 10 from latitude `from` to its pole, closed by a disk:
  // short of, at and past the equator. Reversed, the same solid is a cavity, its
  // faces reversed: the cap is concave, as a spherical dimple or seat cut into a part.
  // Both ways the cap is the disk's O-grid around its pole (pole_rims.h), every rim
  // node in two quads. The concave caps' O-grid came out inverted (mirrored twice)
  // and lost to two curves with corners on the rim, whose quads along a rim at the
  // equator have three rim nodes in one tangent plane: degenerate, or inverted past it.
  for (const double degrees : {30.0, 0.0, -30.0}) {
    for (const bool concave : {false, true}) {
      SCOPED_TRACE(std::to_string(degrees) + (concave ? " degrees, concave" : " degrees, convex"));
      TopoDS_Shape cap = BRepPrimAPI_MakeSphere(10.0, degrees * M_PI / 180, M_PI / 2).Shape();
      if (concave) cap.Reverse();
      const ShapeMeshResult result = checked_and_meshed(cap, "sphere_cap", 2.0);
      const ShapeIndex index(cap);
      ASSERT_EQ(result.mesh.scaled_jacobian.size(), result.mesh.quads.size());
      for (const FaceMesh& f : result.mesh.faces) {
        if (BRepAdaptor_Surface(index.face(f.face)).GetType() != GeomAbs_Sphere) continue;
        EXPECT_EQ(f.template_tree.substr(0, 2), "O5") << f.template_tree;
        const double worst = face_worst(result.mesh, f);
        EXPECT_GT(worst, 0.5);
      }
    }
  }
}

TEST(ShapeMeshing, SphereCapsWithAHoleAreDecomposedAroundTheirPole) {
  // A hemispherical dimple of radius 8 in a block, and a dome of radius 8 on it, each
  // drilled through off its pole by a hole of radius 2: the sphere's face has its
  // pole, its seam and a hole. It was refused ("a hole and a pole"); around a
  // sphere's pole (a smooth one) the face is decomposed in polar (x, y).
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(40, 40, 20).Shape();
  const TopoDS_Shape ball = BRepPrimAPI_MakeSphere(gp_Pnt(20, 20, 20), 8).Shape();
  const TopoDS_Shape drill = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(24, 20, -1), gp_Dir(0, 0, 1)), 2, 40).Shape();
  const TopoDS_Shape dimple = BRepAlgoAPI_Cut(BRepAlgoAPI_Cut(block, ball).Shape(), drill).Shape();
  const TopoDS_Shape dome = BRepAlgoAPI_Cut(BRepAlgoAPI_Fuse(block, ball).Shape(), drill).Shape();
  for (const auto& [shape, name] : {std::pair{dimple, "dimple"}, std::pair{dome, "dome"}}) {
    SCOPED_TRACE(name);
    const ShapeMeshResult result = checked_and_meshed(shape, name, 2.0);
    const ShapeIndex index(shape);
    int spheres = 0;
    for (const FaceMesh& f : result.mesh.faces) {
      if (BRepAdaptor_Surface(index.face(f.face)).GetType() != GeomAbs_Sphere) continue;
      ++spheres;
      const double worst = face_worst(result.mesh, f);
      EXPECT_GT(worst, 0.3);
    }
    EXPECT_EQ(spheres, 1);
  }
}

TEST(ShapeMeshing, GeneratedMachinedParts) {
  // Parts built from seeds by OpenCASCADE's booleans, fillets and chamfers
  // (generated_parts.h): holes, bosses, slots, dimples, fillets and chamfers where
  // they fall. Every face is meshed but those the mesher's per-face check finds
  // damaged (a fillet's face OpenCASCADE's own checker calls invalid), and each mesh
  // is checked like the parts': conforming, closed where the shape is, on its faces,
  // no corner inverted against the surface normal (check_file). Random parts found
  // concave sphere caps meshed inverted, faces around a pole with a hole refused or
  // cracked, lenses and D-shapes of two edges refused or flat, and arcs whose chords
  // crossed a notch.
  int parts = 0, collapsed_refusals = 0;
  const std::string path = (fs::temp_directory_path() / "generated_part.brep").string();
  const std::vector<int> seeds = testing::cases(40);  // case i is seed i + 1
  for (int i : seeds) {
    const auto seed = static_cast<std::uint32_t>(i + 1);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", " + testing::case_trace(i));
    if (!write_generated_part(seed, path)) continue;  // OpenCASCADE crashed building it
    ++parts;
    const TopoDS_Shape part = read_shape(path);
    check_file(path);
    ShapeMeshOptions options;
    options.keep_going = true;
    const ShapeMeshResult result = mesh_shape(part, options);
    // Refused: damaged faces alone. A decomposed face whose patches leave an interior
    // node a millionth of the size from a neighbour (a collapsed quad with sound
    // angles) has it moved off by the smoother (core/repair/smoothing.cpp, compass steps
    // from the longest edge around it); counted below.
    for (const RefusedFace& f : result.mesh.refused_faces) {
      if (f.code == RefusalCode::inverted_quads && f.reason.find("collapsed") != std::string::npos) {
        ++collapsed_refusals;
        continue;
      }
      EXPECT_EQ(f.code, RefusalCode::damaged) << f.reason;
    }
    // The round kept is one that refused the fewest faces.
    ASSERT_EQ(result.refused_per_round.size(), static_cast<std::size_t>(result.refinement_rounds + 1));
    const int fewest = *std::min_element(result.refused_per_round.begin(), result.refused_per_round.end());
    EXPECT_EQ(static_cast<int>(result.mesh.refused_faces.size()), fewest);
    EXPECT_EQ(result.refused_per_round[result.kept_round], fewest);
    // Of rounds that tie, the first is kept; no two rounds in a row before the last
    // refused as many faces as the best before them (two such end the refinement).
    const std::vector<int>& rounds = result.refused_per_round;
    const auto first_fewest = std::find(rounds.begin(), rounds.end(), fewest);
    EXPECT_EQ(result.kept_round, static_cast<int>(first_fewest - rounds.begin()));
    for (std::size_t r = 2; r + 1 < rounds.size(); ++r) {
      const int best_before = *std::min_element(rounds.begin(), rounds.begin() + r - 1);
      EXPECT_FALSE(rounds[r - 1] >= best_before && rounds[r] >= best_before) << "round " << r;
    }
  }
  fs::remove(path);
  // The generator builds most seeds' parts (30 of the 40; of every Nth, as many in share).
  if (testing::whole_set()) EXPECT_GE(4 * parts, 3 * static_cast<int>(seeds.size()));
  EXPECT_EQ(collapsed_refusals, 0);
}

TEST(ShapeMeshing, FacesCoarseForTheirCurvatureGetFinerEdges) {
  // Generated part 31 at a tenth of its diagonal: its face 22, a fillet band about 1.5
  // wide twisting along 25, got 3 segments a side, and 3 of its 20 quads stayed
  // inverted (-0.75), their corners' surface normals up to 66 degrees apart. Only
  // faces of at most 16 quads had their edges refined; a face with a quad spanning
  // more than 45 degrees of its surface's turning now has them refined too.
  const std::string path = (fs::temp_directory_path() / "generated_part_31.brep").string();
  if (!write_generated_part(31, path)) GTEST_SKIP() << "OpenCASCADE crashed building generated part 31";
  const TopoDS_Shape part = read_shape(path);
  fs::remove(path);
  ShapeMeshOptions options;
  options.keep_going = true;
  options.size = mesh_shape(part, options).size * 25 / 10;
  const ShapeMeshResult result = mesh_shape(part, options);
  for (const RefusedFace& refused : result.mesh.refused_faces) ADD_FAILURE() << refused.reason;
  EXPECT_GE(result.refinement_rounds, 1);
  EXPECT_EQ(result.inverted, 0);
}

// A lens of two shallow arcs from (x, 0, 0) to (x + 1.2, 0, 0), bulging 0.05 each way:
// the sliver a boolean leaves between two overlapping holes, or a hole and a fillet.
TopoDS_Wire lens_wire(double x) {
  const gp_Pnt a(x, 0, 0), b(x + 1.2, 0, 0);
  BRepBuilderAPI_MakeWire wire;
  wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(a, gp_Pnt(x + 0.6, -0.05, 0), b).Value()).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(b, gp_Pnt(x + 0.6, 0.05, 0), a).Value()).Edge());
  return wire.Wire();
}

TEST(ShapeMeshing, LoopsOfTwoShortEdgesGetFourSegments) {
  // At a size twice the lens's length each arc would be one segment, and a loop of
  // two cannot be meshed: both edges of a two-edge loop get two at least.
  ShapeMeshOptions options;
  options.size = 2.4;
  const ShapeMeshResult lens = mesh_shape(BRepBuilderAPI_MakeFace(lens_wire(0.0)).Face(), options);
  EXPECT_TRUE(lens.mesh.refused_faces.empty());
  EXPECT_EQ(lens.mesh.quads.size(), 1u);
  // A D: a shallow arc closed by a line. The arc gets 3 and the line 1, so no
  // corner of the quad is the line's middle (180 degrees: 2 and 2 gave that).
  BRepBuilderAPI_MakeWire d;
  d.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(gp_Pnt(0, 0, 0), gp_Pnt(0.6, 0.1, 0), gp_Pnt(1.2, 0, 0)).Value()).Edge());
  d.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(1.2, 0, 0), gp_Pnt(0, 0, 0)).Edge());
  const ShapeMeshResult d_mesh = mesh_shape(BRepBuilderAPI_MakeFace(d.Wire()).Face(), options);
  ASSERT_EQ(d_mesh.mesh.quads.size(), 1u);
  ASSERT_EQ(d_mesh.mesh.scaled_jacobian.size(), 1u);
  EXPECT_GT(d_mesh.mesh.scaled_jacobian[0], 0.05);
  for (NodeId n : d_mesh.mesh.quads[0]) EXPECT_GT(distance(d_mesh.mesh.nodes[n], Vec3{0.6, 0, 0}), 0.05) << n;
  // The same lens as a hole in a plate 10 across.
  BRepBuilderAPI_MakeFace plate(BRepBuilderAPI_MakePolygon(gp_Pnt(-5, -5, 0), gp_Pnt(5, -5, 0), gp_Pnt(5, 5, 0),
                                                           gp_Pnt(-5, 5, 0), true).Wire());
  TopoDS_Wire hole = lens_wire(-0.6);
  hole.Reverse();
  plate.Add(hole);
  const ShapeMeshResult holed = mesh_shape(plate.Face(), options);
  EXPECT_TRUE(holed.mesh.refused_faces.empty());
  EXPECT_EQ(holed.inverted, 0);
  // The hole has 4 segments, and nodes = 1 + quads + boundary_edges / 2 - holes.
  std::map<std::pair<NodeId, NodeId>, int> uses;
  for (const Quad& q : holed.mesh.quads) {
    for (int i = 0; i < 4; ++i) ++uses[std::minmax(q[i], q[(i + 1) % 4])];
  }
  long long boundary = 0, on_hole = 0;
  const auto near_hole = [&](NodeId n) { return norm(holed.mesh.nodes[n]) < 0.61; };
  for (const auto& [edge, count] : uses) {
    if (count != 1) continue;
    ++boundary;
    if (near_hole(edge.first) && near_hole(edge.second)) ++on_hole;
  }
  EXPECT_EQ(on_hole, 4);
  EXPECT_EQ(static_cast<long long>(holed.mesh.nodes.size()),
            1 + static_cast<long long>(holed.mesh.quads.size()) + boundary / 2 - 1);
}

TEST(ShapeMeshing, ChordsThatCrossAnotherEdgeAreRefined) {
  // A disk of radius 10 with a notch cut almost to its top: the notch's side x = 0
  // ends 0.05 under the arc, whose chords at size 3.6 (12 over 258 degrees) cut 0.17
  // inside it. The loop of segments crossed itself there and the face was refused;
  // the arc is refined (doubled) until its chords clear the notch.
  const gp_Circ circle(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 10.0);
  const gp_Pnt top(std::sqrt(100.0 - 9.95 * 9.95), 9.95, 0), right(std::sqrt(91.0), -3, 0);
  BRepBuilderAPI_MakeWire wire;
  wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(circle, top, right, true).Value()).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(right, gp_Pnt(0, -3, 0)).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(0, -3, 0), gp_Pnt(0, 9.95, 0)).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 9.95, 0), top).Edge());
  ASSERT_TRUE(wire.IsDone());
  ShapeMeshOptions options;
  options.size = 3.6;
  const ShapeMeshResult result = mesh_shape(BRepBuilderAPI_MakeFace(wire.Wire()).Face(), options);
  EXPECT_TRUE(result.mesh.refused_faces.empty());
  EXPECT_EQ(result.inverted, 0);
  EXPECT_GE(result.refinement_rounds, 1);
  // Only the arc was refined: the three lines keep their counts from the size.
  std::map<std::pair<NodeId, NodeId>, int> uses;
  for (const Quad& q : result.mesh.quads) {
    for (int i = 0; i < 4; ++i) ++uses[std::minmax(q[i], q[(i + 1) % 4])];
  }
  int on_arc = 0, on_lines = 0;
  for (const auto& [edge, count] : uses) {
    if (count != 1) continue;
    const Vec3 &a = result.mesh.nodes[edge.first], &b = result.mesh.nodes[edge.second];
    const bool arc = std::abs(norm(a) - 10) < 1e-6 && std::abs(norm(b) - 10) < 1e-6;
    ++(arc ? on_arc : on_lines);
  }
  EXPECT_GE(on_arc, 24);
  EXPECT_LE(on_lines, 4 + 4 + 1 + 1);  // 12.9 / 3.6, 9.5 / 3.6 and the short line, made even
}

TEST(ShapeMeshing, CutsAcrossAGrooveGetSegmentsForTheirTurn) {
  // A shaft of radius 19.6 with an O-ring groove (a torus tube of radius 1.05 at
  // z = 29.9) whose edge a milled flat (x >= 17.9, z from 10.2 to 30.7) cuts into:
  // the groove's face has 7 edges and is decomposed, its cuts crossing the tube.
  // Straight in the face's chart, such a cut is up to a half circle of 3.3 in space:
  // at size 3.07 it got 1 or 2 segments, where edges of that turn get 4 (one per 45
  // degrees), and 8 of 96 quads folded across the tube stayed inverted (the face
  // refused). Its cuts now get as many segments as edges of the same turn.
  TopoDS_Shape shaft = BRepPrimAPI_MakeCylinder(19.6, 41).Shape();
  shaft = BRepAlgoAPI_Cut(shaft, BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(0, 0, 29.9), gp_Dir(0, 0, 1)), 19.6, 1.05).Shape())
              .Shape();
  shaft = BRepAlgoAPI_Cut(shaft, BRepPrimAPI_MakeBox(gp_Pnt(17.9, -19.6, 10.2), gp_Pnt(57, 19.6, 30.7)).Shape()).Shape();
  int tori = 0;
  for (TopExp_Explorer f(shaft, TopAbs_FACE); f.More(); f.Next()) {
    tori += BRepAdaptor_Surface(TopoDS::Face(f.Current())).GetType() == GeomAbs_Torus;
  }
  ASSERT_GE(tori, 1);
  ShapeMeshOptions options;
  options.size = 3.07;
  const ShapeMeshResult result = mesh_shape(shaft, options);
  for (const RefusedFace& refused : result.mesh.refused_faces) ADD_FAILURE() << refused.reason;
  EXPECT_EQ(result.inverted, 0);
  ASSERT_FALSE(result.mesh.scaled_jacobian.empty());
  EXPECT_GT(*std::min_element(result.mesh.scaled_jacobian.begin(), result.mesh.scaled_jacobian.end()), 0.2);
}

// A quarter ring between radii 9.2 and 10.5 around the z axis, meshed alone at size
// 1.2; `split_outer`: the outer arc in two edges at 45 degrees, else the end on the x
// axis in two edges at its middle. The face has five edges either way, so no chain
// of opposite edges makes it mapped.
ShapeMeshResult mesh_quarter_ring_band(bool split_outer) {
  const gp_Ax2 axis(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  BRepBuilderAPI_MakeWire wire;
  if (split_outer) {
    wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(9.2, 0, 0), gp_Pnt(10.5, 0, 0)).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(gp_Circ(axis, 10.5), 0, M_PI / 4).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(gp_Circ(axis, 10.5), M_PI / 4, M_PI / 2).Edge());
  } else {
    wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(9.2, 0, 0), gp_Pnt(9.85, 0, 0)).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(9.85, 0, 0), gp_Pnt(10.5, 0, 0)).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(gp_Circ(axis, 10.5), 0, M_PI / 2).Edge());
  }
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 10.5, 0), gp_Pnt(0, 9.2, 0)).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Circ(axis, 9.2), 0, M_PI / 2).Edge());
  if (!wire.IsDone()) throw std::runtime_error("the quarter ring's wire is not closed");
  ShapeMeshOptions options;
  options.size = 1.2;
  return mesh_shape(BRepBuilderAPI_MakeFace(wire.Wire()).Face(), options);
}

void expect_one_mapped_face(const ShapeMeshResult& result, std::size_t quads) {
  ASSERT_EQ(result.mesh.faces.size(), 1u);
  EXPECT_EQ(result.mesh.faces[0].template_tree, "T0");
  EXPECT_EQ(result.mesh.quads.size(), quads);
  EXPECT_EQ(result.inverted, 0);
}

TEST(ShapeMeshing, BandOneQuadWideGetsEqualLongSides) {
  // The quarter ring 1.3 wide with its outer arc in two edges: at size 1.2 the outer
  // arc rounds to 7 + 7 segments, the inner to 12, the ends to 1 (an even total: no
  // parity change comes to help). One quad across has no room for a transition, so
  // the interval assignment must make the long sides equal (band_balance.h), and the
  // face is a mapped grid.
  expect_one_mapped_face(mesh_quarter_ring_band(true), 14);  // a quad per segment of the longer side
}

TEST(ShapeMeshing, BandWithUnequalEndsGetsEqualEndsToo) {
  // The quarter ring with one end in two edges (1 + 1 segments) and the other one
  // segment: after its long sides are made equal (14 and 14) the total is odd, and
  // the parity fix used to change a long side (its summed goal is the largest),
  // which left the band unbalanced and its mesh a transition. The band balance gives
  // the one-segment end a second segment instead (and the parity fix changes both
  // long sides or neither), and the band is a mapped grid two quads across.
  expect_one_mapped_face(mesh_quarter_ring_band(false), 28);  // two quads per segment of the long sides
}

TEST(ShapeMeshing, WasherHalvesShareTheRingBalanceEvenly) {
  // A washer whose outer and inner circles are each two half edges (as1-tu-203.stp's,
  // radii 7.5 and 5). At size 2.64 the outer halves round to 9 + 9 against 6 + 6
  // inside; closing the gap of 6, every step costs the same (count_cost is linear
  // below the goals), and the first half used to take most of them: the mapped
  // ring's quads leaned by two segments (worst 0.117, as on the part). Spread, the
  // halves stay equal and the ring is upright (0.966).
  const gp_Ax2 axis(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  BRepBuilderAPI_MakeWire outer, inner;
  outer.Add(BRepBuilderAPI_MakeEdge(gp_Circ(axis, 7.5), 0, M_PI).Edge());
  outer.Add(BRepBuilderAPI_MakeEdge(gp_Circ(axis, 7.5), M_PI, 2 * M_PI).Edge());
  inner.Add(BRepBuilderAPI_MakeEdge(gp_Circ(axis, 5.0), 0, M_PI).Edge());
  inner.Add(BRepBuilderAPI_MakeEdge(gp_Circ(axis, 5.0), M_PI, 2 * M_PI).Edge());
  BRepBuilderAPI_MakeFace face(outer.Wire());
  face.Add(TopoDS::Wire(inner.Wire().Reversed()));
  ShapeMeshOptions options;
  options.size = 2.64;
  const ShapeMeshResult result = mesh_shape(face.Face(), options);
  ASSERT_EQ(result.mesh.faces.size(), 1u);
  EXPECT_EQ(result.mesh.quads.size(), 12u);  // one ring of 12: both loops 6 + 6
  EXPECT_EQ(result.inverted, 0);
  const double worst = *std::min_element(result.mesh.scaled_jacobian.begin(), result.mesh.scaled_jacobian.end());
  EXPECT_GT(worst, 0.8);
}

TEST(ShapeMeshing, RingBalanceKeepsLongEdgesNearTheirGoals) {
  // A frame 2 wide around a 96 x 16 opening, its outer rim notched ten times (1 wide,
  // 0.5 deep) along the top: at size 2 each notch adds three one-segment edges, and
  // the outer rim's total is some 30 over the inner one's. Every step of the ring
  // balance that lowers the bottom edge (goal 50) costs the same, so it used to give
  // up nearly all its segments alone; it may now fall to half its goal, and the
  // other edges take the rest.
  BRepBuilderAPI_MakePolygon outer;
  outer.Add(gp_Pnt(0, 0, 0));
  outer.Add(gp_Pnt(100, 0, 0));
  outer.Add(gp_Pnt(100, 20, 0));
  for (int k = 9; k >= 0; --k) {
    const double x = 5 + 10 * k;
    outer.Add(gp_Pnt(x + 0.5, 20, 0));
    outer.Add(gp_Pnt(x + 0.5, 19.5, 0));
    outer.Add(gp_Pnt(x - 0.5, 19.5, 0));
    outer.Add(gp_Pnt(x - 0.5, 20, 0));
  }
  outer.Add(gp_Pnt(0, 20, 0));
  outer.Close();
  BRepBuilderAPI_MakePolygon inner(gp_Pnt(2, 2, 0), gp_Pnt(2, 18, 0), gp_Pnt(98, 18, 0), gp_Pnt(98, 2, 0), true);
  BRepBuilderAPI_MakeFace face(outer.Wire());
  face.Add(inner.Wire());
  ASSERT_TRUE(face.IsDone());
  ShapeMeshOptions options;
  options.size = 2.0;
  options.keep_going = true;
  const ShapeMeshResult result = mesh_shape(face.Face(), options);
  const ShapeIndex index(face.Face());
  ASSERT_FALSE(result.changes.empty());
  for (const IntervalChange& change : result.changes) {
    const BRepAdaptor_Curve curve(index.edge(change.edge));
    const double goal = std::max(1.0, GCPnts_AbscissaPoint::Length(curve) / options.size);
    EXPECT_GE(2.0 * change.to, goal - 1e-9) << "edge " << change.edge << " from " << change.from << " to " << change.to;
  }
  ASSERT_EQ(result.mesh.faces.size(), 1u);
  EXPECT_EQ(result.inverted, 0);
}

// A disk of radius 5, 0.05 thick, with six thin bars standing across its top rim:
// the cylinder's side is a band cut open along its seam whose top rim is twelve arcs
// (split where the bars cross it) and whose bottom rim is one circle. The bars'
// widths alternate so that the arcs do too.
TopoDS_Shape disk_with_bars_across_its_rim() {
  TopoDS_Shape shape = BRepPrimAPI_MakeCylinder(5.0, 0.05).Shape();
  for (int k = 0; k < 6; ++k) {
    const double angle = k * M_PI / 3;
    const double width = k % 2 == 0 ? 0.6 : 0.3;
    gp_Trsf turn;
    turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), angle);
    const TopoDS_Shape bar =
        BRepBuilderAPI_Transform(BRepPrimAPI_MakeBox(gp_Pnt(4.0, -width / 2, 0.05), 2.0, width, 0.5).Shape(), turn).Shape();
    shape = BRepAlgoAPI_Fuse(shape, bar).Shape();
  }
  return shape;
}

TEST(ShapeMeshing, ABandAroundASeamGetsEqualRims) {
  // The band is one segment high at size 0.5: with rims of different totals it has
  // no room for a transition (the templates' T1 and T2 need two rows) and its quads
  // fold. Its rims are balanced as a ring's two loops are (ring_balance.h).
  ShapeMeshOptions options;
  options.size = 0.5;
  const TopoDS_Shape shape = disk_with_bars_across_its_rim();
  const ShapeIndex index(shape);
  int band = -1;
  for (int f = 0; f < index.face_count(); ++f) {
    if (BRepAdaptor_Surface(index.face(f)).GetType() == GeomAbs_Cylinder) band = f;
  }
  ASSERT_GE(band, 0);
  const ShapeMeshResult result = mesh_shape(shape, options);
  EXPECT_TRUE(result.mesh.refused_faces.empty());
  EXPECT_GE(result.balanced_rings, 1);
  const auto meshed = std::find_if(result.mesh.faces.begin(), result.mesh.faces.end(),
                                   [&](const FaceMesh& f) { return f.face == band; });
  ASSERT_NE(meshed, result.mesh.faces.end());
  // Equal rims of n segments, one segment high: one row of n quads.
  const double circumference = 2 * M_PI * 5.0;
  EXPECT_GE(meshed->quad_count, static_cast<std::int64_t>(circumference / options.size) - 2);
  EXPECT_LE(meshed->quad_count, static_cast<std::int64_t>(2 * circumference / options.size));
  for (std::int64_t q = meshed->first_quad; q < meshed->first_quad + meshed->quad_count; ++q) {
    EXPECT_GT(result.mesh.scaled_jacobian[q], 1e-6) << "quad " << q;
  }
}

// A strip 10 long and 0.2 wide in the plane z = 0: its bottom side one edge, its top
// side two edges of 7 and 3, so that arc length spaces the two sides differently.
TopoDS_Face strip_of_unequal_sides() {
  BRep_Builder builder;
  const gp_Pnt corners[5] = {gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0), gp_Pnt(10, 0.2, 0), gp_Pnt(3, 0.2, 0),
                             gp_Pnt(0, 0.2, 0)};
  TopoDS_Vertex v[5];
  for (int i = 0; i < 5; ++i) builder.MakeVertex(v[i], corners[i], 1e-7);
  BRepBuilderAPI_MakeWire wire;
  for (int i = 0; i < 5; ++i) wire.Add(BRepBuilderAPI_MakeEdge(v[i], v[(i + 1) % 5]).Edge());
  return BRepBuilderAPI_MakeFace(wire.Wire(), Standard_True).Face();
}

TEST(ShapeMeshing, ANarrowBandsLongSidesFaceEachOther) {
  // At size 1.2 both long sides get 9 segments, the top 3 + 6 (spacings 1 and 1.17),
  // the bottom 9 of 1.11: by arc length, node i of one side lies up to 0.33 along
  // from node i of the other across a band 0.2 wide, and the quads lean (worst scaled
  // Jacobian 0.5). The bottom, one edge, takes its nodes across from the top's
  // (band_alignment.h): the quads are rectangles.
  ShapeMeshOptions options;
  options.size = 1.2;
  const ShapeMeshResult result = mesh_shape(strip_of_unequal_sides(), options);
  ASSERT_TRUE(result.mesh.refused_faces.empty());
  EXPECT_EQ(result.aligned_bands, 1);
  EXPECT_EQ(result.mesh.quads.size(), 9u);
  for (std::size_t q = 0; q < result.mesh.quads.size(); ++q) {
    EXPECT_GT(result.mesh.scaled_jacobian[q], 0.99) << "quad " << q;
  }
}

// A plate face in z = 0: a circle of radius `radius` around a polygonal hole whose
// corners lie at `corner` from the centre, at the angles `angles` (radians,
// increasing): the ring between them is `radius - corner` wide at the corners and
// wider between them.
TopoDS_Face circle_around_a_polygon(double radius, double corner, const std::vector<double>& angles) {
  const gp_Circ circle(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), radius);
  const TopoDS_Wire outer = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle).Edge()).Wire();
  BRepBuilderAPI_MakePolygon polygon;
  for (double a : angles) polygon.Add(gp_Pnt(corner * std::cos(a), corner * std::sin(a), 0));
  polygon.Close();
  BRepBuilderAPI_MakeFace face(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), outer);
  TopoDS_Wire hole = polygon.Wire();
  hole.Reverse();
  face.Add(hole);
  return face.Face();
}

TopoDS_Face circle_around_a_hexagon(double radius, double corner) {
  std::vector<double> angles;
  for (int i = 0; i < 6; ++i) angles.push_back(M_PI / 6 + i * M_PI / 3);
  return circle_around_a_polygon(radius, corner, angles);
}

TEST(ShapeMeshing, AThinRingsCircleFacesItsOtherLoopsNodes) {
  // A ring 0.3 to 0.93 wide. At size 3 both loops get 11 segments (ring_balance.h),
  // but the circle cut by its own arc length from its vertex puts its nodes up to
  // half a segment along from the hexagon's: the mapped ring folds and the face is
  // decomposed (worst 0.07). The circle, one closed edge, takes its nodes where the
  // hexagon's project onto it (band_alignment.h): one mapped ring of 11 quads, each
  // crossing the ring (worst sin 60 degrees, the hexagon's corner).
  ShapeMeshOptions options;
  options.size = 3.0;
  const ShapeMeshResult result = mesh_shape(circle_around_a_hexagon(5.0, 4.7), options);
  ASSERT_TRUE(result.mesh.refused_faces.empty());
  ASSERT_EQ(result.mesh.faces.size(), 1u);
  EXPECT_EQ(result.aligned_bands, 1);
  EXPECT_EQ(result.mesh.faces[0].template_tree, "R1");
  EXPECT_EQ(result.mesh.quads.size(), 11u);
  double worst = 1;
  for (double q : result.mesh.scaled_jacobian) worst = std::min(worst, q);
  EXPECT_GT(worst, 0.85);
}

// One face of a part meshed whole at the default size (--keep-going): its template
// tree begins with `tree` and its worst scaled Jacobian (printed) is over
// `worst_above`.
void expect_part_face(const fs::path& part, int face, const std::string& tree, double worst_above) {
  ShapeMeshOptions options;
  options.keep_going = true;
  const ShapeMeshResult result = mesh_shape(read_shape(part.string()), options);
  const auto meshed = std::find_if(result.mesh.faces.begin(), result.mesh.faces.end(),
                                   [&](const FaceMesh& f) { return f.face == face; });
  ASSERT_NE(meshed, result.mesh.faces.end()) << part << " face " << face;
  double worst = 1;
  for (std::int64_t q = meshed->first_quad; q < meshed->first_quad + meshed->quad_count; ++q) {
    worst = std::min(worst, result.mesh.scaled_jacobian[q]);
  }
  EXPECT_EQ(meshed->template_tree.substr(0, tree.size()), tree);
  EXPECT_GT(worst, worst_above);
}

// The same for a part of ../shared/data/cad; skips when the parts are absent.
void expect_shared_part_face(const std::string& file, int face, const std::string& tree, double worst_above) {
  const fs::path part = fs::path(TQUAD_SHARED_CAD_DIR) / file;
  if (!fs::exists(part)) GTEST_SKIP() << "no " << part << " (the CAD parts are not shipped)";
  expect_part_face(part, face, tree, worst_above);
}

// The same for a part of the FreeCAD users' corpus, taken out of its archive
// (../shared/data/corpus) into a temporary folder; skips when the archive is absent.
void expect_corpus_part_face(const std::string& file, int face, const std::string& tree, double worst_above) {
  const fs::path archive = fs::path(TQUAD_SHARED_CAD_DIR) / ".." / "corpus" / "freecad-library-119.tar.xz";
  if (!fs::exists(archive)) GTEST_SKIP() << "no " << archive << " (the corpus is not shipped)";
  const fs::path folder = fs::temp_directory_path() / ("tquad_corpus_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string command =
      "tar -xJf '" + archive.string() + "' -C '" + folder.string() + "' 'parts/" + file + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  expect_part_face(folder / "parts" / file, face, tree, worst_above);
  fs::remove_all(folder);
}

TEST(ShapeMeshing, SmoothedNodesStayOnTheirFaces) {
  // SFU1605-200.step at D/25: a ball screw whose thread faces are thin helical
  // B-spline bands. Smoothing them moved nodes past the bands' sides in (u, v),
  // where the B-spline is extrapolated: off the face (up to 0.2 mm off its surface)
  // with sound corners, so no measure of the quads saw it. Every node of every
  // meshed B-spline face must lie on its surface, where it projects inside the
  // face's (u, v) box (the margins are for boundary nodes, placed on edges within
  // their tolerance).
  const fs::path archive = fs::path(TQUAD_SHARED_CAD_DIR) / ".." / "corpus" / "freecad-library-119.tar.xz";
  if (!fs::exists(archive)) GTEST_SKIP() << "no " << archive << " (the corpus is not shipped)";
  const fs::path folder = fs::temp_directory_path() / ("tquad_corpus_box_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string file = "SFU1605-200.step";
  const std::string command = "tar -xJf '" + archive.string() + "' -C '" + folder.string() + "' 'parts/" + file + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const TopoDS_Shape shape = read_shape((folder / "parts" / file).string());
  fs::remove_all(folder);
  ShapeMeshOptions options;
  options.keep_going = true;
  options.size = diagonal(shape) / 25;
  const ShapeMeshResult result = mesh_shape(shape, options);
  const ShapeIndex index(shape);
  int checked = 0;
  for (const FaceMesh& f : result.mesh.faces) {
    const TopoDS_Face& face = index.face(f.face);
    const BRepAdaptor_Surface adaptor(face);
    if (adaptor.GetType() != GeomAbs_BSplineSurface || adaptor.IsUPeriodic() || adaptor.IsVPeriodic()) continue;
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    const double du = 1e-4 * (u1 - u0), dv = 1e-4 * (v1 - v0);
    TopLoc_Location location;
    ShapeAnalysis_Surface surface(BRep_Tool::Surface(face, location));
    const gp_Trsf to_local = location.Transformation().Inverted();
    const double off = std::max(1e-6 * diagonal(shape), 2 * std::max(BRep_Tool::MaxTolerance(face, TopAbs_EDGE),
                                                                       BRep_Tool::MaxTolerance(face, TopAbs_VERTEX)));
    std::set<NodeId> nodes;
    for (std::int64_t k = f.first_quad; k < f.first_quad + f.quad_count; ++k) {
      nodes.insert(result.mesh.quads[k].begin(), result.mesh.quads[k].end());
    }
    for (NodeId n : nodes) {
      const Vec3& p = result.mesh.nodes[n];
      const gp_Pnt2d uv = surface.ValueOfUV(gp_Pnt(p.x, p.y, p.z).Transformed(to_local), 1e-7);
      EXPECT_LE(surface.Gap(), off) << "face " << f.face << " node " << n << " off its surface";
      EXPECT_TRUE(uv.X() >= u0 - du && uv.X() <= u1 + du && uv.Y() >= v0 - dv && uv.Y() <= v1 + dv)
          << "face " << f.face << " node " << n << " at (u, v) (" << uv.X() << ", " << uv.Y() << "), the face's box ["
          << u0 << ", " << u1 << "] x [" << v0 << ", " << v1 << "]";
    }
    ++checked;
  }
  EXPECT_GT(checked, 10) << "the part's B-spline faces";
}

TEST(ShapeMeshing, AThinRingIsBalancedAgainAfterABandsBalance) {
  // GT2Pulley.stp face 54: a circle of radius 1.25 around a hexagonal socket of
  // circumradius 1.155, the circle shared with a chamfer band around a seam. The
  // ring was balanced, then the band's balance changed the circle's count and the
  // ring was decomposed (worst 0.017, the part's worst). Balanced again
  // (interval_assignment.h) and aligned (band_alignment.h), it is one mapped ring.
  expect_corpus_part_face("GT2Pulley.stp", 54, "R", 0.3);
}

TEST(ShapeMeshing, ABandWithAPoleAtACornerIsBalancedAndMapped) {
  // DC-Motor_3-6V.step face 93: a B-spline band 0.15 to 0.3 wide and 4.5 long whose
  // surface collapses at one corner (a degenerate edge there). Left out of the band
  // balance for that edge, its long sides kept unequal counts, and a transition one
  // quad across left two of its 7 quads inverted: the face was refused. The pole is
  // one node of the loop, a corner like any other; balanced, the band is a mapped grid.
  expect_corpus_part_face("DC-Motor_3-6V.step", 93, "T0", 0.5);
}

TEST(ShapeMeshing, AThinRingsFacingArcsKeepEqualCounts) {
  // SampleCrankshaft4A.stp face 103: a flat ring 3.2 wide between radii 25.4 and
  // 28.6, each circle two half arcs, the outer ones shared with a cylinder. At the
  // default size the ring's loop totals were balanced (14 and 14) but its outer arcs
  // ended at 6 and 8 against 7 and 7 inside, the mapped ring folded and the face was
  // decomposed into 35 quads of mean 0.47; facing arcs chained, it is one ring.
  expect_shared_part_face("SampleCrankshaft4A.stp", 103, "R", 0.9);
}

TEST(ShapeMeshing, APoorFacesDecompositionSearchesItsPatchesCorners) {
  // linkrods.step face 26: a B-spline wedge 0.5 long, two long sides and two pairs of
  // tiny arcs. At the default size its corners gave 9 quads, worst 0.266 (the part's
  // worst); its decomposition's one patch, meshed with the corner set that meshes it
  // best (MeshOptions::search_patch_corners), gives 0.53.
  expect_shared_part_face("linkrods.step", 26, "D", 0.45);
}

TEST(ShapeMeshing, IgesInput) {
  // The bracket written as IGES (BRep mode, which keeps faces and shared edges) reads
  // back and meshes every face.
  const TopoDS_Shape bracket = read_shape(std::string(TQUAD_SOURCE_DIR) + "/resources/shapes/filleted_bracket.brep");
  const std::string path = (fs::temp_directory_path() / "bracket.igs").string();
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 1);  // 1: BRep mode
  ASSERT_TRUE(writer.AddShape(bracket));
  writer.ComputeModel();
  ASSERT_TRUE(writer.Write(path.c_str()));
  const FileReport r = check_file(path);
  fs::remove(path);
  EXPECT_EQ(r.faces, 9);
  EXPECT_EQ(r.refused, 0);
}

TEST(ShapeMeshing, AnIgesSeamOfTwoEdgesClosesTheMesh) {
  // A cylinder 2 high written as IGES trimmed surfaces (faces mode, as FreeCAD
  // writes it): its side's seam comes back as two edges between the same two
  // vertices. At size 3 each is one segment, and the mesh's two sides of the seam
  // are one mesh edge in two quads: the closure check (face_mesh_closure.h) called
  // that an edge segment in no quad and refused the face as an internal failure.
  const std::string path = (fs::temp_directory_path() / "short_cylinder.igs").string();
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 0);  // 0: faces mode
  ASSERT_TRUE(writer.AddShape(BRepPrimAPI_MakeCylinder(5, 2).Shape()));
  writer.ComputeModel();
  ASSERT_TRUE(writer.Write(path.c_str()));
  ShapeMeshOptions options;
  options.size = 3;
  options.keep_going = true;
  const ShapeMeshResult result = mesh_shape(read_shape(path), options);
  fs::remove(path);
  EXPECT_TRUE(result.mesh.refused_faces.empty()) << result.mesh.refused_faces.front().reason;
  EXPECT_EQ(result.mesh.faces.size(), 3u);
}

// The shipped bracket written as IGES (in millimetres, B-rep entities) by OpenCASCADE.
std::string bracket_as_iges() {
  const TopoDS_Shape bracket = read_shape(std::string(TQUAD_SOURCE_DIR) + "/resources/shapes/filleted_bracket.brep");
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 1);
  EXPECT_TRUE(writer.AddShape(bracket));
  writer.ComputeModel();
  std::ostringstream text;
  EXPECT_TRUE(writer.Write(text));
  return text.str();
}

std::string file_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

int count_faces(const TopoDS_Shape& shape) {
  int faces = 0;
  for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next()) ++faces;
  return faces;
}

// `text` written to a temporary file `name` and read: the faces read, or -1 with the
// refusal's message in `refusal`.
int faces_read(const std::string& name, const std::string& text, std::string& refusal) {
  const std::string path = (fs::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  int faces = -1;
  try {
    faces = count_faces(read_shape(path));
  } catch (const InputError& e) {
    refusal = e.what();
  }
  fs::remove(path);
  return faces;
}

// `text` with its one `from` made `to`.
std::string edited(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(ShapeMeshing, SewingJoinsTrimmedSurfacesIntoTheSolidsMesh) {
  // The bracket written as IGES trimmed surfaces (type 144, as many systems write
  // IGES): each face comes with edges of its own, so the mesh falls apart along 21
  // pairs of edges. Sewn, it is the B-rep bracket's mesh again: the same nodes and
  // quads, and no unsewn pair; face numbers stay those of the file.
  const std::string source = std::string(TQUAD_SOURCE_DIR) + "/resources/shapes/filleted_bracket.brep";
  const TopoDS_Shape bracket = read_shape(source);
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 0);
  ASSERT_TRUE(writer.AddShape(bracket));
  writer.ComputeModel();
  const fs::path path = fs::temp_directory_path() / "bracket_trimmed_surfaces.igs";
  ASSERT_TRUE(writer.Write(path.string().c_str()));
  const TopoDS_Shape faces = read_shape(path.string());
  fs::remove(path);
  const ShapeMeshResult solid = mesh_shape(bracket, ShapeMeshOptions{});
  const ShapeMeshResult apart = mesh_shape(faces, ShapeMeshOptions{});
  EXPECT_EQ(apart.unsewn_edges.size(), 21u);
  EXPECT_GT(apart.mesh.nodes.size(), solid.mesh.nodes.size());
  ShapeMeshOptions sew;
  sew.sew = true;
  const ShapeMeshResult sewn = mesh_shape(faces, sew);
  EXPECT_EQ(sewn.sewn_edges, 21);
  EXPECT_TRUE(sewn.unsewn_edges.empty());
  EXPECT_EQ(sewn.mesh.nodes.size(), solid.mesh.nodes.size());
  EXPECT_EQ(sewn.mesh.quads.size(), solid.mesh.quads.size());
  ASSERT_EQ(sewn.mesh.faces.size(), apart.mesh.faces.size());
  for (std::size_t i = 0; i < sewn.mesh.faces.size(); ++i) EXPECT_EQ(sewn.mesh.faces[i].face, apart.mesh.faces[i].face);
  // Sewing a shape that has no free edges changes nothing.
  const ShapeMeshResult solid_sewn = mesh_shape(bracket, sew);
  EXPECT_EQ(solid_sewn.sewn_edges, 0);
  EXPECT_EQ(solid_sewn.mesh.nodes.size(), solid.mesh.nodes.size());
}

TEST(ShapeMeshing, AnIgesShellThatLostAFaceIsRefused) {
  // The bracket as IGES with its first direction entity's type 123 made 193 (a
  // random edit did that): the face whose plane it orients does not transfer, and
  // OpenCASCADE's shell came through with 8 faces of 9, meshed with exit 0 before.
  std::string refusal;
  EXPECT_EQ(faces_read("bracket_lost_face.igs", edited(bracket_as_iges(), "\n123,", "\n193,"), refusal), -1);
  EXPECT_NE(refusal.find("is damaged: the shell at directory entry 5 lost its face 1 of 9"), std::string::npos)
      << refusal;
}

TEST(ShapeMeshing, AnIgesFaceThatDoesNotReadWholeIsRefused) {
  // The bracket as IGES with its first face's outer-loop flag 1 made 7: the face's
  // entity does not read whole. Random edits did that to a face of tank.brep written
  // as IGES, which came back with 53 faces of 52 and exit 0.
  std::string iges = bracket_as_iges();
  const std::size_t face = iges.find("\n510,");
  ASSERT_NE(face, std::string::npos) << "no face entity in the parameter section";
  const std::size_t flag = iges.find(",1,1,", face);
  ASSERT_LT(flag, iges.find(';', face)) << "the first face's parameters are not surface, 1 loop, flag 1";
  iges.replace(flag, 5, ",1,7,");
  std::string refusal;
  EXPECT_EQ(faces_read("bracket_bad_face_flag.igs", iges, refusal), -1);
  EXPECT_NE(refusal.find("(type 510) did not read (Parameter Data : parameter 3 (Outer Loop flag)"),
            std::string::npos)
      << refusal;
}

TEST(ShapeMeshing, AnIgesUnitFlagThatDisagreesWithItsNameIsRefused) {
  // The bracket as IGES, unit flag 2 and name "MM", with the flag made 1 (inches):
  // OpenCASCADE scales by the flag, and the bracket came out 25.4 times too large.
  const std::string iges = bracket_as_iges();
  std::string refusal;
  EXPECT_EQ(faces_read("bracket.igs", iges, refusal), 9) << refusal;
  EXPECT_EQ(faces_read("bracket_unit_flag.igs", edited(iges, ",2,2HMM,", ",1,2HMM,"), refusal), -1);
  EXPECT_NE(refusal.find("unit flag 1 means IN but its unit name is 'MM'"), std::string::npos) << refusal;
}

TEST(ShapeMeshing, AStepLineCutShortIsRefusedNotMeshedLarger) {
  // A random edit of 918_pump_carter_sup_21_03_2006.stp cut an oriented edge's line
  // to "#2815=ORIENTED_6,.F.);": the parser dropped it, the edge loop after it came
  // one edge short with no failure of its own, and OpenCASCADE's healing made the
  // face reach past it: all 119 faces, the part twice as large, with exit 0.
  const fs::path part = fs::path(TQUAD_SHARED_CAD_DIR) / "918_pump_carter_sup_21_03_2006.stp";
  if (!fs::exists(part)) GTEST_SKIP() << "no " << part << " (the CAD parts are not shipped)";
  const std::string step =
      edited(file_text(part), "#2815=ORIENTED_EDGE('',*,*,#2776,.F.);", "#2815=ORIENTED_6,.F.);");
  std::string refusal;
  EXPECT_EQ(faces_read("pump_line_cut.stp", step, refusal), -1);
  EXPECT_NE(refusal.find("is damaged: Undefined Parsing: Line 2466: Incorrect syntax"), std::string::npos)
      << refusal;
}

TEST(ShapeMeshing, FacesLeftOutGiveTheirNeighboursRoomToBeEven) {
  // 918_pump_carter_sup_21_03_2006.stp without its faces 98 to 100 (left out, as a
  // damaged vertex there refuses them) kept face 37 odd with no odd partner and no
  // edge of its own to change, and the whole part was refused; the edges beside the
  // left-out faces give the way out.
  const fs::path part = fs::path(TQUAD_SHARED_CAD_DIR) / "918_pump_carter_sup_21_03_2006.stp";
  if (!fs::exists(part)) GTEST_SKIP() << "no " << part << " (the CAD parts are not shipped)";
  ShapeMeshOptions options;
  for (int f = 0; f < 119; ++f) if (f < 98 || f > 100) options.faces.push_back(f);
  const ShapeMeshResult result = mesh_shape(read_shape(part.string()), options);
  EXPECT_EQ(result.mesh.refused_faces.size(), 0u);
  EXPECT_GT(result.mesh.quads.size(), 0u);
}

// Two boxes side by side written as one STEP file, returned as its text.
std::string two_boxes_as_step() {
  TopoDS_Compound boxes;
  BRep_Builder builder;
  builder.MakeCompound(boxes);
  builder.Add(boxes, BRepPrimAPI_MakeBox(10.0, 10.0, 10.0).Shape());
  builder.Add(boxes, BRepPrimAPI_MakeBox(gp_Pnt(20.0, 0.0, 0.0), 10.0, 10.0, 10.0).Shape());
  STEPControl_Writer writer;
  EXPECT_EQ(writer.Transfer(boxes, STEPControl_AsIs), IFSelect_RetDone);
  const fs::path path = fs::temp_directory_path() / "two_boxes_written.step";
  EXPECT_EQ(writer.Write(path.string().c_str()), IFSelect_RetDone);
  const std::string text = file_text(path);
  fs::remove(path);
  return text;
}

TEST(ShapeMeshing, AStepBodyWhoseShellDoesNotReadIsRefused) {
  // The first CLOSED_SHELL's type name damaged: its MANIFOLD_SOLID_BREP no longer
  // reads, OpenCASCADE transfers the other box alone, and the file was meshed as
  // one box of two with exit 0 (found so on a five-body part).
  const std::string step = two_boxes_as_step();
  std::string refusal;
  EXPECT_EQ(faces_read("two_boxes.step", step, refusal), 12) << refusal;
  EXPECT_EQ(faces_read("two_boxes_one_shell_damaged.step", edited(step, "CLOSED_SHELL(", "CLOSED_SHELX("), refusal),
            -1);
  EXPECT_NE(refusal.find("(MANIFOLD_SOLID_BREP) did not read (Parameter n0.2 (outer)"), std::string::npos)
      << refusal;
}

TEST(ShapeMeshing, ExampleShapes) { check_folder(fs::path(TQUAD_SOURCE_DIR) / "resources" / "shapes"); }

TEST(ShapeMeshing, SharedCadParts) {
  const fs::path dir(TQUAD_SHARED_CAD_DIR);
  if (!fs::is_directory(dir)) GTEST_SKIP() << "no CAD parts at " << dir << " (they are not shipped)";
  check_folder(dir);
}

TEST(ShapeMeshing, OutputDoesNotDependOnThreads) {
  const TopoDS_Shape shape = read_shape(std::string(TQUAD_SOURCE_DIR) + "/resources/shapes/filleted_bracket.brep");
  ShapeMeshOptions one, many;
  one.threads = 1;
  many.threads = 4;
  one.keep_going = many.keep_going = true;
  const ShapeMesh a = mesh_shape(shape, one).mesh, b = mesh_shape(shape, many).mesh;
  ASSERT_EQ(a.quads, b.quads);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) ASSERT_TRUE(a.nodes[i] == b.nodes[i]) << "node " << i;
}

// A 100 x 60 plate face with round holes of radius 8 centred on `centres`.
TopoDS_Shape plate_with_holes(const std::vector<gp_Pnt>& centres) {
  BRepBuilderAPI_MakePolygon outline(gp_Pnt(0, 0, 0), gp_Pnt(100, 0, 0), gp_Pnt(100, 60, 0), gp_Pnt(0, 60, 0), true);
  BRepBuilderAPI_MakeFace face(outline.Wire());
  for (const gp_Pnt& c : centres) {
    TopoDS_Wire hole = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(c, gp_Dir(0, 0, 1)), 8.0)));
    hole.Reverse();  // inner wires run the other way round
    face.Add(hole);
  }
  return face.Face();
}

TEST(ShapeMeshing, FaceWithOneHoleIsCutInTwo) {
  const FileReport r = check_primitive(plate_with_holes({gp_Pnt(50, 30, 0)}), "plate_one_hole");
  EXPECT_EQ(r.refused, 0);
  // A ring: a one-edge outer wire around a hole.
  TopoDS_Wire hole = BRepBuilderAPI_MakeWire(
      BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 5.0)));
  hole.Reverse();
  BRepBuilderAPI_MakeFace ring(BRepBuilderAPI_MakeWire(
      BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 20.0))));
  ring.Add(hole);
  EXPECT_EQ(check_primitive(ring.Face(), "ring").refused, 0);
}

TEST(ShapeMeshing, FacesWithSeveralHolesAreDecomposed) {
  const std::vector<std::vector<gp_Pnt>> layouts = {
      {gp_Pnt(25, 30, 0), gp_Pnt(75, 30, 0)},
      {gp_Pnt(15, 15, 0), gp_Pnt(85, 15, 0), gp_Pnt(85, 45, 0), gp_Pnt(15, 45, 0), gp_Pnt(50, 30, 0)}};
  for (const std::vector<gp_Pnt>& centres : layouts) {
    const std::string name = "plate_" + std::to_string(centres.size()) + "_holes";
    EXPECT_EQ(check_primitive(plate_with_holes(centres), name).refused, 0) << name;
    const ShapeMeshResult result = mesh_shape(plate_with_holes(centres), ShapeMeshOptions{});
    ASSERT_EQ(result.mesh.faces.size(), 1u);
    EXPECT_EQ(result.mesh.faces[0].template_tree.substr(0, 1), "D") << result.mesh.faces[0].template_tree;
    // One face with h holes: nodes = 1 + quads + boundary_edges / 2 - h.
    long long boundary_edges = 0;
    std::map<std::pair<NodeId, NodeId>, int> uses;
    for (const Quad& q : result.mesh.quads) {
      for (int i = 0; i < 4; ++i) ++uses[{std::min(q[i], q[(i + 1) % 4]), std::max(q[i], q[(i + 1) % 4])}];
    }
    for (const auto& [edge, count] : uses) boundary_edges += count == 1 ? 1 : 0;
    EXPECT_EQ(static_cast<long long>(result.mesh.nodes.size()),
              1 + static_cast<long long>(result.mesh.quads.size()) + boundary_edges / 2 -
                  static_cast<long long>(centres.size()))
        << name;
  }
}

TEST(ShapeMeshing, RefusedFacesNameTheFace) {
  // A drilled cone (generated_parts.h): its side face, with a pole and a hole, is
  // refused, and named.
  const TopoDS_Shape cone = drilled_cone(0, 0, 0);
  const ShapeIndex index(cone);
  int side = -1;
  for (int f = 0; f < index.face_count(); ++f) {
    if (BRepAdaptor_Surface(index.face(f)).GetType() == GeomAbs_Cone) side = f;
  }
  ASSERT_GE(side, 0);
  try {
    mesh_shape(cone, ShapeMeshOptions{});
    FAIL() << "a drilled cone's side should be refused without --keep-going";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face " + std::to_string(side)), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tquad

namespace tquad {
namespace {

TopoDS_Shape bracket() {
  return read_shape(std::string(TQUAD_SOURCE_DIR) + "/resources/shapes/filleted_bracket.brep");
}

TEST(ShapePipeline, ReportsItsStagesInOrderAndEveryFace) {
  std::vector<std::string> stages;
  int faces_done = 0, faces_total = 0;
  ShapeMeshOptions options;
  options.progress = [&](const MeshProgress& p) {
    if (stages.empty() || stages.back() != p.stage) stages.push_back(p.stage);
    if (p.stage == "mesh faces" && p.total > 1) {
      faces_done = std::max(faces_done, p.done);
      faces_total = p.total;
    }
  };
  const ShapeMeshResult result = mesh_shape(bracket(), options);
  EXPECT_EQ(stages, (std::vector<std::string>{"index", "assign intervals", "discretize edges", "mesh faces",
                                              "assemble"}));
  EXPECT_EQ(faces_total, 9);
  EXPECT_EQ(faces_done, 9);
  EXPECT_EQ(result.mesh.faces.size(), 9u);
}

TEST(ShapePipeline, CancelStopsMeshingWithoutAResult) {
  std::atomic<bool> cancel{true};
  ShapeMeshOptions options;
  options.cancel = &cancel;
  EXPECT_THROW(mesh_shape(bracket(), options), MeshCancelled);
  // Raised from the progress hook once the first face is done.
  cancel = false;
  int faces_after_cancel = 0;
  options.progress = [&](const MeshProgress& p) {
    if (p.stage != "mesh faces" || p.total <= 1) return;
    if (cancel) ++faces_after_cancel;
    cancel = true;
  };
  options.threads = 1;
  EXPECT_THROW(mesh_shape(bracket(), options), MeshCancelled);
  EXPECT_EQ(faces_after_cancel, 0) << "no face is meshed after the cancel";
}

}  // namespace
}  // namespace tquad

namespace tquad {
namespace {

// Two 10 x 10 squares side by side, each made on its own (so each has its own edge
// on x = 10), in one compound: the faces touch along that line without sharing it.
TopoDS_Shape two_unsewn_squares() {
  BRep_Builder builder;
  TopoDS_Compound both;
  builder.MakeCompound(both);
  builder.Add(both, BRepBuilderAPI_MakeFace(gp_Pln(), 0, 10, 0, 10).Face());
  builder.Add(both, BRepBuilderAPI_MakeFace(gp_Pln(), 10, 20, 0, 10).Face());
  return both;
}

TEST(UnsewnEdges, FacesTouchingWithEdgesOfTheirOwnAreFoundAndReported) {
  const TopoDS_Shape shape = two_unsewn_squares();
  const ShapeIndex index(shape);
  const std::vector<UnsewnEdgePair> pairs = unsewn_edge_pairs(index);
  ASSERT_EQ(pairs.size(), 1u);
  for (const int e : {pairs[0].first, pairs[0].second}) {
    const BRepAdaptor_Curve curve(index.edge(e));
    EXPECT_NEAR(curve.Value(curve.FirstParameter()).X(), 10.0, 1e-9) << "edge " << e << " is not on x = 10";
  }
  ShapeMeshOptions options;
  options.size = 2.0;
  const ShapeMeshResult result = mesh_shape(shape, options);
  ASSERT_EQ(result.unsewn_edges.size(), 1u);
  EXPECT_EQ(result.unsewn_edges[0].first, pairs[0].first);
  // Meshing only one of the two faces leaves no crack to report.
  options.faces = {0};
  EXPECT_TRUE(mesh_shape(shape, options).unsewn_edges.empty());
}

TEST(UnsewnEdges, SewnOpenAndNonManifoldShapesHaveNone) {
  for (const char* name : {"filleted_bracket.brep", "open_box.brep", "three_fins.brep", "plate_with_hole.step",
                           "cylinder.brep"}) {
    const fs::path path = fs::path(TQUAD_SOURCE_DIR) / "resources" / "shapes" / name;
    EXPECT_TRUE(unsewn_edge_pairs(ShapeIndex(read_shape(path.string()))).empty()) << name;
  }
}

}  // namespace
}  // namespace tquad
