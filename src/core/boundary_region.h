// mesh_boundary_region: the boundary route every front end takes (the CLI's boundary
// files, the Python module's mesh_boundary): one region meshed with its given
// corners, or with the best corner set when asked (corner_search.h), checked, and
// smoothed when asked (smooth_region).
//
// Where the given corners' mesh still has an inverted quad after that, the corner
// search runs too and its mesh is kept if it has fewer inverted quads: a valid mesh
// with other corners serves a user better than a folded one with theirs. Measured
// on the generated property cases: of the 12 of 12,000 boundaries whose smoothed
// mesh kept an inverted quad (5 mildly non-convex, 7 curved), 10 have none with the
// searched corners; the two left have a cusp (a corner of nearly 0 degrees between
// two bent sides).
#pragma once

#include <optional>

#include "core/boundary_loop.h"
#include "core/mesher.h"
#include "core/shape_mesh.h"
#include "core/vec3.h"

namespace tquad {

struct BoundaryRegionMesh {
  QuadMesh mesh;
  std::optional<CornerSearch> corner_search;  // when the search ran
};

// `plane_normal`: the loop's plane when it is planar, else std::nullopt. Throws
// InputError as mesh_boundary does; an invalid mesh is std::logic_error.
BoundaryRegionMesh mesh_boundary_region(const BoundaryLoop& loop, const MeshOptions& options,
                                        const std::optional<Vec3>& plane_normal, bool smooth, bool best_corners);

}  // namespace tquad
