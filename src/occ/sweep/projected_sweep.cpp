#include "occ/sweep/projected_sweep.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Curve2d.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <ElCLib.hxx>
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
#include <functional>
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

// Why s and t are not the caps of a one-to-one sweep, or "" with the columns filled.
std::string check_pair(const ShapeIndex& index, const std::map<int, FaceEdges>& faces, int s, int t,
                       std::vector<ProjectedColumn>& columns, int& groups) {
  const FaceEdges& source = faces.at(s);
  const FaceEdges& target = faces.at(t);
  for (int e : source.ids) {
    if (target.ids.count(e)) return face_name(s) + " and " + face_name(t) + " share edge " + std::to_string(e);
  }
  if (source.ids.size() != target.ids.size()) {
    return face_name(s) + " and " + face_name(t) + " have different numbers of edges (" +
           std::to_string(source.ids.size()) + " and " + std::to_string(target.ids.size()) + ")";
  }
  // The side faces on each edge (a side of the solid is on two faces).
  std::map<int, std::vector<int>> faces_on;
  for (const auto& [f, edges] : faces) {
    if (f == s || f == t) continue;
    for (int e : edges.ids) faces_on[e].push_back(f);
  }
  columns.clear();
  std::set<int> used;
  const auto forward = [](const TopoDS_Edge& e) { return e.Orientation() == TopAbs_FORWARD; };
  for (int e : source.ids) {
    ProjectedColumn column;
    column.source_edge = e;
    int bottom = e, from = -1;
    for (;;) {
      int f = -1;
      for (int g : faces_on[bottom]) {
        if (g != from) f = g;
      }
      if (f < 0) return "edge " + std::to_string(bottom) + " of the sweep's sides has no side face above it";
      const FaceEdges& edges = faces.at(f);
      if (!four_sided(edges)) {
        return "side " + face_name(f) + " is not four-sided along the sweep (" +
               (edges.wires != 1 ? std::to_string(edges.wires) + " wires"
                                 : std::to_string(edges.loop.size()) + " edges" +
                                       (edges.degenerate ? ", one collapsed to a point" : "")) +
               ")";
      }
      if (!used.insert(f).second) return "side " + face_name(f) + " is met twice going up the sides";
      const int at = static_cast<int>(std::find(edges.loop_ids.begin(), edges.loop_ids.end(), bottom) -
                                      edges.loop_ids.begin());
      const int top = edges.loop_ids[(at + 2) % 4];
      const auto on_cap = [&](int i) { return source.ids.count(edges.loop_ids[i]) || target.ids.count(edges.loop_ids[i]); };
      if (on_cap((at + 1) % 4) || on_cap((at + 3) % 4) || source.ids.count(top)) {
        return "side " + face_name(f) + " does not run from an edge of " + face_name(s) + " to the opposite edge on " +
               face_name(t);
      }
      // The wire runs bottom, the link up from its end, top (backwards), the link down
      // to its start. The column's bottoms all run one way: a band whose bottom does
      // not (its wire runs the other way round) has its links swapped.
      ProjectedBand band;
      band.face = f;
      band.bottom = edges.loop[at];
      band.top = edges.loop[(at + 2) % 4];
      const TopoDS_Edge& up = edges.loop[(at + 1) % 4];
      const TopoDS_Edge& down = edges.loop[(at + 3) % 4];
      const bool swap = !column.bands.empty() && forward(band.bottom) != column.bands.back().top_forward;
      band.bottom_forward = forward(band.bottom) != swap;
      band.top_forward = forward(band.top) == swap;
      band.first_link = swap ? up : down;
      band.second_link = swap ? down : up;
      band.first_forward = swap ? forward(up) : !forward(down);
      band.second_forward = swap ? !forward(down) : forward(up);
      for (const TopoDS_Edge& link : {band.first_link, band.second_link}) {
        band.length = std::max(band.length, GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(link)));
      }
      column.bands.push_back(band);
      if (target.ids.count(top)) break;
      bottom = top;
      from = f;
    }
    columns.push_back(column);
  }
  if (used.size() + 2 != faces.size()) {
    for (const auto& [f, edges] : faces) {
      if (f != s && f != t && !used.count(f)) {
        return "side " + face_name(f) + " is in no column of sides from " + face_name(s) + " to " + face_name(t);
      }
    }
  }
  // Groups: columns that share a link (union-find); they must stack alike.
  std::vector<int> parent(columns.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  const std::function<int(int)> root = [&](int i) { return parent[i] == i ? i : parent[i] = root(parent[i]); };
  std::map<int, int> column_of_link;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    for (const ProjectedBand& band : columns[c].bands) {
      for (const TopoDS_Edge& link : {band.first_link, band.second_link}) {
        const auto [it, fresh] = column_of_link.emplace(index.edge_index(link), static_cast<int>(c));
        if (!fresh) parent[root(static_cast<int>(c))] = root(it->second);
      }
    }
  }
  std::map<int, int> group_of_root;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const int r = root(static_cast<int>(c));
    const auto [it, fresh] = group_of_root.emplace(r, static_cast<int>(group_of_root.size()));
    columns[c].group = it->second;
    if (columns[c].bands.size() != columns[r].bands.size()) {
      return "the sides above edges " + std::to_string(columns[c].source_edge) + " and " +
             std::to_string(columns[r].source_edge) + " of " + face_name(s) + " are stacked differently (" +
             std::to_string(columns[c].bands.size()) + " and " + std::to_string(columns[r].bands.size()) + " faces)";
    }
  }
  groups = static_cast<int>(group_of_root.size());
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
    std::vector<ProjectedColumn> columns;
    int groups = 0;
    const std::string why = check_pair(index, faces, s, t, columns, groups);
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
      out.columns = columns;
      out.groups = groups;
      best_rank = rank;
    }
  }
  if (out.source >= 0) out.why_not.clear();
  if (out.source < 0 && out.why_not.empty()) out.why_not = "no two faces are joined by four-sided side faces";
  return out;
}

