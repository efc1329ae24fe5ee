#include "occ/model/edge_contraction.h"

#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>

namespace tquad {

namespace {

// The distance from the middle of edge a to edge b (infinity when it cannot be
// measured).
double middle_to_edge(const TopoDS_Edge& a, const TopoDS_Edge& b) {
  const BRepAdaptor_Curve curve(a);
  const gp_Pnt middle = curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter()));
  BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(middle).Vertex(), b);
  return distance.IsDone() && distance.NbSolution() > 0 ? distance.Value() : INFINITY;
}

// Whether edge e may be contracted as far as face f's wires say: each wire holding it
// keeps two edges that are not short, and the nearest such edges before and after it
// (its sides beside it) are not closer to each other than `bound` (a strip).
bool contractible_in_face(const ShapeIndex& index, int f, int e, const std::vector<char>& is_short, double bound) {
  const TopoDS_Face& face = index.face(f);
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
    std::vector<int> wire;
    std::vector<TopoDS_Edge> shapes;
    for (BRepTools_WireExplorer it(TopoDS::Wire(w.Current()), face); it.More(); it.Next()) {
      if (BRep_Tool::Degenerated(it.Current())) continue;
      wire.push_back(index.edge_index(it.Current()));
      shapes.push_back(it.Current());
    }
    const auto at = std::find(wire.begin(), wire.end(), e);
    if (at == wire.end()) continue;
    const int n = static_cast<int>(wire.size());
    const int k = static_cast<int>(at - wire.begin());
    if (std::count_if(wire.begin(), wire.end(), [&](int x) { return !is_short[x]; }) < 2) return false;
    int before = k, after = k;
    do before = (before + n - 1) % n; while (is_short[wire[before]]);
    do after = (after + 1) % n; while (is_short[wire[after]]);
    if (middle_to_edge(shapes[before], shapes[after]) < bound || middle_to_edge(shapes[after], shapes[before]) < bound) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::vector<int> edges_to_contract(const ShapeIndex& index, const std::vector<double>& lengths,
                                   const std::vector<char>& usable, double size,
                                   const std::vector<char>& strips) {
  const double bound = kContractedEdgeRatio * size;
  const int edges = index.edge_count();
  std::vector<char> is_short(edges, 0);
  bool any = false;
  for (int e = 0; e < edges; ++e) {
    if ((!usable.empty() && !usable[e]) || BRep_Tool::Degenerated(index.edge(e))) continue;
    is_short[e] = lengths[e] < bound;
    any = any || is_short[e];
  }
  if (!any) return {};
  // Vertex groups as edges are accepted, each with its members, so that no group
  // spans more than the bound.
  std::vector<int> group(index.vertex_count());
  std::vector<std::vector<int>> members(index.vertex_count());
  for (int v = 0; v < index.vertex_count(); ++v) {
    group[v] = v;
    members[v] = {v};
  }
  std::vector<int> out;
  for (int e = 0; e < edges; ++e) {
    if (!is_short[e]) continue;
    try {
      const TopoDS_Edge& edge = index.edge(e);
      TopoDS_Vertex first, last;
      TopExp::Vertices(edge, first, last);
      if (first.IsNull() || last.IsNull() || first.IsSame(last)) continue;
      bool contractible = !index.faces_of_edge(e).empty();
      for (int f : index.faces_of_edge(e)) {
        const bool strip = !strips.empty() && strips[f];
        contractible = contractible && !BRep_Tool::IsClosed(edge, index.face(f)) &&
                       (strip || contractible_in_face(index, f, e, is_short, bound));
      }
      if (!contractible) continue;
      const int a = group[index.vertex_index(first)], b = group[index.vertex_index(last)];
      if (a == b) continue;
      double span = 0;
      for (int u : members[a]) {
        for (int v : members[b]) span = std::max(span, BRep_Tool::Pnt(index.vertex(u)).Distance(BRep_Tool::Pnt(index.vertex(v))));
      }
      if (!(span < bound)) continue;
      for (int v : members[b]) group[v] = a;
      members[a].insert(members[a].end(), members[b].begin(), members[b].end());
      members[b].clear();
      out.push_back(e);
    } catch (const Standard_Failure&) {  // a damaged edge stays as it is
    }
  }
  // A short edge left out whose two ends were joined all the same (two short edges
  // between the same two vertices, as where two holes touch) would be a side from a
  // node to itself: it is contracted too.
  for (int e = 0; e < edges && !out.empty(); ++e) {
    if (!is_short[e] || std::find(out.begin(), out.end(), e) != out.end()) continue;
    TopoDS_Vertex first, last;
    TopExp::Vertices(index.edge(e), first, last);
    if (first.IsNull() || last.IsNull() || first.IsSame(last)) continue;
    if (group[index.vertex_index(first)] == group[index.vertex_index(last)]) out.push_back(e);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace tquad
