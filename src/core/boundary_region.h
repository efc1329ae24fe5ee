// mesh_boundary_region: the boundary route every front end takes (the CLI's boundary
// files, the Python module's mesh_boundary): one region meshed with its given
// corners, or with the best corner set when asked (corner_search.h), smoothed when
// asked (smooth_region), checked (check_disk_mesh: once on the default route, by
// smooth_region when it smooths; the corner search's result again), and its quality
// measured once, as measure_mesh_quality measures it.
//
// Where the given corners' mesh still has an inverted quad after that, the corner
// search runs too and its mesh is kept if it has fewer inverted quads: a valid mesh
// with other corners serves a user better than a folded one with theirs; then, for
// a planar loop, the face decomposition (planar_loop_decomposition.h), kept on the
// same terms. On the generated property cases, most of the few boundaries whose
// smoothed mesh kept an inverted quad (mildly non-convex or curved) have none with
// the searched corners, and those left (triangles with a cusp) none with the
// decomposition.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "core/geometry/boundary_loop.h"
#include "core/templates/mesher.h"
#include "core/mesh/quality.h"
#include "core/mesh/shape_mesh.h"
#include "core/geometry/vec3.h"

namespace tquad {

struct BoundaryRegionMesh {
  QuadMesh mesh;
  std::optional<CornerSearch> corner_search;  // when the search ran
  bool decomposed = false;                    // meshed by mesh_planar_loop_decomposed
  PerQuadQuality quality;                     // each quad's, signed by the plane's normal or its own
  QualitySummary summary;                     // of `quality`
  // Wall time of each stage: "mesh" (the templates; the corner search, with its
  // smoothing, when it runs), "smooth" (with the check of its result), "check" (of
  // an unsmoothed mesh, or of the corner search's), "quality".
  std::map<std::string, double> stage_seconds;
};

// `plane_normal`: the loop's plane when it is planar, else std::nullopt. Throws
// InputError as mesh_boundary does; an invalid mesh is std::logic_error.
BoundaryRegionMesh mesh_boundary_region(const BoundaryLoop& loop, const MeshOptions& options,
                                        const std::optional<Vec3>& plane_normal, bool smooth, bool best_corners);

// The region as a shape of one face (face 0) with its per-quad quality, for the
// writers and the report; moves the region's arrays.
ShapeMesh boundary_shape_mesh(BoundaryRegionMesh&& region);

}  // namespace tquad
