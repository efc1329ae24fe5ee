#include "core/geometry/boundary_loop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "core/geometry/box3.h"
#include "core/input_error.h"
#include "core/geometry/planar_self_intersection.h"

namespace tquad {

std::vector<int> curve_segment_counts(const std::vector<int>& sorted_corners, int point_count) {
  std::vector<int> counts;
  const int k = static_cast<int>(sorted_corners.size());
  for (int i = 0; i < k; ++i) {
    const int next = i + 1 < k ? sorted_corners[i + 1] : sorted_corners[0] + point_count;
    counts.push_back(next - sorted_corners[i]);
  }
  return counts;
}

namespace {

void check_sizes(const BoundaryLoop& loop) {
  const auto n = loop.points.size();
  if (n < 4) {
    throw InputError("boundary has " + std::to_string(n) +
                     " points; a quad mesh needs a closed loop of at least 4 segments");
  }
  if (n % 2 != 0) {
    throw InputError("boundary has " + std::to_string(n) +
                     " segments, an odd number; every quad mesh has an even number of "
                     "boundary segments (add or remove one point)");
  }
  if (n > 100000000) {
    throw InputError("boundary has " + std::to_string(n) + " points, more than 1e8");
  }
}

std::vector<int> check_corners(const BoundaryLoop& loop) {
  const int n = static_cast<int>(loop.points.size());
  const auto& corners = loop.corners;
  if (corners.size() < 2 || corners.size() > 4) {
    throw InputError("boundary has " + std::to_string(corners.size()) +
                     " corners; templates need 2, 3 or 4 (one per curve)");
  }
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (corners[i] < 0 || corners[i] >= n) {
      throw InputError("corner " + std::to_string(i) + " has index " +
                       std::to_string(corners[i]) + ", outside the points 0.." +
                       std::to_string(n - 1));
    }
  }
  std::vector<int> sorted = corners;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i) {
    if (sorted[i] == sorted[i - 1]) {
      throw InputError("corner index " + std::to_string(sorted[i]) +
                       " is given twice; each curve needs at least one segment");
    }
  }
  return sorted;
}

void check_points(const BoundaryLoop& loop) {
  const int n = static_cast<int>(loop.points.size());
  for (int i = 0; i < n; ++i) {
    const Vec3& p = loop.points[i];
    if (!is_finite(p)) {
      throw InputError("point " + std::to_string(i) + " has a coordinate that is NaN or infinite");
    }
    if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kMaxCoordinate) {
      throw InputError("point " + std::to_string(i) + " has a coordinate beyond 1e12 in magnitude: the products " +
                       "the geometry takes would overflow");
    }
  }
  // Two boundary points at one place: the loop touches itself (in 3D the planar
  // crossing check below does not see it, and the mesh would have coincident nodes).
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  const auto key = [&](int i) { return std::tie(loop.points[i].x, loop.points[i].y, loop.points[i].z); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  for (int k = 1; k < n; ++k) {
    if (key(order[k]) == key(order[k - 1])) {
      const int a = std::min(order[k], order[k - 1]), b = std::max(order[k], order[k - 1]);
      if (b == a + 1 || (a == 0 && b == n - 1)) continue;  // a zero-length segment: named below
      throw InputError("points " + std::to_string(a) + " and " + std::to_string(b) +
                       " coincide: the boundary touches itself");
    }
  }
  const double shortest_allowed = kShortestSegmentFraction * bounding_box(loop.points).diagonal();
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    if (loop.points[i] == loop.points[j]) {
      throw InputError("segment " + std::to_string(i) + " from point " + std::to_string(i) +
                       " to point " + std::to_string(j) + " has zero length");
    }
    const double length = norm(loop.points[j] - loop.points[i]);
    if (length < shortest_allowed) {
      char text[96];
      std::snprintf(text, sizeof text, " is %.3g long, under %g of the boundary's extent", length,
                    kShortestSegmentFraction);
      throw InputError("segment " + std::to_string(i) + " from point " + std::to_string(i) + " to point " +
                       std::to_string(j) + text + ": its points coincide but for rounding");
    }
  }
}

}  // namespace

std::vector<int> validate_boundary(const BoundaryLoop& loop) {
  check_sizes(loop);
  std::vector<int> sorted = check_corners(loop);
  check_points(loop);
  check_planar_self_intersection(loop.points);
  return sorted;
}

}  // namespace tquad
