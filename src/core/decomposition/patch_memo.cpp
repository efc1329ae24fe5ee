#include "core/decomposition/patch_memo.h"

#include <cstring>

#include "core/decomposition/corner_search.h"

namespace tquad {

namespace {

bool same_points(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0);
}

}  // namespace

const QuadMesh& PatchMeshMemo::mesh(const BoundaryLoop& loop, const MeshOptions& options) {
  for (const Entry& e : entries_) {
    if (e.loop.corners == loop.corners && same_points(e.loop.points, loop.points) && e.options == options) {
      return e.mesh;
    }
  }
  QuadMesh mesh;
  if (options.search_patch_corners) {
    MeshOptions given = options;
    given.search_patch_corners = false;
    mesh = mesh_patch_best_corners(loop, given, this->mesh(loop, given));  // a deque's references stay valid
  } else {
    mesh = mesh_boundary(loop, options);
  }
  entries_.push_back({loop, options, std::move(mesh)});
  return entries_.back().mesh;
}

}  // namespace tquad
