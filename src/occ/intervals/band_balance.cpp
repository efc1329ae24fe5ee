#include "occ/intervals/band_balance.h"

#include <TopExp_Explorer.hxx>

#include <algorithm>

#include "occ/intervals/edge_discretization.h"
#include "occ/face/face_boundary.h"
#include "occ/face/face_corners.h"

namespace tquad {

namespace {

// The shape edges along one side of a face, and its segment count.
struct Side {
  std::vector<int> edges;
  int segments = 0;
};

// The longest edge of a side that is in no chain; -1 when all are.
int longest_free_edge(const Side& side, const std::vector<int>& chain_of, const std::vector<int>& segments) {
  int chosen = -1;
  for (int e : side.edges) {
    if (chain_of[e] < 0 && (chosen < 0 || segments[e] > segments[chosen])) chosen = e;
  }
  return chosen;
}

// Passes over the bands: the second balances again what a later band unbalanced.
constexpr int kBalancePasses = 3;

}  // namespace

int balance_narrow_bands(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<int>& segments,
                           const std::vector<std::vector<int>>& chains, EdgeSpacings* kept,
                           std::vector<std::pair<int, int>>* paired) {
  std::vector<char> in_pair(index.edge_count(), 0);
  std::vector<int> chain_of(index.edge_count(), -1);
  for (std::size_t c = 0; c < chains.size(); ++c) for (int e : chains[c]) chain_of[e] = static_cast<int>(c);
  // Only a face with two or more one-segment edges can be such a band; its corners
  // are chosen on a provisional discretization of its edges' counts as they are.
  std::vector<int> candidates;
  std::vector<int> provisional(index.edge_count(), 0);
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f]) continue;
    int single = 0;
    for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) {
      single += segments[index.edge_index(it.Current())] <= kNarrowBand ? 1 : 0;
    }
    if (single < 2) continue;
    candidates.push_back(f);
    for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) {
      const int e = index.edge_index(it.Current());
      provisional[e] = segments[e];
    }
  }
  std::vector<Vec3> nodes;
  const std::vector<EdgeNodes> edges = discretize_edges(index, provisional, nodes, kept);
  int balanced = 0;
  std::vector<std::pair<int, std::vector<Side>>> bands;  // face, its four sides
  for (int f : candidates) {
    FaceBoundary b;
    std::vector<int> corners;
    try {
      b = face_boundary(index, f, edges, nodes);
      if (b.inner_wires > 0) continue;
      if (std::find(b.is_seam.begin(), b.is_seam.end(), 1) != b.is_seam.end()) continue;
      corners = choose_face_corners(b, f, {}, false);
    } catch (...) {
      continue;  // the face's own meshing will say what is wrong (a missing pcurve, ...)
    }
    if (corners.size() != 4) continue;
    // Sides between corners, each a run of whole wire edges.
    std::vector<Side> sides(4);
    bool whole_edges = true;
    const int n = static_cast<int>(b.nodes.size());
    for (int k = 0; k < 4 && whole_edges; ++k) {
      const int first = corners[k], last = corners[(k + 1) % 4];
      whole_edges = std::find(b.edge_start.begin(), b.edge_start.end(), first) != b.edge_start.end();
      sides[k].segments = ((last - first) % n + n) % n;
      for (std::size_t j = 0; j < b.edge_start.size(); ++j) {
        if (((b.edge_start[j] - first) % n + n) % n < sides[k].segments) sides[k].edges.push_back(b.edge_index[j]);
      }
    }
    if (!whole_edges) continue;
    bands.push_back({f, std::move(sides)});
  }
  // Each band's sides counted as the segments stand now, not as they were discretized
  // above: a band sharing an edge with one balanced before it sees that edge's new
  // count (taken from the discretization, a second band raised a shared edge by its
  // whole first difference and left the first band with 15 segments against 9, a
  // transition one quad across). A band a later one unbalanced is balanced again in
  // the next pass; counts only grow, and kBalancePasses bounds the passes.
  const auto live = [&](const Side& side) {
    int count = 0;
    for (int e : side.edges) count += segments[e];
    return count;
  };
  for (int pass = 0; pass < kBalancePasses; ++pass) {
    bool changed = false;
    for (auto& [f, sides] : bands) {
      for (Side& side : sides) side.segments = live(side);
      for (int k = 0; k < 2; ++k) {
        if (sides[k + 1].segments > kNarrowBand || sides[(k + 3) % 4].segments > kNarrowBand) continue;
        const Side& a = sides[k];
        const Side& c = sides[k + 2];
        const bool unequal = a.segments != c.segments;
        if (unequal) {
          const Side& shorter = a.segments < c.segments ? a : c;
          // The longest edge of the shorter side takes the difference: a free edge
          // alone, or else a chained edge with its whole chain (whose faces stay mapped).
          int chosen = longest_free_edge(shorter, chain_of, segments);
          if (chosen < 0) {
            for (int e : shorter.edges) if (chosen < 0 || segments[e] > segments[chosen]) chosen = e;
          }
          if (chosen < 0) continue;
          const int difference = std::abs(a.segments - c.segments);
          if (chain_of[chosen] < 0) segments[chosen] += difference;
          else for (int e : chains[chain_of[chosen]]) segments[e] += difference;
          ++balanced;
          changed = true;
        }
        // Ends of different counts (1 and 2) leave the band odd, and the parity fix
        // would change some edge of it: the shorter end's longest free edge takes the
        // difference, and the band is even and mapped.
        const Side& end1 = sides[k + 1];
        const Side& end2 = sides[(k + 3) % 4];
        if (end1.segments != end2.segments) {
          const int e = longest_free_edge(end1.segments < end2.segments ? end1 : end2, chain_of, segments);
          if (e >= 0) {
            segments[e] += std::abs(end1.segments - end2.segments);
            changed = true;
          }
        }
        const int ea = longest_free_edge(a, chain_of, segments), ec = longest_free_edge(c, chain_of, segments);
        if (paired && ea >= 0 && ec >= 0 && ea != ec && !in_pair[ea] && !in_pair[ec]) {
          paired->push_back({ea, ec});
          in_pair[ea] = in_pair[ec] = 1;
        }
        if (unequal) break;
      }
    }
    if (!changed) break;
  }
  return balanced;
}

}  // namespace tquad
