#include "occ/intervals/edge_discretization.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/templates/count_fitting.h"
#include "core/input_error.h"
#include "occ/model/occ_vec.h"

namespace tquad {

TopoDS_Edge forward(const TopoDS_Edge& e) { return TopoDS::Edge(e.Oriented(TopAbs_FORWARD)); }

namespace {

// Total turning of the curve's tangent (radians), from 64 samples.
double tangent_turn(const BRepAdaptor_Curve& curve) {
  constexpr int kSamples = 64;
  const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
  double turn = 0;
  gp_Vec previous;
  bool have_previous = false;
  for (int i = 0; i <= kSamples; ++i) {
    gp_Pnt p;
    gp_Vec d;
    curve.D1(t0 + (t1 - t0) * i / kSamples, p, d);
    if (d.Magnitude() <= gp::Resolution()) continue;
    if (have_previous) turn += previous.Angle(d);
    previous = d;
    have_previous = true;
  }
  return turn;
}

// An edge point this many times the box's diagonal out of the box is off every face
// the edge bounds: a damaged curve. A random edit of an IGES file moved one pole of a
// B-spline edge many orders of magnitude farther out than the box is across; the
// command then worked long before its arc-length spacing failed the whole job.
constexpr double kStrayOverDiagonal = 1.0;
constexpr int kStraySamples = 64;

// How far (the largest distance over kStraySamples + 1 points) the curve goes out of
// the box; 0 inside it.
double distance_out_of(const BRepAdaptor_Curve& curve, const Box3& box) {
  const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
  double farthest = 0;
  for (int i = 0; i <= kStraySamples; ++i) {
    const Vec3 p = to_vec3(curve.Value(t0 + (t1 - t0) * i / kStraySamples));
    const Vec3 out{std::max({box.low.x - p.x, p.x - box.high.x, 0.0}),
                   std::max({box.low.y - p.y, p.y - box.high.y, 0.0}),
                   std::max({box.low.z - p.z, p.z - box.high.z, 0.0})};
    farthest = std::max(farthest, norm(out));
  }
  return farthest;
}

// A vertex whose tolerance is this fraction of the box's diagonal joins edges that do
// not meet: OpenCASCADE's healing widened it to bridge the gap, and the mesh would
// pull the edges to the vertex's point across it. Random edits of STEP files (a
// point's coordinate changed) gave tolerances of a few percent of the diagonal to far
// beyond it; undamaged parts stay under a tenth of a percent.
constexpr double kGapOverDiagonal = 0.01;

// Why the edge's vertices make it unusable, or "" when they do not.
std::string wide_vertex(const TopoDS_Edge& edge, double diagonal) {
  TopoDS_Vertex first, last;
  TopExp::Vertices(edge, first, last);
  for (const TopoDS_Vertex& v : {first, last}) {
    if (v.IsNull()) continue;
    const double tolerance = BRep_Tool::Tolerance(v);
    if (!(tolerance > kGapOverDiagonal * diagonal)) continue;
    const gp_Pnt p = BRep_Tool::Pnt(v);
    char text[240];
    std::snprintf(text, sizeof text,
                  "ends at the vertex at (%.6g, %.6g, %.6g), whose tolerance %.3g is over 1%% of the shape's %.3g "
                  "across: the edges there do not meet",
                  p.X(), p.Y(), p.Z(), tolerance, diagonal);
    return text;
  }
  return "";
}

}  // namespace

std::map<int, std::string> unusable_edges(const ShapeIndex& index, const Box3& box) {
  std::map<int, std::string> bad;
  for (int e = 0; e < index.edge_count(); ++e) {
    const TopoDS_Edge edge = forward(index.edge(e));
    if (BRep_Tool::Degenerated(edge)) continue;
    try {
      if (!BRep_Tool::IsGeometric(edge)) {
        bad[e] = "has no 3D curve";
        continue;
      }
      const BRepAdaptor_Curve curve(edge);
      const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
      if (!std::isfinite(t0) || !std::isfinite(t1) || !(t0 < t1)) {
        bad[e] = "has no finite parameter range";
        continue;
      }
      for (double t : {t0, 0.5 * (t0 + t1), t1}) {
        gp_Pnt p;
        gp_Vec d;
        curve.D1(t, p, d);
        if (!std::isfinite(p.X() + p.Y() + p.Z()) || !std::isfinite(d.X() + d.Y() + d.Z())) {
          bad[e] = "evaluates to a non-finite point";
          break;
        }
      }
      if (bad.count(e)) continue;
      const double length = GCPnts_AbscissaPoint::Length(curve);
      if (!std::isfinite(length)) {
        bad[e] = "has no finite length";
        continue;
      }
      if (const std::string gap = wide_vertex(edge, box.diagonal()); !gap.empty()) {
        bad[e] = gap;
        continue;
      }
      const double out = distance_out_of(curve, box);
      if (out > kStrayOverDiagonal * box.diagonal()) {
        char text[160];
        std::snprintf(text, sizeof text, "strays %.3g out of the shape's bounding box, which is %.3g across", out,
                      box.diagonal());
        bad[e] = text;
      }
    } catch (const Standard_Failure& failure) {
      bad[e] = std::string("cannot be evaluated (OpenCASCADE: ") + failure.GetMessageString() + ")";
    } catch (const std::exception& failure) {
      bad[e] = std::string("cannot be evaluated (") + failure.what() + ")";
    }
  }
  return bad;
}

int segments_for_turn(double turn, int per_turn) {
  const double max_segment_turn = 2 * M_PI / std::max(per_turn, kDefaultSegmentsPerTurn);
  if (!(turn > 0)) return 1;  // NaN too
  return std::max(1, static_cast<int>(std::ceil(std::min(turn, 1e3) / max_segment_turn - 1e-9)));
}

std::vector<int> edge_turn_minimums(const ShapeIndex& index, const std::vector<char>& usable, int per_turn) {
  std::vector<int> minimum(index.edge_count(), 0);
  for (int e = 0; e < index.edge_count(); ++e) {
    if (!usable.empty() && !usable[e]) continue;
    const TopoDS_Edge edge = forward(index.edge(e));
    if (BRep_Tool::Degenerated(edge)) continue;
    minimum[e] = segments_for_turn(tangent_turn(BRepAdaptor_Curve(edge)), per_turn);
  }
  return minimum;
}

std::vector<int> edge_segment_counts(const ShapeIndex& index, double size, std::vector<double>& lengths) {
  return edge_segment_counts(index, size, edge_turn_minimums(index), lengths);
}

std::vector<int> edge_segment_counts(const ShapeIndex& index, double size, const std::vector<int>& turn_minimums,
                                     std::vector<double>& lengths, const std::vector<char>& usable) {
  std::vector<int> segments = turn_minimums;
  lengths.assign(index.edge_count(), 0.0);
  for (int e = 0; e < index.edge_count(); ++e) {
    if (!usable.empty() && !usable[e]) continue;
    const TopoDS_Edge edge = forward(index.edge(e));
    if (BRep_Tool::Degenerated(edge)) continue;
    lengths[e] = GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(edge));
    if (!(lengths[e] / size <= kMaxCurveSegments)) {  // before an int holds the count
      check_goal(lengths[e] / size, "edge " + std::to_string(e));
    }
    segments[e] = std::max(segments[e], static_cast<int>(std::lround(lengths[e] / size)));
  }
  return segments;
}

