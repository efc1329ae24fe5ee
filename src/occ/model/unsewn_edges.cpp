#include "occ/model/unsewn_edges.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>

namespace tquad {

namespace {

struct FreeEdge {
  int edge = 0;
  gp_Pnt first, last, middle;
  double tolerance = 0;
};

// An edge used once by one face: not a seam (used twice by its face), not shared.
bool is_free(const ShapeIndex& index, int e) {
  const TopoDS_Edge& edge = index.edge(e);
  if (BRep_Tool::Degenerated(edge) || index.faces_of_edge(e).size() != 1) return false;
  return !BRep_Tool::IsClosed(edge, index.face(index.faces_of_edge(e).front()));
}

bool free_edge(const ShapeIndex& index, int e, FreeEdge& out) {
  try {
    const TopoDS_Edge& edge = index.edge(e);
    TopoDS_Vertex v0, v1;
    TopExp::Vertices(edge, v0, v1);
    if (v0.IsNull() || v1.IsNull()) return false;
    const BRepAdaptor_Curve curve(edge);
    out.edge = e;
    out.first = BRep_Tool::Pnt(v0);
    out.last = BRep_Tool::Pnt(v1);
    out.middle = curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter()));
    out.tolerance = std::max({BRep_Tool::Tolerance(edge), BRep_Tool::Tolerance(v0), BRep_Tool::Tolerance(v1)});
    return true;
  } catch (const Standard_Failure&) {
    return false;  // an edge that cannot be evaluated is refused elsewhere (unusable_edges)
  }
}

// Within which two free edges count as one: twice their tolerances summed.
double coincidence_tolerance(const FreeEdge& a, const FreeEdge& b) { return 2 * (a.tolerance + b.tolerance); }

bool coincide(const FreeEdge& a, const FreeEdge& b) {
  const double tolerance = coincidence_tolerance(a, b);
  const bool same_ends = (a.first.Distance(b.first) <= tolerance && a.last.Distance(b.last) <= tolerance) ||
                         (a.first.Distance(b.last) <= tolerance && a.last.Distance(b.first) <= tolerance);
  return same_ends && a.middle.Distance(b.middle) <= tolerance;
}

}  // namespace

std::vector<UnsewnEdgePair> unsewn_edge_pairs(const ShapeIndex& index) {
  std::vector<FreeEdge> edges;
  double widest = 0;
  for (int e = 0; e < index.edge_count(); ++e) {
    FreeEdge f;
    if (is_free(index, e) && free_edge(index, e, f)) {
      edges.push_back(f);
      widest = std::max(widest, f.tolerance);
    }
  }
  // Swept along x of the mid points: only edges whose mid points are closer in x
  // than the largest tolerance allows can coincide.
  std::sort(edges.begin(), edges.end(), [](const FreeEdge& a, const FreeEdge& b) { return a.middle.X() < b.middle.X(); });
  std::vector<UnsewnEdgePair> pairs;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size() && edges[j].middle.X() - edges[i].middle.X() <= 4 * widest; ++j) {
      if (coincide(edges[i], edges[j])) {
        pairs.push_back({std::min(edges[i].edge, edges[j].edge), std::max(edges[i].edge, edges[j].edge),
                         coincidence_tolerance(edges[i], edges[j])});
      }
    }
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const UnsewnEdgePair& a, const UnsewnEdgePair& b) { return a.first != b.first ? a.first < b.first : a.second < b.second; });
  return pairs;
}

}  // namespace tquad
