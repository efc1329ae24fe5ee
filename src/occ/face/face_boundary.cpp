#include "occ/face/face_boundary.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>

#include "core/face_refusal.h"
#include "core/input_error.h"
#include "core/decomposition/planar_domain.h"
#include "occ/model/occ_vec.h"
#include <stdexcept>

namespace tquad {

namespace {

// Unit tangent of an edge occurrence, in its direction of travel, at parameter t.
Vec3 travel_tangent(const TopoDS_Edge& occurrence, double t) {
  const BRepAdaptor_Curve curve(occurrence);
  gp_Pnt p;
  gp_Vec d;
  curve.D1(t, p, d);
  Vec3 v = to_vec3(d);
  if (occurrence.Orientation() == TopAbs_REVERSED) v = -1.0 * v;
  const double length = norm(v);
  return length > 0 ? (1.0 / length) * v : v;
}

// Outer normal of the face (its surface `surface`) at (u, v).
Vec3 face_normal(const TopoDS_Face& face, const BRepAdaptor_Surface& surface, double u, double v) {
  gp_Pnt p;
  gp_Vec du, dv;
  surface.D1(u, v, p, du, dv);
  Vec3 n = to_vec3(du.Crossed(dv));
  if (face.Orientation() == TopAbs_REVERSED) n = -1.0 * n;
  const double length = norm(n);
  return length > 0 ? (1.0 / length) * n : n;
}

// 3D length along a closed loop of nodes to each node (size + 1 entries).
std::vector<double> loop_arc_lengths(const std::vector<NodeId>& loop, const std::vector<Vec3>& nodes) {
  std::vector<double> arc{0.0};
  for (std::size_t i = 0; i < loop.size(); ++i) {
    arc.push_back(arc.back() + distance(nodes[loop[i]], nodes[loop[(i + 1) % loop.size()]]));
  }
  return arc;
}

}  // namespace

double signed_uv_area(const std::vector<Vec3>& uv) { return 0.5 * twice_signed_area(uv); }

bool is_disk_around_pole(const FaceBoundary& b) {
  return b.has_degenerate_edge && std::find(b.is_seam.begin(), b.is_seam.end(), 1) != b.is_seam.end();
}

Vec3 polar_to_uv(const PolarMap& m, const Vec3& xy) {
  const double r = std::hypot(xy.x, xy.y);
  double theta = std::atan2(-m.side * xy.y, xy.x);
  double turns;  // of the period, from u_ref
  if (m.angle < 2 * M_PI) {
    turns = theta / m.angle + 0.5;  // a sector: theta in [-angle / 2, angle / 2], no wrap
  } else {
    if (theta < 0) theta += 2 * M_PI;
    turns = theta / (2 * M_PI);
  }
  return {m.u_ref + turns * m.period, m.pole_v + m.side * r * m.radius, 0.0};
}

namespace {

// The polar map of a face periodic in u (period) around its pole at v = pole_v that
// holds the loop points `uv`: u_ref their least u, radius their greatest |v - pole_v|,
// side that of the farthest. The angle stays a full turn.
PolarMap polar_map_around(const std::vector<Vec3>& uv, double pole_v, double period) {
  PolarMap m;
  m.period = period;
  m.pole_v = pole_v;
  m.u_ref = uv[0].x;
  m.radius = 0;
  for (const Vec3& p : uv) {
    m.u_ref = std::min(m.u_ref, p.x);
    if (std::abs(p.y - pole_v) > m.radius) {
      m.radius = std::abs(p.y - pole_v);
      m.side = p.y > pole_v ? 1.0 : -1.0;
    }
  }
  return m;
}

// The polar (x, y) of a (u, v): the inverse of polar_to_uv.
Vec3 uv_to_polar(const PolarMap& m, const Vec3& uv) {
  const double theta = m.angle < 2 * M_PI ? m.angle * ((uv.x - m.u_ref) / m.period - 0.5)
                                          : 2 * M_PI * (uv.x - m.u_ref) / m.period;
  const double r = std::abs(uv.y - m.pole_v) / m.radius;
  return {r * std::cos(theta), -m.side * r * std::sin(theta), 0.0};
}

// How far the surface turns around its pole at v = pole_v: the length of the circle
// v = pole_v + side * delta over its mean distance from the pole, for delta a
// thousandth of the face's extent in v (64 chords: 4e-4 short of the limit).
double angle_around_pole(const BRepAdaptor_Surface& surface, const PolarMap& m) {
  const int samples = 64;
  const double v = m.pole_v + m.side * 1e-3 * m.radius;
  const gp_Pnt pole = surface.Value(m.u_ref, m.pole_v);
  double circle = 0, distance_sum = 0;
  gp_Pnt previous = surface.Value(m.u_ref, v);
  for (int i = 1; i <= samples; ++i) {
    const gp_Pnt p = surface.Value(m.u_ref + m.period * i / samples, v);
    circle += p.Distance(previous);
    distance_sum += p.Distance(pole);
    previous = p;
  }
  return distance_sum > 0 ? circle / (distance_sum / samples) : 0.0;
}

// Under this fraction of the face's (u, v) extent in both directions, a degenerate
// edge's pcurve is a point of the chart, not a pole (is_pole_edge).
constexpr double kChartPointSpan = 1e-3;

}  // namespace

bool is_pole_edge(const TopoDS_Edge& edge, const TopoDS_Face& face) {
  if (!BRep_Tool::Degenerated(edge)) return false;
  double f = 0, l = 0;
  const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, f, l);
  if (pcurve.IsNull()) return true;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  double du = 0, dv = 0;
  const gp_Pnt2d ends[3] = {pcurve->Value(f), pcurve->Value(0.5 * (f + l)), pcurve->Value(l)};
  for (const gp_Pnt2d& a : ends) {
    for (const gp_Pnt2d& b : ends) {
      du = std::max(du, std::abs(a.X() - b.X()));
      dv = std::max(dv, std::abs(a.Y() - b.Y()));
    }
  }
  return du > kChartPointSpan * (u1 - u0) || dv > kChartPointSpan * (v1 - v0);
}

