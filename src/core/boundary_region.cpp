#include "core/boundary_region.h"

#include <stdexcept>
#include <string>

#include "core/corner_search.h"
#include "core/mesh_validation.h"
#include "core/quality.h"
#include "core/smoothing.h"

namespace tquad {

BoundaryRegionMesh mesh_boundary_region(const BoundaryLoop& loop, const MeshOptions& options,
                                        const std::optional<Vec3>& plane_normal, bool smooth, bool best_corners) {
  const int boundary_points = static_cast<int>(loop.points.size());
  BoundaryRegionMesh out;
  if (best_corners) {
    CornerSearchResult found = mesh_boundary_best_corners(loop, options, plane_normal, smooth);
    out.mesh = std::move(found.mesh);
    out.corner_search = found.search;
  } else {
    out.mesh = mesh_boundary(loop, options);
    const std::string problem = check_disk_mesh(out.mesh, boundary_points);
    if (!problem.empty()) throw std::logic_error("the mesh is invalid: " + problem);
    if (smooth) smooth_region(out.mesh, boundary_points, plane_normal);
    const QualitySummary given = summarize_quality(out.mesh, plane_normal);
    if (given.inverted > 0) {
      CornerSearchResult found = mesh_boundary_best_corners(loop, options, plane_normal, smooth);
      const QualitySummary searched = summarize_quality(found.mesh, plane_normal);
      if (searched.inverted < given.inverted) {
        out.mesh = std::move(found.mesh);
        out.corner_search = found.search;
        out.corner_search->after_inverted = true;
      }
    }
  }
  const std::string problem = check_disk_mesh(out.mesh, boundary_points);
  if (!problem.empty()) throw std::logic_error("the mesh is invalid: " + problem);
  return out;
}

}  // namespace tquad
