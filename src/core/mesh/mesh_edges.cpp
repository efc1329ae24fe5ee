#include "core/mesh/mesh_edges.h"
#include "core/cancellation.h"

#include <algorithm>
#include <utility>

namespace tquad {

MeshEdges::MeshEdges(std::size_t node_count, const std::vector<Quad>& quads) {
  // Every directed quad side, listed at its lower node (with repeats), then each
  // node's list sorted and its repeats dropped.
  std::vector<std::size_t> first(node_count + 1, 0);
  for (const Quad& q : quads) {
    poll_cancellation(4);
    for (int i = 0; i < 4; ++i) ++first[static_cast<std::size_t>(std::min(q[i], q[(i + 1) % 4])) + 1];
  }
  for (std::size_t n = 0; n < node_count; ++n) first[n + 1] += first[n];
  std::vector<NodeId> listed(first[node_count]);
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (const Quad& q : quads) {
    poll_cancellation(4);
    for (int i = 0; i < 4; ++i) {
      const auto [lo, hi] = std::minmax(q[i], q[(i + 1) % 4]);
      listed[next[static_cast<std::size_t>(lo)]++] = hi;
    }
  }
  lower_first_.assign(node_count + 1, 0);
  higher_.reserve(listed.size() / 2 + 1);
  for (std::size_t n = 0; n < node_count; ++n) {
    const auto begin = listed.begin() + static_cast<std::ptrdiff_t>(first[n]);
    const auto end = listed.begin() + static_cast<std::ptrdiff_t>(first[n + 1]);
    std::sort(begin, end);
    higher_.insert(higher_.end(), begin, std::unique(begin, end));
    lower_first_[n + 1] = higher_.size();
  }
}

std::size_t MeshEdges::index(NodeId a, NodeId b) const {
  const auto [lo, hi] = std::minmax(a, b);
  if (lo < 0 || static_cast<std::size_t>(lo) + 1 >= lower_first_.size()) return npos;
  const auto begin = higher_.begin() + static_cast<std::ptrdiff_t>(lower_first_[static_cast<std::size_t>(lo)]);
  const auto end = higher_.begin() + static_cast<std::ptrdiff_t>(lower_first_[static_cast<std::size_t>(lo) + 1]);
  const auto it = std::lower_bound(begin, end, hi);
  return it != end && *it == hi ? static_cast<std::size_t>(it - higher_.begin()) : npos;
}

}  // namespace tquad
