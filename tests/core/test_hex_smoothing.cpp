// smooth_hexahedra on generated grids of hexahedra: a node pushed through its
// neighbours (inverting hexahedra) comes back and every hexahedron is valid again;
// on jittered valid grids no node's worst hexahedron gets worse, so the grid's worst
// does not drop.
#include <gtest/gtest.h>

#include <random>

#include "case_stride.h"
#include "core/repair/hex_smoothing.h"

namespace tquad {
namespace {

// An n x n x n grid of unit hexahedra; its interior nodes free.
struct Grid {
  std::vector<Vec3> nodes;
  std::vector<Hex> hexes;
  std::vector<HexSmoothingNode> free;
};

Grid grid(int n) {
  Grid g;
  const auto id = [n](int i, int j, int k) { return static_cast<NodeId>((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) g.nodes.push_back(Vec3{double(i), double(j), double(k)});
    }
  }
  std::vector<std::vector<std::int64_t>> around(g.nodes.size());
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const Hex h{id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),     id(i, j + 1, k),
                    id(i, j, k + 1),     id(i + 1, j, k + 1),     id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        for (NodeId v : h) around[v].push_back(static_cast<std::int64_t>(g.hexes.size()));
        g.hexes.push_back(h);
      }
    }
  }
  for (int k = 1; k < n; ++k) {
    for (int j = 1; j < n; ++j) {
      for (int i = 1; i < n; ++i) {
        HexSmoothingNode f;
        f.node = id(i, j, k);
        f.neighbours = {id(i - 1, j, k), id(i + 1, j, k), id(i, j - 1, k), id(i, j + 1, k), id(i, j, k - 1), id(i, j, k + 1)};
        f.hexes = around[f.node];
        g.free.push_back(f);
      }
    }
  }
  return g;
}

double worst(const Grid& g) {
  double w = 1;
  for (const Hex& h : g.hexes) {
    std::array<Vec3, 8> p;
    for (int i = 0; i < 8; ++i) p[i] = g.nodes[h[i]];
    w = std::min(w, hex_scaled_jacobian(p));
  }
  return w;
}

TEST(HexSmoothing, ANodePushedThroughItsNeighboursComesBack) {
  for (int c : testing::cases(60)) {
    SCOPED_TRACE(testing::case_trace(c));
    std::mt19937 rng(c);
    Grid g = grid(3 + c % 3);
    std::uniform_int_distribution<std::size_t> pick(0, g.free.size() - 1);
    std::uniform_real_distribution<double> u(-1, 1);
    const NodeId pushed = g.free[pick(rng)].node;
    g.nodes[pushed] = g.nodes[pushed] + Vec3{1.3 * (u(rng) > 0 ? 1 : -1), 0.4 * u(rng), 0.4 * u(rng)};
    ASSERT_LE(worst(g), 1e-6);  // tangled
    EXPECT_GT(smooth_hexahedra(g.nodes, g.hexes, g.free, 50), 0);
    EXPECT_GT(worst(g), 0.5);
  }
}

TEST(HexSmoothing, NoNodesWorstHexahedronGetsWorse) {
  for (int c : testing::cases(60)) {
    SCOPED_TRACE(testing::case_trace(c));
    std::mt19937 rng(100 + c);
    Grid g = grid(4);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    for (const HexSmoothingNode& f : g.free) g.nodes[f.node] = g.nodes[f.node] + Vec3{u(rng), u(rng), u(rng)};
    const double before = worst(g);
    ASSERT_GT(before, 0);
    smooth_hexahedra(g.nodes, g.hexes, g.free, 20);
    EXPECT_GE(worst(g), before);
  }
}

}  // namespace
}  // namespace tquad
