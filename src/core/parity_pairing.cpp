#include "core/parity_pairing.h"

#include <deque>
#include <utility>

#include "core/count_fitting.h"

namespace tquad {

namespace {

// Changes every curve of the unit by the step (+1 or -1) that keeps the unit nearer
// its goals, never below a minimum.
void change_unit(const ParityUnit& unit, const std::vector<double>& goal, const std::vector<int>& minimum,
                 std::vector<int>& count) {
  bool can_lower = true;
  double up = 0, down = 0;
  for (int c : unit.curves) {
    can_lower = can_lower && count[c] - 1 >= std::max(1, minimum[c]);
    up += count_cost(count[c] + 1, goal[c]) - count_cost(count[c], goal[c]);
    down += count_cost(count[c] - 1, goal[c]) - count_cost(count[c], goal[c]);
  }
  const int step = can_lower && down < up ? -1 : 1;
  for (int c : unit.curves) count[c] += step;
}

}  // namespace

int make_nodes_even(std::vector<char> odd, const std::vector<ParityUnit>& units, const std::vector<double>& goal,
                    const std::vector<int>& minimum, std::vector<int>& count) {
  const int nodes = static_cast<int>(odd.size());
  std::vector<std::vector<std::pair<int, int>>> neighbours(nodes);  // (node, unit)
  std::vector<std::vector<int>> own_units(nodes);
  for (int u = 0; u < static_cast<int>(units.size()); ++u) {
    const std::vector<int>& flips = units[u].flipped;
    if (flips.size() == 2) {
      neighbours[flips[0]].push_back({flips[1], u});
      neighbours[flips[1]].push_back({flips[0], u});
    } else if (flips.size() == 1) {
      own_units[flips[0]].push_back(u);
    }
  }
  const auto summed_goal = [&](int u) {
    double sum = 0;
    for (int c : units[u].curves) sum += goal[c];
    return sum;
  };
  for (int start = 0; start < nodes; ++start) {
    if (!odd[start]) continue;
    // Breadth-first search for the nearest other odd node.
    std::vector<std::pair<int, int>> came_from(nodes, {-1, -1});  // (previous node, unit)
    std::vector<char> seen(nodes, 0);
    std::deque<int> queue{start};
    seen[start] = 1;
    int found = -1;
    while (!queue.empty() && found < 0) {
      const int n = queue.front();
      queue.pop_front();
      for (const auto& [m, u] : neighbours[n]) {
        if (seen[m]) continue;
        seen[m] = 1;
        came_from[m] = {n, u};
        if (odd[m]) { found = m; break; }
        queue.push_back(m);
      }
    }
    if (found >= 0) {
      for (int n = found; n != start; n = came_from[n].first) change_unit(units[came_from[n].second], goal, minimum, count);
      odd[start] = odd[found] = 0;
    } else if (!own_units[start].empty()) {
      int best = own_units[start][0];
      for (int u : own_units[start]) if (summed_goal(u) > summed_goal(best)) best = u;
      change_unit(units[best], goal, minimum, count);
      odd[start] = 0;
    } else {
      return start;
    }
  }
  return -1;
}

}  // namespace tquad
