#include "occ/sweep/projected_sweep.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Curve2d.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <ShapeAnalysis_Curve.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "core/geometry/affine_fit.h"
#include "core/input_error.h"
#include "occ/model/occ_vec.h"
#include "occ/model/shape_index.h"

namespace tquad {

namespace {

std::string face_name(int f) { return "face " + std::to_string(f); }

// What the search reads of one face.
struct FaceEdges {
  int wires = 0;
  bool degenerate = false;          // an edge collapsed to a point
  bool planar = false;
  std::vector<TopoDS_Edge> loop;    // the outer wire's edges in order, as they occur
  std::vector<int> loop_ids;        // their shape edge indices
  std::set<int> ids;                // every edge of the face
};

FaceEdges face_edges(const ShapeIndex& index, int f) {
  FaceEdges out;
  const TopoDS_Face& face = index.face(f);
  out.planar = BRepAdaptor_Surface(face).GetType() == GeomAbs_Plane;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++out.wires;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    out.ids.insert(index.edge_index(e.Current()));
    if (BRep_Tool::Degenerated(TopoDS::Edge(e.Current()))) out.degenerate = true;
  }
  if (out.wires == 1) {
    for (BRepTools_WireExplorer e(BRepTools::OuterWire(face), face); e.More(); e.Next()) {
      out.loop.push_back(e.Current());
      out.loop_ids.push_back(index.edge_index(e.Current()));
    }
  }
  return out;
}

bool four_sided(const FaceEdges& f) { return f.wires == 1 && f.loop.size() == 4 && !f.degenerate; }

// Why s and t are not the caps of a one-to-one sweep, or "" with the sides filled.
std::string check_pair(const std::map<int, FaceEdges>& faces, int s, int t, std::vector<ProjectedSide>& sides) {
  const FaceEdges& source = faces.at(s);
  const FaceEdges& target = faces.at(t);
  for (int e : source.ids) {
    if (target.ids.count(e)) return face_name(s) + " and " + face_name(t) + " share edge " + std::to_string(e);
  }
  if (source.ids.size() != target.ids.size()) {
    return face_name(s) + " and " + face_name(t) + " have different numbers of edges (" +
           std::to_string(source.ids.size()) + " and " + std::to_string(target.ids.size()) + ")";
  }
  sides.clear();
  std::set<int> used_source, used_target;
  for (const auto& [f, edges] : faces) {
    if (f == s || f == t) continue;
    if (!four_sided(edges)) {
      return "side " + face_name(f) + " is not four-sided along the sweep (" +
             (edges.wires != 1 ? std::to_string(edges.wires) + " wires"
                               : std::to_string(edges.loop.size()) + " edges" +
                                     (edges.degenerate ? ", one collapsed to a point" : "")) +
             ")";
    }
    int at = -1;
    for (int i = 0; i < 4; ++i) {
      if (source.ids.count(edges.loop_ids[i])) {
        if (at >= 0) return "side " + face_name(f) + " has two edges on the source " + face_name(s);
        at = i;
      }
    }
    const auto on_cap = [&](int i) { return source.ids.count(edges.loop_ids[i]) || target.ids.count(edges.loop_ids[i]); };
    if (at < 0 || !target.ids.count(edges.loop_ids[(at + 2) % 4]) || on_cap((at + 1) % 4) || on_cap((at + 3) % 4)) {
      return "side " + face_name(f) + " does not run from an edge of " + face_name(s) + " to the opposite edge on " +
             face_name(t);
    }
    if (!used_source.insert(edges.loop_ids[at]).second || !used_target.insert(edges.loop_ids[(at + 2) % 4]).second) {
      return "side " + face_name(f) + " shares its cap edge with another side";
    }
    ProjectedSide side;
    side.face = f;
    side.source_edge = edges.loop_ids[at];
    const auto forward = [](const TopoDS_Edge& e) { return e.Orientation() == TopAbs_FORWARD; };
    side.source = edges.loop[at];
    side.second_link = edges.loop[(at + 1) % 4];
    side.target = edges.loop[(at + 2) % 4];
    side.first_link = edges.loop[(at + 3) % 4];
    // The wire runs source (first link's end to the second's), second link (source to
    // target), target (backwards), first link (backwards).
    side.source_forward = forward(side.source);
    side.second_forward = forward(side.second_link);
    side.target_forward = !forward(side.target);
    side.first_forward = !forward(side.first_link);
    sides.push_back(side);
  }
  if (used_source.size() != source.ids.size()) {
    return std::to_string(source.ids.size() - used_source.size()) + " edges of the source " + face_name(s) +
           " have no side face";
  }
  return "";
}

// The parameter at the arc fraction f of the curve, from its first parameter.
double parameter_at(const BRepAdaptor_Curve& curve, double f) {
  const double first = curve.FirstParameter(), last = curve.LastParameter();
  if (f <= 0) return first;
  if (f >= 1) return last;
  const GCPnts_AbscissaPoint point(curve, f * GCPnts_AbscissaPoint::Length(curve), first);
  return point.IsDone() ? point.Parameter() : first + f * (last - first);
}

// The (u, v) on `face` of the point at fraction w of edge occurrence `edge`, w
// counted in the sweep's direction (`forward`: as its parameter grows).
gp_Pnt2d uv_at(const TopoDS_Edge& edge, const TopoDS_Face& face, bool forward, double w) {
  const BRepAdaptor_Curve curve(edge);
  return BRepAdaptor_Curve2d(edge, face).Value(parameter_at(curve, forward ? w : 1 - w));
}

// The boundary's misfit carried inside: at x, the mean of the residuals at the rim
// points `from` (those listed in `samples`), weighted by the inverse cube of their
// distance to x (Shepard's interpolation); the residual itself at a rim point.
Vec3 carried_residual(const Vec3& x, const std::vector<Vec3>& from, const std::vector<Vec3>& residuals,
                      const std::vector<int>& samples) {
  Vec3 sum{0, 0, 0};
  double weights = 0;
  for (int j : samples) {
    const Vec3 d = x - from[j];
    const double r2 = dot(d, d);
    if (!(r2 > 0)) return residuals[j];
    const double w = 1.0 / (r2 * std::sqrt(r2));
    sum += w * residuals[j];
    weights += w;
  }
  return weights > 0 ? (1.0 / weights) * sum : sum;
}

// The misfits b_i - A(a_i) of an affine map.
std::vector<Vec3> residuals_of(const AffineMap& map, const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  std::vector<Vec3> out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = b[i] - map(a[i]);
  return out;
}

}  // namespace

