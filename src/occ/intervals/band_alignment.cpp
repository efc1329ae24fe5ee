#include "occ/intervals/band_alignment.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_Curve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <cmath>
#include <optional>

#include "occ/intervals/band_balance.h"
#include "occ/face/face_boundary.h"
#include "occ/face/face_corners.h"
#include "occ/model/occ_vec.h"

namespace tquad {

namespace {

// Loop positions from a to b going forward, as a count.
int forward_count(int a, int b, int n) { return ((b - a) % n + n) % n; }

// The wire edge (index into b.edge_start) that holds loop segment [p, p + 1].
int wire_edge_at(const FaceBoundary& b, int p) {
  const int n = static_cast<int>(b.nodes.size());
  int held = -1, best = n + 1;
  for (std::size_t k = 0; k < b.edge_start.size(); ++k) {
    const int back = forward_count(b.edge_start[k], p, n);
    if (back < best) { best = back; held = static_cast<int>(k); }
  }
  return held;
}

// The length of the side of `segments` from loop position `from`, by its chords.
double side_length(const FaceBoundary& b, const std::vector<Vec3>& nodes, int from, int segments) {
  const int n = static_cast<int>(b.nodes.size());
  double length = 0;
  for (int i = 0; i < segments; ++i) length += distance(nodes[b.nodes[(from + i) % n]], nodes[b.nodes[(from + i + 1) % n]]);
  return length;
}

// Whether `params` (new inner parameters of an edge now at `own`) keep the edge's
// nodes in order along it (its parameter's direction) with no segment under
// kShortestShare of the even one.
bool spaced_in_order(const TopoDS_Edge& edge, const EdgeNodes& own, const std::vector<double>& params) {
  const int n = static_cast<int>(own.params.size()) - 1;
  const double first = own.params.front(), last = own.params.back();
  const BRepAdaptor_Curve adaptor(edge);
  double length = 0;
  for (int i = 0; i < n; ++i) length += distance(to_vec3(adaptor.Value(own.params[i])), to_vec3(adaptor.Value(own.params[i + 1])));
  const double even = length / n;
  std::vector<double> all{first};
  all.insert(all.end(), params.begin(), params.end());
  all.push_back(last);
  const double direction = last > first ? 1.0 : -1.0;
  for (int i = 0; i < n; ++i) {
    if (!((all[i + 1] - all[i]) * direction > 0)) return false;
    const double chord = distance(to_vec3(adaptor.Value(all[i])), to_vec3(adaptor.Value(all[i + 1])));
    if (!(chord >= kShortestShare * even)) return false;
  }
  return true;
}

// The follower's new inner parameters, in the edge's forward order, or nothing (a
// target further than `widest` from the curve: the band is not narrow there).
std::optional<std::vector<double>> projected_parameters(const TopoDS_Edge& edge, const EdgeNodes& own,
                                                        const std::vector<Vec3>& targets, bool forward,
                                                        double widest) {
  double u0 = 0, u1 = 0;
  const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, u0, u1);
  if (curve.IsNull()) return std::nullopt;
  const int n = static_cast<int>(own.params.size()) - 1;
  if (n < 2 || static_cast<int>(targets.size()) != n - 1) return std::nullopt;
  const double first = own.params.front(), last = own.params.back();
  std::vector<double> params;
  for (int i = 0; i < n - 1; ++i) {
    const Vec3& target = targets[forward ? i : n - 2 - i];
    GeomAPI_ProjectPointOnCurve projection(gp_Pnt(target.x, target.y, target.z), curve, first, last);
    if (projection.NbPoints() == 0 || !(projection.LowerDistance() <= widest)) return std::nullopt;
    params.push_back(projection.LowerDistanceParameter());
  }
  if (!spaced_in_order(edge, own, params)) return std::nullopt;
  return params;
}

// A thin ring's follower: `targets` (the leader rim's nodes in loop order) projected
// onto the closed edge's curve. The target nearest the edge's vertex node (`vertex`,
// which stays) is left out; the others, in cyclic order from it, must run one way
// along the curve. Returns the follower's inner parameters in its forward order, or
// nothing (a target further than `widest`, out of order, or a segment under
// kShortestShare of the even one).
std::optional<std::vector<double>> ring_parameters(const TopoDS_Edge& edge, const EdgeNodes& own,
                                                   const std::vector<Vec3>& targets, const Vec3& vertex,
                                                   double widest) {
  double u0 = 0, u1 = 0;
  const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, u0, u1);
  if (curve.IsNull()) return std::nullopt;
  const int m = static_cast<int>(targets.size());
  if (static_cast<int>(own.params.size()) != m + 1 || m < 3) return std::nullopt;
  const double first = own.params.front(), last = own.params.back();
  if (!(last > first)) return std::nullopt;  // OpenCASCADE's edges run up their parameter
  int nearest = 0;
  for (int i = 1; i < m; ++i) {
    if (distance(targets[i], vertex) < distance(targets[nearest], vertex)) nearest = i;
  }
  std::vector<double> params;
  for (int j = 1; j < m; ++j) {
    const Vec3& target = targets[(nearest + j) % m];
    GeomAPI_ProjectPointOnCurve projection(gp_Pnt(target.x, target.y, target.z), curve, first, last);
    if (projection.NbPoints() == 0 || !(projection.LowerDistance() <= widest)) return std::nullopt;
    params.push_back(projection.LowerDistanceParameter());
  }
  // One way along the curve: the loops may run either way round each other.
  const bool rising = params.back() > params.front();
  if (!rising) std::reverse(params.begin(), params.end());
  if (!spaced_in_order(edge, own, params)) return std::nullopt;
  return params;
}

