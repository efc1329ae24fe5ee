#include "core/geometry/planar_self_intersection.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/geometry/box3.h"
#include "core/input_error.h"
#include "core/geometry/planar_predicates.h"

namespace tquad {

Vec3 newell_normal(const std::vector<Vec3>& p) {
  Vec3 n;
  const std::size_t count = p.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % count];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

bool planar_normal(const std::vector<Vec3>& p, Vec3& unit_normal) {
  if (p.size() < 3) return false;  // no plane: the loop's own check names what is short
  const Vec3 n = newell_normal(p);
  Vec3 centroid;
  for (const Vec3& q : p) centroid += q;
  centroid = (1.0 / static_cast<double>(p.size())) * centroid;
  const double size = bounding_box(p).diagonal();
  const double area2 = norm(n);
  if (area2 <= 1e-14 * size * size) return false;
  unit_normal = (1.0 / area2) * n;
  for (const Vec3& q : p) {
    if (std::abs(dot(q - centroid, unit_normal)) > 1e-9 * size) return false;
  }
  return true;
}

namespace {

using Point2 = Vec3;  // projected on the loop's plane, z = 0

[[noreturn]] void report_crossing(int i, int j, int n) {
  throw InputError("boundary crosses itself: segment " + std::to_string(i) + " (points " +
                   std::to_string(i) + "-" + std::to_string((i + 1) % n) + ") meets segment " +
                   std::to_string(j) + " (points " + std::to_string(j) + "-" +
                   std::to_string((j + 1) % n) + ")");
}

// Projects the loop on its plane; returns false when the loop is not planar.
bool project_if_planar(const std::vector<Vec3>& p, std::vector<Point2>& out) {
  const Vec3 extent = bounding_box(p).extent();
  Vec3 normal;
  if (norm(newell_normal(p)) <= 1e-14 * dot(extent, extent)) {
    // No net area (a bow-tie, or a loop on a line): look for the crossing in the
    // coordinate plane where the loop spreads most; report it if there is one.
    normal = extent.x <= extent.y && extent.x <= extent.z ? Vec3{1, 0, 0}
             : extent.y <= extent.z                      ? Vec3{0, 1, 0}
                                                         : Vec3{0, 0, 1};
  } else if (!planar_normal(p, normal)) {
    return false;
  }
  // An orthonormal basis of the plane.
  const Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  Vec3 e1 = cross(normal, helper);
  e1 = (1.0 / norm(e1)) * e1;
  const Vec3 e2 = cross(normal, e1);
  out.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) out[i] = {dot(p[i], e1), dot(p[i], e2), 0.0};
  return true;
}

void check_fold_backs(const std::vector<Point2>& q) {
  const int n = static_cast<int>(q.size());
  for (int i = 0; i < n; ++i) {
    const Point2& a = q[(i + n - 1) % n];
    const Point2& b = q[i];
    const Point2& c = q[(i + 1) % n];
    const double along = (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y);
    if (orient2d(a, b, c) == 0 && along < 0) {
      throw InputError("boundary folds back on itself at point " + std::to_string(i));
    }
  }
}

void check_segment_crossings(const std::vector<Point2>& q) {
  const int n = static_cast<int>(q.size());
  std::vector<PlanarSegment> segments;
  for (int i = 0; i < n; ++i) segments.push_back({q[i], q[(i + 1) % n]});
  const auto crossing = find_segment_crossing(segments, [n](int i, int j) {
    return j == i + 1 || (i == 0 && j == n - 1);  // neighbours share a point
  });
  if (crossing) report_crossing(crossing->first, crossing->second, n);
}

}  // namespace

void check_planar_self_intersection(const std::vector<Vec3>& points) {
  std::vector<Point2> q;
  if (!project_if_planar(points, q)) return;
  check_fold_backs(q);
  check_segment_crossings(q);
  Vec3 normal;
  if (!planar_normal(points, normal)) {
    throw InputError("boundary encloses no area: it lies on a line or retraces itself");
  }
}

std::optional<std::pair<int, int>> find_segment_crossing(const std::vector<PlanarSegment>& segments,
                                                         const std::function<bool(int, int)>& neighbours) {
  const int n = static_cast<int>(segments.size());
  if (n == 0) return std::nullopt;
  double xmin = segments[0].a.x, xmax = xmin, ymin = segments[0].a.y, ymax = ymin;
  for (const PlanarSegment& s : segments) {
    for (const Vec3& p : {s.a, s.b}) {
      xmin = std::min(xmin, p.x); xmax = std::max(xmax, p.x);
      ymin = std::min(ymin, p.y); ymax = std::max(ymax, p.y);
    }
  }
  // A grid of about n cells: segments of a boundary have similar sizes, so each falls
  // in a few cells and only near segments are compared.
  const int cells_per_side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(n))));
  const double cw = std::max(xmax - xmin, 1e-300) / cells_per_side;
  const double ch = std::max(ymax - ymin, 1e-300) / cells_per_side;
  auto cell_x = [&](double x) { return std::min(cells_per_side - 1, static_cast<int>((x - xmin) / cw)); };
  auto cell_y = [&](double y) { return std::min(cells_per_side - 1, static_cast<int>((y - ymin) / ch)); };
  std::vector<std::vector<int>> cells(static_cast<std::size_t>(cells_per_side) * cells_per_side);
  for (int i = 0; i < n; ++i) {
    const Vec3 &a = segments[i].a, &b = segments[i].b;
    for (int cx = cell_x(std::min(a.x, b.x)); cx <= cell_x(std::max(a.x, b.x)); ++cx) {
      for (int cy = cell_y(std::min(a.y, b.y)); cy <= cell_y(std::max(a.y, b.y)); ++cy) {
        cells[static_cast<std::size_t>(cy) * cells_per_side + cx].push_back(i);
      }
    }
  }
  for (const auto& cell : cells) {
    for (std::size_t s = 0; s < cell.size(); ++s) {
      for (std::size_t t = s + 1; t < cell.size(); ++t) {
        const int i = std::min(cell[s], cell[t]);
        const int j = std::max(cell[s], cell[t]);
        if (i == j || neighbours(i, j)) continue;
        if (segments_meet(segments[i].a, segments[i].b, segments[j].a, segments[j].b)) return std::make_pair(i, j);
      }
    }
  }
  return std::nullopt;
}

}  // namespace tquad