namespace {

// The parameter at arc length s from the start (s > 0) or the end (s < 0) of the curve.
double parameter_at(const BRepAdaptor_Curve& curve, double s, int e) {
  const GCPnts_AbscissaPoint at(curve, s, s > 0 ? curve.FirstParameter() : curve.LastParameter());
  if (!at.IsDone()) throw InputError("edge " + std::to_string(e) + ": no point at a given arc length (a damaged curve?)");
  return at.Parameter();
}

// Edge e's nodes at n > 0 segments by arc length along its 3D curve: even, but for the
// segment at a cusp end (`cusp`), which is that end's length where the even ones
// would be shorter; the others share what is left evenly.
EdgeSpacing arc_length_spacing(const TopoDS_Edge& edge, int e, int n, const CuspEnds& cusp) {
  double u0 = 0, u1 = 0;
  BRep_Tool::Range(edge, u0, u1);
  const BRepAdaptor_Curve curve(edge);
  const double even = cusp.edge_length / n;
  const bool first_long = cusp.first > even, last_long = cusp.last > even;
  // n, or at least 2 where an end is long: an end is at most a third of the edge, so it
  // is longer than the even segments only for n >= 4.
  const int middle = n - first_long - last_long;
  EdgeSpacing out;
  out.segments = n;
  out.params.push_back(u0);
  if (first_long) out.params.push_back(parameter_at(curve, cusp.first, e));
  const double from = first_long ? out.params.back() : u0;
  const double to = last_long ? parameter_at(curve, -cusp.last, e) : u1;
  if (middle > 1) {
    GCPnts_UniformAbscissa spacing(curve, middle + 1, from, to);
    if (!spacing.IsDone() || spacing.NbPoints() != middle + 1) {
      throw InputError("edge " + std::to_string(e) + ": its arc-length discretization failed (a damaged curve?)");
    }
    for (int i = 2; i <= middle; ++i) out.params.push_back(spacing.Parameter(i));
  }
  if (last_long) out.params.push_back(to);
  out.params.push_back(u1);
  for (int i = 1; i < n; ++i) out.inner_points.push_back(to_vec3(curve.Value(out.params[i])));
  return out;
}

// Edge e's nodes at n > 0 segments where its size field puts them (local_sizes.h).
EdgeSpacing graded_spacing(const TopoDS_Edge& edge, int e, int n, const EdgeSizing& sizing) {
  double u0 = 0, u1 = 0;
  BRep_Tool::Range(edge, u0, u1);
  const BRepAdaptor_Curve curve(edge);
  const double length = GCPnts_AbscissaPoint::Length(curve);
  EdgeSpacing out;
  out.segments = n;
  out.params.push_back(u0);
  for (double s : graded_positions(sizing, length, n)) out.params.push_back(parameter_at(curve, s, e));
  out.params.push_back(u1);
  for (int i = 1; i < n; ++i) out.inner_points.push_back(to_vec3(curve.Value(out.params[i])));
  return out;
}

}  // namespace

