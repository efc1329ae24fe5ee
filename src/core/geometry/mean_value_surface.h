// MeanValueSurface: a smooth surface through a curved 3D loop, for a loop whose
// templates' mesh folds (fitted_surface.h then has no sheet to keep the nodes on).
//
// Over the loop's mean plane (its Newell normal), the height of a point is the mean
// value interpolation of the loop points' heights (Floater, "Mean value coordinates",
// 2003): smooth inside the loop, exact on it, defined for a non-convex loop, and the
// plane itself for a planar one. It is a membrane: flatter than the templates'
// surface on a doubly curved loop (the middle of a sphere octant's mesh at radius
// 0.76 instead of 0.90), so it is the fallback, not the first choice.
#pragma once

#include <vector>

#include "core/geometry/mean_plane.h"

namespace tquad {

class MeanValueSurface {
 public:
  // Through the loop, over `plane` (MeanPlane::of_loop of the same loop).
  MeanValueSurface(const MeanPlane& plane, const std::vector<Vec3>& loop_points);

  const MeanPlane& plane() const { return plane_; }

  // The surface over plane coordinates `param`, and its normal there (oriented as the
  // loop, any length); false on the loop itself. Cost: O(loop points).
  bool place(const Vec3& param, Vec3& position, Vec3& normal) const;

 private:
  // The height over (x, y) and its derivatives; false on the loop (where the
  // interpolation is not smooth) and where it fails numerically.
  bool height(double x, double y, double& h, double& hx, double& hy) const;

  MeanPlane plane_;
  std::vector<double> xs_, ys_, heights_;
};

}  // namespace tquad