ProjectedCaps find_projected_caps(const ShapeIndex& index, const std::vector<int>& solid_faces, int given_source,
                                  int given_target) {
  ProjectedCaps out;
  std::map<int, FaceEdges> faces;
  std::vector<int> not_sides;
  for (int f : solid_faces) {
    faces.emplace(f, face_edges(index, f));
    if (!four_sided(faces.at(f))) not_sides.push_back(f);
  }
  // Every face but the caps is four-sided: at most two faces may not be.
  std::vector<std::pair<int, int>> pairs;
  if (given_source >= 0) {
    pairs.emplace_back(given_source, given_target);
  } else if (not_sides.size() > 2) {
    out.why_not = "it has " + std::to_string(not_sides.size()) + " faces that are not four-sided (" +
                  face_name(not_sides[0]) + ", " + face_name(not_sides[1]) + ", " + face_name(not_sides[2]) +
                  (not_sides.size() > 3 ? ", ..." : "") + "): at most the two caps may be";
    return out;
  } else {
    for (int s : solid_faces) {
      for (int t : solid_faces) {
        if (s == t) continue;
        const bool covers = std::all_of(not_sides.begin(), not_sides.end(), [&](int f) { return f == s || f == t; });
        if (covers) pairs.emplace_back(s, t);
      }
    }
  }
  std::tuple<std::size_t, int> best_rank{0, -1};
  int why_depth = -1;
  for (const auto& [s, t] : pairs) {
    std::vector<ProjectedSide> sides;
    const std::string why = check_pair(faces, s, t, sides);
    if (!why.empty()) {
      // The reason met furthest into the checks: past the caps' own tests, a side's.
      const int depth = why.rfind("side ", 0) == 0 ? 2 : why.find(" share edge ") == std::string::npos ? 1 : 0;
      if (depth > why_depth) {
        out.why_not = why;
        why_depth = depth;
      }
      continue;
    }
    const std::tuple<std::size_t, int> rank{faces.at(s).ids.size(), faces.at(s).planar + faces.at(t).planar};
    if (out.source < 0 || rank > best_rank) {
      out.source = s;
      out.target = t;
      out.sides = sides;
      best_rank = rank;
    }
  }
  if (out.source >= 0) out.why_not.clear();
  if (out.source < 0 && out.why_not.empty()) out.why_not = "no two faces are joined by four-sided side faces";
  return out;
}