ProjectedPaths::ProjectedPaths(const ShapeIndex& index, const ProjectedCaps& caps, const std::vector<Vec3>& points,
                               const std::vector<bool>& rim, double tol)
    : index_(index), caps_(caps), rim_of_(points.size(), -1), source_(points) {
  std::vector<BRepAdaptor_Curve> source_curves;
  std::vector<double> group_height(caps.groups, 0.0);
  for (const ProjectedColumn& column : caps.columns) {
    std::vector<BandFrame> frames;
    double stack = 0;
    for (const ProjectedBand& band : column.bands) {
      const TopoDS_Face& face = index.face(band.face);
      BandFrame frame;
      int i = 0;
      for (const auto& [edge, forward] : {std::pair(band.bottom, band.bottom_forward), std::pair(band.top, band.top_forward)}) {
        for (double w : {0.0, 1.0}) {
          const gp_Pnt2d uv = uv_at(edge, face, forward, w);
          frame.u[i] = uv.X();
          frame.v[i] = uv.Y();
          ++i;
        }
      }
      frames.push_back(frame);
      stack += band.length;
    }
    frames_.push_back(frames);
    group_height[column.group] = std::max(group_height[column.group], stack);
    source_curves.emplace_back(column.bands.front().bottom);
  }
  for (double h : group_height) height_ = std::max(height_, h);
  ShapeAnalysis_Curve projector;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!rim[i]) {
      interior_.push_back(static_cast<int>(i));
      continue;
    }
    const gp_Pnt p(points[i].x, points[i].y, points[i].z);
    std::vector<std::pair<double, double>> found(caps.columns.size());  // (distance, parameter) per column
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < caps.columns.size(); ++c) {
      gp_Pnt foot;
      double parameter = 0;
      projector.Project(source_curves[c], p, tol, foot, parameter, true);
      // On a periodic curve (an arc of a circle) the projection may land on the rest
      // of the circle: the distance counts on the edge's own range only.
      const BRepAdaptor_Curve& curve = source_curves[c];
      if (curve.IsPeriodic() && (parameter < curve.FirstParameter() || parameter > curve.LastParameter())) {
        parameter = ElCLib::InPeriod(parameter, curve.FirstParameter(), curve.FirstParameter() + curve.Period());
      }
      parameter = std::clamp(parameter, curve.FirstParameter(), curve.LastParameter());
      const double d = p.Distance(curve.Value(parameter));
      found[c] = {d, parameter};
      best = std::min(best, d);
    }
    if (!(best <= 1e3 * tol)) {
      throw InputError("a boundary node of the source " + face_name(caps.source) + " at (" +
                       std::to_string(points[i].x) + ", " + std::to_string(points[i].y) + ", " +
                       std::to_string(points[i].z) + ") lies on none of its edges");
    }
    RimPoint r;
    r.index = static_cast<int>(i);
    // The columns it lies on: the nearest, and a neighbour sharing its vertex.
    std::vector<std::size_t> order(caps.columns.size());
    for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return found[a].first < found[b].first; });
    for (std::size_t c : order) {
      if (!(found[c].first <= best + 10 * tol) || r.columns.size() == 2) break;
      const ProjectedColumn& column = caps.columns[c];
      const BRepAdaptor_Curve& curve = source_curves[c];
      const double length = GCPnts_AbscissaPoint::Length(curve);
      const double along =
          length > 0 ? GCPnts_AbscissaPoint::Length(curve, curve.FirstParameter(), found[c].second) / length : 0;
      OnColumn on;
      on.column = static_cast<int>(c);
      on.s = std::clamp(column.bands.front().bottom_forward ? along : 1 - along, 0.0, 1.0);
      for (const ProjectedBand& band : column.bands) {
        const TopoDS_Face& face = index.face(band.face);
        const gp_Pnt2d bottom = uv_at(band.bottom, face, band.bottom_forward, on.s);
        const gp_Pnt2d top = uv_at(band.top, face, band.top_forward, on.s);
        on.ends.push_back({bottom.X(), bottom.Y(), top.X(), top.Y()});
      }
      // Exactly where the source's mesh put it, on the first band's bottom.
      on.ends.front()[0] = BRepAdaptor_Curve2d(column.bands.front().bottom, index.face(column.bands.front().face))
                               .Value(found[c].second)
                               .X();
      on.ends.front()[1] = BRepAdaptor_Curve2d(column.bands.front().bottom, index.face(column.bands.front().face))
                               .Value(found[c].second)
                               .Y();
      r.columns.push_back(on);
      // A point inside an edge is on one column only.
      if (on.s > 1e-9 && on.s < 1 - 1e-9) break;
    }
    rim_of_[i] = static_cast<int>(rim_.size());
    rim_.push_back(r);
    source_rim_.push_back(points[i]);
  }
  if (rim_.size() < 3) throw InputError("the source " + face_name(caps.source) + " has under 3 boundary nodes");
  // At most 128 rim points carry the misfit inside: it varies slowly along the rim.
  const std::size_t stride = std::max<std::size_t>(1, rim_.size() / 128);
  for (std::size_t k = 0; k < rim_.size(); k += stride) samples_.push_back(static_cast<int>(k));
  std::size_t most_bands = 1;
  for (const ProjectedColumn& column : caps.columns) most_bands = std::max(most_bands, column.bands.size());
  set_layers(static_cast<int>(most_bands));  // the target is the last layer, whatever their count
  target_rim_ = rim_at(layers_);
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

