#include "core/templates/region_regrouping.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>

namespace tquad {

namespace {

std::vector<int> own_offsets(const CurveCounts& counts) {
  std::vector<int> offsets{0};
  for (std::size_t i = 0; i + 1 < counts.size(); ++i) offsets.push_back(offsets.back() + counts[i]);
  return offsets;
}

bool two_curves_fit_t5(int a, int b) { return a >= 4 && b >= 4; }

// Splits curve k of a three-curve region in two (x, y) so that the pairs (x, n[k+1])
// and (y, n[k+2]) become as equal as possible; ties go to the most even split.
std::vector<int> split_longest_of_three(const CurveCounts& n) {
  const int k = static_cast<int>(std::max_element(n.begin(), n.end()) - n.begin());
  const int total = n[k], next = n[(k + 1) % 3], after = n[(k + 2) % 3];
  int best_x = total / 2, best_cost = -1;
  for (int x = 1; x < total; ++x) {
    const int cost = 4 * (std::abs(x - next) + std::abs(total - x - after)) + std::abs(2 * x - total);
    if (best_cost < 0 || cost < best_cost) { best_cost = cost; best_x = x; }
  }
  std::vector<int> offsets = own_offsets(n);
  offsets.push_back(offsets[k] + best_x);
  std::sort(offsets.begin(), offsets.end());
  return offsets;
}

std::vector<int> regroup_three(const CurveCounts& n) {
  const int one = static_cast<int>(std::find(n.begin(), n.end(), 1) - n.begin());
  const int prev = (one + 2) % 3, next = (one + 1) % 3;
  const std::vector<int> offsets = own_offsets(n);
  // Merging with the next curve drops the corner between them (corner one + 1);
  // merging with the previous drops corner `one`.
  const int merged_next = n[one] + n[next], merged_prev = n[one] + n[prev];
  const bool fit_next = two_curves_fit_t5(merged_next, n[prev]);
  const bool fit_prev = two_curves_fit_t5(merged_prev, n[next]);
  if (fit_next || fit_prev) {
    const bool use_next = fit_next && (!fit_prev || std::abs(merged_next - n[prev]) <=
                                                        std::abs(merged_prev - n[next]));
    const int dropped = use_next ? (one + 1) % 3 : one;
    std::vector<int> kept;
    for (int i = 0; i < 3; ++i) if (i != dropped) kept.push_back(offsets[i]);
    return kept;
  }
  return split_longest_of_three(n);
}

std::vector<int> regroup_two(const CurveCounts& n) {
  if (n[0] == 1 || n[1] == 1) {
    // The one-edge curve faces the middle piece of the other, split (x, 1, x).
    const int single = n[0] == 1 ? 0 : 1;
    const int other = n[1 - single];  // odd, since the total is even
    const int start = single == 0 ? 1 : 0;                // offset where `other` starts
    const int x = (other - 1) / 2;
    std::vector<int> offsets{0, start == 0 ? x : 1 + x, start == 0 ? x + 1 : 1 + x + 1};
    if (start == 0) offsets.push_back(other);
    else offsets.insert(offsets.begin() + 1, 1);
    return offsets;
  }
  return {0, n[0] / 2, n[0], n[0] + n[1] / 2};
}

}  // namespace

std::vector<int> regroup_curves(const CurveCounts& counts) {
  const int minimum = *std::min_element(counts.begin(), counts.end());
  if (counts.size() == 3 && minimum < 2) return regroup_three(counts);
  if (counts.size() == 2 && minimum < 4) return regroup_two(counts);
  return own_offsets(counts);
}

CurveCounts counts_from_offsets(const std::vector<int>& offsets, int total_edges) {
  CurveCounts counts;
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const int next = i + 1 < offsets.size() ? offsets[i + 1] : total_edges + offsets[0];
    counts.push_back(next - offsets[i]);
  }
  return counts;
}

}  // namespace tquad
