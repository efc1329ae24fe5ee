// The eight-node quad's fold test (quadratic_quad.h): straight edges keep the corners'
// quality, a gently curved edge stays valid, a middle bent past the opposite side of
// a thin quad folds it.
#include <gtest/gtest.h>

#include "core/mesh/quadratic_quad.h"

namespace tquad {
namespace {

// A w x h rectangle with straight edges (middles at the chords' middles).
std::array<Vec3, 8> rectangle(double w, double h) {
  return {Vec3{0, 0, 0}, Vec3{w, 0, 0}, Vec3{w, h, 0}, Vec3{0, h, 0},
          Vec3{w / 2, 0, 0}, Vec3{w, h / 2, 0}, Vec3{w / 2, h, 0}, Vec3{0, h / 2, 0}};
}

TEST(QuadraticQuad, StraightRectangleIsPerfect) {
  EXPECT_NEAR(quadratic_quad_min_scaled_jacobian(rectangle(2, 1)), 1.0, 1e-12);
}

TEST(QuadraticQuad, GentlyCurvedEdgeStaysValid) {
  auto q = rectangle(1, 1);
  q[4].y = 0.1;  // the bottom edge bulges inwards a tenth of the height
  const double sj = quadratic_quad_min_scaled_jacobian(q);
  EXPECT_GT(sj, 0.0);
  EXPECT_LT(sj, 1.0);
}

TEST(QuadraticQuad, MiddleBentPastTheOppositeSideFolds) {
  auto q = rectangle(4, 0.1);
  q[4].y = 0.3;  // the bottom edge's middle above the top edge
  EXPECT_LE(quadratic_quad_min_scaled_jacobian(q), 0.0);
}

TEST(QuadraticQuad, DegenerateCornersAreNotValid) {
  const std::array<Vec3, 8> flat{};
  EXPECT_LE(quadratic_quad_min_scaled_jacobian(flat), 0.0);
}

// Two thin quads side by side (x in [0, 4] and [4, 8], y in [0, 0.1]), second order,
// the first quad's bottom middle bent above its top: that quad gets straight edges,
// the shared middle between the two is moved once, and both end valid.
TEST(QuadraticQuad, FoldedQuadsGetStraightEdges) {
  ShapeMesh mesh;
  mesh.nodes = {{0, 0, 0}, {4, 0, 0}, {8, 0, 0}, {0, 0.1, 0}, {4, 0.1, 0}, {8, 0.1, 0}};
  mesh.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  // Middles: 6 bottom-left (bent), 7 shared (bent sideways), 8 top-left, 9 left,
  // 10 bottom-right, 11 right, 12 top-right.
  mesh.nodes.insert(mesh.nodes.end(), {{2, 0.3, 0}, {4.05, 0.05, 0}, {2, 0.1, 0}, {0, 0.05, 0},
                                       {6, 0, 0}, {8, 0.05, 0}, {6, 0.1, 0}});
  mesh.mid_nodes = {{6, 7, 8, 9}, {10, 11, 12, 7}};
  ASSERT_LE(quadratic_quad_min_scaled_jacobian(element_positions(mesh, 0)), 0.0);
  EXPECT_EQ(straighten_folded_quads(mesh), 2);  // nodes 6 and 7; the others are on their chords
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_GT(quadratic_quad_min_scaled_jacobian(element_positions(mesh, k)), 0.0);
  }
  EXPECT_EQ(mesh.nodes[6], (Vec3{2, 0, 0}));
  EXPECT_EQ(mesh.nodes[7], (Vec3{4, 0.05, 0}));
  EXPECT_EQ(straighten_folded_quads(mesh), 0) << "nothing left to do";
}

}  // namespace
}  // namespace tquad
