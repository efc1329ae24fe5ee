// Helpers for tests of layout changes (flat_corner_turns.h, sharp_corner_flips.h):
// quads compared whatever node each starts at, quads counted per node, and the
// check that a mesh of a loop of boundary nodes [0, boundary) stays conforming.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad::testing {

// Each quad as the rotation of its node cycle that starts at its lowest node.
inline std::set<Quad> canonical(const std::vector<Quad>& quads) {
  std::set<Quad> out;
  for (Quad q : quads) {
    std::rotate(q.begin(), std::min_element(q.begin(), q.end()), q.end());
    out.insert(q);
  }
  return out;
}

inline std::vector<int> quads_per_node(const std::vector<Quad>& quads, std::size_t nodes) {
  std::vector<int> count(nodes, 0);
  for (const Quad& q : quads) for (NodeId n : q) ++count[n];
  return count;
}

// Every inner edge in two quads (once each way), every edge of the boundary loop
// (boundary nodes [0, boundary) in order) in one.
inline void expect_conforming(const std::vector<Quad>& quads, int boundary) {
  std::map<std::pair<NodeId, NodeId>, int> directed;
  for (const Quad& q : quads) for (int i = 0; i < 4; ++i) ++directed[{q[i], q[(i + 1) % 4]}];
  for (const auto& [edge, times] : directed) {
    EXPECT_EQ(times, 1);
    const bool on_boundary = edge.first < boundary && edge.second < boundary && edge.second == (edge.first + 1) % boundary;
    EXPECT_EQ(directed.count({edge.second, edge.first}), on_boundary ? 0u : 1u) << edge.first << " -> " << edge.second;
  }
}

}  // namespace tquad::testing
