#include "core/decomposition/cut_intervals.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "core/templates/count_fitting.h"
#include "core/input_error.h"
#include "core/decomposition/parity_pairing.h"

namespace tquad {

namespace {

struct CutProblem {
  const PlanarDomain& domain;
  const FaceDecomposition& d;
  int cuts, patches;
  std::vector<double> goal;
  std::vector<int> minimum;
  std::vector<std::vector<int>> patches_of_cut;  // a cut's patches, with repeats

  CutProblem(const PlanarDomain& domain, const FaceDecomposition& d, double size,
             const std::vector<int>& turn_minimums)
      : domain(domain), d(d), cuts(static_cast<int>(d.cuts.size())), patches(static_cast<int>(d.patches.size())),
        goal(cuts), minimum(cuts, 1), patches_of_cut(cuts) {
    for (int p = 0; p < patches; ++p) {
      for (const PatchSide& side : d.patches[p].sides) if (side.is_cut) patches_of_cut[side.index].push_back(p);
    }
    // A cut of a three-sided patch: kThreeCurveSideMinimum.
    for (int c = 0; c < cuts; ++c) {
      for (int p : patches_of_cut[c]) if (d.patches[p].sides.size() == 3) minimum[c] = kThreeCurveSideMinimum;
      if (c < static_cast<int>(turn_minimums.size())) minimum[c] = std::max(minimum[c], turn_minimums[c]);
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

// Makes every patch even by changing the groups of cuts (parity_pairing.h). False
// when some odd patch cannot be reached.
bool make_patches_even(const CutProblem& pr, const std::vector<std::vector<int>>& groups, std::vector<int>& count) {
  std::vector<ParityUnit> units;
  for (const std::vector<int>& group : groups) {
    ParityUnit u{group, {}};
    std::map<int, int> held;
    for (int c : group) for (int p : pr.patches_of_cut[c]) ++held[p];
    for (const auto& [p, n] : held) if (n % 2 != 0) u.flipped.push_back(p);
    units.push_back(std::move(u));
  }
  std::vector<char> odd(pr.patches);
  for (int p = 0; p < pr.patches; ++p) odd[p] = pr.patch_total(p, count) % 2 != 0;
  return make_nodes_even(odd, units, pr.goal, pr.minimum, count) < 0;
}

}  // namespace

std::vector<int> assign_cut_intervals(const PlanarDomain& domain, const FaceDecomposition& d, double size,
                                      const std::vector<int>& turn_minimums) {
  if (domain.point_count() % 2 != 0) {
    throw InputError("the boundary has " + std::to_string(domain.point_count()) +
                     " segments, an odd number; a quad mesh needs an even total");
  }
  const CutProblem pr(domain, d, size, turn_minimums);
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
