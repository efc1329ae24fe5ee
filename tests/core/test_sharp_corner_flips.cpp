// flip_lopsided_sharp_corners (sharp_corner_flips.h): a boundary node at a sharp
// corner in two quads, one of them poor there, ends in one quad; nothing else changes.
#include <gtest/gtest.h>

#include "core/mesh/quality.h"
#include "core/repair/sharp_corner_flips.h"
#include "quad_layouts.h"

namespace tquad {
namespace {

using testing::canonical;
using testing::quads_per_node;

// A 3 x 3 square: boundary nodes 0-11 counter-clockwise from (0, 0), inner nodes 12
// (1, 1), 13 (2, 1), 14 (1, 2), 15 (2, 2).
std::vector<Vec3> square_nodes() {
  return {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {3, 2, 0}, {3, 3, 0}, {2, 3, 0},
          {1, 3, 0}, {0, 3, 0}, {0, 2, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {1, 2, 0}, {2, 2, 0}};
}
constexpr int kBoundaryNodes = 12;

std::vector<Quad> grid_quads() {
  return {{0, 1, 12, 11},  {1, 2, 13, 12},   {2, 3, 4, 13},   {11, 12, 14, 10}, {12, 13, 15, 14},
          {13, 4, 5, 15},  {10, 14, 8, 9},   {14, 15, 7, 8},  {15, 5, 6, 7}};
}

// The grid with its two lower-left quads cut along 0-13 instead of 1-12: corner node
// 0 (90 degrees) lies in two quads, 26.6 degrees in one (scaled Jacobian 0.447) and
// 63.4 in the other.
std::vector<Quad> quads_with_a_lopsided_corner() {
  std::vector<Quad> quads = grid_quads();
  quads[0] = {0, 1, 2, 13};
  quads[1] = {13, 12, 11, 0};
  return quads;
}

std::vector<Vec3> up(std::size_t n) { return std::vector<Vec3>(n, Vec3{0, 0, 1}); }

TEST(SharpCornerFlips, ALopsidedCornerEndsInOneQuad) {
  const std::vector<Vec3> nodes = square_nodes();
  std::vector<Quad> quads = quads_with_a_lopsided_corner();
  EXPECT_EQ(flip_lopsided_sharp_corners(quads, kBoundaryNodes, nodes, up(nodes.size()), FlipDiagonal::better_now), 1);
  EXPECT_EQ(canonical(quads), canonical(grid_quads()));  // the better diagonal: the grid again
}

TEST(SharpCornerFlips, TheOtherDiagonalKeepsTheMeshConforming) {
  const std::vector<Vec3> nodes = square_nodes();
  std::vector<Quad> quads = quads_with_a_lopsided_corner();
  EXPECT_EQ(flip_lopsided_sharp_corners(quads, kBoundaryNodes, nodes, up(nodes.size()), FlipDiagonal::other), 1);
  EXPECT_NE(canonical(quads), canonical(grid_quads()));
  const std::vector<int> count = quads_per_node(quads, nodes.size());
  EXPECT_EQ(count[0], 1);
  for (std::size_t n = kBoundaryNodes; n < nodes.size(); ++n) EXPECT_GE(count[n], 3) << "inner node " << n;
  testing::expect_conforming(quads, kBoundaryNodes);
}

TEST(SharpCornerFlips, EvenSplitsAndFlatCornersAreLeftAsTheyAre) {
  std::vector<Vec3> nodes = square_nodes();
  std::vector<Quad> grid = grid_quads();
  EXPECT_EQ(flip_lopsided_sharp_corners(grid, kBoundaryNodes, nodes, up(nodes.size()), FlipDiagonal::better_now), 0);
  EXPECT_EQ(grid, grid_quads());
  // Inner node 12 moved to (0.1, 0.4): boundary nodes 1 and 11 lie in two quads each
  // with corners of 24 and 9.5 degrees there (scaled Jacobians 0.41 and 0.16), but
  // on a straight boundary, where one quad would take 180 degrees.
  nodes[12] = {0.1, 0.4, 0};
  EXPECT_EQ(flip_lopsided_sharp_corners(grid, kBoundaryNodes, nodes, up(nodes.size()), FlipDiagonal::better_now), 0);
  EXPECT_EQ(grid, grid_quads());
}

}  // namespace
}  // namespace tquad
