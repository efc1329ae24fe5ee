// PlanarDomain: a face's region in a planar chart (its (u, v) space scaled so that
// lengths match the surface, or any other plane), given by closed loops of boundary
// points that the mesh must keep: loops[0] is the outer loop, counter-clockwise;
// every other loop is a hole, clockwise, so the domain lies to the left of every
// loop. z is ignored.
//
// Boundary points are numbered loop after loop: point i of loop l is domain node
// offset(l) + i. Meshes built on a domain keep these nodes first, in this order.
#pragma once

#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

struct DomainLoop {
  std::vector<Vec3> points;
  // Per point (or empty): a CAD vertex, where the boundary may turn sharply. A sharp
  // vertex always becomes a patch corner; a smooth one is an ordinary point.
  std::vector<char> vertex;
};

struct PlanarDomain {
  std::vector<DomainLoop> loops;

  int loop_count() const { return static_cast<int>(loops.size()); }
  int hole_count() const { return loop_count() - 1; }
  int offset(int loop) const {
    int n = 0;
    for (int l = 0; l < loop; ++l) n += static_cast<int>(loops[l].points.size());
    return n;
  }
  int point_count() const { return offset(loop_count()); }
};

// Twice the signed area of a loop (z ignored): positive when counter-clockwise.
inline double twice_signed_area(const std::vector<Vec3>& loop) {
  double twice = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3& a = loop[i];
    const Vec3& b = loop[(i + 1) % loop.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return twice;
}

}  // namespace tquad
