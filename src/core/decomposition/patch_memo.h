// PatchMeshMemo: template meshes of patches kept by their input, for routes that mesh
// the same patch more than once. An O-grid's cut places t and t + 4 (of 8) give the
// same two halves in the other order, so each half was meshed, and untangled, twice,
// and the repeats made a large share of the untangler's repair tries.
#pragma once

#include <deque>
#include <vector>

#include "core/templates/mesher.h"

namespace tquad {

class PatchMeshMemo {
 public:
  // mesh_boundary(loop, options), computed once per input: the loop's points bit for
  // bit, its corners and the options. A loop the templates refuse throws each time.
  // With options.search_patch_corners, mesh_patch_best_corners (corner_search.h) from
  // the given corners' mesh, itself kept as the same options without the search.
  const QuadMesh& mesh(const BoundaryLoop& loop, const MeshOptions& options);

 private:
  struct Entry {
    BoundaryLoop loop;
    MeshOptions options;
    QuadMesh mesh;
  };
  std::deque<Entry> entries_;  // a few per face, searched in turn; references stay valid
};

}  // namespace tquad
