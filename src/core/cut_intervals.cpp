#include "core/cut_intervals.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <stdexcept>
#include <string>

#include "core/count_fitting.h"
#include "core/input_error.h"

namespace tquad {

namespace {

struct CutProblem {
  const PlanarDomain& domain;
  const FaceDecomposition& d;
  int cuts, patches;
  std::vector<double> goal;
  std::vector<int> minimum;
  std::vector<std::vector<int>> patches_of_cut;  // a cut's patches, with repeats

  CutProblem(const PlanarDomain& domain, const FaceDecomposition& d, double size)
      : domain(domain), d(d), cuts(static_cast<int>(d.cuts.size())), patches(static_cast<int>(d.patches.size())),
        goal(cuts), minimum(cuts, 1), patches_of_cut(cuts) {
    for (int p = 0; p < patches; ++p) {
      for (const PatchSide& side : d.patches[p].sides) if (side.is_cut) patches_of_cut[side.index].push_back(p);
    }
    // A cut of a three-sided patch takes at least 2 edges: the templates' minimum
    // for three curves (a triangle of 4 edges would be one quad with a straight angle).
    for (int c = 0; c < cuts; ++c) {
      for (int p : patches_of_cut[c]) if (d.patches[p].sides.size() == 3) minimum[c] = 2;
      goal[c] = std::max(d.cuts[c].length / size, static_cast<double>(minimum[c]));
      check_goal(goal[c], "cut " + std::to_string(c));
    }
  }

