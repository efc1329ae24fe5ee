// Parity: after assign_even_intervals every meshed face has an even boundary total,
// with few, small changes.
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <gp_Ax1.hxx>
#include <gp_Circ.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <map>

#include "occ/intervals/edge_discretization.h"
#include "occ/intervals/interval_assignment.h"
#include "occ/shape_mesher.h"
#include "occ/model/shape_index.h"

namespace tquad {
namespace {

TopoDS_Shape triangle_face(double a) {
  BRepBuilderAPI_MakePolygon polygon(gp_Pnt(0, 0, 0), gp_Pnt(a, 0, 0), gp_Pnt(0.5 * a, 0.8 * a, 0), true);
  return BRepBuilderAPI_MakeFace(polygon.Wire()).Face();
}

// A prism on a triangle: with size = a, the triangles have 1 + 1 + 1 = 3 edges (odd).
TopoDS_Shape triangular_prism(double a, double height) {
  return BRepPrimAPI_MakePrism(triangle_face(a), gp_Vec(0, 0, height)).Shape();
}

void expect_all_even(const TopoDS_Shape& shape, double size, int max_changes) {
  const ShapeIndex index(shape);
  std::vector<double> lengths;
  std::vector<int> segments = edge_segment_counts(index, size, lengths);
  int odd_before = 0;
  for (int f = 0; f < index.face_count(); ++f) odd_before += face_boundary_total(index, f, segments) % 2;
  EXPECT_GT(odd_before, 0) << "the case should start with odd faces";
  const std::vector<char> meshed(index.face_count(), 1);
  const auto changes = assign_even_intervals(index, meshed, lengths, size, segments);
  for (int f = 0; f < index.face_count(); ++f) {
    EXPECT_EQ(face_boundary_total(index, f, segments) % 2, 0) << "face " << f;
  }
  EXPECT_LE(static_cast<int>(changes.size()), max_changes);
  for (const IntervalChange& c : changes) {
    EXPECT_EQ(std::abs(c.to - c.from), 1);
    EXPECT_GE(c.to, 1);
  }
}

TEST(IntervalAssignment, ClosedPrismPairsItsOddTriangles) {
  // The two triangles are odd; the shortest path between them crosses one side face:
  // two edge changes.
  expect_all_even(triangular_prism(1.0, 2.0), 1.0, 2);
}

TEST(IntervalAssignment, OpenFaceUsesOneOfItsOwnEdges) {
  expect_all_even(triangle_face(1.0), 1.0, 1);
}

TEST(IntervalAssignment, MeshedPrismIsWatertight) {
  ShapeMeshOptions options;
  options.size = 0.34;  // 3 edges per unit: triangles 3 + 3 + 2 or similar, odd
  const ShapeMeshResult r = mesh_shape(triangular_prism(1.0, 2.0), options);
  EXPECT_TRUE(r.mesh.refused_faces.empty());
  std::map<std::pair<NodeId, NodeId>, int> uses;
  for (const Quad& q : r.mesh.quads) {
    for (int i = 0; i < 4; ++i) {
      const NodeId a = q[i], b = q[(i + 1) % 4];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  for (const auto& [edge, count] : uses) EXPECT_EQ(count, 2) << edge.first << "-" << edge.second;
}

// A cylinder of radius 10 and height 20 capped by a flat cone (apex 2 above the
// rim), cylinder and cone each in four quarter faces, the bottom one disk of four
// arcs. Each cone quarter is bounded by its rim arc, two generatrices shared with
// the next quarters only, and its apex (a degenerate edge).
TopoDS_Shape cone_capped_cylinder_in_quarters() {
  BRepBuilderAPI_Sewing sewing;
  const gp_Ax1 axis(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  BRepBuilderAPI_MakeWire bottom;
  for (int k = 0; k < 4; ++k) {
    const double a = k * M_PI / 2;
    const gp_Pnt rim_low(10 * std::cos(a), 10 * std::sin(a), 0), rim_high(10 * std::cos(a), 10 * std::sin(a), 20);
    sewing.Add(BRepPrimAPI_MakeRevol(BRepBuilderAPI_MakeEdge(rim_low, rim_high).Edge(), axis, M_PI / 2).Shape());
    sewing.Add(BRepPrimAPI_MakeRevol(BRepBuilderAPI_MakeEdge(rim_high, gp_Pnt(0, 0, 22)).Edge(), axis, M_PI / 2).Shape());
    const gp_Circ circle(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 10);
    bottom.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(circle, a, a + M_PI / 2, true).Value()).Edge());
  }
  sewing.Add(BRepBuilderAPI_MakeFace(bottom.Wire()).Face());
  sewing.Perform();
  return sewing.SewedShape();
}

TEST(IntervalAssignment, AConeQuartersEdgesBesideItsApexTakeTwoSegmentsOrMore) {
  // A face of three edges besides a degenerate one (the apex) is meshed as a triangle,
  // whose sides want two segments or more (count_fitting.h); its generatrices
  // (10.2 long, 1 segment at the size 10) are shared with the next quarters only.
  // With 1, 2, 1 it was one quad, a corner of 135 degrees at its arc's middle and two
  // at the apex (scaled Jacobian 0.693; tank.brep's end caps, quarter disks with
  // their centres collapsed, were three quads with a corner of 157.5 degrees on the
  // arc: 0.381).
  const TopoDS_Shape shape = cone_capped_cylinder_in_quarters();
  const ShapeIndex index(shape);
  ShapeMeshOptions options;
  options.size = 10;
  const ShapeMeshResult result = mesh_shape(shape, options);
  int cones = 0;
  for (const FaceMesh& face : result.mesh.faces) {
    if (BRepAdaptor_Surface(index.face(face.face)).GetType() != GeomAbs_Cone) continue;
    ++cones;
    double worst = 1;
    for (std::int64_t q = face.first_quad; q < face.first_quad + face.quad_count; ++q) {
      worst = std::min(worst, result.mesh.scaled_jacobian[q]);
    }
    EXPECT_GE(face.quad_count, 3) << "face " << face.face;
    EXPECT_GT(worst, 0.8) << "face " << face.face;
  }
  EXPECT_EQ(cones, 4);
}

}  // namespace
}  // namespace tquad
