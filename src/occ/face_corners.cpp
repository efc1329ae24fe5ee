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
    if (b.turn[k] >= kCornerTurn && chosen.size() < 4) chosen.push_back(k);
  }
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