double face_pole_angle(const TopoDS_Face& face) {
  const BRepAdaptor_Surface surface(face);
  if (!surface.IsUPeriodic()) return 0.0;
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    if (!is_pole_edge(edge, face)) continue;
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (pcurve.IsNull()) return 0.0;
    double u_min = 0, u_max = 0, v_min = 0, v_max = 0;
    BRepTools::UVBounds(face, u_min, u_max, v_min, v_max);
    PolarMap m;
    m.period = surface.UPeriod();
    m.u_ref = u_min;
    m.pole_v = pcurve->Value(0.5 * (first + last)).Y();
    m.side = 0.5 * (v_min + v_max) > m.pole_v ? 1.0 : -1.0;
    m.radius = std::max(std::abs(v_min - m.pole_v), std::abs(v_max - m.pole_v));
    return m.radius > 0 ? angle_around_pole(surface, m) : 0.0;
  }
  return 0.0;
}

std::optional<PoleSector> pole_sector(const FaceBoundary& b, const TopoDS_Face& face) {
  if (!is_disk_around_pole(b) || b.inner_wires > 0 || b.polar) return std::nullopt;
  const BRepAdaptor_Surface surface(face);
  if (!surface.IsUPeriodic()) return std::nullopt;
  const int n = static_cast<int>(b.nodes.size());
  PolarMap m = polar_map_around(b.uv, b.pole_v, surface.UPeriod());
  if (!(m.radius > 0)) return std::nullopt;
  // The apex: the one loop node on the pole (within a millionth of the face's
  // extent in v: pcurves of other systems' files end there only to their tolerance).
  std::vector<int> apex;
  for (int i = 0; i < n; ++i) {
    if (std::abs(b.uv[i].y - m.pole_v) <= 1e-6 * m.radius) apex.push_back(i);
  }
  if (apex.size() != 1) return std::nullopt;
  m.angle = angle_around_pole(surface, m);
  if (!(m.angle > 0) || m.angle >= kSectorAngleBelow) return std::nullopt;
  // The seam's ends at the rim: where the loop passes between a seam edge and
  // another one, the apex aside. A sharp vertex elsewhere on the rim would be a
  // corner the sector's halves miss.
  PoleSector sector;
  sector.apex = apex[0];
  std::vector<int> ends;
  const int edges = static_cast<int>(b.edge_start.size());
  for (int k = 0; k < edges; ++k) {
    const int start = b.edge_start[k];
    if (start == sector.apex) continue;
    if (b.is_seam[k] != b.is_seam[(k + edges - 1) % edges]) {
      ends.push_back(start);
    } else if (b.turn[k] > kSectorRimTurn) {
      return std::nullopt;
    }
  }
  if (ends.size() != 2) return std::nullopt;
  // In walking order: the apex, the first side, the rim, the second side.
  const auto ahead = [&](int from, int to) { return ((to - from) % n + n) % n; };
  if (ahead(sector.apex, ends[1]) < ahead(sector.apex, ends[0])) std::swap(ends[0], ends[1]);
  sector.rim_start = ends[0];
  sector.rim_end = ends[1];
  FaceBoundary& out = sector.boundary;
  out = b;
  out.uv.clear();
  for (const Vec3& p : b.uv) out.uv.push_back(uv_to_polar(m, p));
  out.polar = m;
  return sector;
}