int ProjectedPaths::layers_for(double size) const {
  int most = 1;
  std::vector<int> per_group(caps_.groups, 0);
  std::vector<bool> seen(caps_.groups, false);
  for (const ProjectedColumn& column : caps_.columns) {
    if (seen[column.group]) continue;
    seen[column.group] = true;
    // The group's longest link per band (over its columns).
    std::vector<double> lengths(column.bands.size(), 0.0);
    for (const ProjectedColumn& other : caps_.columns) {
      if (other.group != column.group) continue;
      for (std::size_t b = 0; b < lengths.size(); ++b) lengths[b] = std::max(lengths[b], other.bands[b].length);
    }
    int sum = 0;
    for (double l : lengths) sum += std::max(1, static_cast<int>(std::lround(l / size)));
    most = std::max(most, sum);
  }
  return most;
}

void ProjectedPaths::set_layers(int layers) {
  starts_.assign(caps_.groups, {});
  for (const ProjectedColumn& column : caps_.columns) {
    std::vector<int>& starts = starts_[column.group];
    if (!starts.empty()) continue;
    const std::size_t bands = column.bands.size();
    if (static_cast<int>(bands) > layers) {
      throw InputError(std::to_string(layers) + " layers are fewer than the " + std::to_string(bands) +
                       " side faces stacked above edge " + std::to_string(column.source_edge));
    }
    std::vector<double> lengths(bands, 0.0);
    for (const ProjectedColumn& other : caps_.columns) {
      if (other.group != column.group) continue;
      for (std::size_t b = 0; b < bands; ++b) lengths[b] = std::max(lengths[b], other.bands[b].length);
    }
    // Each band at least one layer, the rest shared after length (largest remainder).
    double total = 0;
    for (double l : lengths) total += l;
    std::vector<int> share(bands, 1);
    const int spare = layers - static_cast<int>(bands);
    std::vector<std::pair<double, std::size_t>> remainders;
    int given = 0;
    for (std::size_t b = 0; b < bands; ++b) {
      const double exact = total > 0 ? spare * lengths[b] / total : static_cast<double>(spare) / bands;
      share[b] += static_cast<int>(std::floor(exact));
      given += static_cast<int>(std::floor(exact));
      remainders.emplace_back(exact - std::floor(exact), b);
    }
    std::sort(remainders.begin(), remainders.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    for (int k = 0; k < spare - given; ++k) ++share[remainders[k % bands].second];
    starts.push_back(0);
    for (int n : share) starts.push_back(starts.back() + n);
  }
  layers_ = layers;
}

std::pair<int, double> ProjectedPaths::band_at(int column, double k) const {
  const std::vector<int>& starts = starts_[caps_.columns[column].group];
  const int bands = static_cast<int>(starts.size()) - 1;
  int b = 0;
  while (b + 1 < bands && k > starts[b + 1]) ++b;
  const double span = starts[b + 1] - starts[b];
  return {b, std::clamp((k - starts[b]) / span, 0.0, 1.0)};
}

std::vector<Vec3> ProjectedPaths::rim_at(double k) const {
  // Per column, its band at k, the fraction through it, and its links' (u, v) there.
  struct Place {
    int band = 0;
    double t = 0;
    gp_Pnt2d first, second;
  };
  std::vector<Place> places(caps_.columns.size());
  std::map<int, BRepAdaptor_Surface> surfaces;
  for (std::size_t c = 0; c < caps_.columns.size(); ++c) {
    Place& place = places[c];
    std::tie(place.band, place.t) = band_at(static_cast<int>(c), k);
    const ProjectedBand& band = caps_.columns[c].bands[place.band];
    const TopoDS_Face& face = index_.face(band.face);
    place.first = uv_at(band.first_link, face, band.first_forward, place.t);
    place.second = uv_at(band.second_link, face, band.second_forward, place.t);
    surfaces.try_emplace(band.face, face);
  }
  std::vector<Vec3> out;
  out.reserve(rim_.size());
  for (const RimPoint& r : rim_) {
    const OnColumn& on = r.columns.front();
    const Place& place = places[on.column];
    const BandFrame& f = frames_[on.column][place.band];
    const std::array<double, 4>& e = on.ends[place.band];
    const double s = on.s, t = place.t;
    // Transfinite interpolation of the band's four edges (a Coons patch) in its (u, v).
    const double u = (1 - t) * e[0] + t * e[2] + (1 - s) * place.first.X() + s * place.second.X() -
                     ((1 - s) * (1 - t) * f.u[0] + s * (1 - t) * f.u[1] + (1 - s) * t * f.u[2] + s * t * f.u[3]);
    const double v = (1 - t) * e[1] + t * e[3] + (1 - s) * place.first.Y() + s * place.second.Y() -
                     ((1 - s) * (1 - t) * f.v[0] + s * (1 - t) * f.v[1] + (1 - s) * t * f.v[2] + s * t * f.v[3]);
    out.push_back(to_vec3(surfaces.at(caps_.columns[on.column].bands[place.band].face).Value(u, v)));
  }
  return out;
}

std::vector<Vec3> ProjectedPaths::at(double k) const {
  if (k <= 0) return source_;
  if (k >= layers_) return target_;
  const double t = k / layers_;
  const std::vector<Vec3> rim = rim_at(k);
  std::vector<Vec3> out = source_;
  for (std::size_t j = 0; j < rim_.size(); ++j) out[rim_[j].index] = rim[j];
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

std::vector<int> ProjectedPaths::faces_at(int point, double k) const {
  std::vector<int> out;
  if (point < 0 || point >= static_cast<int>(rim_of_.size()) || rim_of_[point] < 0) return out;
  {
    const RimPoint& r = rim_[rim_of_[point]];
    for (const OnColumn& on : r.columns) {
      const std::vector<int>& starts = starts_[caps_.columns[on.column].group];
      const auto& bands = caps_.columns[on.column].bands;
      for (std::size_t b = 0; b < bands.size(); ++b) {
        if (k >= starts[b] - 1e-9 && k <= starts[b + 1] + 1e-9) out.push_back(bands[b].face);
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace tquad
