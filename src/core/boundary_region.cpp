#include "core/boundary_region.h"

#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/decomposition/corner_search.h"
#include "core/elapsed.h"
#include "core/mesh/mesh_validation.h"
#include "core/decomposition/planar_loop_decomposition.h"
#include "core/repair/smoothing.h"

namespace tquad {

namespace {

// The final check of every front end: a failure is the mesher's fault.
void check_mesh(const QuadMesh& mesh, int boundary_points) {
  const std::string problem = check_disk_mesh(mesh, boundary_points);
  if (!problem.empty()) throw std::logic_error("the mesh is invalid: " + problem);
}

// A mesh's quality as measure_mesh_quality would measure it: per quad, and summed up.
struct MeasuredQuality {
  PerQuadQuality per_quad;
  QualitySummary summary;
};
MeasuredQuality measure(const QuadMesh& mesh, const std::optional<Vec3>& plane_normal) {
  MeasuredQuality out{per_quad_quality(mesh.nodes, mesh.quads, plane_normal), {}};
  out.summary = summarize_quality(out.per_quad);
  return out;
}

void keep_quality(BoundaryRegionMesh& region, MeasuredQuality measured) {
  region.quality = std::move(measured.per_quad);
  region.summary = measured.summary;
}

}  // namespace

BoundaryRegionMesh mesh_boundary_region(const BoundaryLoop& loop, const MeshOptions& options,
                                        const std::optional<Vec3>& plane_normal, bool smooth, bool best_corners) {
  const int boundary_points = static_cast<int>(loop.points.size());
  BoundaryRegionMesh out;
  auto started = std::chrono::steady_clock::now();
  const auto stage_done = [&](const std::string& stage) {
    out.stage_seconds[stage] += seconds_since(started);
    started = std::chrono::steady_clock::now();
  };
  if (best_corners) {
    CornerSearchResult found = mesh_boundary_best_corners(loop, options, plane_normal, smooth);
    out.mesh = std::move(found.mesh);
    out.corner_search = found.search;
    stage_done("mesh");
    check_mesh(out.mesh, boundary_points);
    stage_done("check");
    keep_quality(out, measure(out.mesh, plane_normal));
    stage_done("quality");
    return out;
  }
  out.mesh = mesh_boundary(loop, options);
  stage_done("mesh");
  // One check of the mesh returned. The smoother only needs valid node indices,
  // which the templates guarantee (the corner search smooths its candidates
  // unchecked too); smooth_region checks what it returns. Checking the templates'
  // mesh as well cost a noticeable share of the route's time on large meshes.
  if (smooth) {
    smooth_region(out.mesh, boundary_points, plane_normal);
    stage_done("smooth");
  } else {
    check_mesh(out.mesh, boundary_points);
    stage_done("check");
  }
  keep_quality(out, measure(out.mesh, plane_normal));
  stage_done("quality");
  if (out.summary.inverted > 0) {
    CornerSearchResult found =
        mesh_boundary_best_corners(loop, options, plane_normal, smooth, smooth ? &out.mesh : nullptr);
    MeasuredQuality found_quality = measure(found.mesh, plane_normal);
    stage_done("mesh");
    if (found_quality.summary.inverted < out.summary.inverted) {
      check_mesh(found.mesh, boundary_points);
      out.mesh = std::move(found.mesh);
      out.corner_search = found.search;
      out.corner_search->after_inverted = true;
      keep_quality(out, std::move(found_quality));
      stage_done("check");
    }
  }
  if (out.summary.inverted > 0 && plane_normal) {
    std::optional<QuadMesh> decomposed = mesh_planar_loop_decomposed(loop, *plane_normal, options);
    if (decomposed) {
      if (smooth) smooth_region(*decomposed, boundary_points, plane_normal);
      MeasuredQuality decomposed_quality = measure(*decomposed, plane_normal);
      stage_done("mesh");
      if (decomposed_quality.summary.inverted < out.summary.inverted) {
        check_mesh(*decomposed, boundary_points);
        out.mesh = std::move(*decomposed);
        out.decomposed = true;
        keep_quality(out, std::move(decomposed_quality));
        stage_done("check");
      }
    }
  }
  return out;
}

ShapeMesh boundary_shape_mesh(BoundaryRegionMesh&& region) {
  ShapeMesh shape = single_face_mesh(std::move(region.mesh));
  shape.faces[0].corner_search = region.corner_search;
  shape.lee_lo = std::move(region.quality.lee_lo);
  shape.scaled_jacobian = std::move(region.quality.scaled_jacobian);
  return shape;
}

}  // namespace tquad
