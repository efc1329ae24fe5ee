// The transfinite maps interpolate their curves, and a T0 grid on a rectangle with
// uniform sides is the exact tensor grid.
#include <gtest/gtest.h>

#include "boundary_generators.h"
#include "core/geometry/curve_geometry.h"
#include "core/templates/mapped_grid.h"
#include "core/templates/mesher.h"
#include "core/templates/patch_maps.h"

namespace tquad {
namespace {

std::vector<NodeId> ids(int first, int count) {
  std::vector<NodeId> v;
  for (int i = 0; i < count; ++i) v.push_back(first + i);
  return v;
}

TEST(TransfiniteMaps, QuadPatchInterpolatesItsCurves) {
  // Four curved sides of a patch, as explicit polylines.
  std::vector<Vec3> nodes;
  auto add = [&](const testing::Curve& c, int n) {
    for (int i = 0; i <= n; ++i) nodes.push_back(c(static_cast<double>(i) / n));
  };
  const Vec3 p00{0, 0, 0}, p10{2, 0, 0}, p11{2, 1, 0}, p01{0, 1.2, 0};  // arcs are planar
  add(testing::arc(p00, p10, -0.1), 8);
  add(testing::arc(p10, p11, 0.05), 5);
  add(testing::line(p11, p01), 6);
  add(testing::arc(p01, p00, -0.2), 4);
  const CurveGeometry s0(ids(0, 9), nodes), s1(ids(9, 6), nodes), s2(ids(15, 7), nodes),
      s3(ids(22, 5), nodes);
  const QuadPatchMap F(s0, s1, s2, s3);
  for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    EXPECT_LE(distance(F(t, 0), s0.at(t)), 1e-12);
    EXPECT_LE(distance(F(1, t), s1.at(t)), 1e-12);
    EXPECT_LE(distance(F(t, 1), s2.at(1 - t)), 1e-12);
    EXPECT_LE(distance(F(0, t), s3.at(1 - t)), 1e-12);
  }
}

TEST(TransfiniteMaps, TriPatchInterpolatesItsCurvesAndReproducesPlanarTriangles) {
  std::vector<Vec3> nodes;
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0.3, 0.8, 0};
  for (int i = 0; i <= 4; ++i) nodes.push_back(testing::line(a, b)(i / 4.0));
  for (int i = 0; i <= 4; ++i) nodes.push_back(testing::line(b, c)(i / 4.0));
  for (int i = 0; i <= 4; ++i) nodes.push_back(testing::line(c, a)(i / 4.0));
  const CurveGeometry s0(ids(0, 5), nodes), s1(ids(5, 5), nodes), s2(ids(10, 5), nodes);
  const TriPatchMap T(s0, s1, s2);
  for (double t : {0.1, 0.5, 0.9}) {
    EXPECT_LE(distance(T({1 - t, t, 0}), s0.at(t)), 1e-12);
    EXPECT_LE(distance(T({0, 1 - t, t}), s1.at(t)), 1e-12);
    EXPECT_LE(distance(T({t, 0, 1 - t}), s2.at(t)), 1e-12);
  }
  // Straight sides: the map is the linear (barycentric) one.
  const std::array<double, 3> l{0.2, 0.3, 0.5};
  EXPECT_LE(distance(T(l), l[0] * a + l[1] * b + l[2] * c), 1e-12);
}

TEST(TransfiniteMaps, MappedGridOfAUniformRectangleIsTheTensorGrid) {
  const QuadMesh mesh = mesh_boundary(testing::square_boundary(6, 6, 3, 3));
  ASSERT_EQ(mesh.template_tree, "T0");
  ASSERT_EQ(mesh.quads.size(), 18u);
  for (const Vec3& p : mesh.nodes) {
    const double i = p.x * 6, j = p.y * 3;
    EXPECT_NEAR(i, std::round(i), 1e-12);
    EXPECT_NEAR(j, std::round(j), 1e-12);
  }
}

TEST(TransfiniteMaps, MappedGridFollowsGradedSpacing) {
  // Bottom and top graded the same way: every grid column is a straight vertical line
  // at the boundary nodes' x.
  std::mt19937 rng(1);
  const std::vector<int> counts{8, 4, 8, 4};
  const auto graded = testing::spacing_params(8, testing::Spacing::Graded, 1.3, rng);
  std::vector<double> reversed_graded;
  for (auto it = graded.rbegin(); it != graded.rend(); ++it) reversed_graded.push_back(1 - *it);
  const auto uniform = testing::spacing_params(4, testing::Spacing::Uniform, 1, rng);
  const Vec3 p0{0, 0, 0}, p1{2, 0, 0}, p2{2, 1, 0}, p3{0, 1, 0};
  const BoundaryLoop loop = testing::sample_loop(
      {testing::line(p0, p1), testing::line(p1, p2), testing::line(p2, p3), testing::line(p3, p0)},
      counts, {graded, uniform, reversed_graded, uniform});
  const QuadMesh mesh = mesh_boundary(loop);
  for (std::size_t k = loop.points.size(); k < mesh.nodes.size(); ++k) {
    bool on_a_column = false;
    for (double t : graded) on_a_column |= std::abs(mesh.nodes[k].x - 2 * t) < 1e-12;
    EXPECT_TRUE(on_a_column) << "node " << k << " x " << mesh.nodes[k].x;
  }
}

}  // namespace
}  // namespace tquad
