#include "core/repair/reflex_corners.h"
#include "core/cancellation.h"

#include <vector>

namespace tquad {

int split_reflex_corner_quads(QuadMesh& mesh, int boundary_points, const Vec3& normal) {
  std::vector<int> uses(mesh.nodes.size(), 0);
  for (const Quad& q : mesh.quads) {
    poll_cancellation(4);
    for (NodeId n : q) ++uses[n];
  }
  int split = 0;
  const std::size_t original = mesh.quads.size();
  for (std::size_t k = 0; k < original; ++k) {
    const Quad q = mesh.quads[k];
    bool reflex = false;
    for (int j = 0; j < 4 && !reflex; ++j) {
      const NodeId at = q[j];
      if (at >= boundary_points || uses[at] != 1) continue;
      const Vec3& p = mesh.nodes[at];
      reflex = dot(cross(mesh.nodes[q[(j + 1) % 4]] - p, mesh.nodes[q[(j + 3) % 4]] - p), normal) < 0;
    }
    if (!reflex) continue;
    const Vec3 centre = 0.25 * (mesh.nodes[q[0]] + mesh.nodes[q[1]] + mesh.nodes[q[2]] + mesh.nodes[q[3]]);
    Quad inner;
    for (int j = 0; j < 4; ++j) {
      inner[j] = static_cast<NodeId>(mesh.nodes.size());
      mesh.nodes.push_back(mesh.nodes[q[j]] + (1.0 / 3.0) * (centre - mesh.nodes[q[j]]));
    }
    mesh.quads[k] = inner;
    for (int j = 0; j < 4; ++j) mesh.quads.push_back({q[j], q[(j + 1) % 4], inner[(j + 1) % 4], inner[j]});
    ++split;
  }
  return split;
}

}  // namespace tquad
