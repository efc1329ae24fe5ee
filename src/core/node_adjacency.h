// NodeAdjacency: compressed per-node lists of a quad mesh, the edge neighbours of each
// node and the quads around it, used by the node-moving passes (untangle.h,
// smoothing.h).
#pragma once

#include <cstddef>
#include <vector>

#include "core/quad_mesh.h"

namespace tquad {

// Items of node i are items[offsets[i] .. offsets[i+1]).
struct CompressedLists {
  std::vector<int> offsets, items;

  // add_pairs(add) calls add(node, item) for every pair; it is called twice (count,
  // then fill), and must give the same pairs in the same order both times.
  template <typename AddPairs>
  static CompressedLists build(std::size_t nodes, const AddPairs& add_pairs) {
    CompressedLists a;
    a.offsets.assign(nodes + 1, 0);
    add_pairs([&](NodeId node, int) { ++a.offsets[node + 1]; });
    for (std::size_t i = 0; i < nodes; ++i) a.offsets[i + 1] += a.offsets[i];
    a.items.resize(a.offsets.back());
    // Filled with offsets[node] as node's cursor, which ends where node + 1 starts;
    // then each start is put back from the node before. (A cursor array of its own
    // was 4 bytes a node at the smoother's peak.)
    add_pairs([&](NodeId node, int item) { a.items[a.offsets[node]++] = item; });
    for (std::size_t i = nodes; i > 0; --i) a.offsets[i] = a.offsets[i - 1];
    a.offsets[0] = 0;
    return a;
  }
};

// The quads around each node, in quad order.
inline CompressedLists quads_around_nodes(std::size_t nodes, const std::vector<Quad>& quads) {
  return CompressedLists::build(nodes, [&](auto add) {
    for (std::size_t k = 0; k < quads.size(); ++k) for (NodeId n : quads[k]) add(n, static_cast<int>(k));
  });
}

struct NodeAdjacency {
  CompressedLists neighbours;  // edge neighbours (once each for an interior node)
  CompressedLists quads_of;    // quads around each node

  NodeAdjacency(std::size_t nodes, const std::vector<Quad>& quads) {
    // Each interior edge appears once in each direction, so following directed edges
    // gives every interior node each neighbour exactly once.
    neighbours = CompressedLists::build(nodes, [&](auto add) {
      for (const Quad& q : quads) for (int i = 0; i < 4; ++i) add(q[i], q[(i + 1) % 4]);
    });
    quads_of = quads_around_nodes(nodes, quads);
  }
};

}  // namespace tquad
