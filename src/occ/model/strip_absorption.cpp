#include "occ/model/strip_absorption.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <optional>

#include "occ/model/edge_contraction.h"
#include "occ/intervals/edge_discretization.h"

namespace tquad {

namespace {

// Points sampled inside each side to measure the strip's width: enough to find a
// bulge between the ends of sides that are arcs or gentle curves.
constexpr int kWidthSamples = 9;

double point_to_edge(const gp_Pnt& p, const TopoDS_Edge& edge) {
  BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(p).Vertex(), edge);
  return distance.IsDone() && distance.NbSolution() > 0 ? distance.Value() : INFINITY;
}

// The largest distance from a sample of a's points (its ends and kWidthSamples
// inside) to edge b.
double farthest_from(const TopoDS_Edge& a, const TopoDS_Edge& b) {
  const BRepAdaptor_Curve curve(a);
  const double u0 = curve.FirstParameter(), u1 = curve.LastParameter();
  double out = 0;
  for (int i = 0; i <= kWidthSamples + 1; ++i) {
    out = std::max(out, point_to_edge(curve.Value(u0 + (u1 - u0) * i / (kWidthSamples + 1)), b));
  }
  return out;
}

gp_Pnt point_of(const TopoDS_Vertex& v) { return BRep_Tool::Pnt(v); }

// Face f as a strip, or nothing: one wire whose edges are all usable and no seam,
// exactly two of them not short, within `bound` of each other everywhere.
std::optional<AbsorbedStrip> as_strip(const ShapeIndex& index, int f, const std::vector<double>& lengths,
                                      const std::vector<char>& usable, double bound) {
  const TopoDS_Face& face = index.face(f);
  int wires = 0;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
  if (wires != 1) return std::nullopt;
  std::vector<int> sides;
  TopExp_Explorer w(face, TopAbs_WIRE);
  for (BRepTools_WireExplorer it(TopoDS::Wire(w.Current()), face); it.More(); it.Next()) {
    const TopoDS_Edge& edge = it.Current();
    const int e = index.edge_index(edge);
    if (BRep_Tool::Degenerated(edge) || BRep_Tool::IsClosed(edge, face)) return std::nullopt;
    if (!usable.empty() && !usable[e]) return std::nullopt;
    if (lengths[e] >= bound) sides.push_back(e);
  }
  if (sides.size() != 2 || sides[0] == sides[1]) return std::nullopt;
  const int a = sides[0], b = sides[1];
  // Curves a width w apart differ in length by at most w times their turning; the
  // ends are within the bound of each other, through short edges or a shared vertex.
  if (std::abs(lengths[a] - lengths[b]) > 2 * M_PI * bound) return std::nullopt;
  for (int g : index.faces_of_edge(a)) {
    if (g == f) continue;
    const std::vector<int>& of_b = index.faces_of_edge(b);
    if (std::find(of_b.begin(), of_b.end(), g) != of_b.end()) return std::nullopt;
  }
  const TopoDS_Edge ea = forward(index.edge(a)), eb = forward(index.edge(b));
  TopoDS_Vertex a0, a1, b0, b1;
  TopExp::Vertices(ea, a0, a1);
  TopExp::Vertices(eb, b0, b1);
  if (a0.IsNull() || a1.IsNull() || b0.IsNull() || b1.IsNull()) return std::nullopt;
  const double same = std::max(point_of(a0).Distance(point_of(b0)), point_of(a1).Distance(point_of(b1)));
  const double opposite = std::max(point_of(a0).Distance(point_of(b1)), point_of(a1).Distance(point_of(b0)));
  const bool reversed = opposite < same;
  if (std::min(same, opposite) >= bound) return std::nullopt;
  const double width = std::max(farthest_from(ea, eb), farthest_from(eb, ea));
  if (!(width < bound)) return std::nullopt;
  // The longer side is kept: its nodes are the better spaced for both.
  AbsorbedStrip strip;
  strip.face = f;
  strip.kept = lengths[a] >= lengths[b] ? a : b;
  strip.merged = strip.kept == a ? b : a;
  strip.reversed = reversed;
  strip.width = width;
  return strip;
}

// Whether the contraction joined each end of the strip's kept side to the
// corresponding end of its merged side.
bool ends_joined(const ShapeIndex& index, const AbsorbedStrip& strip) {
  TopoDS_Vertex k0, k1, m0, m1;
  TopExp::Vertices(forward(index.edge(strip.kept)), k0, k1);
  TopExp::Vertices(forward(index.edge(strip.merged)), m0, m1);
  if (strip.reversed) std::swap(m0, m1);
  return index.vertex_index(k0) == index.vertex_index(m0) && index.vertex_index(k1) == index.vertex_index(m1);
}

}  // namespace

std::vector<AbsorbedStrip> strips_to_absorb(const ShapeIndex& index, const std::vector<char>& meshed,
                                            const std::vector<double>& lengths, const std::vector<char>& usable,
                                            double size) {
  const double bound = kContractedEdgeRatio * size;
  std::vector<AbsorbedStrip> out;
  std::vector<char> taken(index.edge_count(), 0);  // a side of a strip already found
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f]) continue;
    try {
      const std::optional<AbsorbedStrip> strip = as_strip(index, f, lengths, usable, bound);
      if (!strip || taken[strip->kept] || taken[strip->merged]) continue;
      taken[strip->kept] = taken[strip->merged] = 1;
      out.push_back(*strip);
    } catch (const Standard_Failure&) {  // a damaged face is meshed (or refused) as it is
    }
  }
  return out;
}

std::vector<AbsorbedStrip> contract_and_absorb(ShapeIndex& index, std::vector<AbsorbedStrip> strips,
                                               const std::vector<double>& lengths, const std::vector<char>& usable,
                                               double size, std::vector<int>& contracted) {
  while (true) {
    std::vector<char> exempt(index.face_count(), 0);
    for (const AbsorbedStrip& s : strips) exempt[s.face] = 1;
    contracted = edges_to_contract(index, lengths, usable, size, exempt);
    index.contract_edges(contracted);
    const auto apart = std::find_if(strips.begin(), strips.end(),
                                    [&](const AbsorbedStrip& s) { return !ends_joined(index, s); });
    if (apart == strips.end()) break;
    strips.erase(apart);  // each pass drops one: a strip's exemption can join another's ends
  }
  for (const AbsorbedStrip& s : strips) index.merge_edge(s.merged, s.kept, s.reversed);
  return strips;
}

}  // namespace tquad
