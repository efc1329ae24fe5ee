#include "occ/interval_assignment.h"

#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <deque>

#include "core/input_error.h"

namespace tquad {

int face_boundary_total(const ShapeIndex& index, int face, const std::vector<int>& segments) {
  int total = 0;
  // The explorer meets a seam edge twice, once per orientation, as the face's
  // boundary loop does.
  for (TopExp_Explorer it(index.face(face), TopAbs_EDGE); it.More(); it.Next()) {
    total += segments[index.edge_index(it.Current())];
  }
  return total;
}

namespace {

bool is_seam_of(const ShapeIndex& index, int edge, int face) {
  return BRep_Tool::IsClosed(index.edge(edge), index.face(face));
}

// Edges usable to flip parities: not degenerate, not a seam, on at least one meshed face.
bool can_change(const ShapeIndex& index, const std::vector<char>& meshed, int edge) {
  if (BRep_Tool::Degenerated(index.edge(edge))) return false;
  bool on_meshed = false;
  for (int f : index.faces_of_edge(edge)) {
    if (!meshed[f]) continue;
    if (is_seam_of(index, edge, f)) return false;
    on_meshed = true;
  }
  return on_meshed;
}

struct Changer {
  const std::vector<double>& lengths;
  double size;
  std::vector<int>& segments;
  std::vector<IntervalChange> changes;
  void change(int edge) {
    const int n = segments[edge];
    const double ideal = lengths[edge] / size;
    const int to = (n >= 2 && std::abs(n - 1 - ideal) < std::abs(n + 1 - ideal)) ? n - 1 : n + 1;
    changes.push_back({edge, n, to});
    segments[edge] = to;
  }
};

}  // namespace

std::vector<IntervalChange> assign_even_intervals(const ShapeIndex& index,
                                                  const std::vector<char>& meshed,
                                                  const std::vector<double>& lengths, double size,
                                                  std::vector<int>& segments) {
  const int faces = index.face_count();
  // Face adjacency through changeable edges shared by two meshed faces.
  std::vector<std::vector<std::pair<int, int>>> neighbours(faces);  // (face, edge)
  std::vector<std::vector<int>> own_edges(faces);  // changeable edges on no other meshed face
  for (int e = 0; e < index.edge_count(); ++e) {
    if (!can_change(index, meshed, e)) continue;
    std::vector<int> on;
    for (int f : index.faces_of_edge(e)) if (meshed[f]) on.push_back(f);
    if (on.size() == 2) {
      neighbours[on[0]].push_back({on[1], e});
      neighbours[on[1]].push_back({on[0], e});
    } else if (on.size() == 1) {
      own_edges[on[0]].push_back(e);
    }
  }

  Changer changer{lengths, size, segments, {}};
  std::vector<char> odd(faces, 0);
  for (int f = 0; f < faces; ++f) odd[f] = meshed[f] && face_boundary_total(index, f, segments) % 2 != 0;

  for (int start = 0; start < faces; ++start) {
    if (!odd[start]) continue;
    // Breadth-first search for the nearest other odd face.
    std::vector<std::pair<int, int>> came_from(faces, {-1, -1});  // (previous face, edge)
    std::vector<char> seen(faces, 0);
    std::deque<int> queue{start};
    seen[start] = 1;
    int found = -1;
    while (!queue.empty() && found < 0) {
      const int f = queue.front();
      queue.pop_front();
      for (const auto& [g, e] : neighbours[f]) {
        if (seen[g]) continue;
        seen[g] = 1;
        came_from[g] = {f, e};
        if (odd[g]) { found = g; break; }
        queue.push_back(g);
      }
    }
    if (found >= 0) {
      for (int f = found; f != start; f = came_from[f].first) changer.change(came_from[f].second);
      odd[start] = odd[found] = 0;
    } else if (!own_edges[start].empty()) {
      // The longest free edge changes least, relatively.
      int best = own_edges[start][0];
      for (int e : own_edges[start]) if (lengths[e] > lengths[best]) best = e;
      changer.change(best);
      odd[start] = 0;
    } else {
      throw InputError("face " + std::to_string(start) +
                       " has an odd number of boundary segments and no edge whose count can "
                       "change without making another face odd");
    }
  }
  return changer.changes;
}

}  // namespace tquad
