#include "occ/intervals/interval_assignment.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>

#include <cmath>
#include <map>
#include <optional>

#include "core/templates/count_fitting.h"
#include "core/input_error.h"
#include "core/decomposition/parity_pairing.h"
#include "occ/intervals/band_balance.h"
#include "occ/intervals/pole_rims.h"
#include "occ/intervals/band_alignment.h"
#include "occ/intervals/ring_balance.h"

namespace tquad {

int face_boundary_total(const ShapeIndex& index, int face, const std::vector<int>& segments) {
  int total = 0;
  // The explorer meets a seam edge twice, once per orientation, as the face's
  // boundary loop does.
  for (TopExp_Explorer it(index.face(face), TopAbs_EDGE); it.More(); it.Next()) {
    const int e = index.edge_index(it.Current());
    if (!index.contracted(e)) total += segments[e];
  }
  return total;
}

namespace {

// The unit of edges changed together: the faces holding an odd number of them (the
// explorer meets a seam twice, as the face's loop does) are the ones it flips.
ParityUnit edge_unit(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<int> edges) {
  ParityUnit unit{std::move(edges), {}};
  std::map<int, int> held;
  for (int e : unit.curves) {
    for (int f : index.faces_of_edge(e)) {
      if (!meshed[f]) continue;
      for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) {
        if (index.edge_index(it.Current()) == e) ++held[f];
      }
    }
  }
  for (const auto& [f, count] : held) if (count % 2 != 0) unit.flipped.push_back(f);
  return unit;
}

// An edge's goal: its length / size, at least its floor (count_fitting.h).
double edge_goal(const std::vector<double>& lengths, double size, const std::vector<int>& floor, int e) {
  return std::max(lengths[e] / size, static_cast<double>(std::max(1, floor[e])));
}

}  // namespace

std::vector<IntervalChange> make_faces_even(const ShapeIndex& index, const std::vector<char>& meshed,
                                            const std::vector<double>& lengths, double size,
                                            std::vector<int>& segments, const std::vector<int>& minimum,
                                            const std::vector<std::vector<int>>& chains,
                                            const std::vector<std::pair<int, int>>& paired) {
  const int edges = index.edge_count();
  const std::vector<int> before = segments;
  const std::vector<int> floor = minimum.empty() ? std::vector<int>(edges, 1) : minimum;
  // Units: the chains, and every other edge of a meshed face on its own.
  std::vector<char> chained(edges, 0);
  std::vector<ParityUnit> units;
  for (const std::vector<int>& chain : chains) {
    for (int e : chain) chained[e] = 1;
    units.push_back(edge_unit(index, meshed, chain));
  }
  for (const auto& [a, b] : paired) {
    if (chained[a] || chained[b]) continue;
    chained[a] = chained[b] = 1;
    units.push_back(edge_unit(index, meshed, {a, b}));
  }
  for (int e = 0; e < edges; ++e) {
    if (chained[e] || segments[e] <= 0 || BRep_Tool::Degenerated(index.edge(e))) continue;
    units.push_back(edge_unit(index, meshed, {e}));
  }
  std::vector<double> goal(edges, 1.0);
  for (int e = 0; e < edges; ++e) if (segments[e] > 0) goal[e] = edge_goal(lengths, size, floor, e);
  std::vector<char> odd(index.face_count(), 0);
  for (int f = 0; f < index.face_count(); ++f) odd[f] = meshed[f] && face_boundary_total(index, f, segments) % 2 != 0;
  const int stuck = make_nodes_even(odd, units, goal, floor, segments);
  if (stuck >= 0) {
    throw InputError("face " + std::to_string(stuck) +
                     " has an odd number of boundary segments and no edge whose count can "
                     "change without making another face odd");
  }
  std::vector<IntervalChange> changes;
  for (int e = 0; e < edges; ++e) if (segments[e] != before[e]) changes.push_back({e, before[e], segments[e]});
  return changes;
}

std::vector<IntervalChange> assign_even_intervals(const ShapeIndex& index, const std::vector<char>& meshed,
                                                  const std::vector<double>& lengths, double size,
                                                  std::vector<int>& segments, const std::vector<int>& minimum) {
  return make_faces_even(index, meshed, lengths, size, segments, minimum, {});
}

