#include "core/boundary_region.h"

#include <stdexcept>
#include <string>

#include "core/corner_search.h"
#include "core/mesh_validation.h"
#include "core/quality.h"
#include "core/smoothing.h"

namespace tquad {

namespace {

// The final check of every front end: a failure is the mesher's fault.
void check_mesh(const QuadMesh& mesh, int boundary_points) {
  const std::string problem = check_disk_mesh(mesh, boundary_points);
  if (!problem.empty()) throw std::logic_error("the mesh is invalid: " + problem);
}

}  // namespace

BoundaryRegionMesh mesh_boundary_region(const BoundaryLoop& loop, const MeshOptions& options,
                                        const std::optional<Vec3>& plane_normal, bool smooth, bool best_corners) {
  const int boundary_points = static_cast<int>(loop.points.size());
  if (best_corners) {
    CornerSearchResult found = mesh_boundary_best_corners(loop, options, plane_normal, smooth);
    check_mesh(found.mesh, boundary_points);
    return {std::move(found.mesh), found.search};
  }
  BoundaryRegionMesh out{mesh_boundary(loop, options), std::nullopt};
  // Checked as the templates left it; smooth_region checks what it returns.
  check_mesh(out.mesh, boundary_points);
  if (smooth) smooth_region(out.mesh, boundary_points, plane_normal);
  const long long inverted = summarize_quality(out.mesh, plane_normal).inverted;
  if (inverted > 0) {
    CornerSearchResult found =
        mesh_boundary_best_corners(loop, options, plane_normal, smooth, smooth ? &out.mesh : nullptr);
    if (summarize_quality(found.mesh, plane_normal).inverted < inverted) {
      check_mesh(found.mesh, boundary_points);
      out.mesh = std::move(found.mesh);
      out.corner_search = found.search;
      out.corner_search->after_inverted = true;
    }
  }
  return out;
}

}  // namespace tquad