// Whether a face has two wires, one of them a single edge: the only faces the ring
// pass can align, found without building every face's boundary.
bool two_loops_one_a_single_edge(const TopoDS_Face& face) {
  int wires = 0;
  bool single = false;
  for (TopoDS_Iterator w(face); w.More(); w.Next()) {
    if (w.Value().ShapeType() != TopAbs_WIRE) continue;
    ++wires;
    int edges = 0;
    for (TopoDS_Iterator e(w.Value()); e.More(); e.Next()) ++edges;
    single = single || edges == 1;
  }
  return wires == 2 && single;
}

// The length of a closed loop of nodes, by its chords.
double loop_length(const std::vector<NodeId>& loop, const std::vector<Vec3>& nodes) {
  double length = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) length += distance(nodes[loop[i]], nodes[loop[(i + 1) % loop.size()]]);
  return length;
}

// Moves the follower edge e's inner nodes to `params` (and its kept spacing).
void move_follower(const TopoDS_Edge& edge, const std::vector<double>& params, EdgeNodes& en,
                   std::vector<Vec3>& nodes, EdgeSpacings* kept, int e) {
  const BRepAdaptor_Curve curve(edge);
  const int m = static_cast<int>(params.size()) + 1;
  for (int i = 0; i + 1 < m; ++i) {
    en.params[i + 1] = params[i];
    nodes[en.nodes[i + 1]] = to_vec3(curve.Value(params[i]));
  }
  if (kept && e < static_cast<int>(kept->last.size()) && kept->last[e].segments == m) {
    kept->last[e].params = en.params;
    for (int i = 0; i + 1 < m; ++i) kept->last[e].inner_points[i] = nodes[en.nodes[i + 1]];
  }
}

}  // namespace

