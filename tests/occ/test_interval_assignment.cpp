// Parity: after assign_even_intervals every meshed face has an even boundary total,
// with few, small changes.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <gp_Vec.hxx>

#include <map>

#include "occ/edge_discretization.h"
#include "occ/interval_assignment.h"
#include "occ/shape_mesher.h"

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

}  // namespace
}  // namespace tquad
