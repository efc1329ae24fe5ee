// Counts shared by several curves (a chain of opposite sides kept equal), and the one
// place that says how near a count is to a curve's goal (its length / size).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <cstdio>

#include "core/input_error.h"

namespace tquad {

// Beyond this many segments a curve's goal is refused (the size is absurdly small
// for the shape); counts stay far inside int.
constexpr double kMaxCurveSegments = 1e8;

// Throws InputError naming `what` when a goal is not a positive finite number of
// segments under kMaxCurveSegments.
inline void check_goal(double goal, const std::string& what) {
  if (!(goal > 0) || !(goal <= kMaxCurveSegments)) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", goal);
    throw InputError(what + " would need " + text + " segments, over the limit of 1e8; the size is too small for it");
  }
}

// A side of a three-curve region (a face bounded by three edges, a three-sided patch)
// takes at least this many segments: the templates' minimum for three curves, and a
// triangle of 4 segments would be one quad with a straight angle (scaled Jacobian 0).
constexpr int kThreeCurveSideMinimum = 2;

// Relative cost of count n for a curve with goal g: |n - g| / g.
inline double count_cost(int n, double goal) { return std::abs(n - goal) / goal; }

// The count n >= lowest minimizing the sum of count_cost over `goals` (the first of
// equal costs). The sum is convex and piecewise linear with its kinks at the goals,
// so the best integer is the floor or the ceiling of one of them, or `lowest`.
inline int best_common_count(const std::vector<double>& goals, int lowest) {
  std::vector<int> candidates{lowest};
  for (double g : goals) {
    candidates.push_back(std::max(lowest, static_cast<int>(std::floor(g))));
    candidates.push_back(std::max(lowest, static_cast<int>(std::ceil(g))));
  }
  std::sort(candidates.begin(), candidates.end());
  int best = lowest;
  double best_cost = INFINITY;
  for (int n : candidates) {
    double cost = 0;
    for (double g : goals) cost += count_cost(n, g);
    if (cost < best_cost - 1e-12) { best_cost = cost; best = n; }
  }
  return best;
}

// Disjoint sets of curves (union-find with path halving).
class CurveSets {
 public:
  explicit CurveSets(int count) : parent_(count) {
    for (int i = 0; i < count; ++i) parent_[i] = i;
  }
  int root(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(int a, int b) { parent_[root(a)] = root(b); }

 private:
  std::vector<int> parent_;
};

// Whether two goals are near enough to share one count: opposite sides further
// apart than this are better left to the templates' transitions than distorted.
constexpr double kChainRatio = 1.5;
inline bool near_enough_to_chain(double a, double b) { return std::max(a, b) <= kChainRatio * std::min(a, b); }

// A balance of a ring's rim totals (ring_balance.h) takes a curve's count under
// 1 / kStrayRatio of its goal (and a segment or more under it) only when no other
// step closes the gap. Cost per step (count_cost) is the same all the way down, so
// one long edge would otherwise give up nearly all its segments to make up for the
// short edges of the rim beside it (each at least one segment), and the face on its
// other side would be meshed along it in one stretched segment. Raising a count only
// refines the faces along the curve, and is not held back.
constexpr double kStrayRatio = 2.0;

// Whether changing a curve's count from `from` to `to` lowers it that far (above).
inline bool strays_from_goal(int from, int to, double goal) {
  return to < from && goal - to >= 1.0 && kStrayRatio * to < goal;
}

}  // namespace tquad
