// AffineMap: x -> M (x - from) + to, the least-squares affine map between two lists of
// corresponding points, as the sweep's layers are placed from its caps' boundaries
// (Roca and Sarrate's least-squares projection; docs/design.md, "Sweeping").
#pragma once

#include <array>
#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

struct AffineMap {
  Vec3 from, to;                    // the two lists' centroids
  std::array<Vec3, 3> rows{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};  // M by rows

  Vec3 operator()(const Vec3& x) const {
    const Vec3 d = x - from;
    return to + Vec3{dot(rows[0], d), dot(rows[1], d), dot(rows[2], d)};
  }

  // The map minimizing sum |A(a_i) - b_i|^2 over affine A. When the a_i span less than
  // 3D (a planar cap's boundary), the part of M along what they do not span is the
  // smallest (zero): a point off their plane moves as its foot on the plane does.
  // Throws std::invalid_argument when the lists differ in length or are empty.
  static AffineMap fit(const std::vector<Vec3>& a, const std::vector<Vec3>& b);
};

}  // namespace tquad
