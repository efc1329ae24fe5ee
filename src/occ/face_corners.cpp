#include "occ/face_corners.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/input_error.h"

namespace tquad {

namespace {

constexpr double kCornerTurn = 20.0 * M_PI / 180.0;

std::vector<int> requested_corners(const FaceBoundary& b, int face, const std::vector<int>& requested) {
  if (requested.size() < 2 || requested.size() > 4) {
    throw InputError("--corners for face " + std::to_string(face) + " lists " +
                     std::to_string(requested.size()) + " vertices; give 2, 3 or 4");
  }
  std::vector<int> corners;
  for (int vertex : requested) {
    const auto it = std::find(b.start_vertex.begin(), b.start_vertex.end(), vertex);
    if (it == b.start_vertex.end()) {
      throw InputError("--corners: vertex " + std::to_string(vertex) + " is not on the outer wire of face " +
                       std::to_string(face));
    }
    corners.push_back(b.edge_start[it - b.start_vertex.begin()]);
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}

// Length of the loop from position a forward to position c.
double loop_length(const FaceBoundary& b, int a, int c) {
  const double total = b.arc_length.back();
  const double d = b.arc_length[c] - b.arc_length[a];
  return d >= 0 ? d : d + total;
}

// Among more than four convex vertices (wire edge indices), the four that make the
// best logical rectangle: each turning close to 90 degrees, and opposite curves of
// similar length. An L-shaped profile becomes a bent strip this way (its outer and
// inner paths opposite), not a square with a notch in one side. At most the 12
// sharpest vertices are tried (495 sets).
std::vector<int> best_four(const FaceBoundary& b, std::vector<int> candidates) {
  if (candidates.size() > 12) candidates.resize(12);
  std::sort(candidates.begin(), candidates.end());
  const int n = static_cast<int>(candidates.size());
  double best_score = INFINITY;
  std::vector<int> best;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k)
        for (int l = k + 1; l < n; ++l) {
          const int set[4] = {candidates[i], candidates[j], candidates[k], candidates[l]};
          double score = 0, lengths[4];
          for (int c = 0; c < 4; ++c) {
            score += std::abs(b.turn[set[c]] - M_PI / 2) / (M_PI / 2);
            lengths[c] = loop_length(b, b.edge_start[set[c]], b.edge_start[set[(c + 1) % 4]]);
          }
          for (int c = 0; c < 2; ++c) {
            score += std::abs(lengths[c] - lengths[c + 2]) / (lengths[c] + lengths[c + 2]);
          }
          if (score < best_score) { best_score = score; best.assign(set, set + 4); }
        }
  return best;
}

}  // namespace

std::vector<int> choose_face_corners(const FaceBoundary& b, int face, const std::vector<int>& requested) {
  if (!requested.empty()) return requested_corners(b, face, requested);
  const int loop = static_cast<int>(b.nodes.size());
  const int edges = static_cast<int>(b.edge_start.size());
  if (edges == 1) return {0, loop / 2};

  std::vector<int> order(edges);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int c) { return b.turn[a] > b.turn[c]; });
  std::vector<int> chosen;
  for (int k : order) {
    if (b.turn[k] >= kCornerTurn) chosen.push_back(k);
  }
  if (chosen.size() > 4) chosen = best_four(b, chosen);
  if (chosen.size() < 2) {
    if (edges <= 4) {
      chosen.resize(edges);
      std::iota(chosen.begin(), chosen.end(), 0);
    } else {
      chosen.assign(order.begin(), order.begin() + 4);
    }
  }
  std::vector<int> corners;
  for (int k : chosen) corners.push_back(b.edge_start[k]);
  std::sort(corners.begin(), corners.end());
  return corners;
}

}  // namespace tquad
