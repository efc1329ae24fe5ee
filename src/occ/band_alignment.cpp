#include "occ/band_alignment.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_Curve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <cmath>
#include <optional>

#include "occ/band_balance.h"
#include "occ/face_boundary.h"
#include "occ/face_corners.h"
#include "occ/occ_vec.h"

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
    GeomAPI_ProjectPointOnCurve projection(gp_Pnt(target.x, target.y, target.z), curve, std::min(first, last),
                                           std::max(first, last));
    if (projection.NbPoints() == 0 || !(projection.LowerDistance() <= widest)) return std::nullopt;
    params.push_back(projection.LowerDistanceParameter());
  }
  // In order along the edge, no segment under kShortestShare of the even one.
  const BRepAdaptor_Curve adaptor(edge);
  double length = 0;
  for (int i = 0; i < n; ++i) length += distance(to_vec3(adaptor.Value(own.params[i])), to_vec3(adaptor.Value(own.params[i + 1])));
  const double even = length / n;
  std::vector<double> all{first};
  all.insert(all.end(), params.begin(), params.end());
  all.push_back(last);
  const double direction = last > first ? 1.0 : -1.0;
  for (int i = 0; i < n; ++i) {
    if (!((all[i + 1] - all[i]) * direction > 0)) return std::nullopt;
    const double chord = distance(to_vec3(adaptor.Value(all[i])), to_vec3(adaptor.Value(all[i + 1])));
    if (!(chord >= kShortestShare * even)) return std::nullopt;
  }
  return params;
}

}  // namespace

int align_narrow_bands(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<EdgeNodes>& edges,
                       std::vector<Vec3>& nodes, EdgeSpacings* kept) {
  std::vector<char> frozen(index.edge_count(), 0);
  int aligned = 0;
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
      if (b.inner_wires > 0 || b.has_degenerate_edge) continue;
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
        const BRepAdaptor_Curve curve(forward(index.edge(e)));
        EdgeNodes& en = edges[e];
        for (int i = 0; i + 1 < m; ++i) {
          en.params[i + 1] = (*params)[i];
          nodes[en.nodes[i + 1]] = to_vec3(curve.Value((*params)[i]));
        }
        if (kept && e < static_cast<int>(kept->last.size()) && kept->last[e].segments == m) {
          kept->last[e].params = en.params;
          for (int i = 0; i + 1 < m; ++i) kept->last[e].inner_points[i] = nodes[en.nodes[i + 1]];
        }
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

}  // namespace tquad
