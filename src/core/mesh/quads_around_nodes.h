// QuadsAroundNodes: a mesh's quads with each node's list of quads kept up to date as
// quads are replaced, for the layout changes made in place (flat_corner_turns.h,
// sharp_corner_flips.h).
#pragma once

#include <algorithm>
#include "core/cancellation.h"
#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

class QuadsAroundNodes {
 public:
  QuadsAroundNodes(std::vector<Quad>& quads, std::size_t nodes) : quads_(quads), around_(nodes) {
    for (std::size_t q = 0; q < quads_.size(); ++q) {
      poll_cancellation(4);
      for (NodeId n : quads_[q]) around_[n].push_back(static_cast<int>(q));
    }
  }
  const std::vector<int>& of(NodeId n) const { return around_[n]; }
  const Quad& quad(int q) const { return quads_[q]; }
  // Quad q replaced by `quad`.
  void set(int q, const Quad& quad) {
    for (NodeId n : quads_[q]) around_[n].erase(std::find(around_[n].begin(), around_[n].end(), q));
    quads_[q] = quad;
    for (NodeId n : quads_[q]) around_[n].push_back(q);
  }

 private:
  std::vector<Quad>& quads_;
  std::vector<std::vector<int>> around_;
};

}  // namespace tquad
