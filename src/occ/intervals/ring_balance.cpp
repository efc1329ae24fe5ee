#include "occ/intervals/ring_balance.h"

#include <cmath>
#include <cstdlib>

#include "core/templates/count_fitting.h"
#include "occ/intervals/interval_assignment.h"

namespace tquad {

namespace {

// A gap closed in more steps than this is left to the templates.
constexpr int kMaxSteps = 64;

// Steps of equal cost (count_cost is linear away from the goals: every step below
// them costs the same) go to the unit left nearest its goals, by the square of
// count_cost. With the first such unit taking them all, a washer's outer halves got
// unequal counts against inner halves of equal ones, though both outer goals were
// alike, and the mapped ring between them leaned by two segments, with a poor worst
// quad. The square alone, not as a tie-break, moved counts into other faces too and
// lowered their mean quality (a crescent's, for one).
double squared_cost(int n, double goal) {
  const double relative = count_cost(n, goal);
  return relative * relative;
}

int total(const std::vector<int>& edges, const std::vector<int>& segments) {
  int sum = 0;
  for (int e : edges) sum += segments[e];
  return sum;
}

// The two rims of a ring: its two wires, or its one wire's runs on either side of a
// seam (the one edge the wire meets twice: a tube's band cut open along its seam).
// Empty when the face is no ring.
std::vector<std::vector<int>> ring_rims(const WireEdges& wires) {
  if (wires.size() == 2) return wires;
  if (wires.size() != 1) return {};
  const std::vector<int>& wire = wires[0];
  const int n = static_cast<int>(wire.size());
  int first = -1, second = -1;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (wire[i] != wire[j]) continue;
      if (first >= 0) return {};  // two seams: no ring
      first = i;
      second = j;
    }
  }
  if (first < 0) return {};
  std::vector<std::vector<int>> rims(2);
  for (int k = first + 1; k < second; ++k) rims[0].push_back(wire[k]);
  for (int k = second + 1; k < n + first; ++k) rims[1].push_back(wire[k % n]);
  if (rims[0].empty() || rims[1].empty()) return {};
  return rims;
}

}  // namespace

int balance_rings(FaceWireEdges& face_wires, const std::vector<char>& meshed, const std::vector<double>& goal,
                  const std::vector<double>& extent, const std::vector<int>& floor, std::vector<int>& segments,
                  const std::vector<std::vector<int>>& chains) {
  const ShapeIndex& index = face_wires.index();
  // Units: the chains, then each edge not in one.
  std::vector<std::vector<int>> units = chains;
  std::vector<char> chained(index.edge_count(), 0);
  for (const std::vector<int>& chain : chains) for (int e : chain) chained[e] = 1;
  for (int e = 0; e < index.edge_count(); ++e) if (!chained[e] && segments[e] > 0) units.push_back({e});
  std::vector<int> unit_of(index.edge_count(), -1);
  for (std::size_t u = 0; u < units.size(); ++u) for (int e : units[u]) unit_of[e] = static_cast<int>(u);

  int balanced = 0;
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f]) continue;
    const auto& wires = face_wires.of(f);
    if (!wires) continue;
    const std::vector<std::vector<int>> rims = ring_rims(*wires);
    if (rims.empty()) continue;
    const std::vector<int>& a = rims[0];
    const std::vector<int>& b = rims[1];
    double goal_a = 0, goal_b = 0, extent_a = 0, extent_b = 0;
    for (int e : a) { goal_a += goal[e]; extent_a += extent[e]; }
    for (int e : b) { goal_b += goal[e]; extent_b += extent[e]; }
    if (!near_enough_to_chain(goal_a, goal_b) && !near_enough_to_chain(extent_a, extent_b)) continue;
    int gap = total(a, segments) - total(b, segments);
    if (gap == 0) continue;
    for (int step = 0; step < kMaxSteps && gap != 0; ++step) {
      // The unit and direction that shrink |gap| at the least cost.
      int best_unit = -1, best_direction = 0;
      int best_strays = 0;
      double best_cost = INFINITY, best_tie_break = INFINITY;
      std::vector<int> candidates;
      for (int e : a) candidates.push_back(unit_of[e]);
      for (int e : b) candidates.push_back(unit_of[e]);
      for (int u : candidates) {
        if (u < 0) continue;
        int in_a = 0, in_b = 0;
        for (int e : units[u]) {
          for (int x : a) in_a += x == e ? 1 : 0;
          for (int x : b) in_b += x == e ? 1 : 0;
        }
        const int effect = in_a - in_b;  // gap change per +1 on the unit
        if (effect == 0) continue;
        const int direction = (gap > 0) == (effect > 0) ? -1 : 1;
        if (std::abs(gap + direction * effect) >= std::abs(gap)) continue;
        double cost = 0, tie_break = 0;
        int strays = 0;
        bool allowed = true;
        for (int e : units[u]) {
          const int n = segments[e] + direction;
          allowed = allowed && n >= std::max(1, floor[e]);
          strays += strays_from_goal(segments[e], n, goal[e]) ? 1 : 0;
          cost += count_cost(n, goal[e]) - count_cost(segments[e], goal[e]);
          tie_break += squared_cost(n, goal[e]) - squared_cost(segments[e], goal[e]);
        }
        const bool cheaper =
            best_unit < 0 || strays < best_strays ||
            (strays == best_strays &&
             (cost < best_cost - 1e-12 || (cost <= best_cost + 1e-12 && tie_break < best_tie_break - 1e-12)));
        if (allowed && cheaper) {
          best_strays = strays;
          best_cost = cost;
          best_tie_break = tie_break;
          best_unit = u;
          best_direction = direction;
        }
      }
      if (best_unit < 0) break;
      for (int e : units[best_unit]) segments[e] += best_direction;
      gap = total(a, segments) - total(b, segments);
    }
    balanced += gap == 0 ? 1 : 0;
  }
  return balanced;
}

}  // namespace tquad
