#include "occ/interval_assignment.h"

#include <BRepTools.hxx>
#include <TopoDS_Wire.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <deque>
#include <map>

#include "core/count_fitting.h"
#include "core/input_error.h"
#include "occ/band_balance.h"

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

// A set of edges changed together by one (+1 or -1 on each): a chain of opposite
// edges, or a single edge. It flips the parity of the meshed faces that hold an odd
// number of its edges (a face holding two edges of a chain, or a seam twice, keeps
// its parity).
struct ChangeUnit {
  std::vector<int> edges;
  std::vector<int> flipped_faces;
};

ChangeUnit make_unit(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<int> edges) {
  ChangeUnit unit{std::move(edges), {}};
  std::map<int, int> held;
  for (int e : unit.edges) {
    for (int f : index.faces_of_edge(e)) {
      if (!meshed[f]) continue;
      for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) {
        if (index.edge_index(it.Current()) == e) ++held[f];
      }
    }
  }
  for (const auto& [f, count] : held) if (count % 2 != 0) unit.flipped_faces.push_back(f);
  return unit;
}

// Changes a unit by +1 or -1, whichever stays nearer the goals (relative change),
// never below an edge's minimum.
struct Changer {
  const std::vector<double>& lengths;
  double size;
  std::vector<int>& segments;
  const std::vector<int>& minimum;
  std::vector<IntervalChange> changes;
  void change(const ChangeUnit& unit) {
    bool can_lower = true;
    double up = 0, down = 0;
    for (int e : unit.edges) {
      const int n = segments[e];
      const double ideal = std::max(lengths[e] / size, 1e-9);
      can_lower = can_lower && n - 1 >= std::max(1, minimum.empty() ? 1 : minimum[e]);
      up += count_cost(n + 1, ideal) - count_cost(n, ideal);
      down += count_cost(n - 1, ideal) - count_cost(n, ideal);
    }
    const int step = can_lower && down < up ? -1 : 1;
    for (int e : unit.edges) {
      changes.push_back({e, segments[e], segments[e] + step});
      segments[e] += step;
    }
  }
};

}  // namespace

std::vector<IntervalChange> make_faces_even(const ShapeIndex& index, const std::vector<char>& meshed,
                                            const std::vector<double>& lengths, double size,
                                            std::vector<int>& segments, const std::vector<int>& minimum,
                                            const std::vector<std::vector<int>>& chains) {
  const int faces = index.face_count();
  // Units: the chains, and every other edge of a meshed face on its own.
  std::vector<char> chained(index.edge_count(), 0);
  std::vector<ChangeUnit> units;
  for (const std::vector<int>& chain : chains) {
    for (int e : chain) chained[e] = 1;
    units.push_back(make_unit(index, meshed, chain));
  }
  for (int e = 0; e < index.edge_count(); ++e) {
    if (chained[e] || segments[e] <= 0 || BRep_Tool::Degenerated(index.edge(e))) continue;
    units.push_back(make_unit(index, meshed, {e}));
  }
  // Face adjacency through units that flip exactly two faces; units that flip one.
  std::vector<std::vector<std::pair<int, int>>> neighbours(faces);  // (face, unit)
  std::vector<std::vector<int>> own_units(faces);
  for (int u = 0; u < static_cast<int>(units.size()); ++u) {
    const std::vector<int>& flips = units[u].flipped_faces;
    if (flips.size() == 2) {
      neighbours[flips[0]].push_back({flips[1], u});
      neighbours[flips[1]].push_back({flips[0], u});
    } else if (flips.size() == 1) {
      own_units[flips[0]].push_back(u);
    }
  }

  Changer changer{lengths, size, segments, minimum, {}};
  std::vector<char> odd(faces, 0);
  for (int f = 0; f < faces; ++f) odd[f] = meshed[f] && face_boundary_total(index, f, segments) % 2 != 0;

  for (int start = 0; start < faces; ++start) {
    if (!odd[start]) continue;
    // Breadth-first search for the nearest other odd face.
    std::vector<std::pair<int, int>> came_from(faces, {-1, -1});  // (previous face, unit)
    std::vector<char> seen(faces, 0);
    std::deque<int> queue{start};
    seen[start] = 1;
    int found = -1;
    while (!queue.empty() && found < 0) {
      const int f = queue.front();
      queue.pop_front();
      for (const auto& [g, u] : neighbours[f]) {
        if (seen[g]) continue;
        seen[g] = 1;
        came_from[g] = {f, u};
        if (odd[g]) { found = g; break; }
        queue.push_back(g);
      }
    }
    if (found >= 0) {
      for (int f = found; f != start; f = came_from[f].first) changer.change(units[came_from[f].second]);
      odd[start] = odd[found] = 0;
    } else if (!own_units[start].empty()) {
      // The longest free unit changes least, relatively.
      auto length_of = [&](int u) {
        double sum = 0;
        for (int e : units[u].edges) sum += lengths[e];
        return sum;
      };
      int best = own_units[start][0];
      for (int u : own_units[start]) if (length_of(u) > length_of(best)) best = u;
      changer.change(units[best]);
      odd[start] = 0;
    } else {
      throw InputError("face " + std::to_string(start) +
                       " has an odd number of boundary segments and no edge whose count can "
                       "change without making another face odd");
    }
  }
  return changer.changes;
}

