#include "core/decomposition/patch_stitching.h"
#include "core/cancellation.h"

namespace tquad {

std::string append_patch(QuadMesh& mesh, const std::vector<NodeId>& loop, const std::vector<int>& corners,
                         const MeshOptions& options, PatchMeshMemo* memo) {
  BoundaryLoop region;
  region.corners = corners;
  for (NodeId id : loop) region.points.push_back(mesh.nodes[id]);
  PatchMeshMemo this_patch_only;
  const QuadMesh& patch = (memo ? *memo : this_patch_only).mesh(region, options);
  const NodeId base = static_cast<NodeId>(mesh.nodes.size());
  const int m = static_cast<int>(loop.size());
  mesh.nodes.insert(mesh.nodes.end(), patch.nodes.begin() + m, patch.nodes.end());
  for (Quad quad : patch.quads) {
    poll_cancellation(1);
    for (NodeId& v : quad) v = v < m ? loop[v] : base + (v - m);
    mesh.quads.push_back(quad);
  }
  return patch.template_tree;
}

}  // namespace tquad
