// untangle_mesh: repair inverted and degenerate quads left by the templates.
//
// Template placement (eqs. 3 and 4) gives well-shaped elements when the counts suit
// the geometry, but a curve with few edges on a long side (counts 22, 1, 4, 37 on a
// kite, say) can fold a quad. Such quads are repaired by Laplacian smoothing of the
// interior nodes around them, in growing rings: each node moves to the mean of its
// edge neighbours (Gauss-Seidel sweeps), boundary nodes stay fixed. On a convex planar
// region the limit is Tutte's barycentric embedding, whose faces are convex, so the
// repair succeeds there; connectivity never changes (topological equivalence holds).
// On a curved 3D region nodes move in their tangent plane only, estimated from the
// quads around them.
#pragma once

#include <optional>

#include "core/mesh/quad_mesh.h"

namespace tquad {

struct UntangleResult {
  long long bad_before = 0;  // quads with an inverted or degenerate corner that interior nodes can fix
  long long bad_after = 0;
  long long moved_nodes = 0;
};

// `boundary_points`: the first nodes are the boundary loop and never move.
// `plane_normal`: the region's normal when it is planar, else std::nullopt.
UntangleResult untangle_mesh(QuadMesh& mesh, int boundary_points,
                             const std::optional<Vec3>& plane_normal);

}  // namespace tquad
