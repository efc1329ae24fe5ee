// MeanPlane: a right-handed frame (e1, e2, normal) on a plane, and the plane a curved
// 3D loop is seen from: through its first point, normal to its Newell normal (the
// loop counter-clockwise about it). A curved loop's mesh is smoothed in that plane's
// coordinates (fitted_surface.h, mean_value_surface.h), which needs the loop's
// projection on it to be a simple polygon.
#pragma once

#include <optional>
#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

struct MeanPlane {
  Vec3 origin, e1, e2, normal;

  // The frame through `origin` with unit normal `unit_normal`.
  static MeanPlane with_normal(const Vec3& origin, const Vec3& unit_normal);

  // nullopt when the loop has no area in any direction or its projection on the
  // plane crosses or touches itself.
  static std::optional<MeanPlane> of_loop(const std::vector<Vec3>& loop_points);

  // (x, y, height) of a point in the frame, and back.
  Vec3 local(const Vec3& point) const {
    const Vec3 d = point - origin;
    return {dot(d, e1), dot(d, e2), dot(d, normal)};
  }
  Vec3 point_at(double x, double y, double height) const { return origin + x * e1 + y * e2 + height * normal; }
  // The normal of a height function with these slopes along e1 and e2 (the cross
  // product of (e1 + slope_x normal) and (e2 + slope_y normal)), not of unit length.
  Vec3 normal_of_slopes(double slope_x, double slope_y) const { return normal - slope_x * e1 - slope_y * e2; }
};

}  // namespace tquad
