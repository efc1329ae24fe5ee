#include "core/templates/o_grid.h"

#include <algorithm>

#include "core/geometry/planar_predicates.h"

namespace tquad {

namespace {

// The outer point nearest to rim point `rim` whose cut to it stays inside the domain,
// other than `taken`; -1 when there is none.
int nearest_reachable_outer(const PlanarDomain& d, int rim, int taken) {
  const Vec3& r = d.loops[1].points[rim];
  const int n = static_cast<int>(d.loops[0].points.size());
  std::vector<std::pair<double, int>> by_distance;
  for (int i = 0; i < n; ++i) if (i != taken) by_distance.push_back({distance(r, d.loops[0].points[i]), i});
  std::sort(by_distance.begin(), by_distance.end());
  for (const auto& [length, i] : by_distance) {
    if (length > 0 && cut_obstacles(d, 0, i, 1, rim).empty()) return i;
  }
  return -1;
}

}  // namespace

std::optional<FaceDecomposition> o_grid_decomposition(const PlanarDomain& d, int rim_point) {
  if (d.loop_count() != 2) return std::nullopt;
  const int rim_size = static_cast<int>(d.loops[1].points.size());
  const int i1 = rim_point % rim_size, i2 = (i1 + rim_size / 2) % rim_size;
  const int o1 = nearest_reachable_outer(d, i1, -1);
  if (o1 < 0 || i1 == i2) return std::nullopt;
  const int o2 = nearest_reachable_outer(d, i2, o1);
  if (o2 < 0) return std::nullopt;
  // The two cuts must not cross each other.
  const Vec3 &a1 = d.loops[0].points[o1], &b1 = d.loops[1].points[i1];
  const Vec3 &a2 = d.loops[0].points[o2], &b2 = d.loops[1].points[i2];
  if (segments_meet(a1, b1, a2, b2)) return std::nullopt;

  FaceDecomposition out;
  const int rim_offset = d.offset(1);
  // Pieces: outer o1 -> o2, outer o2 -> o1, rim i2 -> i1, rim i1 -> i2 (loop order).
  out.pieces = {{0, o1, o2}, {0, o2, o1}, {1, i2, i1}, {1, i1, i2}};
  out.cuts = {{o1, rim_offset + i1, distance(a1, b1)}, {o2, rim_offset + i2, distance(a2, b2)}};
  // Half A: outer o1 -> o2, across to i2, rim i2 -> i1, back to o1; half B likewise.
  out.patches.push_back({{{false, 0, false}, {true, 1, false}, {false, 2, false}, {true, 0, true}}});
  out.patches.push_back({{{false, 1, false}, {true, 0, false}, {false, 3, false}, {true, 1, true}}});
  return out;
}

}  // namespace tquad
