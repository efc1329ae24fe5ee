#include "core/decomposition/breadth_first_placement.h"

#include <algorithm>
#include <deque>

#include "core/mesh/node_adjacency.h"

namespace tquad {

std::vector<PlacementStep> breadth_first_placement(const std::vector<Vec3>& nodes, const std::vector<Quad>& quads,
                                                   std::size_t boundary_count) {
  const NodeAdjacency adjacency(nodes.size(), quads);
  const CompressedLists& near = adjacency.neighbours;
  std::vector<char> placed(nodes.size(), 0), queued(nodes.size(), 0);
  for (std::size_t i = 0; i < boundary_count && i < nodes.size(); ++i) placed[i] = queued[i] = 1;
  std::deque<NodeId> queue;
  // An interior node lists each of its neighbours, so the first ring is found from
  // the interior side.
  for (std::size_t i = boundary_count; i < nodes.size(); ++i) {
    for (int k = near.offsets[i]; k < near.offsets[i + 1]; ++k) {
      if (placed[near.items[k]]) {
        queue.push_back(static_cast<NodeId>(i));
        queued[i] = 1;
        break;
      }
    }
  }
  std::vector<PlacementStep> steps;
  steps.reserve(nodes.size() - std::min(boundary_count, nodes.size()));
  while (!queue.empty()) {
    const NodeId node = queue.front();
    queue.pop_front();
    NodeId best = -1;
    double best_distance = 0;
    for (int k = near.offsets[node]; k < near.offsets[node + 1]; ++k) {
      const NodeId other = near.items[k];
      if (placed[other]) {
        const double d = norm(nodes[other] - nodes[node]);
        if (best < 0 || d < best_distance || (d == best_distance && other < best)) {
          best = other;
          best_distance = d;
        }
      } else if (!queued[other]) {
        queue.push_back(other);
        queued[other] = 1;
      }
    }
    steps.push_back({node, best});
    placed[node] = 1;
  }
  return steps;
}

}  // namespace tquad
