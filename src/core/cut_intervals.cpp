#include "core/cut_intervals.h"

#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>

#include "core/input_error.h"

namespace tquad {

std::vector<int> assign_cut_intervals(const PlanarDomain& domain, const FaceDecomposition& d, double size) {
  if (domain.point_count() % 2 != 0) {
    throw InputError("the boundary has " + std::to_string(domain.point_count()) +
                     " segments, an odd number; a quad mesh needs an even total");
  }
  const int cuts = static_cast<int>(d.cuts.size()), patches = static_cast<int>(d.patches.size());
  // Patches on each side of each cut, and every patch's boundary total.
  std::vector<std::vector<int>> patches_of_cut(cuts);
  std::vector<int> total(patches, 0);
  for (int p = 0; p < patches; ++p) {
    for (const PatchSide& side : d.patches[p].sides) {
      if (side.is_cut) patches_of_cut[side.index].push_back(p);
      else total[p] += piece_segments(domain, d.pieces[side.index]);
    }
  }
  // A cut of a three-sided patch takes at least 2 edges: the templates' minimum for
  // three curves (a triangle of 4 edges would be one quad with a straight angle).
  std::vector<double> goal(cuts);
  std::vector<int> count(cuts), minimum(cuts, 1);
  for (int c = 0; c < cuts; ++c) {
    for (int p : patches_of_cut[c]) if (d.patches[p].sides.size() == 3) minimum[c] = 2;
    goal[c] = d.cuts[c].length / size;
    count[c] = std::max(minimum[c], static_cast<int>(std::lround(goal[c])));
  }
  for (int c = 0; c < cuts; ++c) for (int p : patches_of_cut[c]) total[p] += count[c];

  // Breadth-first spanning tree from patch 0; parent_cut[p] joins p to its parent.
  std::vector<int> parent_cut(patches, -1), order;
  std::vector<char> seen(patches, 0);
  std::deque<int> queue{0};
  seen[0] = 1;
  while (!queue.empty()) {
    const int p = queue.front();
    queue.pop_front();
    order.push_back(p);
    for (const PatchSide& side : d.patches[p].sides) {
      if (!side.is_cut) continue;
      for (int q : patches_of_cut[side.index]) {
        if (seen[q]) continue;
        seen[q] = 1;
        parent_cut[q] = side.index;
        queue.push_back(q);
      }
    }
  }
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const int p = *it, c = parent_cut[p];
    if (c < 0 || total[p] % 2 == 0) continue;
    const int step = (count[c] > minimum[c] && std::abs(count[c] - 1 - goal[c]) < std::abs(count[c] + 1 - goal[c])) ? -1 : 1;
    count[c] += step;
    for (int q : patches_of_cut[c]) total[q] += step;
  }
  for (int p = 0; p < patches; ++p) {
    if (total[p] % 2 != 0) throw std::logic_error("patch " + std::to_string(p) + " kept an odd total");
  }
  return count;
}

}  // namespace tquad
