#include "core/repair/area_untangling.h"
#include "core/cancellation.h"

#include <algorithm>
#include <cmath>

#include "core/mesh/node_adjacency.h"

namespace tquad {

namespace {

// Passes over the nodes near inverted corners; each pass moves every such node to its
// best place given the others, and a fold a few layers deep needs a few passes.
constexpr int kMaxPasses = 100;
// Passes stop when this many in a row have not brought the fewest inverted corners
// yet seen lower. Without that a fuzzed curved loop ran all kMaxPasses passes again
// and again, its inverted corners growing in number, before everything went back:
// time lost for nothing, and many times more of it under the sanitizers.
constexpr int kStalledPasses = 10;

// The walls' slope over the steepest corner constraint: steep enough never to bind
// inside the box.
constexpr double kWallSlope = 1e3;

// The shortest edge a move may leave at the node, over its neighbours' spread (a
// fuzzed spike of a boundary drew a node onto a boundary node, a zero-length edge).
constexpr double kMinEdgeRatio = 1e-3;

double cross2(const Vec3& a, const Vec3& b) { return a.x * b.y - a.y * b.x; }

// Signed area (twice the triangle's) of corner j of quad q.
double corner_area(const Quad& q, int j, const std::vector<Vec3>& p, double orientation) {
  const Vec3& at = p[q[j]];
  return orientation * cross2(p[q[(j + 1) % 4]] - at, p[q[(j + 3) % 4]] - at);
}

// t <= slope . d + offset, d the node's displacement.
struct Constraint {
  double sx = 0, sy = 0, offset = 0;
  double at(double dx, double dy) const { return sx * dx + sy * dy + offset; }
};

class AreaUntangler {
 public:
  AreaUntangler(const std::vector<Quad>& quads, int fixed, std::vector<Vec3>& param, double orientation,
                const std::function<bool(int, const Vec3&)>& place)
      : quads_(quads), fixed_(fixed), param_(param), orientation_(orientation), place_(place),
        adjacency_(param.size(), quads) {}

  AreaUntanglingResult run() {
    AreaUntanglingResult result;
    result.inverted_before = inverted_corners(quads_, param_, orientation_);
    result.inverted_after = result.inverted_before;
    const std::vector<Vec3> start = param_;
    int fewest = result.inverted_before, stalled = 0;
    for (int pass = 0; pass < kMaxPasses && result.inverted_after > 0 && stalled < kStalledPasses; ++pass) {
      long long moves = 0;
      for (int n : nodes_near_inverted_corners()) moves += move_to_best_place(n) ? 1 : 0;
      result.moves += moves;
      result.inverted_after = inverted_corners(quads_, param_, orientation_);
      if (moves == 0) break;
      stalled = result.inverted_after < fewest ? 0 : stalled + 1;
      fewest = std::min(fewest, result.inverted_after);
    }
    if (result.inverted_after >= result.inverted_before) {
      // No fewer folded corners: the nodes go back (through place_, so the caller's data follow)
      // rather than leave a fold spread over more quads.
      for (int n = fixed_; n < static_cast<int>(param_.size()); ++n) {
        if (param_[n].x == start[n].x && param_[n].y == start[n].y) continue;
        if (place_(n, start[n])) param_[n] = start[n];
      }
      result.inverted_after = inverted_corners(quads_, param_, orientation_);
      result.moves = 0;
    }
    return result;
  }

 private:
  // Movable nodes of the quads with an inverted corner and of the quads around them.
  std::vector<int> nodes_near_inverted_corners() const {
    std::vector<char> chosen(param_.size(), 0);
    const CompressedLists& around = adjacency_.quads_of;
    for (const Quad& q : quads_) {
      poll_cancellation(4);
      bool inverted = false;
      for (int j = 0; j < 4 && !inverted; ++j) inverted = corner_area(q, j, param_, orientation_) <= 0;
      if (!inverted) continue;
      for (NodeId n : q) {
        for (int k = around.offsets[n]; k < around.offsets[n + 1]; ++k) {
          for (NodeId m : quads_[around.items[k]]) chosen[m] = 1;
        }
      }
    }
    std::vector<int> nodes;
    for (int n = fixed_; n < static_cast<int>(param_.size()); ++n) {
      if (chosen[n]) nodes.push_back(n);
    }
    return nodes;
  }

  // The corners around node n (its own and its two neighbours' in each quad) as affine
  // functions of its displacement, found exactly from three evaluations (they are
  // affine in one node's position).
  std::vector<Constraint> corner_constraints(int n, double step) {
    std::vector<Constraint> constraints;
    const Vec3 start = param_[n];
    const CompressedLists& around = adjacency_.quads_of;
    for (int k = around.offsets[n]; k < around.offsets[n + 1]; ++k) {
      const Quad& q = quads_[around.items[k]];
      const int i = static_cast<int>(std::find(q.begin(), q.end(), n) - q.begin());
      for (int j : {i, (i + 1) % 4, (i + 3) % 4}) {
        Constraint c;
        param_[n] = start;
        c.offset = corner_area(q, j, param_, orientation_);
        param_[n] = start + Vec3{step, 0, 0};
        c.sx = (corner_area(q, j, param_, orientation_) - c.offset) / step;
        param_[n] = start + Vec3{0, step, 0};
        c.sy = (corner_area(q, j, param_, orientation_) - c.offset) / step;
        constraints.push_back(c);
      }
    }
    param_[n] = start;
    return constraints;
  }

