// append_patch: a region bounded by nodes already in a mesh, meshed by the templates
// and added to that mesh. Its boundary nodes are shared by index, so patches built
// one after another on common sides conform without any merging.
#pragma once

#include <string>
#include <vector>

#include "core/templates/mesher.h"
#include "core/decomposition/patch_memo.h"

namespace tquad {

// `loop` walks the region's boundary (node ids of `mesh`, each once); `corners` are
// positions in it. Returns the patch's template tree. Throws as mesh_boundary does.
// With `memo`, a patch meshed before (the same points and corners) is not meshed again.
std::string append_patch(QuadMesh& mesh, const std::vector<NodeId>& loop, const std::vector<int>& corners,
                         const MeshOptions& options, PatchMeshMemo* memo = nullptr);

}  // namespace tquad
