#include "core/decomposition/coarse_triangulation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "core/geometry/planar_predicates.h"

namespace tquad {

double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 p[3] = {a, b, c};
  double smallest = M_PI;
  for (int i = 0; i < 3; ++i) {
    const Vec3 u = p[(i + 1) % 3] - p[i], v = p[(i + 2) % 3] - p[i];
    if (norm(u) * norm(v) == 0) return 0;
    smallest = std::min(smallest, std::abs(signed_angle(u, v)));
  }
  return smallest;
}

namespace {

// The ring being cut: positions into a doubly linked list over vertex ids (a bridge
// vertex appears twice, with one id).
class EarCutter {
 public:
  EarCutter(const std::vector<Vec3>& points, std::vector<int> ring, const EarFilter& avoid)
      : points_(points), ring_(std::move(ring)), avoid_(avoid) {
    const int n = static_cast<int>(ring_.size());
    next_.resize(n);
    prev_.resize(n);
    for (int i = 0; i < n; ++i) {
      next_[i] = (i + 1) % n;
      prev_[i] = (i + n - 1) % n;
    }
    alive_.assign(n, 1);
    remaining_ = n;
    // Relative to the polygon's own size, not to its distance from the origin.
    double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
    for (int id : ring_) {
      lo_x = std::min(lo_x, points_[id].x); hi_x = std::max(hi_x, points_[id].x);
      lo_y = std::min(lo_y, points_[id].y); hi_y = std::max(hi_y, points_[id].y);
    }
    const double extent = std::max(hi_x - lo_x, hi_y - lo_y);
    area_tolerance_ = 1e-12 * extent * extent;
  }

  std::vector<CoarseTriangle> run() {
    std::vector<CoarseTriangle> triangles;
    // Small rings keep every ear's value exact after each cut (up to O(n^3)); larger
    // ones look again only at the cut ear's neighbours, and rescan when none is left.
    const bool exact = ring_.size() <= 400;
    std::vector<double> quality(ring_.size(), -1);
    for (std::size_t i = 0; i < ring_.size(); ++i) quality[i] = ear_quality(static_cast<int>(i));
    while (remaining_ > 3) {
      int best = pick(quality);
      if (best < 0) {  // cached values may be stale: rescan once
        for (std::size_t i = 0; i < ring_.size(); ++i) if (alive_[i]) quality[i] = ear_quality(static_cast<int>(i));
        best = pick(quality);
        if (best < 0) throw TriangulationFailure("no ear left among " + std::to_string(remaining_) + " ring vertices");
      }
      triangles.push_back({ring_[prev_[best]], ring_[best], ring_[next_[best]]});
      const int p = prev_[best], q = next_[best];
      next_[p] = q;
      prev_[q] = p;
      alive_[best] = 0;
      --remaining_;
      if (exact) {
        // Only the ears at p and q change shape; an ear elsewhere that was valid stays
        // valid with the same triangle (cutting an ear removes a vertex and adds a side
        // inside the cut ear, which another empty ear triangle cannot cross), so only
        // the invalid ones are looked at again.
        for (std::size_t i = 0; i < ring_.size(); ++i) {
          const int k = static_cast<int>(i);
          if (alive_[i] && (quality[i] < 0 || k == p || k == q)) quality[i] = ear_quality(k);
        }
      } else {
        quality[p] = ear_quality(p);
        quality[q] = ear_quality(q);
      }
    }
    int last = 0;
    while (!alive_[last]) ++last;
    const Vec3 &a = points_[ring_[prev_[last]]], &b = points_[ring_[last]], &c = points_[ring_[next_[last]]];
    if (orient2d(a, b, c) <= area_tolerance_) throw TriangulationFailure("the last triangle is degenerate");
    triangles.push_back({ring_[prev_[last]], ring_[last], ring_[next_[last]]});
    return triangles;
  }

 private:
  // The valid ear of the best shape, ears to avoid only when no other is left.
  int pick(const std::vector<double>& quality) const {
    int best = -1;
    double best_score = 0;
    for (std::size_t i = 0; i < ring_.size(); ++i) {
      if (!alive_[i] || quality[i] < 0) continue;
      const int k = static_cast<int>(i);
      const double score = quality[i] - (avoid_ && avoid_(ring_[prev_[k]], ring_[k], ring_[next_[k]]) ? 4.0 : 0.0);
      if (best < 0 || score > best_score) { best = k; best_score = score; }
    }
    return best;
  }