namespace {

// The outer wire's edge occurrences other than its seams, joined into closed loops
// (occurrence indices): each continues with the occurrence that starts at the node
// where it ends, the next in the wire's order first. Around a plain disk that is one
// loop, the rim; where the seam passes through a hole, the wire runs rim, seam,
// hole, seam, and without the seam the hole closes on its own. Empty when the
// occurrences do not close.
std::vector<std::vector<int>> loops_without_seams(const FaceBoundary& b) {
  const int edges = static_cast<int>(b.edge_start.size());
  const int n = static_cast<int>(b.nodes.size());
  std::vector<int> kept;
  for (int k = 0; k < edges; ++k) if (!b.is_seam[k]) kept.push_back(k);
  const auto start = [&](int k) { return b.nodes[b.edge_start[k]]; };
  const auto end = [&](int k) { return b.nodes[(k + 1 < edges ? b.edge_start[k + 1] : n) % n]; };
  const int count = static_cast<int>(kept.size());
  std::vector<char> used(count, 0);
  std::vector<std::vector<int>> loops;
  for (int s = 0; s < count; ++s) {
    if (used[s]) continue;
    std::vector<int> loop{s};
    used[s] = 1;
    while (end(kept[loop.back()]) != start(kept[s])) {
      int next = -1;
      for (int d = 1; d < count && next < 0; ++d) {
        const int j = (loop.back() + d) % count;
        if (!used[j] && start(kept[j]) == end(kept[loop.back()])) next = j;
      }
      if (next < 0) return {};
      used[next] = 1;
      loop.push_back(next);
    }
    for (int& i : loop) i = kept[i];
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace

FaceBoundary around_pole(const FaceBoundary& b, const TopoDS_Face& face, int face_index,
                         const std::vector<Vec3>& nodes) {
  const BRepAdaptor_Surface surface(face);
  const std::string name = "face " + std::to_string(face_index);
  if (!surface.IsUPeriodic()) {
    throw FaceRefusalError(RefusalCode::not_supported, name + " has a seam and a pole but is not periodic in u; not supported yet");
  }
  if (std::find(b.is_seam.begin(), b.is_seam.end(), 0) == b.is_seam.end()) {
    throw FaceRefusalError(RefusalCode::not_supported, name + " has no edge besides its seam and pole");
  }
  const std::vector<std::vector<int>> loops = loops_without_seams(b);
  if (loops.empty()) {
    throw FaceRefusalError(RefusalCode::not_supported, name + ": its outer wire without its seam does not close");
  }
  // Each loop's nodes, (u, v) and edges, walked as in the wire.
  const int n = static_cast<int>(b.nodes.size());
  std::vector<NodeLoop> walked;
  std::vector<Vec3> all_uv;
  for (const std::vector<int>& loop : loops) {
    NodeLoop& w = walked.emplace_back();
    for (int k : loop) {
      const int first = b.edge_start[k];
      const int last = k + 1 < static_cast<int>(b.edge_start.size()) ? b.edge_start[k + 1] : n;
      w.edge_start.push_back(static_cast<int>(w.nodes.size()));
      w.edge_index.push_back(b.edge_index[k]);
      for (int i = first; i < last; ++i) {
        w.nodes.push_back(b.nodes[i]);
        w.uv.push_back(b.uv[i]);
        all_uv.push_back(b.uv[i]);
      }
    }
  }
  const PolarMap m = polar_map_around(all_uv, b.pole_v, surface.UPeriod());
  for (NodeLoop& w : walked) {
    for (Vec3& p : w.uv) p = uv_to_polar(m, p);
  }
  // The outer loop encloses the most; the others are holes the seam went through.
  std::size_t outer = 0;
  for (std::size_t i = 1; i < walked.size(); ++i) {
    if (std::abs(twice_signed_area(walked[i].uv)) > std::abs(twice_signed_area(walked[outer].uv))) outer = i;
  }
  FaceBoundary out;
  out.has_degenerate_edge = true;
  out.inner_wires = b.inner_wires + static_cast<int>(walked.size()) - 1;
  out.nodes = walked[outer].nodes;
  out.uv = walked[outer].uv;
  out.edge_start = walked[outer].edge_start;
  out.edge_index = walked[outer].edge_index;
  for (int k : loops[outer]) {
    out.start_vertex.push_back(b.start_vertex[k]);
    out.is_seam.push_back(0);
    out.turn.push_back(b.turn[k]);
  }
  out.polar = m;
  out.arc_length = loop_arc_lengths(out.nodes, nodes);  // for the corner choice
  out.holes = b.holes;
  for (NodeLoop& hole : out.holes) {
    for (Vec3& p : hole.uv) p = uv_to_polar(m, p);
  }
  for (std::size_t i = 0; i < walked.size(); ++i) {
    if (i != outer) out.holes.push_back(std::move(walked[i]));
  }
  out.smooth_pole = face_pole_angle(face) >= kSmoothPoleAngle;
  return out;
}

bool runs_counter_clockwise(const FaceBoundary& b, const TopoDS_Face& face) {
  return (signed_uv_area(b.uv) > 0) == (face.Orientation() != TopAbs_REVERSED);
}

namespace {

// One wire walked in order: its edges' shared nodes (each edge's last node is the next
// one's first, so it is left out), their (u, v) from the pcurves, and per edge
// occurrence where it starts. Degenerate edges add no node.
struct WireWalk {
  std::vector<NodeId> nodes;
  std::vector<Vec3> uv;
  struct Occurrence {
    TopoDS_Edge edge;
    double first_param, last_param;  // in travel order
    int start;                       // loop position of its first node
    NodeId start_node;
    bool seam;
  };
  std::vector<Occurrence> occurrences;
  bool has_degenerate_edge = false;
  double pole_v = 0;  // v of the first degenerate edge
};

WireWalk walk_wire(const TopoDS_Wire& wire, const TopoDS_Face& face, int face_index, const ShapeIndex& index,
                   const std::vector<EdgeNodes>& edges) {
  WireWalk w;
  std::vector<std::pair<int, NodeId>> ends;  // each occurrence's edge and its last node
  for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next()) {
    const TopoDS_Edge& occurrence = it.Current();
    const int e = index.edge_index(occurrence);
    if (index.contracted(e)) continue;  // its two ends are one node (edge_contraction.h)
    const EdgeNodes& en = edges[e];
    double f = 0, l = 0;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(occurrence, face, f, l);
    if (pcurve.IsNull()) throw std::runtime_error("edge " + std::to_string(e) + " has no pcurve on face " + std::to_string(face_index));
    if (en.degenerate) {
      if (is_pole_edge(occurrence, face)) {
        if (!w.has_degenerate_edge) w.pole_v = pcurve->Value(0.5 * (f + l)).Y();
        w.has_degenerate_edge = true;
      }
      continue;
    }
    if (en.nodes.size() < 2 || en.params.size() != en.nodes.size()) {
      throw std::runtime_error("edge " + std::to_string(e) + " of face " + std::to_string(face_index) + " was not discretized");
    }
    const bool reversed = occurrence.Orientation() == TopAbs_REVERSED;
    const int n = static_cast<int>(en.nodes.size()) - 1;
    w.occurrences.push_back({occurrence, reversed ? en.params[n] : en.params[0], reversed ? en.params[0] : en.params[n],
                             static_cast<int>(w.nodes.size()), en.nodes[reversed ? n : 0],
                             BRep_Tool::IsClosed(occurrence, face)});
    for (int k = 0; k < n; ++k) {
      const int i = reversed ? n - k : k;
      w.nodes.push_back(en.nodes[i]);
      const gp_Pnt2d p = pcurve->Value(en.params[i]);
      w.uv.push_back({p.X(), p.Y(), 0.0});
    }
    ends.push_back({e, en.nodes[reversed ? 0 : n]});
  }
  // Each edge ends where the next one starts: a wire closed by two vertices at one
  // point (a boolean left one on a generated part) would leave a crack there.
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const NodeId next = w.occurrences[(k + 1) % ends.size()].start_node;
    if (ends[k].second != next) {
      throw FaceRefusalError(RefusalCode::damaged,
                             "face " + std::to_string(face_index) + ": its edge " + std::to_string(ends[k].first) +
                                 " ends at another vertex than the next edge of its wire starts at, though at one "
                                 "point (a wire closed by two vertices? a damaged file?)");
    }
  }
  return w;
}

}  // namespace

FaceBoundary face_boundary(const ShapeIndex& index, int face_index, const std::vector<EdgeNodes>& edges,
                           const std::vector<Vec3>& nodes) {
  const TopoDS_Face& face = index.face(face_index);
  const TopoDS_Wire outer = BRepTools::OuterWire(face);
  if (outer.IsNull()) {
    throw FaceRefusalError(RefusalCode::damaged, "face " + std::to_string(face_index) + " has no outer wire (a damaged file?)");
  }
  FaceBoundary b;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
    if (w.Current().IsSame(outer)) continue;
    ++b.inner_wires;
    const WireWalk hole = walk_wire(TopoDS::Wire(w.Current()), face, face_index, index, edges);
    if (hole.nodes.empty()) {  // OpenCASCADE's wire explorer found no edge joined to the next
      throw FaceRefusalError(RefusalCode::damaged, "face " + std::to_string(face_index) + "'s hole " +
                                                       std::to_string(b.inner_wires) +
                                                       " gives no edge in order: its edges do not join end to end (a wire closed by two vertices at one "
                                                       "point? a damaged file?)");
    }
    NodeLoop loop{hole.nodes, hole.uv, {}, {}};
    for (const WireWalk::Occurrence& o : hole.occurrences) {
      loop.edge_start.push_back(o.start);
      loop.edge_index.push_back(index.edge_index(o.edge));
    }
    b.holes.push_back(std::move(loop));
  }
  const WireWalk walk = walk_wire(outer, face, face_index, index, edges);
  if (walk.nodes.empty()) {
    throw FaceRefusalError(RefusalCode::damaged, "face " + std::to_string(face_index) + " has no edge in its outer wire (a damaged file?)");
  }
  b.nodes = walk.nodes;
  b.uv = walk.uv;
  b.has_degenerate_edge = walk.has_degenerate_edge;
  b.pole_v = walk.pole_v;
  for (const WireWalk::Occurrence& o : walk.occurrences) {
    b.edge_start.push_back(o.start);
    b.start_vertex.push_back(o.start_node);
    b.edge_index.push_back(index.edge_index(o.edge));
    b.is_seam.push_back(o.seam);
  }
  const auto& occurrences = walk.occurrences;
  b.arc_length = loop_arc_lengths(b.nodes, nodes);
  // Turning angle at each edge start: from the previous occurrence's end tangent to
  // this one's start tangent, signed by the face normal there.
  const int count = static_cast<int>(occurrences.size());
  // One surface adaptor for the face: each costs the face's (u, v) bounds, every
  // pcurve's, and one per corner made a large share of the main thread's work before
  // the faces are meshed.
  const BRepAdaptor_Surface surface(face);
  for (int k = 0; k < count; ++k) {
    const WireWalk::Occurrence& in = occurrences[(k + count - 1) % count];
    const WireWalk::Occurrence& out = occurrences[k];
    const Vec3 a = travel_tangent(in.edge, in.last_param), c = travel_tangent(out.edge, out.first_param);
    const Vec3& uv = b.uv[b.edge_start[k]];
    const double angle = std::atan2(dot(cross(a, c), face_normal(face, surface, uv.x, uv.y)), dot(a, c));
    b.turn.push_back(angle);
  }
  // Convex corners turn left around the outer normal when the loop runs
  // counter-clockwise around it: counter-clockwise in (u, v) for a FORWARD face,
  // clockwise for a REVERSED one. Otherwise the signs are flipped.
  if (!runs_counter_clockwise(b, face)) for (double& t : b.turn) t = -t;
  return b;
}

}  // namespace tquad
