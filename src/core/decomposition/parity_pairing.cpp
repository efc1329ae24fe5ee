#include "core/decomposition/parity_pairing.h"

#include <deque>
#include <utility>

#include "core/templates/count_fitting.h"

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
  const auto best_own_unit = [&](int n) {
    int best = own_units[n][0];
    for (int u : own_units[n]) if (summed_goal(u) > summed_goal(best)) best = u;
    return best;
  };
  for (int start = 0; start < nodes; ++start) {
    if (!odd[start]) continue;
    // Breadth-first search for the nearest node `wanted` accepts; its path back.
    std::vector<std::pair<int, int>> came_from(nodes, {-1, -1});  // (previous node, unit)
    const auto nearest = [&](const auto& wanted) {
      std::vector<char> seen(nodes, 0);
      std::deque<int> queue{start};
      seen[start] = 1;
      while (!queue.empty()) {
        const int n = queue.front();
        queue.pop_front();
        for (const auto& [m, u] : neighbours[n]) {
          if (seen[m]) continue;
          seen[m] = 1;
          came_from[m] = {n, u};
          if (wanted(m)) return m;
          queue.push_back(m);
        }
      }
      return -1;
    };
    const auto change_path_to = [&](int end) {
      for (int n = end; n != start; n = came_from[n].first) change_unit(units[came_from[n].second], goal, minimum, count);
    };
    if (const int partner = nearest([&](int m) { return odd[m] != 0; }); partner >= 0) {
      change_path_to(partner);
      odd[partner] = 0;
    } else if (!own_units[start].empty()) {
      change_unit(units[best_own_unit(start)], goal, minimum, count);
    } else if (const int exit = nearest([&](int m) { return !own_units[m].empty(); }); exit >= 0) {
      // No odd partner and no unit of its own: the path to the nearest node with a
      // unit of its own, and that unit (the nodes on the way flip twice). Faces left
      // out of a shape (refused, or not in --faces) give their neighbours such units:
      // a shape meshed without a few of its faces had one odd face among meshed
      // neighbours only, and was refused as impossible to make even.
      change_path_to(exit);
      change_unit(units[best_own_unit(exit)], goal, minimum, count);
    } else {
      return start;
    }
    odd[start] = 0;
  }
  return -1;
}

}  // namespace tquad
