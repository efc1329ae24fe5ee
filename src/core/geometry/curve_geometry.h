// CurveGeometry: one boundary curve of a region as a polyline parametrized by
// normalized 3D arc length on [0, 1] (the discrete curves psi, xi of eqs. 1 and 2).
#pragma once

#include <vector>

#include "core/mesh/quad_mesh.h"
#include "core/geometry/vec3.h"

namespace tquad {

class CurveGeometry {
 public:
  CurveGeometry(const std::vector<NodeId>& ids, const std::vector<Vec3>& nodes);

  // Point at normalized arc length t in [0, 1] (linear between polyline points).
  Vec3 at(double t) const;
  // Normalized arc length of the curve's i-th point.
  double param(int i) const { return params_[i]; }
  const Vec3& point(int i) const { return points_[i]; }
  double length() const { return length_; }
  int edges() const { return static_cast<int>(points_.size()) - 1; }

 private:
  std::vector<Vec3> points_;
  std::vector<double> params_;
  double length_ = 0.0;
};

}  // namespace tquad
