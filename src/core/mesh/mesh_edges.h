// MeshEdges: every undirected edge of a quad mesh once, numbered, so that per-edge
// data (a second-order quad's middle node, say) lives in a plain array reached from
// either quad of the edge, without hashing.
#pragma once

#include <cstddef>
#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

class MeshEdges {
 public:
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  MeshEdges(std::size_t node_count, const std::vector<Quad>& quads);

  std::size_t count() const { return higher_.size(); }
  // The number of edge a-b (either order), or npos when no quad has it.
  std::size_t index(NodeId a, NodeId b) const;

 private:
  // Edges by their lower node: edges lower_first_[n] .. lower_first_[n + 1] - 1 run
  // from n to higher_[e], ascending.
  std::vector<std::size_t> lower_first_;
  std::vector<NodeId> higher_;
};

}  // namespace tquad
