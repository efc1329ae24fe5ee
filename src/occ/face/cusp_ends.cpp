#include "occ/face/cusp_ends.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace tquad {

namespace {

// Chords closer than this leave the tip's quad a worse corner than the sine of 15
// degrees (0.26), below the parts' typical worst quads; wider corners are left alone.
constexpr double kCuspAngle = 15.0 * M_PI / 180.0;
// Curves tangent at the tip part linearly (the chord angle grows 4 times from a
// quarter of the length to all of it); curves meeting at an angle barely part.
constexpr double kPartingRatio = 1.5;

struct EdgeEnd {
  int edge;
  bool first;  // the edge's first vertex (FORWARD orientation), else its last
};

double end_length(double size, double length) { return std::min(size, length / 3.0); }

// The point at arc length s from one end of the curve, or none where OpenCASCADE fails.
std::optional<gp_Pnt> point_from_end(const BRepAdaptor_Curve& curve, bool first, double s) {
  try {
    const GCPnts_AbscissaPoint at(curve, first ? s : -s, first ? curve.FirstParameter() : curve.LastParameter());
    if (!at.IsDone()) return std::nullopt;
    return curve.Value(at.Parameter());
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

// The angle at `tip` between the chords to the two ends' points at fraction t of their
// end lengths, or none.
std::optional<double> chord_angle(const gp_Pnt& tip, const BRepAdaptor_Curve& a, const EdgeEnd& end_a, double length_a,
                                  const BRepAdaptor_Curve& b, const EdgeEnd& end_b, double length_b, double t) {
  const auto pa = point_from_end(a, end_a.first, t * length_a);
  const auto pb = point_from_end(b, end_b.first, t * length_b);
  if (!pa || !pb) return std::nullopt;
  const gp_Vec va(tip, *pa), vb(tip, *pb);
  if (va.Magnitude() <= gp::Resolution() || vb.Magnitude() <= gp::Resolution()) return std::nullopt;
  return va.Angle(vb);
}

bool parting_cusp(const ShapeIndex& index, const std::vector<double>& sizes, const std::vector<double>& lengths,
                  const EdgeEnd& a, const EdgeEnd& b) {
  const TopoDS_Edge edge_a = TopoDS::Edge(index.edge(a.edge).Oriented(TopAbs_FORWARD));
  const TopoDS_Edge edge_b = TopoDS::Edge(index.edge(b.edge).Oriented(TopAbs_FORWARD));
  const BRepAdaptor_Curve curve_a(edge_a), curve_b(edge_b);
  const gp_Pnt tip = curve_a.Value(a.first ? curve_a.FirstParameter() : curve_a.LastParameter());
  const double length_a = end_length(sizes[a.edge], lengths[a.edge]);
  const double length_b = end_length(sizes[b.edge], lengths[b.edge]);
  const auto near = chord_angle(tip, curve_a, a, length_a, curve_b, b, length_b, 0.25);
  if (!near || *near >= kCuspAngle) return false;
  const auto far = chord_angle(tip, curve_a, a, length_a, curve_b, b, length_b, 1.0);
  return far && *far >= kPartingRatio * *near;
}

// Face f's usable edges' ends by vertex; seam edges (the face on both sides) and closed
// edges are left out: their ends are no corner of the face.
std::map<int, std::vector<EdgeEnd>> ends_by_vertex(const ShapeIndex& index, int f, const std::vector<double>& lengths) {
  std::map<int, std::vector<EdgeEnd>> ends;
  std::vector<int> seen;
  const TopoDS_Face& face = index.face(f);
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const int e = index.edge_index(it.Current());
    if (e < 0 || !(lengths[e] > 0.0) || std::find(seen.begin(), seen.end(), e) != seen.end()) continue;
    seen.push_back(e);
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    if (BRep_Tool::IsClosed(edge, face)) continue;
    TopoDS_Vertex first, last;
    TopExp::Vertices(TopoDS::Edge(edge.Oriented(TopAbs_FORWARD)), first, last);
    if (first.IsNull() || last.IsNull() || first.IsSame(last)) continue;
    ends[index.vertex_index(first)].push_back({e, true});
    ends[index.vertex_index(last)].push_back({e, false});
  }
  return ends;
}

}  // namespace

std::vector<CuspEnds> cusp_ends(const ShapeIndex& index, const std::vector<double>& sizes,
                                const std::vector<double>& lengths) {
  std::vector<CuspEnds> out(index.edge_count());
  const auto mark = [&](const EdgeEnd& end) {
    (end.first ? out[end.edge].first : out[end.edge].last) = end_length(sizes[end.edge], lengths[end.edge]);
    out[end.edge].edge_length = lengths[end.edge];
  };
  for (int f = 0; f < index.face_count(); ++f) {
    for (const auto& [vertex, ends] : ends_by_vertex(index, f, lengths)) {
      if (ends.size() != 2 || !parting_cusp(index, sizes, lengths, ends[0], ends[1])) continue;
      mark(ends[0]);
      mark(ends[1]);
    }
  }
  return out;
}

std::vector<CuspEnds> cusp_ends(const ShapeIndex& index, double size, const std::vector<double>& lengths) {
  return cusp_ends(index, std::vector<double>(index.edge_count(), size), lengths);
}

}  // namespace tquad