  bool move_to_best_place(int n) {
    const CompressedLists& next = adjacency_.neighbours;
    const int first = next.offsets[n], last = next.offsets[n + 1];
    if (last == first) return false;
    const Vec3 start = param_[n];
    double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
    for (int k = first; k < last; ++k) {
      const Vec3& p = param_[next.items[k]];
      lo_x = std::min(lo_x, p.x - start.x), hi_x = std::max(hi_x, p.x - start.x);
      lo_y = std::min(lo_y, p.y - start.y), hi_y = std::max(hi_y, p.y - start.y);
    }
    const double size = std::max(hi_x - lo_x, hi_y - lo_y);
    if (!(size > 0) || !std::isfinite(size)) return false;
    std::vector<Constraint> constraints = corner_constraints(n, size);
    double steepest = 0;
    for (const Constraint& c : constraints) steepest = std::max({steepest, std::abs(c.sx), std::abs(c.sy)});
    if (!(steepest > 0) || !std::isfinite(steepest)) return false;
    const double wall = kWallSlope * steepest;
    constraints.push_back({wall, 0, -wall * lo_x});
    constraints.push_back({-wall, 0, wall * hi_x});
    constraints.push_back({0, wall, -wall * lo_y});
    constraints.push_back({0, -wall, wall * hi_y});

    const auto worst_at = [&](double dx, double dy) {
      double worst = INFINITY;
      for (const Constraint& c : constraints) worst = std::min(worst, c.at(dx, dy));
      return worst;
    };
    const double now = worst_at(0, 0);
    double best = now, best_x = 0, best_y = 0;
    // The linear program's optimum is a point where three constraints are equal.
    const int m = static_cast<int>(constraints.size());
    for (int a = 0; a < m; ++a) {
      for (int b = a + 1; b < m; ++b) {
        for (int c = b + 1; c < m; ++c) {
          const Constraint& A = constraints[a];
          const Constraint& B = constraints[b];
          const Constraint& C = constraints[c];
          const double a11 = A.sx - B.sx, a12 = A.sy - B.sy, r1 = B.offset - A.offset;
          const double a21 = A.sx - C.sx, a22 = A.sy - C.sy, r2 = C.offset - A.offset;
          const double det = a11 * a22 - a12 * a21;
          if (std::abs(det) <= 1e-14 * (std::abs(a11 * a22) + std::abs(a12 * a21))) continue;
          const double dx = (r1 * a22 - a12 * r2) / det, dy = (a11 * r2 - r1 * a21) / det;
          if (!std::isfinite(dx) || !std::isfinite(dy)) continue;
          const double value = worst_at(dx, dy);
          if (value > best) best = value, best_x = dx, best_y = dy;
        }
      }
    }
    // A gain below rounding of the areas is no gain.
    if (!(best > now + 1e-12 * size * size)) return false;
    const Vec3 target = start + Vec3{best_x, best_y, 0};
    // Where no place unfolds every corner, the best one can be a neighbour's own
    // place (its corners' areas 0 instead of negative): a node never goes within
    // kMinEdgeRatio of the neighbours' spread of a neighbour.
    for (int k = first; k < last; ++k) {
      const Vec3& p = param_[next.items[k]];
      if (std::hypot(p.x - target.x, p.y - target.y) < kMinEdgeRatio * size) return false;
    }
    if (!place_(n, target)) return false;
    param_[n] = target;
    return true;
  }

  const std::vector<Quad>& quads_;
  int fixed_;
  std::vector<Vec3>& param_;
  double orientation_;
  const std::function<bool(int, const Vec3&)>& place_;
  NodeAdjacency adjacency_;
};

}  // namespace

int inverted_corners(const std::vector<Quad>& quads, const std::vector<Vec3>& param, double orientation) {
  int inverted = 0;
  for (const Quad& q : quads) {
    poll_cancellation(4);
    for (int j = 0; j < 4; ++j) inverted += corner_area(q, j, param, orientation) <= 0 ? 1 : 0;
  }
  return inverted;
}

AreaUntanglingResult untangle_corner_areas(const std::vector<Quad>& quads, int fixed, std::vector<Vec3>& param,
                                           double orientation,
                                           const std::function<bool(int node, const Vec3& p)>& place) {
  if (fixed >= static_cast<int>(param.size())) {
    AreaUntanglingResult result;
    result.inverted_before = result.inverted_after = inverted_corners(quads, param, orientation);
    return result;
  }
  return AreaUntangler(quads, fixed, param, orientation, place).run();
}

}  // namespace tquad
