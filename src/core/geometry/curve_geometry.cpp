#include "core/geometry/curve_geometry.h"

#include <algorithm>

namespace tquad {

CurveGeometry::CurveGeometry(const std::vector<NodeId>& ids, const std::vector<Vec3>& nodes) {
  points_.reserve(ids.size());
  params_.reserve(ids.size());
  double s = 0.0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    points_.push_back(nodes[ids[i]]);
    if (i > 0) s += distance(points_[i - 1], points_[i]);
    params_.push_back(s);
  }
  length_ = s;
  for (double& p : params_) p = s > 0 ? p / s : 0.0;
  params_.back() = 1.0;
}

Vec3 CurveGeometry::at(double t) const {
  // Written so that a NaN t (from a degenerate patch map) gives the first point
  // rather than an index past the end (fuzz_boundary found such a t).
  if (!(t > 0.0)) return points_.front();
  if (!(t < 1.0)) return points_.back();
  const auto it = std::upper_bound(params_.begin(), params_.end(), t);
  const std::size_t hi = static_cast<std::size_t>(it - params_.begin());
  const std::size_t lo = hi - 1;
  const double span = params_[hi] - params_[lo];
  const double w = span > 0 ? (t - params_[lo]) / span : 0.0;
  return (1.0 - w) * points_[lo] + w * points_[hi];
}

}  // namespace tquad
