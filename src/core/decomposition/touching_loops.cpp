#include "core/decomposition/touching_loops.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace tquad {

namespace {

struct Walk {
  std::vector<Vec3> points;
  std::vector<char> vertex;
  std::vector<int> source;
  std::vector<char> pinched;  // a copy of a point where two loops were spliced
};

// The bisector of the copy's wedge: the domain lies to the left of the loop, so the
// wedge turns counter-clockwise from the outgoing segment to the incoming one
// reversed (any angle in (0, 2 pi): convex, reflex or a cusp).
Vec3 into_wedge(const Vec3& previous, const Vec3& point, const Vec3& next) {
  const double out_angle = std::atan2(next.y - point.y, next.x - point.x);
  const double back_angle = std::atan2(previous.y - point.y, previous.x - point.x);
  double wedge = back_angle - out_angle;
  while (wedge <= 0) wedge += 2 * M_PI;
  while (wedge > 2 * M_PI) wedge -= 2 * M_PI;
  const double bisector = out_angle + wedge / 2;
  return Vec3{std::cos(bisector), std::sin(bisector), 0.0};
}

}  // namespace

SplicedDomain splice_touching_loops(const PlanarDomain& domain, const std::vector<long long>& ids) {
  if (static_cast<int>(ids.size()) != domain.point_count()) {
    throw std::logic_error("splice_touching_loops: one identity per domain point expected");
  }
  std::vector<Walk> loops;
  int offset = 0;
  for (const DomainLoop& loop : domain.loops) {
    Walk w;
    w.points = loop.points;
    w.vertex = loop.vertex.empty() ? std::vector<char>(loop.points.size(), 0) : loop.vertex;
    for (std::size_t i = 0; i < loop.points.size(); ++i) w.source.push_back(offset + static_cast<int>(i));
    w.pinched.assign(loop.points.size(), 0);
    offset += static_cast<int>(loop.points.size());
    loops.push_back(std::move(w));
  }
  SplicedDomain out;
  // Splice loop b into loop a at their first shared point, until no two loops share one.
  for (bool spliced = true; spliced;) {
    spliced = false;
    for (std::size_t a = 0; a < loops.size() && !spliced; ++a) {
      std::multimap<long long, int> at;
      for (std::size_t i = 0; i < loops[a].source.size(); ++i) at.emplace(ids[loops[a].source[i]], static_cast<int>(i));
      for (std::size_t b = a + 1; b < loops.size() && !spliced; ++b) {
        const Walk& h = loops[b];
        for (std::size_t j = 0; j < h.source.size(); ++j) {
          // A loop meets a node twice along a seam: the copy at the hole's point.
          int i = -1;
          const auto [first, last] = at.equal_range(ids[h.source[j]]);
          for (auto it = first; it != last; ++it) {
            if (i < 0 || distance(loops[a].points[it->second], h.points[j]) < distance(loops[a].points[i], h.points[j])) {
              i = it->second;
            }
          }
          if (i < 0) continue;
          const int m = static_cast<int>(h.source.size());
          Walk merged;
          const auto take = [&merged](const Walk& w, int k, bool pinch) {
            merged.points.push_back(w.points[k]);
            merged.vertex.push_back(w.vertex[k]);
            merged.source.push_back(w.source[k]);
            merged.pinched.push_back(pinch || w.pinched[k]);
          };
          const Walk& o = loops[a];
          for (int k = 0; k <= i; ++k) take(o, k, k == i);
          for (int k = 1; k <= m; ++k) take(h, (static_cast<int>(j) + k) % m, k == m);
          for (int k = i + 1; k < static_cast<int>(o.source.size()); ++k) take(o, k, false);
          loops[a] = std::move(merged);
          loops.erase(loops.begin() + static_cast<std::ptrdiff_t>(b));
          ++out.splices;
          spliced = true;
          break;
        }
      }
    }
  }
  // Each copy of a spliced point moves into its own wedge.
  for (Walk& w : loops) {
    const std::vector<Vec3> original = w.points;
    const int n = static_cast<int>(w.points.size());
    for (int k = 0; k < n; ++k) {
      if (!w.pinched[k]) continue;
      const Vec3& previous = original[(k + n - 1) % n];
      const Vec3& next = original[(k + 1) % n];
      const double shorter = std::min(distance(previous, original[k]), distance(next, original[k]));
      w.points[k] = original[k] + (kPinchNudge * shorter) * into_wedge(previous, original[k], next);
    }
  }
  for (Walk& w : loops) {
    DomainLoop loop;
    loop.points = std::move(w.points);
    loop.vertex = std::move(w.vertex);
    out.domain.loops.push_back(std::move(loop));
    out.source.insert(out.source.end(), w.source.begin(), w.source.end());
  }
  return out;
}

}  // namespace tquad