ProjectedPaths::ProjectedPaths(const ShapeIndex& index, const ProjectedCaps& caps, const std::vector<Vec3>& points,
                               const std::vector<bool>& rim, double tol)
    : index_(index), source_(points) {
  std::vector<BRepAdaptor_Curve> source_curves;
  for (const ProjectedSide& side : caps.sides) {
    const TopoDS_Face& face = index.face(side.face);
    SideFrame frame;
    frame.side = side;
    const gp_Pnt2d s0 = uv_at(side.source, face, side.source_forward, 0.0);
    const gp_Pnt2d s1 = uv_at(side.source, face, side.source_forward, 1.0);
    const gp_Pnt2d t0 = uv_at(side.target, face, side.target_forward, 0.0);
    const gp_Pnt2d t1 = uv_at(side.target, face, side.target_forward, 1.0);
    frame.su0 = s0.X(), frame.sv0 = s0.Y(), frame.su1 = s1.X(), frame.sv1 = s1.Y();
    frame.tu0 = t0.X(), frame.tv0 = t0.Y(), frame.tu1 = t1.X(), frame.tv1 = t1.Y();
    sides_.push_back(frame);
    source_curves.emplace_back(side.source);
    for (const TopoDS_Edge& link : {side.first_link, side.second_link}) {
      height_ = std::max(height_, GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(link)));
    }
  }
  ShapeAnalysis_Curve projector;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!rim[i]) {
      interior_.push_back(static_cast<int>(i));
      continue;
    }
    const gp_Pnt p(points[i].x, points[i].y, points[i].z);
    double best = std::numeric_limits<double>::infinity(), best_parameter = 0;
    int best_side = -1;
    for (std::size_t k = 0; k < sides_.size(); ++k) {
      gp_Pnt foot;
      double parameter = 0;
      const double d = projector.Project(source_curves[k], p, tol, foot, parameter, true);
      if (d < best) {
        best = d;
        best_parameter = parameter;
        best_side = static_cast<int>(k);
      }
    }
    if (best_side < 0 || best > 1e3 * tol) {
      throw InputError("a boundary node of the source " + face_name(caps.source) + " at (" +
                       std::to_string(points[i].x) + ", " + std::to_string(points[i].y) + ", " +
                       std::to_string(points[i].z) + ") lies on none of its edges");
    }
    const SideFrame& frame = sides_[best_side];
    const BRepAdaptor_Curve& curve = source_curves[best_side];
    const double length = GCPnts_AbscissaPoint::Length(curve);
    const double along = length > 0 ? GCPnts_AbscissaPoint::Length(curve, curve.FirstParameter(), best_parameter) / length : 0;
    RimPoint r;
    r.index = static_cast<int>(i);
    r.side = best_side;
    r.s = std::clamp(frame.side.source_forward ? along : 1 - along, 0.0, 1.0);
    const TopoDS_Face& face = index.face(frame.side.face);
    const gp_Pnt2d su = BRepAdaptor_Curve2d(frame.side.source, face).Value(best_parameter);
    const gp_Pnt2d tu = uv_at(frame.side.target, face, frame.side.target_forward, r.s);
    r.su = su.X(), r.sv = su.Y(), r.tu = tu.X(), r.tv = tu.Y();
    rim_.push_back(r);
    source_rim_.push_back(points[i]);
  }
  if (rim_.size() < 3) throw InputError("the source " + face_name(caps.source) + " has under 3 boundary nodes");
  // At most 128 rim points carry the misfit inside: it varies slowly along the rim.
  const std::size_t stride = std::max<std::size_t>(1, rim_.size() / 128);
  for (std::size_t k = 0; k < rim_.size(); k += stride) samples_.push_back(static_cast<int>(k));
  target_rim_ = rim_at(1.0);
  // The target's interior: the source's, mapped as the boundary is, then put on the
  // target's surface.
  target_ = source_;
  for (std::size_t k = 0; k < rim_.size(); ++k) target_[rim_[k].index] = target_rim_[k];
  const AffineMap map = AffineMap::fit(source_rim_, target_rim_);
  const std::vector<Vec3> misfit = residuals_of(map, source_rim_, target_rim_);
  ShapeAnalysis_Surface surface(BRep_Tool::Surface(index.face(caps.target)));
  for (int i : interior_) {
    const Vec3 mapped = map(source_[i]) + carried_residual(source_[i], source_rim_, misfit, samples_);
    const gp_Pnt p(mapped.x, mapped.y, mapped.z);
    const gp_Pnt2d uv = surface.ValueOfUV(p, tol);
    target_[i] = to_vec3(surface.Value(uv));
  }
}

