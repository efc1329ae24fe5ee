// NodeAdjacency: compressed per-node lists of a quad mesh, the edge neighbours of each
// node and the quads around it, used by the node-moving passes (untangle.h,
// smoothing.h).
#pragma once

#include <algorithm>
#include "core/cancellation.h"
#include <cstddef>
#include <vector>

#include "core/mesh/quad_mesh.h"

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

// add_pairs for the lists' build(): (node, quad) for each corner of each quad, in quad
// order.
inline auto quad_corner_pairs(const std::vector<Quad>& quads) {
  return [&quads](auto add) {
    for (std::size_t k = 0; k < quads.size(); ++k) {
      poll_cancellation(2);
      for (NodeId n : quads[k]) add(n, static_cast<int>(k));
    }
  };
}

// The quads around each node, in quad order.
inline CompressedLists quads_around_nodes(std::size_t nodes, const std::vector<Quad>& quads) {
  return CompressedLists::build(nodes, quad_corner_pairs(quads));
}

// Per-node lists of non-negative items in the order added, in four slots a node (-1
// where it holds fewer) and, for a node with more, the rest in a list sorted by node.
// A node of a quad mesh mostly has four quads and is the lower end of four quad
// sides: for such lists this takes 16 bytes a node where CompressedLists takes 16 a
// quad and 4 a node, less at the smoother's and the mesh check's peaks on large meshes.
class SlottedLists {
 public:
  // add_pairs(add) calls add(node, item) for every pair, item >= 0, once.
  template <typename AddPairs>
  static SlottedLists build(std::size_t nodes, const AddPairs& add_pairs) {
    SlottedLists lists;
    lists.slots_.assign(4 * nodes, -1);
    lists.has_more_.assign(nodes, false);
    add_pairs([&](NodeId node, int item) {
      int* slot = &lists.slots_[4 * static_cast<std::size_t>(node)];
      int i = 0;
      while (i < 4 && slot[i] >= 0) ++i;
      if (i < 4) {
        slot[i] = item;
      } else {
        lists.more_.push_back({node, item});
        lists.has_more_[node] = true;
      }
    });
    std::stable_sort(lists.more_.begin(), lists.more_.end(),
                     [](const More& a, const More& b) { return a.node < b.node; });
    return lists;
  }

  // Calls visit(item) for each item of node n, in the order added.
  template <typename Visit>
  void for_each(NodeId n, const Visit& visit) const {
    const int* slot = &slots_[4 * static_cast<std::size_t>(n)];
    for (int i = 0; i < 4 && slot[i] >= 0; ++i) visit(slot[i]);
    if (!has_more_[n]) return;
    auto it = std::lower_bound(more_.begin(), more_.end(), n, [](const More& m, NodeId node) { return m.node < node; });
    for (; it != more_.end() && it->node == n; ++it) visit(it->item);
  }

  // The first item of node n, or -1 when it has none.
  int first(NodeId n) const { return slots_[4 * static_cast<std::size_t>(n)]; }

 private:
  struct More {
    NodeId node;
    int item;
  };
  std::vector<int> slots_;
  std::vector<bool> has_more_;
  std::vector<More> more_;
};

// The quads around each node, in quad order, in four slots a node (SlottedLists).
inline SlottedLists slotted_quads_around_nodes(std::size_t nodes, const std::vector<Quad>& quads) {
  return SlottedLists::build(nodes, quad_corner_pairs(quads));
}

struct NodeAdjacency {
  CompressedLists neighbours;  // edge neighbours (once each for an interior node)
  CompressedLists quads_of;    // quads around each node

  NodeAdjacency(std::size_t nodes, const std::vector<Quad>& quads) {
    // Each interior edge appears once in each direction, so following directed edges
    // gives every interior node each neighbour exactly once.
    neighbours = CompressedLists::build(nodes, [&](auto add) {
      for (const Quad& q : quads) {
        poll_cancellation(2);
        for (int i = 0; i < 4; ++i) add(q[i], q[(i + 1) % 4]);
      }
    });
    quads_of = quads_around_nodes(nodes, quads);
  }
};

}  // namespace tquad
