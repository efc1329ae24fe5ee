#include "occ/face/face_corners.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/decomposition/corner_search.h"
#include "core/input_error.h"

namespace tquad {

namespace {

constexpr double kCornerTurn = 20.0 * M_PI / 180.0;
// A rounded corner (a fillet's arc) counts as a corner when it turns this much in all.
constexpr double kRoundedCornerTurn = 60.0 * M_PI / 180.0;

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

// A corner candidate: a loop position and how much the boundary turns there.
struct Candidate {
  int position;
  double turn;
};

// Among more than four candidates, the four that make the best logical rectangle:
// each turning close to 90 degrees, and opposite curves of similar length. An
// L-shaped profile becomes a bent strip this way (its outer and inner paths
// opposite), not a square with a notch in one side. At most the 12 sharpest
// candidates are tried (495 sets).
std::vector<Candidate> best_four(const FaceBoundary& b, std::vector<Candidate> candidates) {
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.turn > y.turn; });
  if (candidates.size() > 12) candidates.resize(12);
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& x, const Candidate& y) { return x.position < y.position; });
  const int n = static_cast<int>(candidates.size());
  double best_score = INFINITY;
  std::vector<Candidate> best;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k)
        for (int l = k + 1; l < n; ++l) {
          const Candidate set[4] = {candidates[i], candidates[j], candidates[k], candidates[l]};
          double score = 0, lengths[4];
          for (int c = 0; c < 4; ++c) {
            score += std::abs(set[c].turn - M_PI / 2) / (M_PI / 2);
            lengths[c] = loop_length(b, set[c].position, set[(c + 1) % 4].position);
          }
          for (int c = 0; c < 2; ++c) {
            score += std::abs(lengths[c] - lengths[c + 2]) / (lengths[c] + lengths[c + 2]);
          }
          if (score < best_score) { best_score = score; best.assign(set, set + 4); }
        }
  return best;
}

// Rounded corners: runs of loop nodes where the boundary keeps turning the convex way
// (a fillet's arc between two tangent edges), with their total turning, placed at the
// run's middle node. Turning is measured in the loop's own (u, v) plane, where the
// templates run. Positions already taken are skipped.
std::vector<Candidate> rounded_corners(const FaceBoundary& b, const std::vector<int>& taken) {
  const int n = static_cast<int>(b.uv.size());
  const double orientation = signed_uv_area(b.uv) > 0 ? 1.0 : -1.0;
  std::vector<double> turn(n);
  for (int i = 0; i < n; ++i) {
    const Vec3 a = b.uv[i] - b.uv[(i + n - 1) % n], c = b.uv[(i + 1) % n] - b.uv[i];
    turn[i] = orientation * std::atan2(a.x * c.y - a.y * c.x, a.x * c.x + a.y * c.y);
  }
  constexpr double kBending = 0.5 * M_PI / 180.0;  // a node that turns at least half a degree
  std::vector<Candidate> found;
  // Start after a node that does not bend, so that no run wraps around position 0.
  int start = 0;
  while (start < n && turn[start] > kBending) ++start;
  if (start == n) return found;  // the whole loop bends: a smooth closed curve
  for (int k = 1; k <= n; ++k) {
    const int i = (start + k) % n;
    if (turn[i] <= kBending || std::find(taken.begin(), taken.end(), i) != taken.end()) continue;
    double total = 0;
    std::vector<int> run;
    for (int j = i; turn[j] > kBending && std::find(taken.begin(), taken.end(), j) == taken.end() &&
                    static_cast<int>(run.size()) < n; j = (j + 1) % n) {
      run.push_back(j);
      total += turn[j];
    }
    k += static_cast<int>(run.size()) - 1;
    if (total >= kRoundedCornerTurn) found.push_back({run[run.size() / 2], total});
  }
  return found;
}

}  // namespace

std::vector<int> choose_face_corners(const FaceBoundary& b, int face, const std::vector<int>& requested,
                                     bool with_rounded) {
  if (!requested.empty()) return requested_corners(b, face, requested);
  const int loop = static_cast<int>(b.nodes.size());
  const int edges = static_cast<int>(b.edge_start.size());
  if (edges == 1) return {0, loop / 2};

  std::vector<Candidate> chosen;
  for (int k = 0; k < edges; ++k) {
    if (b.turn[k] >= kCornerTurn) chosen.push_back({b.edge_start[k], b.turn[k]});
  }
  // Fewer than four sharp vertices: fillets' arcs may hold the missing corners.
  if (with_rounded && chosen.size() < 4) {
    std::vector<int> taken;
    for (const Candidate& c : chosen) taken.push_back(c.position);
    for (const Candidate& c : rounded_corners(b, taken)) chosen.push_back(c);
  }
  if (chosen.size() > 4) chosen = best_four(b, chosen);
  if (chosen.size() < 2) {
    chosen.clear();
    if (edges <= 4) {
      for (int k = 0; k < edges; ++k) chosen.push_back({b.edge_start[k], b.turn[k]});
    } else {
      std::vector<int> order(edges);
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return b.turn[x] > b.turn[y]; });
      for (int k = 0; k < 4; ++k) chosen.push_back({b.edge_start[order[k]], b.turn[order[k]]});
    }
  }
  std::vector<int> corners;
  for (const Candidate& c : chosen) corners.push_back(c.position);
  std::sort(corners.begin(), corners.end());
  return corners;
}

std::vector<std::vector<int>> corner_choices(const FaceBoundary& b, int face,
                                             const std::vector<int>& requested) {
  std::vector<std::vector<int>> choices{choose_face_corners(b, face, requested, false)};
  if (requested.empty()) {
    std::vector<int> rounded = choose_face_corners(b, face, requested, true);
    if (rounded != choices[0]) choices.push_back(rounded);
  }
  return choices;
}

std::vector<std::vector<int>> searched_corner_choices(const FaceBoundary& b,
                                                      const std::vector<std::vector<int>>& tried) {
  constexpr double kCandidateTurn = 5.0 * M_PI / 180.0;
  const int edges = static_cast<int>(b.edge_start.size());
  if (edges <= 1) return {};
  std::vector<Candidate> candidates;
  for (int k = 0; k < edges; ++k) {
    if (b.turn[k] >= kCandidateTurn) candidates.push_back({b.edge_start[k], b.turn[k]});
  }
  std::vector<int> taken;
  for (const Candidate& c : candidates) taken.push_back(c.position);
  for (const Candidate& c : rounded_corners(b, taken)) candidates.push_back(c);
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.turn > y.turn; });
  if (candidates.size() > static_cast<std::size_t>(kSearchCandidates)) candidates.resize(kSearchCandidates);
  std::vector<CornerCandidate> ranked;
  for (const Candidate& c : candidates) ranked.push_back({c.position, c.turn});
  return ranked_corner_sets(std::move(ranked), tried, kMaxSearchedSets);
}

}  // namespace tquad