  int side_count(const PatchSide& side, const std::vector<int>& count) const {
    return side.is_cut ? count[side.index] : piece_segments(domain, d.pieces[side.index]);
  }
  int patch_total(int p, const std::vector<int>& count) const {
    int total = 0;
    for (const PatchSide& side : d.patches[p].sides) total += side_count(side, count);
    return total;
  }
};

// Chains of cuts that should be equal: opposite cuts of a four-sided patch. A chain
// that also faces a boundary piece takes that piece's count when it can (so the patch
// is a mapped grid); otherwise the count fitting all its goals best.
std::vector<std::vector<int>> equal_count_chains(const CutProblem& pr, std::vector<int>& count) {
  CurveSets sets(pr.cuts);
  std::vector<std::vector<int>> facing(pr.cuts);  // piece counts opposite each cut
  for (const DomainPatch& patch : pr.d.patches) {
    if (patch.sides.size() != 4) continue;
    for (int k = 0; k < 2; ++k) {
      const PatchSide &a = patch.sides[k], &b = patch.sides[k + 2];
      if (a.is_cut && b.is_cut) {
        if (near_enough_to_chain(pr.goal[a.index], pr.goal[b.index])) sets.join(a.index, b.index);
      } else if (a.is_cut != b.is_cut) {
        const PatchSide& cut = a.is_cut ? a : b;
        const PatchSide& piece = a.is_cut ? b : a;
        facing[cut.index].push_back(piece_segments(pr.domain, pr.d.pieces[piece.index]));
      }
    }
  }
  std::map<int, std::vector<int>> members;
  for (int c = 0; c < pr.cuts; ++c) members[sets.root(c)].push_back(c);
  std::vector<std::vector<int>> chains;
  for (auto& [root, chain] : members) {
    (void)root;
    int lowest = 1;
    std::vector<double> goals;
    std::vector<int> fixed;  // counts of facing pieces near enough to take
    for (int c : chain) {
      lowest = std::max(lowest, pr.minimum[c]);
      goals.push_back(pr.goal[c]);
      for (int n : facing[c]) if (near_enough_to_chain(n, pr.goal[c])) fixed.push_back(n);
    }
    // A facing piece's count makes its patch a mapped grid: when there are such
    // counts, the one nearest the goals that matches most of them; else the best fit.
    int best = fixed.empty() ? best_common_count(goals, lowest) : lowest;
    double best_cost = INFINITY;
    for (int n : fixed) {
      const int m = std::max(n, lowest);
      double cost = 0;
      for (double g : goals) cost += count_cost(m, g);
      for (int f : fixed) cost += f == m ? 0.0 : 1.0;
      if (cost < best_cost - 1e-12) { best_cost = cost; best = m; }
    }
    for (int c : chain) count[c] = best;
    chains.push_back(chain);
  }
  return chains;
}

// A set of cuts changed together by one; it flips the parity of the patches holding
// an odd number of them.
struct Unit {
  std::vector<int> cuts;
  std::vector<int> flipped;
};

// Makes every patch even by changing units (+1 or -1, nearer the goals, never below
// a minimum) along shortest paths between odd patches. False when some odd patch has
// no path (the caller then retries with single cuts).
bool make_patches_even(const CutProblem& pr, const std::vector<std::vector<int>>& groups, std::vector<int>& count) {
  std::vector<Unit> units;
  for (const std::vector<int>& group : groups) {
    Unit u{group, {}};
    std::map<int, int> held;
    for (int c : group) for (int p : pr.patches_of_cut[c]) ++held[p];
    for (const auto& [p, n] : held) if (n % 2 != 0) u.flipped.push_back(p);
    units.push_back(std::move(u));
  }
  std::vector<std::vector<std::pair<int, int>>> neighbours(pr.patches);
  for (int u = 0; u < static_cast<int>(units.size()); ++u) {
    if (units[u].flipped.size() != 2) continue;
    neighbours[units[u].flipped[0]].push_back({units[u].flipped[1], u});
    neighbours[units[u].flipped[1]].push_back({units[u].flipped[0], u});
  }
  auto change = [&](const Unit& unit) {
    bool can_lower = true;
    double up = 0, down = 0;
    for (int c : unit.cuts) {
      can_lower = can_lower && count[c] - 1 >= pr.minimum[c];
      up += count_cost(count[c] + 1, pr.goal[c]) - count_cost(count[c], pr.goal[c]);
      down += count_cost(count[c] - 1, pr.goal[c]) - count_cost(count[c], pr.goal[c]);
    }
    const int step = can_lower && down < up ? -1 : 1;
    for (int c : unit.cuts) count[c] += step;
  };
  std::vector<char> odd(pr.patches);
  for (int p = 0; p < pr.patches; ++p) odd[p] = pr.patch_total(p, count) % 2 != 0;
  for (int start = 0; start < pr.patches; ++start) {
    if (!odd[start]) continue;
    std::vector<std::pair<int, int>> came_from(pr.patches, {-1, -1});
    std::vector<char> seen(pr.patches, 0);
    std::deque<int> queue{start};
    seen[start] = 1;
    int found = -1;
    while (!queue.empty() && found < 0) {
      const int p = queue.front();
      queue.pop_front();
      for (const auto& [q, u] : neighbours[p]) {
        if (seen[q]) continue;
        seen[q] = 1;
        came_from[q] = {p, u};
        if (odd[q]) { found = q; break; }
        queue.push_back(q);
      }
    }
    if (found < 0) return false;
    for (int p = found; p != start; p = came_from[p].first) change(units[came_from[p].second]);
    odd[start] = odd[found] = 0;
  }
  return true;
}

}  // namespace

std::vector<int> assign_cut_intervals(const PlanarDomain& domain, const FaceDecomposition& d, double size) {
  if (domain.point_count() % 2 != 0) {
    throw InputError("the boundary has " + std::to_string(domain.point_count()) +
                     " segments, an odd number; a quad mesh needs an even total");
  }
  const CutProblem pr(domain, d, size);
  std::vector<int> count(pr.cuts);
  const std::vector<std::vector<int>> chains = equal_count_chains(pr, count);
  std::vector<int> chained = count;
  if (!make_patches_even(pr, chains, chained)) {
    // Some odd patch is reached by no chain: single cuts always connect the two
    // patches on their sides, and the patches' totals sum to an even number.
    std::vector<std::vector<int>> singles;
    for (int c = 0; c < pr.cuts; ++c) singles.push_back({c});
    chained = count;
    if (!make_patches_even(pr, singles, chained)) throw std::logic_error("cut counts: a patch stayed odd");
  }
  for (int p = 0; p < pr.patches; ++p) {
    if (pr.patch_total(p, chained) % 2 != 0) throw std::logic_error("patch " + std::to_string(p) + " kept an odd total");
  }
  return chained;
}

}  // namespace tquad
