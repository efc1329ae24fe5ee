#include "core/decomposition/planar_loop_decomposition.h"

#include "core/decomposition/decomposed_mesher.h"
#include "core/input_error.h"
#include "core/geometry/mean_plane.h"
#include "core/decomposition/planar_domain.h"

namespace tquad {

// Where the templates folded a loop, its sides bent inwards are where: a reflex point
// of 20 degrees or more becomes a patch corner (DecompositionOptions::reflex_point_turn;
// on the generated property cases a mildly non-convex loop kept an inverted quad with
// 60, none with 10, 15 or 20).
constexpr double kReflexPointTurn = 20.0;

std::optional<QuadMesh> mesh_planar_loop_decomposed(const BoundaryLoop& loop, const Vec3& unit_normal,
                                                    const MeshOptions& options) {
  const std::size_t n = loop.points.size();
  const MeanPlane plane = MeanPlane::with_normal(loop.points[0], unit_normal);
  DomainLoop outer;
  outer.vertex.assign(n, 0);
  double perimeter = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 local = plane.local(loop.points[i]);
    outer.points.push_back({local.x, local.y, 0});
    perimeter += distance(loop.points[i], loop.points[(i + 1) % n]);
  }
  for (int c : loop.corners) outer.vertex[c] = 1;
  PlanarDomain domain;
  domain.loops.push_back(std::move(outer));
  QuadMesh mesh;
  try {
    // The cuts get the boundary's mean spacing.
    DecompositionOptions decomposition;
    decomposition.reflex_point_turn = kReflexPointTurn;
    mesh = mesh_planar_domain(domain, perimeter / static_cast<double>(n), options, decomposition);
  } catch (const InputError&) {
    return std::nullopt;
  }
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    mesh.nodes[i] = i < n ? loop.points[i] : plane.point_at(mesh.nodes[i].x, mesh.nodes[i].y, 0);
  }
  return mesh;
}

}  // namespace tquad
