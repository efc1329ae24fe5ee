// Planar predicates on the x, y of Vec3 points (z ignored), shared by the boundary
// self-intersection check, the coarse triangulation and the face decomposition.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/geometry/vec3.h"

namespace tquad {

// Twice the signed area of triangle (a, b, c): > 0 when it turns left.
inline double orient2d(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// p lies in the bounding box of segment [a, b] (with orient2d == 0: on the segment).
inline bool within_box(const Vec3& a, const Vec3& b, const Vec3& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Closed segments [a, b] and [c, d] share at least one point. Segments whose boxes are
// apart never meet: on nearly collinear segments the orientation signs are rounding
// noise and would report a crossing.
inline bool segments_meet(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
      std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y)) {
    return false;
  }
  const double d1 = orient2d(c, d, a), d2 = orient2d(c, d, b);
  const double d3 = orient2d(a, b, c), d4 = orient2d(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  return (d1 == 0 && within_box(c, d, a)) || (d2 == 0 && within_box(c, d, b)) ||
         (d3 == 0 && within_box(a, b, c)) || (d4 == 0 && within_box(a, b, d));
}

// Signed angle from u to v (radians, in (-pi, pi], > 0 counter-clockwise).
inline double signed_angle(const Vec3& u, const Vec3& v) {
  return std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
}

inline bool same_xy(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y; }

// Direction from `here` to q points into the region left of the path prev -> here ->
// next (a polygon's interior at its vertex `here`, strictly).
inline bool inside_corner(const Vec3& prev, const Vec3& here, const Vec3& next, const Vec3& q) {
  const bool left_of_in = orient2d(prev, here, q) > 0, left_of_out = orient2d(here, next, q) > 0;
  return orient2d(prev, here, next) > 0 ? (left_of_in && left_of_out) : (left_of_in || left_of_out);
}

}  // namespace tquad
