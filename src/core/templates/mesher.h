// mesh_boundary: the template mesher's entry point. Validates the boundary, plans the
// hierarchical decomposition from the curve counts, then places nodes and writes the
// quads of every T0 leaf into one mesh whose subregions share nodes.
//
//   BoundaryLoop loop{points, {0, 10, 20, 30}};
//   QuadMesh mesh = mesh_boundary(loop);          // mesh.template_tree == "T0"
#pragma once

#include "core/geometry/boundary_loop.h"
#include "core/mesh/quad_mesh.h"
#include "core/repair/untangle.h"

namespace tquad {

struct MeshOptions {
  // k of the T4 test k C <= A and k C <= B (paper, section 3). At least 2.
  int t4_ratio = 2;
  // Edges on T5's interior cut (two-curve regions); 0 computes it from the distance
  // between the split nodes. The nearest count that keeps both halves even is used.
  int t5_cut_edges = 0;
  // Refuse inputs whose mesh would exceed this many quads (memory guard).
  long long max_quads = 100'000'000;
  // Repair inverted or degenerate quads by local smoothing (untangle.h).
  bool untangle = true;
  // Mesh each patch of a face decomposition with the corner set among its points that
  // meshes it best (corner_search.h) where its given corners leave a poor quad.
  bool search_patch_corners = false;
};

// Every field equal (a field added above belongs here too).
inline bool operator==(const MeshOptions& a, const MeshOptions& b) {
  return a.t4_ratio == b.t4_ratio && a.t5_cut_edges == b.t5_cut_edges && a.max_quads == b.max_quads &&
         a.untangle == b.untangle && a.search_patch_corners == b.search_patch_corners;
}

// Throws InputError (bad input, message names the point, segment or curve) or
// std::logic_error (an internal inconsistency; never expected).
QuadMesh mesh_boundary(const BoundaryLoop& loop, const MeshOptions& options = {});

// As mesh_boundary, and tells what the untangling pass did.
QuadMesh mesh_boundary(const BoundaryLoop& loop, const MeshOptions& options, UntangleResult& untangled);

}  // namespace tquad