int align_narrow_bands(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<EdgeNodes>& edges,
                       std::vector<Vec3>& nodes, EdgeSpacings* kept) {
  std::vector<char> frozen(index.edge_count(), 0);
  int aligned = 0;
  // Thin rings: a face with one hole and equal loop totals (ring_balance.h), one of
  // whose loops is a single closed edge (a circle around a hexagonal socket, a washer
  // between two circles): that edge takes its nodes where the other loop's nodes
  // project onto it, so that the mapped ring's quads (mapped_ring.h) cross the ring.
  // Its vertex stays, facing the other loop's nearest node.
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f] || !two_loops_one_a_single_edge(index.face(f))) continue;
    FaceBoundary b;
    try {
      b = face_boundary(index, f, edges, nodes);
    } catch (...) {
      continue;  // the face's own meshing says what is wrong
    }
    if (b.inner_wires != 1 || b.holes.size() != 1 || b.has_degenerate_edge) continue;
    // A seam cuts the ring open: the face is a band then, not a ring.
    if (std::find(b.is_seam.begin(), b.is_seam.end(), 1) != b.is_seam.end()) continue;
    const NodeLoop& hole = b.holes[0];
    const int m = static_cast<int>(b.nodes.size());
    if (m < 3 || static_cast<int>(hole.nodes.size()) != m) continue;
    const double along = 0.5 * (loop_length(b.nodes, nodes) + loop_length(hole.nodes, nodes)) / m;
    const std::vector<int> rims[2] = {b.edge_index, hole.edge_index};
    const std::vector<NodeId>* loops[2] = {&b.nodes, &hole.nodes};
    for (int side = 0; side < 2; ++side) {
      if (rims[side].size() != 1) continue;
      const int e = rims[side][0];
      if (frozen[e] || edges[e].degenerate || index.edge(e).IsNull()) continue;
      const std::vector<NodeId>& leader = *loops[1 - side];
      std::vector<Vec3> targets;
      for (NodeId id : leader) targets.push_back(nodes[id]);
      const auto params =
          ring_parameters(forward(index.edge(e)), edges[e], targets, nodes[edges[e].nodes.front()], kNarrowEnd * along);
      if (!params) continue;
      move_follower(forward(index.edge(e)), *params, edges[e], nodes, kept, e);
      frozen[e] = 1;
      for (int other : rims[1 - side]) frozen[other] = 1;
      ++aligned;
      break;
    }
  }
  // Bands: a four-sided face one or two segments wide.
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f]) continue;
    // Only a face with two or more edges of at most kNarrowBand segments can be a band.
    int short_edges = 0;
    for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) {
      const EdgeNodes& en = edges[index.edge_index(it.Current())];
      if (!en.degenerate && !en.nodes.empty() && static_cast<int>(en.nodes.size()) - 1 <= kNarrowBand) ++short_edges;
    }
    if (short_edges < 2) continue;
    FaceBoundary b;
    std::vector<int> corners;
    try {
      b = face_boundary(index, f, edges, nodes);
      if (b.inner_wires > 0) continue;
      corners = choose_face_corners(b, f, {}, false);
    } catch (...) {
      continue;  // the face's own meshing says what is wrong
    }
    if (corners.size() != 4) continue;
    const int n = static_cast<int>(b.nodes.size());
    int count[4];
    for (int k = 0; k < 4; ++k) count[k] = forward_count(corners[k], corners[(k + 1) % 4], n);
    for (int k = 0; k < 2; ++k) {
      if (count[k + 1] > kNarrowBand || count[(k + 3) % 4] > kNarrowBand || count[k] != count[k + 2]) continue;
      if (count[k] < 2) continue;
      const double along = 0.5 * (side_length(b, nodes, corners[k], count[k]) +
                                   side_length(b, nodes, corners[k + 2], count[k + 2])) / count[k];
      // Either long side may follow: one wire edge, not a seam, not frozen.
      for (int follower_side : {k + 2, k}) {
        const int leader_side = follower_side == k ? k + 2 : k;
        const int w = wire_edge_at(b, corners[follower_side]);
        if (w < 0 || b.is_seam[w]) continue;
        const int e = b.edge_index[w];
        const int next = w + 1 < static_cast<int>(b.edge_start.size()) ? b.edge_start[w + 1] : b.edge_start[0] + n;
        if (b.edge_start[w] != corners[follower_side] || next - b.edge_start[w] != count[follower_side]) continue;
        if (frozen[e]) continue;
        // Follower node j (from its side's start) faces leader node count - j.
        const int m = count[follower_side];
        std::vector<Vec3> targets;
        for (int j = 1; j < m; ++j) targets.push_back(nodes[b.nodes[(corners[leader_side + 1 == 4 ? 0 : leader_side + 1] - j + n) % n]]);
        const bool along_edge = edges[e].nodes.size() > 1 && b.nodes[(corners[follower_side] + 1) % n] == edges[e].nodes[1];
        const auto params =
            projected_parameters(forward(index.edge(e)), edges[e], targets, along_edge, kNarrowEnd * along);
        if (!params) continue;
        move_follower(forward(index.edge(e)), *params, edges[e], nodes, kept, e);
        frozen[e] = 1;
        // The leader's edges stay as they are from now on.
        for (int p = 0; p < count[leader_side]; ++p) frozen[b.edge_index[wire_edge_at(b, (corners[leader_side] + p) % n)]] = 1;
        ++aligned;
        break;
      }
    }
  }
  return aligned;
}

std::vector<char> alignable_ring_faces(FaceWireEdges& face_wires, const std::vector<char>& meshed,
                                       const std::vector<double>& lengths, const std::vector<int>& segments) {
  const ShapeIndex& index = face_wires.index();
  std::vector<char> faces(index.face_count(), 0);
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f]) continue;
    const auto& wires = face_wires.of(f);
    if (!wires || wires->size() != 2) continue;
    const int single = (*wires)[0].size() == 1 ? 0 : (*wires)[1].size() == 1 ? 1 : -1;
    if (single < 0) continue;
    const int e = (*wires)[single][0];
    const std::vector<int>& other = (*wires)[1 - single];
    int total = segments[e], others = 0;
    double length = lengths[e];
    for (int o : other) {
      others += segments[o];
      length += lengths[o];
    }
    if (total != others || total < 3 || index.edge(e).IsNull()) continue;
    double u0 = 0, u1 = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(forward(index.edge(e)), u0, u1);
    if (curve.IsNull()) continue;
    const double widest = kNarrowEnd * length / (2.0 * total);
    bool near = true;
    for (int o : other) {
      for (TopExp_Explorer it(index.edge(o), TopAbs_VERTEX); it.More() && near; it.Next()) {
        GeomAPI_ProjectPointOnCurve projection(BRep_Tool::Pnt(TopoDS::Vertex(it.Current())), curve, u0, u1);
        near = projection.NbPoints() > 0 && projection.LowerDistance() <= widest;
      }
    }
    faces[f] = near;
  }
  return faces;
}

}  // namespace tquad
