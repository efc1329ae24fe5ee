#include "core/geometry/fitted_surface.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/mesh/node_adjacency.h"

namespace tquad {

void FittedSurface::fit_nodes(const std::vector<Vec3>& nodes, const std::vector<Quad>& quads) {
  const NodeAdjacency adjacency(nodes.size(), quads);
  std::vector<NodeId> others;
  std::vector<Vec3> around;
  fits_.clear();
  for (std::size_t node = first_interior_; node < nodes.size(); ++node) {
    others.clear();
    for (int k = adjacency.quads_of.offsets[node]; k < adjacency.quads_of.offsets[node + 1]; ++k) {
      for (NodeId other : quads[adjacency.quads_of.items[k]]) {
        if (other != static_cast<NodeId>(node)) others.push_back(other);
      }
    }
    std::sort(others.begin(), others.end());  // each node of the quads around once
    others.erase(std::unique(others.begin(), others.end()), others.end());
    around.clear();
    for (NodeId other : others) around.push_back(plane_.local(nodes[other]));
    fits_.push_back(fit(plane_.local(nodes[node]), around));
  }
}

FittedSurface::Quadric FittedSurface::fit(const Vec3& at, const std::vector<Vec3>& around) {
  Quadric q;
  q.at = at;
  const int m = static_cast<int>(around.size());
  if (m < 2) return q;
  // Offsets scaled by the neighbourhood's size, so that the rank test below does not
  // depend on the units.
  double size = 0;
  for (const Vec3& p : around) size = std::max(size, std::hypot(p.x - at.x, p.y - at.y));
  if (!(size > 0)) return q;
  Eigen::MatrixXd rows(m, 5);
  Eigen::VectorXd heights(m);
  for (int i = 0; i < m; ++i) {
    const double x = (around[i].x - at.x) / size, y = (around[i].y - at.y) / size;
    rows.row(i) << x, y, x * x, x * y, y * y;
    heights(i) = around[i].z - at.z;
  }
  // A relative pivot of 1e-6: below it the nodes leave a direction undetermined.
  for (const int unknowns : {5, 2}) {
    if (m < unknowns) continue;
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(rows.leftCols(unknowns));
    qr.setThreshold(1e-6);
    if (qr.rank() < unknowns) continue;
    const Eigen::VectorXd c = qr.solve(heights);
    q.a = c(0) / size, q.b = c(1) / size;
    if (unknowns == 5) q.c = c(2) / (size * size), q.d = c(3) / (size * size), q.e = c(4) / (size * size);
    return q;
  }
  return q;
}

bool FittedSurface::place(int node, const Vec3& param, Vec3& position, Vec3& normal) const {
  const int i = node - first_interior_;
  if (i < 0 || i >= static_cast<int>(fits_.size())) return false;
  const Quadric& q = fits_[i];
  const double dx = param.x - q.at.x, dy = param.y - q.at.y;
  const double height = q.at.z + q.a * dx + q.b * dy + q.c * dx * dx + q.d * dx * dy + q.e * dy * dy;
  const double slope_x = q.a + 2 * q.c * dx + q.d * dy, slope_y = q.b + q.d * dx + 2 * q.e * dy;
  if (!std::isfinite(height) || !std::isfinite(slope_x) || !std::isfinite(slope_y)) return false;
  position = plane_.point_at(param.x, param.y, height);
  normal = plane_.normal_of_slopes(slope_x, slope_y);
  return true;
}

}  // namespace tquad