namespace {

// The point halfway along an edge's parameter range.
gp_Pnt edge_middle(const ShapeIndex& index, int e) {
  const BRepAdaptor_Curve curve(index.edge(e));
  return curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter()));
}

// Each edge of wire `a` paired with the edge of wire `b` nearest to it (middle to
// middle), when that is one to one both ways; nothing otherwise.
std::vector<std::pair<int, int>> facing_edges(const ShapeIndex& index, const std::vector<int>& a,
                                              const std::vector<int>& b) {
  const auto middles = [&](const std::vector<int>& edges) {
    std::vector<gp_Pnt> out;
    for (int e : edges) out.push_back(edge_middle(index, e));
    return out;
  };
  const std::vector<gp_Pnt> at_a = middles(a), at_b = middles(b);
  // The position in `among` of the middle nearest to `p`.
  const auto nearest = [](const gp_Pnt& p, const std::vector<gp_Pnt>& among) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < among.size(); ++k) if (p.Distance(among[k]) < p.Distance(among[best])) best = k;
    return best;
  };
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t j = nearest(at_a[i], at_b);
    if (nearest(at_b[j], at_a) != i) return {};
    pairs.push_back({a[i], b[j]});
  }
  return pairs;
}

// Edges whose counts a mapped mesh of the face wants equal: the opposite edges of a
// face bounded by four edges, and the facing edges of a ring (a face of two wires of
// as many edges, one or more each, each edge of one nearest to one of the other:
// an annulus meshed as a mapped ring, T0 between its cuts). With equal loop totals
// but arcs of 6 and 8 facing arcs of 7 and 7, a thin ring's mapped mesh folds (and
// the face, decomposed instead, ends with poor quads).
void opposite_edge_pairs(FaceWireEdges& face_wires, int face, std::vector<std::pair<int, int>>& pairs) {
  const auto& wires = face_wires.of(face);
  if (!wires) return;
  if (wires->size() == 1 && (*wires)[0].size() == 4) {
    const std::vector<int>& edges = (*wires)[0];
    for (int k = 0; k < 2; ++k) if (edges[k] != edges[k + 2]) pairs.push_back({edges[k], edges[k + 2]});
  } else if (wires->size() == 2 && (*wires)[0].size() == (*wires)[1].size()) {
    for (const auto& pair : facing_edges(face_wires.index(), (*wires)[0], (*wires)[1])) pairs.push_back(pair);
  }
}

}  // namespace

namespace {

// The three edges of a face bounded by one wire of three edges besides degenerate
// ones (a pole at a corner: a quarter of a disk made with its centre collapsed, as
// a cylinder's end cap split in quarters can be, is meshed as a triangle); nothing
// for other faces.
std::optional<std::vector<int>> three_edges(const ShapeIndex& index, int face) {
  const WireEdges wires = face_wires_with_poles(index, face);
  if (wires.size() != 1) return std::nullopt;
  std::vector<int> edges;
  for (int e : wires[0]) if (e != kPoleEdge) edges.push_back(e);
  if (edges.size() != 3 || edges[0] == edges[1] || edges[1] == edges[2] || edges[0] == edges[2]) return std::nullopt;
  return edges;
}

}  // namespace

void raise_three_edge_face_floors(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<int>& floor) {
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f]) continue;
    if (const auto edges = three_edges(index, f)) {
      for (int e : *edges) floor[e] = std::max(floor[e], kThreeCurveSideMinimum);
    }
  }
}

void raise_two_edge_loop_floors(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<int>& floor) {
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f]) continue;
    for (const std::vector<int>& wire : face_wires_with_poles(index, f)) {
      std::vector<int> edges;
      for (int e : wire) if (e != kPoleEdge) edges.push_back(e);
      if (edges.size() != 2 || edges[0] == edges[1]) continue;  // a seam is in its wire twice
      const bool straight[2] = {is_line_on_plane(index, f, edges[0]), is_line_on_plane(index, f, edges[1])};
      for (int k = 0; k < 2; ++k) {
        if (straight[k]) continue;  // a line keeps its own floor (1)
        floor[edges[k]] = std::max(floor[edges[k]], straight[1 - k] ? 3 : 2);
      }
    }
  }
}

