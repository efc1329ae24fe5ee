// Box3: an axis-aligned bounding box, for sizes relative to a loop's or a shape's
// extent (tolerances, absurd-coordinate checks).
#pragma once

#include <algorithm>
#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

struct Box3 {
  Vec3 low, high;
  Vec3 extent() const { return high - low; }
  double diagonal() const { return norm(high - low); }
};

// The bounding box of the points in [first, last) (at least one).
template <typename It>
Box3 bounding_box(It first, It last) {
  Box3 box{*first, *first};
  for (; first != last; ++first) {
    const Vec3& p = *first;
    box.low = {std::min(box.low.x, p.x), std::min(box.low.y, p.y), std::min(box.low.z, p.z)};
    box.high = {std::max(box.high.x, p.x), std::max(box.high.y, p.y), std::max(box.high.z, p.z)};
  }
  return box;
}

// The bounding box of `points` (at least one).
inline Box3 bounding_box(const std::vector<Vec3>& points) { return bounding_box(points.begin(), points.end()); }

}  // namespace tquad