  // Smallest angle of the ear at ring position i, or -1 when it is not an ear.
  double ear_quality(int i) const {
    const int ia = ring_[prev_[i]], ib = ring_[i], ic = ring_[next_[i]];
    const Vec3 &a = points_[ia], &b = points_[ib], &c = points_[ic];
    if (orient2d(a, b, c) <= area_tolerance_) return -1;
    for (int k = next_[next_[i]]; k != prev_[i]; k = next_[k]) {
      const int id = ring_[k];
      if (id == ia || id == ib || id == ic) continue;
      const Vec3& p = points_[id];
      // On or near a side counts as inside: a vertex on the new side a-c would be left
      // behind as a straight-angle corner of a zero-area remainder.
      const double t = -area_tolerance_;
      if (orient2d(a, b, p) >= t && orient2d(b, c, p) >= t && orient2d(c, a, p) >= t) return -1;
    }
    // The new side a-c must not meet the ring elsewhere (bridged rings touch
    // themselves at bridge ends).
    for (int k = next_[i];; k = next_[k]) {
      const int k2 = next_[k];
      if (k2 == prev_[i]) break;
      const int e0 = ring_[k], e1 = ring_[k2];
      if (e0 == ia || e0 == ic || e1 == ia || e1 == ic) continue;
      if (segments_meet(a, c, points_[e0], points_[e1])) return -1;
    }
    return smallest_angle(a, b, c);
  }

  const std::vector<Vec3>& points_;
  std::vector<int> ring_, next_, prev_;
  const EarFilter& avoid_;
  std::vector<char> alive_;
  int remaining_ = 0;
  double area_tolerance_ = 0;
};

struct Loops {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> ids;  // per loop, its vertex ids in order
};

// Joins every hole to the ring by its shortest bridge inside the domain. A bridge may
// not meet any edge of the ring or of a hole not yet joined, except at its own ends.
std::vector<int> bridged_ring(const Loops& loops) {
  std::vector<int> ring = loops.ids[0];
  std::vector<int> order;
  for (int l = 1; l < static_cast<int>(loops.ids.size()); ++l) order.push_back(l);
  auto max_x = [&](int l) {
    double m = -INFINITY;
    for (int id : loops.ids[l]) m = std::max(m, loops.points[id].x);
    return m;
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return max_x(a) > max_x(b); });
  std::vector<char> joined(loops.ids.size(), 0);
  joined[0] = 1;
  for (int l : order) {
    const std::vector<int>& hole = loops.ids[l];
    const int hn = static_cast<int>(hole.size()), rn = static_cast<int>(ring.size());
    // Candidate bridges, shortest first, from at most kBridgeStarts places of the
    // hole (all of them when none of those gives a bridge): memory stays O(ring)
    // per start even for holes of thousands of points.
    constexpr int kBridgeStarts = 64;
    std::vector<int> starts;
    for (int k = 0; k < std::min(hn, kBridgeStarts); ++k) starts.push_back(k * hn / std::min(hn, kBridgeStarts));
    std::vector<std::pair<double, std::pair<int, int>>> candidates;  // (length, (hole pos, ring pos))
    auto add_candidates = [&](const std::vector<int>& from) {
      candidates.clear();
      for (int h : from) {
        for (int r = 0; r < rn; ++r) candidates.push_back({distance(loops.points[hole[h]], loops.points[ring[r]]), {h, r}});
      }
      std::sort(candidates.begin(), candidates.end());
    };
    add_candidates(starts);
    auto blocked = [&](const Vec3& a, const Vec3& b, int ida, int idb, const std::vector<int>& loop) {
      const int n = static_cast<int>(loop.size());
      for (int k = 0; k < n; ++k) {
        const int e0 = loop[k], e1 = loop[(k + 1) % n];
        if (e0 == ida || e0 == idb || e1 == ida || e1 == idb) continue;
        if (segments_meet(a, b, loops.points[e0], loops.points[e1])) return true;
      }
      return false;
    };
    bool done = false;
    for (int attempt = 0; attempt < 2 && !done; ++attempt) {
      if (attempt == 1) {
        if (static_cast<int>(starts.size()) == hn) break;
        std::vector<int> every(hn);
        for (int h = 0; h < hn; ++h) every[h] = h;
        add_candidates(every);
      }
      for (const auto& [length, where] : candidates) {
        const auto [h, r] = where;
        const int ih = hole[h], ir = ring[r];
        const Vec3 &ph = loops.points[ih], &pr = loops.points[ir];
        if (length == 0) continue;
        if (!inside_corner(loops.points[ring[(r + rn - 1) % rn]], pr, loops.points[ring[(r + 1) % rn]], ph)) continue;
        if (!inside_corner(loops.points[hole[(h + hn - 1) % hn]], ph, loops.points[hole[(h + 1) % hn]], pr)) continue;
        bool clear = !blocked(ph, pr, ih, ir, ring);
        for (std::size_t o = 1; clear && o < loops.ids.size(); ++o) {
          if (!joined[o]) clear = !blocked(ph, pr, ih, ir, loops.ids[o]);
        }
        if (!clear) continue;
        // ring[..r], hole[h], hole[h+1], ..., hole[h], ring[r], ring[r+1..]
        std::vector<int> merged(ring.begin(), ring.begin() + r + 1);
        for (int k = 0; k <= hn; ++k) merged.push_back(hole[(h + k) % hn]);
        merged.insert(merged.end(), ring.begin() + r, ring.end());
        ring = std::move(merged);
        done = true;
        break;
      }
    }
    if (!done) throw TriangulationFailure("hole " + std::to_string(l) + " cannot be bridged to the outer loop");
    joined[l] = 1;
  }
  return ring;
}

