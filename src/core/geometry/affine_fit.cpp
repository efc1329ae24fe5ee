#include "core/geometry/affine_fit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <stdexcept>

namespace tquad {

AffineMap AffineMap::fit(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size() || a.empty()) {
    throw std::invalid_argument("an affine fit needs two non-empty lists of the same length");
  }
  const double n = static_cast<double>(a.size());
  AffineMap map;
  map.from = Vec3{0, 0, 0};
  map.to = Vec3{0, 0, 0};
  for (std::size_t i = 0; i < a.size(); ++i) {
    map.from = map.from + a[i];
    map.to = map.to + b[i];
  }
  map.from = (1.0 / n) * map.from;
  map.to = (1.0 / n) * map.to;
  Eigen::MatrixXd x(a.size(), 3), y(a.size(), 3);
  double scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec3 p = a[i] - map.from, q = b[i] - map.to;
    x.row(static_cast<Eigen::Index>(i)) << p.x, p.y, p.z;
    y.row(static_cast<Eigen::Index>(i)) << q.x, q.y, q.z;
    scale = std::max(scale, norm(p));
  }
  if (!(scale > 0)) return map;  // one point (or all equal): a translation
  // Directions the a_i span less than 1e-9 of their extent count as not spanned.
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver;
  solver.setThreshold(1e-9);
  solver.compute(x);
  const Eigen::MatrixXd m = solver.solve(y);  // 3 x 3: x m = y, so M = m^T
  for (int r = 0; r < 3; ++r) map.rows[r] = Vec3{m(0, r), m(1, r), m(2, r)};
  return map;
}

}  // namespace tquad