std::vector<EdgeNodes> discretize_edges(const ShapeIndex& index, const std::vector<int>& segments,
                                        std::vector<Vec3>& nodes, EdgeSpacings* kept) {
  nodes.clear();
  for (int v = 0; v < index.vertex_count(); ++v) nodes.push_back(to_vec3(BRep_Tool::Pnt(index.vertex(v))));
  if (kept) kept->last.resize(index.edge_count());
  const CuspEnds even;

  std::vector<EdgeNodes> result(index.edge_count());
  for (int e = 0; e < index.edge_count(); ++e) {
    const TopoDS_Edge edge = forward(index.edge(e));
    TopoDS_Vertex first, last;
    TopExp::Vertices(edge, first, last);
    EdgeNodes& out = result[e];
    if (BRep_Tool::Degenerated(edge)) {
      double u0 = 0, u1 = 0;
      BRep_Tool::Range(edge, u0, u1);
      out.degenerate = true;
      out.params = {u0, u1};
      out.nodes = {index.vertex_index(first), index.vertex_index(last)};
      continue;
    }
    const int n = segments[e];
    if (n <= 0 || index.contracted(e)) continue;
    EdgeSpacing own;  // without `kept`: computed for this call alone
    EdgeSpacing& spacing = kept ? kept->last[e] : own;
    if (spacing.segments != n) {
      if (kept && !kept->grading.empty() && kept->grading[e].graded()) {
        spacing = graded_spacing(edge, e, n, kept->grading[e]);
      } else {
        const CuspEnds& cusp = kept && !kept->cusp_ends.empty() ? kept->cusp_ends[e] : even;
        spacing = arc_length_spacing(edge, e, n, cusp);
      }
    }
    out.params = spacing.params;
    if (index.merged_into(e).edge >= 0) continue;  // its nodes are another edge's, below
    out.nodes.push_back(index.vertex_index(first));
    for (const Vec3& p : spacing.inner_points) {
      out.nodes.push_back(static_cast<NodeId>(nodes.size()));
      nodes.push_back(p);
    }
    out.nodes.push_back(index.vertex_index(last));
  }
  // A merged edge (strip_absorption.h) takes the nodes of the edge it is merged into,
  // which the interval assignment gave the same count.
  for (int e = 0; e < index.edge_count(); ++e) {
    const ShapeIndex::MergedInto into = index.merged_into(e);
    if (into.edge < 0 || segments[e] <= 0) continue;
    if (segments[into.edge] != segments[e]) {
      throw std::logic_error("edge " + std::to_string(e) + " is merged into edge " + std::to_string(into.edge) +
                             " but has " + std::to_string(segments[e]) + " segments to its " +
                             std::to_string(segments[into.edge]));
    }
    result[e].nodes = result[into.edge].nodes;
    if (into.reversed) std::reverse(result[e].nodes.begin(), result[e].nodes.end());
  }
  return result;
}

bool is_line_on_plane(const ShapeIndex& index, int f, int e) {
  return BRepAdaptor_Curve(index.edge(e)).GetType() == GeomAbs_Line &&
         BRepAdaptor_Surface(index.face(f), false).GetType() == GeomAbs_Plane;
}

}  // namespace tquad
