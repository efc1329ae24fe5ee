// MeshBuilder: the growing mesh while templates run. Nodes and quads go straight into
// their final arrays (reserved once from the plan), so subregions share nodes by index
// and nothing is merged afterwards.
#pragma once

#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

class MeshBuilder {
 public:
  explicit MeshBuilder(QuadMesh& mesh) : mesh_(mesh) {}

  std::vector<Vec3>& nodes() { return mesh_.nodes; }
  std::vector<Quad>& quads() { return mesh_.quads; }

  NodeId add_node(const Vec3& p) {
    mesh_.nodes.push_back(p);
    return static_cast<NodeId>(mesh_.nodes.size() - 1);
  }

  // A cut of `edges` edges from node `from` to node `to`; its inner nodes are
  // position(s) at s = k / edges, k = 1 .. edges - 1. Returns the cut's node ids and
  // records it as a subregion boundary.
  template <typename PositionAt>
  std::vector<NodeId> add_cut(NodeId from, NodeId to, int edges, const PositionAt& position) {
    std::vector<NodeId> cut;
    cut.reserve(static_cast<std::size_t>(edges) + 1);
    cut.push_back(from);
    for (int k = 1; k < edges; ++k) {
      cut.push_back(add_node(position(static_cast<double>(k) / edges)));
    }
    cut.push_back(to);
    mesh_.subregion_cuts.push_back(cut);
    return cut;
  }

 private:
  QuadMesh& mesh_;
};

}  // namespace tquad