std::vector<IntervalChange> assign_even_intervals(const ShapeIndex& index, const std::vector<char>& meshed,
                                                  const std::vector<double>& lengths, double size,
                                                  std::vector<int>& segments, const std::vector<int>& minimum) {
  return make_faces_even(index, meshed, lengths, size, segments, minimum, {});
}

namespace {

// Faces bounded by exactly four edges (one wire, no pole): their opposite edges.
void opposite_edge_pairs(const ShapeIndex& index, int face, std::vector<std::pair<int, int>>& pairs) {
  const TopoDS_Face& f = index.face(face);
  int wires = 0;
  for (TopExp_Explorer w(f, TopAbs_WIRE); w.More(); w.Next()) ++wires;
  if (wires != 1) return;
  std::vector<int> edges;
  for (BRepTools_WireExplorer it(BRepTools::OuterWire(f), f); it.More(); it.Next()) {
    if (BRep_Tool::Degenerated(it.Current())) return;  // a pole
    edges.push_back(index.edge_index(it.Current()));
  }
  if (edges.size() != 4) return;
  for (int k = 0; k < 2; ++k) if (edges[k] != edges[k + 2]) pairs.push_back({edges[k], edges[k + 2]});
}

}  // namespace

IntervalReport assign_shape_intervals(const ShapeIndex& index, const std::vector<char>& meshed,
                                      const std::vector<double>& lengths, double size, std::vector<int>& segments,
                                      const std::vector<int>& floor) {
  const int edges = index.edge_count();
  const std::vector<int> before = segments;
  auto lowest = [&](int e) { return std::max(1, floor.empty() ? 1 : floor[e]); };
  auto goal = [&](int e) { return std::max(lengths[e] / size, static_cast<double>(lowest(e))); };
  // Chains: opposite edges of four-edge faces, joined when their goals are near
  // enough (count_fitting.h).
  CurveSets sets(edges);
  for (int e = 0; e < edges; ++e) if (segments[e] > 0) check_goal(goal(e), "edge " + std::to_string(e));
  std::vector<std::pair<int, int>> pairs;
  for (int f = 0; f < index.face_count(); ++f) if (meshed[f]) opposite_edge_pairs(index, f, pairs);
  for (const auto& [a, b] : pairs) {
    if (segments[a] <= 0 || segments[b] <= 0) continue;
    if (near_enough_to_chain(goal(a), goal(b))) sets.join(a, b);
  }
  std::vector<std::vector<int>> members(edges);
  for (int e = 0; e < edges; ++e) if (segments[e] > 0) members[sets.root(e)].push_back(e);
  IntervalReport report;
  std::vector<std::vector<int>> chains;
  for (const std::vector<int>& chain : members) {
    if (chain.size() < 2) continue;
    chains.push_back(chain);
    ++report.chains;
    report.chained_edges += static_cast<int>(chain.size());
    std::vector<double> goals;
    int low = 1;
    for (int e : chain) { goals.push_back(goal(e)); low = std::max(low, lowest(e)); }
    const int n = best_common_count(goals, low);
    for (int e : chain) segments[e] = n;
  }
  // Bands one segment wide need equal long sides (band_balance.h).
  report.balanced_bands = balance_one_quad_bands(index, meshed, segments, chains);
  // Faces left odd are made even by changing whole chains (which keeps their faces
  // mapped) or single edges.
  make_faces_even(index, meshed, lengths, size, segments, floor, chains);
  for (int e = 0; e < edges; ++e) {
    if (segments[e] != before[e]) report.changes.push_back({e, before[e], segments[e]});
  }
  return report;
}

}  // namespace tquad