IntervalReport assign_shape_intervals(const ShapeIndex& index, const std::vector<char>& meshed,
                                      const std::vector<double>& lengths, double size, std::vector<int>& segments,
                                      const std::vector<int>& floor, FaceWireEdges& wires,
                                      EdgeSpacings* kept) {
  const int edges = index.edge_count();
  const std::vector<int> before = segments;
  const std::vector<int> floors = floor.empty() ? std::vector<int>(edges, 1) : floor;
  auto lowest = [&](int e) { return std::max(1, floors[e]); };
  auto goal = [&](int e) { return edge_goal(lengths, size, floors, e); };
  // Chains: opposite edges of four-edge faces, joined when their goals are near
  // enough (count_fitting.h).
  CurveSets sets(edges);
  for (int e = 0; e < edges; ++e) if (segments[e] > 0) check_goal(goal(e), "edge " + std::to_string(e));
  std::vector<std::pair<int, int>> pairs;
  for (int f = 0; f < index.face_count(); ++f) if (meshed[f]) opposite_edge_pairs(wires, f, pairs);
  for (const auto& [a, b] : pairs) {
    if (segments[a] <= 0 || segments[b] <= 0) continue;
    if (near_enough_to_chain(goal(a), goal(b))) sets.join(a, b);
  }
  // An edge merged into another (strip_absorption.h) shares its nodes: one chain,
  // whatever their goals.
  for (int e = 0; e < edges; ++e) {
    const int into = index.merged_into(e).edge;
    if (into >= 0 && segments[e] > 0 && segments[into] > 0) sets.join(e, into);
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
  // Rings get equal loop totals (ring_balance.h); bands one segment wide need equal
  // long sides (band_balance.h).
  std::vector<double> goals(edges, 1.0);
  for (int e = 0; e < edges; ++e) if (segments[e] > 0) goals[e] = goal(e);
  std::vector<double> extents(edges, 1.0);
  for (int e = 0; e < edges; ++e) if (segments[e] > 0) extents[e] = lengths[e] / size;
  report.balanced_rings = balance_rings(wires, meshed, goals, extents, floors, segments, chains);
  const std::vector<char> alignable = alignable_ring_faces(wires, meshed, lengths, segments);
  std::vector<std::pair<int, int>> band_sides;
  report.balanced_bands = balance_narrow_bands(index, meshed, segments, chains, kept, &band_sides);
  // A band's balance may undo a ring's (a circle around a hexagonal socket, shared
  // with a chamfer's band whose rims are then made equal). A ring that
  // band_alignment.h can turn into a mapped ring crossing it is balanced again, each
  // band's two long sides moving together so that the band stays balanced.
  std::vector<char> undone = alignable;
  const std::vector<char> still = alignable_ring_faces(wires, meshed, lengths, segments);
  bool any = false;
  for (std::size_t f = 0; f < undone.size(); ++f) {
    undone[f] = undone[f] && !still[f];
    any = any || undone[f];
  }
  if (any) {
    std::vector<std::vector<int>> units = chains;
    for (const auto& [a, b] : band_sides) units.push_back({a, b});
    balance_rings(wires, undone, goals, extents, floors, segments, units);
  }
  // Faces left odd are made even by changing whole chains (which keeps their faces
  // mapped), a band's two long sides together (likewise: a band balanced to equal
  // long sides had one of them raised by one for parity, which its short end could
  // give) or single edges; without the band pairs where that leaves a face odd.
  const std::vector<int> balanced = segments;
  try {
    make_faces_even(index, meshed, lengths, size, segments, floor, chains, band_sides);
  } catch (const InputError&) {
    segments = balanced;
    make_faces_even(index, meshed, lengths, size, segments, floor, chains);
  }
  // Disks around a pole want a multiple of 4 on their rim (pole_rims.h); steps of 2
  // keep the parities just made.
  report.quartered_pole_rims = quarter_pole_rims(index, meshed, goals, floors, segments, chains);
  for (int e = 0; e < edges; ++e) {
    if (segments[e] != before[e]) report.changes.push_back({e, before[e], segments[e]});
  }
  return report;
}

}  // namespace tquad
