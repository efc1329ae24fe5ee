// turn_flat_boundary_corners (flat_corner_turns.h): a boundary node alone in one
// quad at a straight boundary gets a second quad; nothing else changes.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/repair/flat_corner_turns.h"
#include "core/mesh/quality.h"
#include "quad_layouts.h"

namespace tquad {
namespace {

using testing::canonical;
using testing::quads_per_node;

// A 3 x 2 rectangle: boundary nodes 0-9 counter-clockwise from (0, 0), inner nodes 10
// (1, 1) and 11 (2, 1).
std::vector<Vec3> rectangle_nodes() {
  return {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {3, 2, 0},
          {2, 2, 0}, {1, 2, 0}, {0, 2, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
}
constexpr int kBoundaryNodes = 10;

std::vector<Quad> grid_quads() {
  return {{0, 1, 10, 9}, {1, 2, 11, 10}, {2, 3, 4, 11}, {9, 10, 7, 8}, {10, 11, 6, 7}, {11, 4, 5, 6}};
}

// The grid with its two lower-left quads cut along 0-11 instead of 1-10: node 1 lies
// in the quad (0, 1, 2, 11) alone, a corner of 180 degrees there.
std::vector<Quad> quads_with_a_flat_corner() {
  return {{0, 1, 2, 11}, {0, 11, 10, 9}, {2, 3, 4, 11}, {9, 10, 7, 8}, {10, 11, 6, 7}, {11, 4, 5, 6}};
}

std::vector<Vec3> up(std::size_t n) { return std::vector<Vec3>(n, Vec3{0, 0, 1}); }

double worst(const std::vector<Quad>& quads, const std::vector<Vec3>& nodes) {
  double w = 1;
  for (const Quad& q : quads) w = std::min(w, scaled_jacobian({nodes[q[0]], nodes[q[1]], nodes[q[2]], nodes[q[3]]}, {0, 0, 1}));
  return w;
}

TEST(FlatCornerTurns, ALoneNodeAtAStraightBoundaryGetsASecondQuad) {
  const std::vector<Vec3> nodes = rectangle_nodes();
  std::vector<Quad> quads = quads_with_a_flat_corner();
  ASSERT_LT(worst(quads, nodes), 1e-9);
  EXPECT_EQ(turn_flat_boundary_corners(quads, kBoundaryNodes, nodes, up(nodes.size())), 1);
  EXPECT_EQ(canonical(quads), canonical(grid_quads()));  // the grid again: every corner square
  EXPECT_DOUBLE_EQ(worst(quads, nodes), 1.0);
}

TEST(FlatCornerTurns, AGoodMeshIsLeftAsItIs) {
  const std::vector<Vec3> nodes = rectangle_nodes();
  std::vector<Quad> quads = grid_quads();
  EXPECT_FALSE(has_flat_lone_corner(quads, kBoundaryNodes, nodes, up(nodes.size())));
  EXPECT_TRUE(has_flat_lone_corner(quads_with_a_flat_corner(), kBoundaryNodes, nodes, up(nodes.size())));
  EXPECT_EQ(turn_flat_boundary_corners(quads, kBoundaryNodes, nodes, up(nodes.size())), 0);
  EXPECT_EQ(quads, grid_quads());
}

TEST(FlatCornerTurns, ATurnLeavingANeighbourAloneAtAStraightBoundaryGoesOnToACorner) {
  // Node 9 moved to (-1, 0): the boundary runs straight through node 0 too. Turning
  // node 1's quad toward node 0 leaves node 0 alone at 180 degrees, so node 0's quad is
  // turned as well, which leaves node 9 alone at a real corner (63 degrees): two turns.
  // Toward node 2 the first turn would leave node 2 alone at 180 degrees in the quad
  // (1, 2, 3, 4), whose next turn would cut along the boundary edge 3-4: undone.
  std::vector<Vec3> nodes = rectangle_nodes();
  nodes[9] = {-1, 0, 0};
  std::vector<Quad> quads = quads_with_a_flat_corner();
  EXPECT_EQ(turn_flat_boundary_corners(quads, kBoundaryNodes, nodes, up(nodes.size())), 2);
  const std::vector<int> count = quads_per_node(quads, nodes.size());
  EXPECT_EQ(count[1], 2);
  EXPECT_EQ(count[0], 2);
  EXPECT_EQ(count[9], 1);
  for (std::size_t n = kBoundaryNodes; n < nodes.size(); ++n) EXPECT_GE(count[n], 3) << "inner node " << n;
  // Still one closed, conforming mesh of the same six quads' area: every inner edge in
  // two quads (once each way), every boundary edge in one.
  testing::expect_conforming(quads, kBoundaryNodes);
}

}  // namespace
}  // namespace tquad
