#include "core/geometry/mean_plane.h"

#include <cmath>

#include "core/geometry/planar_self_intersection.h"

namespace tquad {

MeanPlane MeanPlane::with_normal(const Vec3& origin, const Vec3& unit_normal) {
  MeanPlane p;
  p.origin = origin;
  p.normal = unit_normal;
  const Vec3 helper = std::abs(unit_normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  p.e1 = cross(helper, unit_normal);
  p.e1 = (1.0 / norm(p.e1)) * p.e1;
  p.e2 = cross(unit_normal, p.e1);
  return p;
}

std::optional<MeanPlane> MeanPlane::of_loop(const std::vector<Vec3>& loop) {
  const int n = static_cast<int>(loop.size());
  const Vec3 area = newell_normal(loop);
  if (n < 3 || !(norm(area) > 0)) return std::nullopt;
  const MeanPlane plane = with_normal(loop[0], (1.0 / norm(area)) * area);
  std::vector<PlanarSegment> segments;
  for (int i = 0; i < n; ++i) segments.push_back({plane.local(loop[i]), plane.local(loop[(i + 1) % n])});
  const auto neighbours = [n](int i, int j) { return j == i + 1 || (i == 0 && j == n - 1); };
  if (find_segment_crossing(segments, neighbours)) return std::nullopt;
  return plane;
}

}  // namespace tquad
