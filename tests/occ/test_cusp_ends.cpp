// cusp_ends (cusp_ends.h): where two edges of a face leave a vertex tangent and part,
// their segments there are as long as the size allows; a sharp corner between straight
// edges is left even.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRep_Tool.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <gp_Circ.hxx>

#include <algorithm>
#include <cmath>

#include "occ/face/cusp_ends.h"
#include "occ/intervals/edge_discretization.h"
#include "occ/shape_mesher.h"

namespace tquad {
namespace {

// A sliver between the x axis and a circle of radius 100 touching it at the origin,
// closed by a straight edge at x = 30 (4.6 wide there): a cusp at the origin.
constexpr double kRadius = 100.0, kLength = 30.0;

TopoDS_Shape tangent_sliver() {
  const gp_Pnt tip(0, 0, 0), foot(kLength, 0, 0);
  const gp_Pnt top(kLength, kRadius - std::sqrt(kRadius * kRadius - kLength * kLength), 0);
  const gp_Circ circle(gp_Ax2(gp_Pnt(0, kRadius, 0), gp_Dir(0, 0, 1)), kRadius);
  BRepBuilderAPI_MakeWire wire(BRepBuilderAPI_MakeEdge(tip, foot).Edge(), BRepBuilderAPI_MakeEdge(foot, top).Edge(),
                               BRepBuilderAPI_MakeEdge(circle, tip, top).Edge());
  return BRepBuilderAPI_MakeFace(wire.Wire(), true).Face();
}

std::vector<double> lengths_of(const ShapeIndex& index) {
  std::vector<double> lengths;
  edge_segment_counts(index, 1.0, lengths);
  return lengths;
}

// The end of edge e at the point p: +1 its first vertex, -1 its last, 0 neither.
int end_at(const ShapeIndex& index, int e, const gp_Pnt& p) {
  TopoDS_Vertex first, last;
  TopExp::Vertices(TopoDS::Edge(index.edge(e).Oriented(TopAbs_FORWARD)), first, last);
  if (BRep_Tool::Pnt(first).Distance(p) < 1e-9) return 1;
  if (BRep_Tool::Pnt(last).Distance(p) < 1e-9) return -1;
  return 0;
}

TEST(CuspEnds, TheTwoEdgesLeavingATangentTipGetTheSizeThereAndNothingElse) {
  const ShapeIndex index(tangent_sliver());
  ASSERT_EQ(index.edge_count(), 3);
  const std::vector<double> lengths = lengths_of(index);
  const double size = 8.0;
  const std::vector<CuspEnds> cusps = cusp_ends(index, size, lengths);
  int graded = 0;
  for (int e = 0; e < 3; ++e) {
    const int tip_end = end_at(index, e, gp_Pnt(0, 0, 0));
    const double at_tip = tip_end > 0 ? cusps[e].first : cusps[e].last;
    const double other = tip_end > 0 ? cusps[e].last : cusps[e].first;
    EXPECT_EQ(other, 0.0) << "edge " << e;
    if (tip_end == 0) {
      EXPECT_FALSE(cusps[e].any()) << "edge " << e << " (the closing edge)";
    } else {
      EXPECT_DOUBLE_EQ(at_tip, std::min(size, lengths[e] / 3)) << "edge " << e;
      ++graded;
    }
  }
  EXPECT_EQ(graded, 2);
}

TEST(CuspEnds, StraightEdgesAtASharpCornerDoNotPartAndStayEven) {
  // A triangle of 5 degrees at the origin: a sharp corner, but its chords' angle is
  // the same at any distance.
  const double angle = 5.0 * M_PI / 180.0;
  BRepBuilderAPI_MakePolygon polygon(gp_Pnt(0, 0, 0), gp_Pnt(30, 0, 0), gp_Pnt(30 * std::cos(angle), 30 * std::sin(angle), 0),
                                     true);
  const ShapeIndex index(BRepBuilderAPI_MakeFace(polygon.Wire(), true).Face());
  for (const CuspEnds& cusp : cusp_ends(index, 8.0, lengths_of(index))) EXPECT_FALSE(cusp.any());
}

TEST(CuspEnds, TheDiscretizationMakesTheTipSegmentThatLongAndTheOthersEven) {
  const ShapeIndex index(tangent_sliver());
  const std::vector<double> lengths = lengths_of(index);
  EdgeSpacings spacings;
  spacings.cusp_ends = cusp_ends(index, 8.0, lengths);
  int axis = -1;  // the straight edge along the x axis
  for (int e = 0; e < 3; ++e) {
    if (end_at(index, e, gp_Pnt(0, 0, 0)) != 0 && end_at(index, e, gp_Pnt(kLength, 0, 0)) != 0) axis = e;
  }
  ASSERT_GE(axis, 0);
  for (int n : {2, 3, 6, 11}) {
    std::vector<Vec3> nodes;
    const std::vector<EdgeNodes> edges = discretize_edges(index, std::vector<int>(3, n), nodes, &spacings);
    std::vector<double> xs;  // the axis edge's nodes from the tip
    for (NodeId id : edges[axis].nodes) xs.push_back(std::abs(nodes[id].x));
    std::sort(xs.begin(), xs.end());
    ASSERT_EQ(xs.size(), static_cast<std::size_t>(n + 1));
    const double even = kLength / n;
    const bool graded = 8.0 > even;  // n = 6 and 11; 8 is not over 30 / 3 = 10
    EXPECT_NEAR(xs[1], graded ? 8.0 : even, 1e-7) << n << " segments";
    const double rest = graded ? (kLength - 8.0) / (n - 1) : even;
    for (int i = 2; i <= n; ++i) EXPECT_NEAR(xs[i] - xs[i - 1], rest, 1e-7) << n << " segments, node " << i;
  }
}

TEST(CuspEnds, TheShapePipelineSpacesTheTipsEdgesSo) {
  // At size 8 the two long edges get round(30 / 8) = 4 segments, 7.5 long if even; the
  // tip's get 8, so no node but the tip's own lies within 7.9 of it (the arc's first
  // node is 8 away along the arc).
  ShapeMeshOptions options;
  options.size = 8.0;
  const ShapeMeshResult result = mesh_shape(tangent_sliver(), options);
  ASSERT_TRUE(result.mesh.refused_faces.empty());
  EXPECT_EQ(result.inverted, 0);
  double nearest = 1e300;
  for (const Vec3& p : result.mesh.nodes) {
    const double d = std::hypot(p.x, p.y, p.z);
    if (d > 1e-9) nearest = std::min(nearest, d);
  }
  EXPECT_GT(nearest, 7.9);
  EXPECT_LT(nearest, 8.0 + 1e-9);
}

TEST(CuspEnds, UnderALocalSizeTheTipSegmentIsThatSizeNotTheGlobalOne) {
  // The sliver's one face sized 2 under a global 8: each of the tip's edges starts with
  // a segment of at most 2, so the nearest node to the tip is within 2 of it, and no
  // two neighbouring segments of the axis edge differ by more than the growth rate.
  ShapeMeshOptions options;
  options.size = 8.0;
  options.local_sizes = {LocalSize{LocalSize::Kind::face, 0, 2.0}};
  const ShapeMeshResult result = mesh_shape(tangent_sliver(), options);
  ASSERT_TRUE(result.mesh.refused_faces.empty());
  double nearest = 1e300;
  std::vector<double> axis;
  for (const Vec3& p : result.mesh.nodes) {
    const double d = std::hypot(p.x, p.y, p.z);
    if (d > 1e-9) nearest = std::min(nearest, d);
    if (std::abs(p.y) < 1e-9 && std::abs(p.z) < 1e-9) axis.push_back(p.x);
  }
  EXPECT_LE(nearest, 2.0 + 1e-9);
  std::sort(axis.begin(), axis.end());
  ASSERT_GE(axis.size(), 4u);
  for (std::size_t i = 2; i < axis.size(); ++i) {
    const double a = axis[i - 1] - axis[i - 2], b = axis[i] - axis[i - 1];
    EXPECT_LE(std::max(a, b) / std::min(a, b), kDefaultGrowthRate + 1e-6) << "node " << i - 1;
  }
}

TEST(CuspEnds, OnACurveTheTipSegmentKeepsTheCurvatureAngle) {
  // The rectangle [0, 3] x [0, 2] less the half disk of radius 1 about (0, 1): the
  // half circle leaves both of its ends tangent to the rectangle's sides there, two
  // cusps. It turns 180 degrees, so 8 segments a turn allow 45 degrees each;
  // min(size, length / 3) alone would give its end segments 60 degrees.
  const gp_Pnt a(0, 0, 0), b(3, 0, 0), c(3, 2, 0), d(0, 2, 0);
  const gp_Circ circle(gp_Ax2(gp_Pnt(0, 1, 0), gp_Dir(0, 0, 1)), 1.0);
  BRepBuilderAPI_MakeWire wire;
  wire.Add(BRepBuilderAPI_MakeEdge(a, b).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(b, c).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(c, d).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(circle, a, d).Edge());
  ASSERT_TRUE(wire.IsDone());
  ShapeMeshOptions options;
  options.size = 8.0;
  const ShapeMeshResult result = mesh_shape(BRepBuilderAPI_MakeFace(wire.Wire(), true).Face(), options);
  ASSERT_TRUE(result.mesh.refused_faces.empty());
  std::vector<double> angles;  // the half circle's nodes, by their angle about its centre
  for (const Vec3& p : result.mesh.nodes) {
    if (std::abs(std::hypot(p.x, p.y - 1.0) - 1.0) < 1e-9 && p.x >= -1e-12) angles.push_back(std::atan2(p.y - 1.0, p.x));
  }
  std::sort(angles.begin(), angles.end());
  ASSERT_GE(angles.size(), 5u);
  EXPECT_NEAR(angles.front(), -M_PI / 2, 1e-9);
  EXPECT_NEAR(angles.back(), M_PI / 2, 1e-9);
  for (std::size_t i = 1; i < angles.size(); ++i) {
    EXPECT_LE(angles[i] - angles[i - 1], M_PI / 4 + 1e-9) << "segment " << i;
  }
}

}  // namespace
}  // namespace tquad