// Lawson flips: a diagonal whose two triangles form a convex quadrilateral is swapped
// for the other diagonal when that raises the pair's smallest angle.
void improve_by_flips(const Loops& loops, std::vector<CoarseTriangle>& triangles) {
  std::map<std::pair<int, int>, int> loop_edges;  // boundary sides never flip
  for (const std::vector<int>& loop : loops.ids) {
    for (std::size_t k = 0; k < loop.size(); ++k) loop_edges[{loop[k], loop[(k + 1) % loop.size()]}] = 1;
  }
  auto key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for (int pass = 0; pass < 100; ++pass) {
    std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> sides;  // edge -> (triangle, corner)
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
      for (int i = 0; i < 3; ++i) sides[key(triangles[t][i], triangles[t][(i + 1) % 3])].push_back({t, i});
    }
    bool flipped = false;
    std::vector<char> touched(triangles.size(), 0);
    for (const auto& [edge, users] : sides) {
      if (users.size() != 2) continue;
      if (loop_edges.count(edge) || loop_edges.count({edge.second, edge.first})) continue;
      const auto [t1, i1] = users[0];
      const auto [t2, i2] = users[1];
      if (touched[t1] || touched[t2]) continue;
      const int a = triangles[t1][i1], b = triangles[t1][(i1 + 1) % 3], c = triangles[t1][(i1 + 2) % 3];
      const int d = triangles[t2][(i2 + 2) % 3];
      if (c == d || sides.count(key(c, d))) continue;
      const Vec3 &pa = loops.points[a], &pb = loops.points[b], &pc = loops.points[c], &pd = loops.points[d];
      // Convex quadrilateral a, d, b, c (counter-clockwise).
      if (orient2d(pc, pa, pd) <= 0 || orient2d(pd, pb, pc) <= 0) continue;
      const double before = std::min(smallest_angle(pa, pb, pc), smallest_angle(pb, pa, pd));
      const double after = std::min(smallest_angle(pc, pa, pd), smallest_angle(pd, pb, pc));
      if (after <= before + 1e-9) continue;
      triangles[t1] = {c, a, d};
      triangles[t2] = {d, b, c};
      touched[t1] = touched[t2] = 1;
      flipped = true;
    }
    if (!flipped) break;
  }
}

void check_triangulation(const Loops& loops, const std::vector<CoarseTriangle>& triangles) {
  std::set<std::pair<int, int>> loop_sides, directed;
  for (const std::vector<int>& loop : loops.ids) {
    for (std::size_t k = 0; k < loop.size(); ++k) loop_sides.insert({loop[k], loop[(k + 1) % loop.size()]});
  }
  for (const CoarseTriangle& t : triangles) {
    for (int i = 0; i < 3; ++i) {
      if (!directed.insert({t[i], t[(i + 1) % 3]}).second) throw TriangulationFailure("a triangle side is used twice");
    }
  }
  for (const auto& [a, b] : directed) {
    if (!loop_sides.count({a, b}) && !directed.count({b, a})) {
      throw TriangulationFailure("a diagonal has a triangle on one side only");
    }
  }
}

}  // namespace

std::vector<CoarseTriangle> triangulate_polygon_with_holes(const std::vector<std::vector<Vec3>>& input,
                                                           const EarFilter& avoid) {
  Loops loops;
  for (const std::vector<Vec3>& loop : input) {
    if (loop.size() < 3) throw TriangulationFailure("a loop has fewer than 3 vertices");
    std::vector<int> ids;
    for (const Vec3& p : loop) {
      ids.push_back(static_cast<int>(loops.points.size()));
      loops.points.push_back(p);
    }
    loops.ids.push_back(std::move(ids));
  }
  std::vector<CoarseTriangle> triangles = EarCutter(loops.points, bridged_ring(loops), avoid).run();
  improve_by_flips(loops, triangles);
  check_triangulation(loops, triangles);
  return triangles;
}

}  // namespace tquad