std::vector<Vec3> ProjectedPaths::rim_at(double t) const {
  // Per side, its links' (u, v) at t.
  std::vector<gp_Pnt2d> first(sides_.size()), second(sides_.size());
  std::vector<BRepAdaptor_Surface> surfaces;
  surfaces.reserve(sides_.size());
  for (std::size_t k = 0; k < sides_.size(); ++k) {
    const ProjectedSide& side = sides_[k].side;
    const TopoDS_Face& face = index_.face(side.face);
    first[k] = uv_at(side.first_link, face, side.first_forward, t);
    second[k] = uv_at(side.second_link, face, side.second_forward, t);
    surfaces.emplace_back(face);
  }
  std::vector<Vec3> out;
  out.reserve(rim_.size());
  for (const RimPoint& r : rim_) {
    const SideFrame& f = sides_[r.side];
    const double s = r.s;
    // Transfinite interpolation of the side's four edges (Coons patch) in its (u, v).
    const double u = (1 - t) * r.su + t * r.tu + (1 - s) * first[r.side].X() + s * second[r.side].X() -
                     ((1 - s) * (1 - t) * f.su0 + s * (1 - t) * f.su1 + (1 - s) * t * f.tu0 + s * t * f.tu1);
    const double v = (1 - t) * r.sv + t * r.tv + (1 - s) * first[r.side].Y() + s * second[r.side].Y() -
                     ((1 - s) * (1 - t) * f.sv0 + s * (1 - t) * f.sv1 + (1 - s) * t * f.tv0 + s * t * f.tv1);
    out.push_back(to_vec3(surfaces[r.side].Value(u, v)));
  }
  return out;
}

std::vector<Vec3> ProjectedPaths::at(double t) const {
  if (t <= 0) return source_;
  if (t >= 1) return target_;
  const std::vector<Vec3> rim = rim_at(t);
  std::vector<Vec3> out = source_;
  for (std::size_t k = 0; k < rim_.size(); ++k) out[rim_[k].index] = rim[k];
  const AffineMap from_source = AffineMap::fit(source_rim_, rim);
  const AffineMap from_target = AffineMap::fit(target_rim_, rim);
  const std::vector<Vec3> source_misfit = residuals_of(from_source, source_rim_, rim);
  const std::vector<Vec3> target_misfit = residuals_of(from_target, target_rim_, rim);
  for (int i : interior_) {
    const Vec3 below = from_source(source_[i]) + carried_residual(source_[i], source_rim_, source_misfit, samples_);
    const Vec3 above = from_target(target_[i]) + carried_residual(target_[i], target_rim_, target_misfit, samples_);
    out[i] = (1 - t) * below + t * above;
  }
  return out;
}

}  // namespace tquad
