#include "occ/sweep/sweep.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax3.hxx>
#include <gp_Lin.hxx>
#include <gp_Pln.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "core/input_error.h"
#include "core/repair/hex_smoothing.h"
#include "occ/model/occ_vec.h"
#include "occ/model/shape_index.h"
#include "occ/sweep/projected_sweep.h"

namespace tquad {

namespace {

// The shape face indices of a sub-shape's faces, ascending.
std::vector<int> faces_of(const ShapeIndex& index, const TopoDS_Shape& shape) {
  std::set<int> out;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) out.insert(index.face_index(it.Current()));
  return {out.begin(), out.end()};
}

std::set<int> edges_of(const ShapeIndex& index, int face) {
  std::set<int> out;
  for (TopExp_Explorer it(index.face(face), TopAbs_EDGE); it.More(); it.Next()) {
    out.insert(index.edge_index(it.Current()));
  }
  return out;
}

std::vector<gp_Pnt> vertex_points(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
  std::vector<gp_Pnt> out;
  for (int i = 1; i <= vertices.Extent(); ++i) out.push_back(BRep_Tool::Pnt(TopoDS::Vertex(vertices(i))));
  return out;
}

gp_Pnt centroid(const std::vector<gp_Pnt>& points) {
  gp_XYZ sum(0, 0, 0);
  for (const gp_Pnt& p : points) sum += p.XYZ();
  return gp_Pnt(sum / static_cast<double>(std::max<std::size_t>(1, points.size())));
}

std::string face_name(int f) { return "face " + std::to_string(f); }

// Room for `extra` more elements, growing by half at least: one copy per solid at
// most, not one per doubling of a large sweep.
template <typename T>
void make_room(std::vector<T>& v, std::size_t extra) {
  const std::size_t needed = v.size() + extra;
  if (needed > v.capacity()) v.reserve(std::max(needed, v.capacity() + v.capacity() / 2));
}

// How the source cap becomes the target: a translation by `d` (an extrusion) or a
// rotation by `angle` about `axis` (a revolution); `at(p, f)` is the fraction f of it.
struct SweepMotion {
  bool rotation = false;
  bool closed = false;  // a full turn: the last layer is the first
  gp_Vec d;
  gp_Ax1 axis;
  double angle = 0.0;

  // The fraction f of the motion, to apply to many points (one rotation's sines a
  // layer, not a node).
  gp_Trsf part(double f) const {
    gp_Trsf out;
    if (rotation) {
      out.SetRotation(axis, f * angle);
    } else {
      out.SetTranslation(f * d);
    }
    return out;
  }
  gp_Pnt at(const gp_Pnt& p, double f) const { return p.Transformed(part(f)); }
  // The path length of p from source to target.
  double length(const gp_Pnt& p) const {
    if (!rotation) return d.Magnitude();
    return std::abs(angle) * gp_Lin(axis).Distance(p);
  }
};

// Whether `motion` takes every vertex of `vs` onto one of `vt`.
bool maps_vertices(const SweepMotion& motion, const std::vector<gp_Pnt>& vs, const std::vector<gp_Pnt>& vt, double tol) {
  return std::all_of(vs.begin(), vs.end(), [&](const gp_Pnt& v) {
    const gp_Pnt moved = motion.at(v, 1.0);
    return std::any_of(vt.begin(), vt.end(), [&](const gp_Pnt& w) { return w.Distance(moved) <= tol; });
  });
}

// Whether edge e, joining the caps, is the path of one point under `motion`: a
// straight segment equal to d, or an arc of `angle` about the axis.
bool is_path(const TopoDS_Edge& edge, const SweepMotion& motion, double tol) {
  const BRepAdaptor_Curve curve(edge);
  const gp_Pnt start = curve.Value(curve.FirstParameter()), end = curve.Value(curve.LastParameter());
  if (!motion.rotation) {
    const gp_Vec along(start, end);
    return curve.GetType() == GeomAbs_Line &&
           std::min((along - motion.d).Magnitude(), (along + motion.d).Magnitude()) <= tol;
  }
  if (curve.GetType() != GeomAbs_Circle) return false;
  const gp_Ax1 circle = curve.Circle().Axis();
  const bool coaxial = circle.IsParallel(motion.axis, 1e-9) &&
                       gp_Lin(motion.axis).Distance(circle.Location()) <= tol;
  const double span = curve.LastParameter() - curve.FirstParameter();
  return coaxial && std::abs(span - std::abs(motion.angle)) <= 1e-7;
}

// What the caps search reads of a solid's faces, computed once: a pair test then
// costs a comparison of vertices, not a walk over the topology.
struct SolidFaces {
  std::vector<int> faces;                // shape face indices
  std::map<int, bool> planar;
  std::map<int, std::vector<gp_Pnt>> vertices;
  std::map<int, std::set<int>> edges;
  std::vector<int> circles;              // edges of the solid that are circular arcs

  SolidFaces(const ShapeIndex& index, std::vector<int> solid_faces) : faces(std::move(solid_faces)) {
    std::set<int> all_edges;
    for (int f : faces) {
      planar[f] = BRepAdaptor_Surface(index.face(f)).GetType() == GeomAbs_Plane;
      vertices[f] = vertex_points(index.face(f));
      edges[f] = edges_of(index, f);
      all_edges.insert(edges[f].begin(), edges[f].end());
    }
    for (int e : all_edges) {
      if (BRepAdaptor_Curve(index.edge(e)).GetType() == GeomAbs_Circle) circles.push_back(e);
    }
  }
};

// Why faces s and t are not the caps of a sweep of the solid, or "" with `motion`
// taking s onto t: first as an extrusion, then as a revolution about the axis of a
// circular edge joining them.
std::string sweep_caps(const ShapeIndex& index, const SolidFaces& solid, int s, int t, double tol,
                       SweepMotion& motion) {
  for (int f : {s, t}) {
    if (!solid.planar.at(f)) return face_name(f) + " is not planar";
  }
  const std::vector<gp_Pnt>& vs = solid.vertices.at(s);
  const std::vector<gp_Pnt>& vt = solid.vertices.at(t);
  if (vs.size() != vt.size()) return face_name(s) + " and " + face_name(t) + " have different numbers of vertices";
  const std::set<int>& source_edges = solid.edges.at(s);
  const std::set<int>& target_edges = solid.edges.at(t);
  std::vector<SweepMotion> candidates;
  SweepMotion shift;
  shift.d = gp_Vec(centroid(vs), centroid(vt));
  const gp_Dir normal = BRepAdaptor_Surface(index.face(s)).Plane().Axis().Direction();
  if (std::abs(shift.d.Dot(gp_Vec(normal))) > tol) candidates.push_back(shift);
  for (int e : solid.circles) {
    if (source_edges.count(e) || target_edges.count(e)) continue;
    const BRepAdaptor_Curve curve(index.edge(e));
    const double span = curve.LastParameter() - curve.FirstParameter();
    if (!(span > 1e-6 && span < 2 * M_PI - 1e-6)) continue;
    for (double sign : {1.0, -1.0}) {
      SweepMotion turn;
      turn.rotation = true;
      turn.axis = curve.Circle().Axis();
      turn.angle = sign * span;
      candidates.push_back(turn);
    }
    break;  // one circle gives the axis; is_path checks the others
  }
  for (const SweepMotion& candidate : candidates) {
    if (!maps_vertices(candidate, vs, vt, tol)) continue;
    if (candidate.rotation) {
      for (const gp_Pnt& v : vs) {
        if (gp_Lin(candidate.axis).Distance(v) <= tol) {
          return face_name(s) + " touches the axis of its revolution: the hexahedra there would be wedges";
        }
      }
    }
    for (int f : solid.faces) {
      if (f == s || f == t) continue;
      for (int e : solid.edges.at(f)) {
        if (source_edges.count(e) || target_edges.count(e) || is_path(index.edge(e), candidate, tol)) continue;
        return "edge " + std::to_string(e) + " of side " + face_name(f) + " is not " +
               (candidate.rotation ? "an arc about the axis" : "a straight segment") + " from the source to the target";
      }
    }
    const std::size_t sides = solid.faces.size() - 2;
    if (sides != source_edges.size()) {
      return "its " + std::to_string(sides) + " side faces are not one per edge of " + face_name(s) + " (" +
             std::to_string(source_edges.size()) + "): side faces split along the sweep are not swept yet";
    }
    motion = candidate;
    return "";
  }
  return face_name(t) + " is not " + face_name(s) + " moved along one vector or turned about an axis";
}

struct SolidCaps {
  int source = -1, target = -1;
  SweepMotion motion;
  std::string why_not;  // when none: the first reason met
  TopoDS_Shape profile;  // a full turn's source: the solid's section by a half-plane
  std::optional<ProjectedCaps> projected;  // no exact motion: the general route's sides
};

// The caps of the solid: the pair given, or the valid pair whose source has the most
// edges (the profile; on a box every pair is valid), the lower face first on a tie.
SolidCaps find_caps(const ShapeIndex& index, const SolidFaces& solid, const SweepOptions& options, double tol) {
  const std::vector<int>& solid_faces = solid.faces;
  SolidCaps best;
  const bool given = options.source >= 0;
  std::size_t best_edges = 0;
  for (int s : solid_faces) {
    for (int t : solid_faces) {
      if (s == t || (given && (s != options.source || t != options.target))) continue;
      SweepMotion motion;
      const std::string why = sweep_caps(index, solid, s, t, tol, motion);
      if (!why.empty()) {
        // The most telling reason: one found past the caps' own tests.
        const bool telling = why.find(" is not planar") == std::string::npos &&
                             why.find(" numbers of vertices") == std::string::npos;
        if (best.why_not.empty() || given || telling) best.why_not = why;
        continue;
      }
      const std::size_t edges = solid.edges.at(s).size();
      if (best.source < 0 || edges > best_edges) {
        best.source = s;
        best.target = t;
        best.motion = motion;
        best_edges = edges;
      }
    }
  }
  if (best.source < 0 && best.why_not.empty()) best.why_not = "it has no two planar faces";
  return best;
}

// Whether face f is a surface of revolution about `axis` (a plane across it, a
// coaxial cylinder, cone, torus or revolved surface, a sphere centred on it).
bool turns_about(const TopoDS_Face& f, const gp_Ax1& axis, double tol) {
  const BRepAdaptor_Surface surface(f);
  const gp_Lin line(axis);
  const auto coaxial = [&](const gp_Ax1& other) {
    return other.IsParallel(axis, 1e-9) && line.Distance(other.Location()) <= tol;
  };
  switch (surface.GetType()) {
    case GeomAbs_Plane: return surface.Plane().Axis().IsParallel(axis, 1e-9);
    case GeomAbs_Cylinder: return coaxial(surface.Cylinder().Axis());
    case GeomAbs_Cone: return coaxial(surface.Cone().Axis());
    case GeomAbs_Torus: return coaxial(surface.Torus().Axis());
    case GeomAbs_Sphere: return line.Distance(surface.Sphere().Location()) <= tol;
    case GeomAbs_SurfaceOfRevolution: return coaxial(surface.AxeOfRevolution());
    default: return false;
  }
}

// A solid whose every face turns about one axis (that of its first circular edge) is a
// full revolution of its section by a half-plane through the axis: that section, the
// profile, is its source. Empty `profile` (with the reason) when it is not one.
SolidCaps full_revolution(const ShapeIndex& index, const TopoDS_Shape& solid, const SolidFaces& faces, double tol,
                          double diagonal) {
  SolidCaps out;
  if (faces.circles.empty()) {
    out.why_not = "no circular edge gives an axis";
    return out;
  }
  const gp_Ax1 axis = BRepAdaptor_Curve(index.edge(faces.circles.front())).Circle().Axis();
  for (int f : faces.faces) {
    if (!turns_about(index.face(f), axis, tol)) {
      out.why_not = face_name(f) + " does not turn about the axis of edge " + std::to_string(faces.circles.front());
      return out;
    }
  }
  // The half-plane at a generic angle from a vertex off the axis (clear of seams).
  const gp_Lin line(axis);
  gp_Vec radial;
  for (const auto& [f, points] : faces.vertices) {
    for (const gp_Pnt& v : points) {
      if (line.Distance(v) > tol) {
        const gp_Vec off(axis.Location(), v);
        radial = off - gp_Vec(axis.Direction()) * off.Dot(gp_Vec(axis.Direction()));
        break;
      }
    }
    if (radial.Magnitude() > 0) break;
  }
  if (!(radial.Magnitude() > 0)) {
    out.why_not = "all its vertices lie on its axis";
    return out;
  }
  gp_Trsf turn;
  turn.SetRotation(axis, 0.4142);
  const gp_Dir x(radial.Transformed(turn)), z = axis.Direction();
  const gp_Dir normal = z.Crossed(x);
  const double reach = 4 * diagonal;
  const gp_Pln plane(gp_Ax3(axis.Location(), normal, x));
  const TopoDS_Face half = BRepBuilderAPI_MakeFace(plane, 0.0, reach, -reach, reach).Face();
  BRepAlgoAPI_Common section(solid, half);
  if (!section.IsDone()) {
    out.why_not = "its section by a half-plane through the axis failed";
    return out;
  }
  TopTools_IndexedMapOfShape pieces;
  TopExp::MapShapes(section.Shape(), TopAbs_FACE, pieces);
  if (pieces.Extent() != 1) {
    out.why_not = "its section by a half-plane through the axis is " + std::to_string(pieces.Extent()) + " faces";
    return out;
  }
  for (const gp_Pnt& v : vertex_points(pieces(1))) {
    if (line.Distance(v) <= tol) {
      out.why_not = "its profile touches the axis of its revolution: the hexahedra there would be wedges";
      return out;
    }
  }
  out.profile = pieces(1);
  out.motion.rotation = true;
  out.motion.closed = true;
  out.motion.axis = axis;
  out.motion.angle = 2 * M_PI;
  return out;
}

double shape_diagonal(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());
}

// One solid's hexahedra, appended to `out`; throws InputError naming what failed.
void sweep_solid(const TopoDS_Shape& shape, const ShapeIndex& index, int solid, const std::vector<int>& solid_faces,
                 const SolidCaps& caps, const SweepOptions& options, double tol, HexMesh& out, SweepResult& times,
                 std::map<int, ShapeMesh>& cap_meshes) {
  double& size = times.size;
  auto start = std::chrono::steady_clock::now();
  ShapeMeshOptions face = options.face;
  face.keep_going = false;
  const bool closed = caps.motion.closed;
  if (!closed) face.faces = {caps.source};
  if (closed) face.damaged_faces.clear();  // numbered for the shape, not the profile
  // A cap another solid swept already is this solid's source as that solid left it:
  // the two share its nodes (merge_shared_face_nodes).
  const auto given = closed ? cap_meshes.end() : cap_meshes.find(caps.source);
  ShapeMeshResult source;
  if (given != cap_meshes.end()) {
    source.mesh = given->second;
    source.size = size;
  } else {
    source = mesh_shape(closed ? caps.profile : shape, face);
  }
  times.source_seconds += seconds_since(start);
  start = std::chrono::steady_clock::now();
  size = source.size;
  // The source's nodes, compacted to those of its quads.
  std::map<NodeId, NodeId> compact;
  std::vector<Vec3> base;
  for (const Quad& q : source.mesh.quads) {
    for (NodeId n : q) {
      if (compact.emplace(n, static_cast<NodeId>(base.size())).second) base.push_back(source.mesh.nodes[n]);
    }
  }
  // Second order: the source's edge middles (on its surface and curves) go through
  // the layers as the corners do, and each corner's path between two layers gets a
  // middle (on the side surfaces: the path is the route's own).
  const bool second = source.mesh.second_order();
  std::map<std::pair<NodeId, NodeId>, NodeId> middle_of;  // source corner pair -> source middle
  std::map<NodeId, NodeId> compact_middle;
  std::vector<Vec3> base_middles;
  if (second) {
    for (std::size_t k = 0; k < source.mesh.quads.size(); ++k) {
      const Quad& q = source.mesh.quads[k];
      for (int i = 0; i < 4; ++i) {
        const NodeId m = source.mesh.mid_nodes[k][i];
        middle_of[std::minmax(q[i], q[(i + 1) % 4])] = m;
        if (compact_middle.emplace(m, static_cast<NodeId>(base_middles.size())).second) {
          base_middles.push_back(source.mesh.nodes[m]);
        }
      }
    }
  }
  // The source's boundary: corners and middles on edges of one quad only.
  std::map<std::pair<NodeId, NodeId>, int> uses;
  for (const Quad& q : source.mesh.quads) {
    for (int i = 0; i < 4; ++i) ++uses[std::minmax(q[i], q[(i + 1) % 4])];
  }
  std::set<NodeId> rim_corners, rim_middles;
  for (const auto& [edge, n] : uses) {
    if (n != 1) continue;
    rim_corners.insert(edge.first);
    rim_corners.insert(edge.second);
    if (second) rim_middles.insert(middle_of.at(edge));
  }
  const long long count = static_cast<long long>(base.size());
  const long long middles = static_cast<long long>(base_middles.size());
  // Where the route puts the first n source points (corners, then middles) at the
  // fraction f of the sweep.
  std::vector<Vec3> points = base;
  points.insert(points.end(), base_middles.begin(), base_middles.end());
  // Where the route puts the first n source points at layer position k (0 to the
  // layers; k + 0.5 between two).
  std::function<std::vector<Vec3>(double, std::size_t)> place;
  int layers = 1;
  double height = 0.0;
  const SweepMotion& motion = caps.motion;
  std::shared_ptr<ProjectedPaths> paths;
  if (caps.projected) {
    std::vector<bool> rim(points.size(), false);
    for (NodeId n : rim_corners) rim[compact.at(n)] = true;
    for (NodeId n : rim_middles) rim[count + compact_middle.at(n)] = true;
    paths = std::make_shared<ProjectedPaths>(index, *caps.projected, points, rim, tol);
    height = paths->height();
    layers = options.layers > 0 ? options.layers : paths->layers_for(size);
    paths->set_layers(layers);  // each stacked side a share
    place = [paths](double k, std::size_t n) {
      std::vector<Vec3> all = paths->at(k);
      all.resize(n);
      return all;
    };
  } else {
    for (const Vec3& p : base) height = std::max(height, motion.length(gp_Pnt(p.x, p.y, p.z)));
    // The longest path over the size; a revolution at most 45 degrees a layer (the
    // rule curved edges follow, edge_discretization.h).
    const int fewest = motion.rotation ? static_cast<int>(std::ceil(std::abs(motion.angle) / (M_PI / 4) - 1e-9)) : 1;
    layers = std::max({1, fewest, static_cast<int>(std::lround(height / size))});
    if (options.layers > 0) layers = options.layers;
    if (closed && layers < 3) layers = 3;  // fewer would join a layer to itself
    place = [&points, &motion, layers](double k, std::size_t n) {
      std::vector<Vec3> moved(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(n));
      if (k == 0) return moved;
      const gp_Trsf move = motion.part(k / layers);
      for (Vec3& p : moved) p = to_vec3(gp_Pnt(p.x, p.y, p.z).Transformed(move));
      return moved;
    };
  }
  const int stored = closed ? layers : layers + 1;  // a full turn's last layer is its first
  const auto offset = static_cast<long long>(out.nodes.size());
  if ((count + middles) * stored + (second ? count * layers : 0) > static_cast<long long>(INT32_MAX) - offset) {
    throw InputError("solid " + std::to_string(solid) + ": the sweep would have over 2^31 nodes; use fewer layers or a larger size");
  }
  const std::size_t hex_count = source.mesh.quads.size() * static_cast<std::size_t>(layers);
  make_room(out.nodes, static_cast<std::size_t>((count + middles) * stored + (second ? count * layers : 0)));
  make_room(out.hexes, hex_count);
  make_room(out.scaled_jacobian, hex_count);
  if (second) {
    make_room(out.mid_nodes, hex_count);
    make_room(out.jacobian_ratio, hex_count);
  }
  // The nodes: every layer's corners, then every layer's middles, then the middles on
  // the paths between layers.
  std::vector<Vec3> layer_middles;
  for (int k = 0; k < stored; ++k) {
    const std::vector<Vec3> moved = place(k, points.size());
    out.nodes.insert(out.nodes.end(), moved.begin(), moved.begin() + count);
    layer_middles.insert(layer_middles.end(), moved.begin() + count, moved.end());
  }
  const auto layer = [&](int k) { return k % stored; };
  const auto at = [&](NodeId n, int k) { return static_cast<NodeId>(offset + layer(k) * count + compact.at(n)); };
  const auto plane_offset = static_cast<long long>(out.nodes.size());
  out.nodes.insert(out.nodes.end(), layer_middles.begin(), layer_middles.end());
  layer_middles = std::vector<Vec3>();
  const auto path_offset = static_cast<long long>(out.nodes.size());
  for (int k = 0; k < layers && second; ++k) {
    const std::vector<Vec3> moved = place(k + 0.5, static_cast<std::size_t>(count));
    out.nodes.insert(out.nodes.end(), moved.begin(), moved.end());
  }
  const auto plane_middle = [&](NodeId a, NodeId b, int k) {
    return static_cast<NodeId>(plane_offset + layer(k) * middles + compact_middle.at(middle_of.at(std::minmax(a, b))));
  };
  const auto path_middle = [&](NodeId n, int k) { return static_cast<NodeId>(path_offset + k * count + compact.at(n)); };
  SweptSolid record;
  record.solid = solid;
  record.source = caps.source;
  record.target = caps.target;
  record.layers = layers;
  record.height = height;
  record.projected = caps.projected.has_value();
  record.rotation = motion.rotation && !record.projected;
  record.vector = motion.rotation ? to_vec3(gp_Vec(motion.axis.Direction())) : to_vec3(motion.d);
  record.point = motion.rotation ? to_vec3(motion.axis.Location()) : Vec3{};
  record.angle = motion.angle;
  record.first_hex = static_cast<std::int64_t>(out.hexes.size());
  long long bad = 0;
  for (const Quad& q : source.mesh.quads) {
    const Vec3 normal = cross(source.mesh.nodes[q[2]] - source.mesh.nodes[q[0]],
                              source.mesh.nodes[q[3]] - source.mesh.nodes[q[1]]);
    // The way the quad moves into the first layer (its corners' mean step).
    Vec3 along{0, 0, 0};
    for (NodeId n : q) along += out.nodes[at(n, 1)] - out.nodes[at(n, 0)];
    const Quad bottom = dot(normal, along) > 0 ? q : Quad{q[0], q[3], q[2], q[1]};
    for (int k = 0; k < layers; ++k) {
      Hex h;
      for (int i = 0; i < 4; ++i) {
        h[i] = at(bottom[i], k);
        h[i + 4] = at(bottom[i], k + 1);
      }
      std::array<Vec3, 8> p;
      for (int i = 0; i < 8; ++i) p[i] = out.nodes[h[i]];
      const double sj = hex_scaled_jacobian(p);
      if (!(sj > 1e-6)) ++bad;
      out.hexes.push_back(h);
      out.scaled_jacobian.push_back(sj);
      if (!second) continue;
      std::array<NodeId, 12> m;
      for (int i = 0; i < 4; ++i) {
        m[i] = plane_middle(bottom[i], bottom[(i + 1) % 4], k);
        m[i + 4] = plane_middle(bottom[i], bottom[(i + 1) % 4], k + 1);
        m[i + 8] = path_middle(bottom[i], k);
      }
      std::array<Vec3, 20> all;
      for (int i = 0; i < 8; ++i) all[i] = p[i];
      for (int i = 0; i < 12; ++i) all[i + 8] = out.nodes[m[i]];
      const double ratio = hex20_jacobian_ratio(all);
      if (!(ratio > 1e-6)) ++bad;
      out.mid_nodes.push_back(m);
      out.jacobian_ratio.push_back(ratio);
    }
  }
  if (bad > 0 && paths && layers > 1) {
    // The general route's layers are a projection, not an exact motion: where it
    // inverts hexahedra, smooth the inner layers' interior nodes without ever making
    // a node's worst hexahedron worse (hex_smoothing.h), then measure again.
    std::vector<std::vector<std::size_t>> quads_of(static_cast<std::size_t>(count));
    std::vector<std::set<NodeId>> joined(static_cast<std::size_t>(count));
    for (std::size_t q = 0; q < source.mesh.quads.size(); ++q) {
      const Quad& quad = source.mesh.quads[q];
      for (int i = 0; i < 4; ++i) {
        const NodeId a = compact.at(quad[i]), b = compact.at(quad[(i + 1) % 4]);
        quads_of[a].push_back(q);
        joined[a].insert(b);
        joined[b].insert(a);
      }
    }
    std::vector<bool> on_rim(static_cast<std::size_t>(count), false);
    for (NodeId n : rim_corners) on_rim[compact.at(n)] = true;
    // A planar target's interior nodes move too, among their own layer's (their mean
    // stays on the plane): its quads are the source's mapped, and may be the tangle.
    const bool flat_target = BRepAdaptor_Surface(index.face(caps.target)).GetType() == GeomAbs_Plane;
    std::vector<HexSmoothingNode> free;
    for (int k = 1; k <= layers; ++k) {
      if (k == layers && !flat_target) break;
      for (NodeId i = 0; i < count; ++i) {
        if (on_rim[i]) continue;
        HexSmoothingNode n;
        n.node = static_cast<NodeId>(offset + k * count + i);
        for (NodeId j : joined[i]) n.neighbours.push_back(static_cast<NodeId>(offset + k * count + j));
        if (k < layers) {
          n.neighbours.push_back(static_cast<NodeId>(offset + (k - 1) * count + i));
          n.neighbours.push_back(static_cast<NodeId>(offset + (k + 1) * count + i));
        }
        for (std::size_t q : quads_of[i]) {
          for (int layer_below : {k - 1, k}) {
            if (layer_below < layers) {
              n.hexes.push_back(record.first_hex + static_cast<std::int64_t>(q) * layers + layer_below);
            }
          }
        }
        free.push_back(std::move(n));
      }
    }
    if (smooth_hexahedra(out.nodes, out.hexes, free, 50) > 0) {
      bad = 0;
      for (std::size_t k = static_cast<std::size_t>(record.first_hex); k < out.hexes.size(); ++k) {
        std::array<Vec3, 8> p;
        for (int i = 0; i < 8; ++i) p[i] = out.nodes[out.hexes[k][i]];
        out.scaled_jacobian[k] = hex_scaled_jacobian(p);
        if (!(out.scaled_jacobian[k] > 1e-6)) ++bad;
        if (!second) continue;
        // The moved nodes' edges are straight inside the solid: their middles halfway.
        std::array<NodeId, 12>& m = out.mid_nodes[k];
        constexpr int kEnds[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                      {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
        std::array<Vec3, 20> all;
        for (int i = 0; i < 8; ++i) all[i] = p[i];
        for (int e = 0; e < 12; ++e) {
          const NodeId a = out.hexes[k][kEnds[e][0]], b = out.hexes[k][kEnds[e][1]];
          const bool inner = [&] {
            for (NodeId n : {a, b}) {
              const long long local = n - offset, layer_of = local / count;
              if (layer_of > 0 && (layer_of < layers || flat_target) && !on_rim[local % count]) return true;
            }
            return false;
          }();
          if (inner) out.nodes[m[e]] = 0.5 * (out.nodes[a] + out.nodes[b]);
          all[8 + e] = out.nodes[m[e]];
        }
        out.jacobian_ratio[k] = hex20_jacobian_ratio(all);
        if (!(out.jacobian_ratio[k] > 1e-6)) ++bad;
      }
    }
  }
  if (bad > 0) {
    throw InputError("solid " + std::to_string(solid) + ": " + std::to_string(bad) +
                     " hexahedra would be inverted or degenerate (source " +
                     (closed ? std::string("its profile") : face_name(caps.source)) + ")");
  }
  record.hex_count = static_cast<std::int64_t>(out.hexes.size()) - record.first_hex;
  out.solids.push_back(record);
  if (!closed) {
    // Both caps' meshes as this sweep left them, for a solid sharing one.
    for (const auto& [f, k] : {std::pair(caps.source, 0), std::pair(caps.target, layers)}) {
      ShapeMesh cap;
      for (NodeId i = 0; i < count; ++i) cap.nodes.push_back(out.nodes[offset + k * count + i]);
      for (NodeId i = 0; i < middles; ++i) cap.nodes.push_back(out.nodes[plane_offset + k * middles + i]);
      for (std::size_t q = 0; q < source.mesh.quads.size(); ++q) {
        Quad quad;
        for (int i = 0; i < 4; ++i) quad[i] = compact.at(source.mesh.quads[q][i]);
        cap.quads.push_back(quad);
        if (!second) continue;
        Quad mids;
        for (int i = 0; i < 4; ++i) mids[i] = static_cast<NodeId>(count + compact_middle.at(source.mesh.mid_nodes[q][i]));
        cap.mid_nodes.push_back(mids);
      }
      cap_meshes.emplace(f, std::move(cap));
    }
  }
  times.layer_seconds += seconds_since(start);
  start = std::chrono::steady_clock::now();
  // A return below leaves the node sets' time counted.
  struct Count {
    std::chrono::steady_clock::time_point start;
    double& into;
    ~Count() { into += seconds_since(start); }
  } count_node_sets{start, times.node_set_seconds};
  // Node sets: the caps (an extrusion's or a partial revolution's), then each side face
  // through the source's boundary nodes on it (a full turn's faces are all sides).
  if (!closed) {
    std::vector<NodeId> source_nodes, target_nodes;
    for (NodeId i = 0; i < count; ++i) {
      source_nodes.push_back(offset + i);
      target_nodes.push_back(static_cast<NodeId>(offset + layers * count + i));
    }
    for (NodeId i = 0; i < middles && second; ++i) {
      source_nodes.push_back(plane_offset + i);
      target_nodes.push_back(static_cast<NodeId>(plane_offset + layers * middles + i));
    }
    out.face_nodes.emplace_back(caps.source, source_nodes);
    out.face_nodes.emplace_back(caps.target, target_nodes);
  }
  if (paths) {
    // The general route knows each rim point's side faces at every layer (stacked
    // sides hold it over their share of the layers only).
    std::map<int, std::vector<NodeId>> on_side;
    for (NodeId original : rim_corners) {
      const NodeId i = compact.at(original);
      for (int k = 0; k < stored; ++k) {
        for (int f : paths->faces_at(i, k)) on_side[f].push_back(static_cast<NodeId>(offset + k * count + i));
      }
      for (int k = 0; k < layers && second; ++k) {
        for (int f : paths->faces_at(i, k + 0.5)) on_side[f].push_back(static_cast<NodeId>(path_offset + k * count + i));
      }
    }
    for (NodeId original : rim_middles) {
      const NodeId i = compact_middle.at(original);
      for (int k = 0; k < stored; ++k) {
        for (int f : paths->faces_at(static_cast<int>(count + i), k)) {
          on_side[f].push_back(static_cast<NodeId>(plane_offset + k * middles + i));
        }
      }
    }
    for (int f : solid_faces) {
      if (f == caps.source || f == caps.target) continue;
      std::vector<NodeId>& nodes = on_side[f];
      std::sort(nodes.begin(), nodes.end());
      out.face_nodes.emplace_back(f, nodes);
    }
    return;
  }
  for (int f : solid_faces) {
    if (f == caps.source || f == caps.target) continue;
    Bnd_Box box;
    BRepBndLib::Add(index.face(f), box);
    box.Enlarge(tol);
    const auto on_face = [&](NodeId original) {
      const Vec3& p = source.mesh.nodes[original];
      const gp_Pnt point(p.x, p.y, p.z);
      if (box.IsOut(point)) return false;
      BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(point).Vertex(), index.face(f));
      return distance.IsDone() && distance.NbSolution() > 0 && distance.Value() <= tol;
    };
    std::vector<NodeId> nodes;
    for (NodeId original : rim_corners) {
      if (!on_face(original)) continue;
      const NodeId i = compact.at(original);
      for (int k = 0; k < stored; ++k) nodes.push_back(static_cast<NodeId>(offset + k * count + i));
      for (int k = 0; k < layers && second; ++k) nodes.push_back(static_cast<NodeId>(path_offset + k * count + i));
    }
    for (NodeId original : rim_middles) {
      if (!on_face(original)) continue;
      const NodeId i = compact_middle.at(original);
      for (int k = 0; k < stored; ++k) nodes.push_back(static_cast<NodeId>(plane_offset + k * middles + i));
    }
    std::sort(nodes.begin(), nodes.end());
    out.face_nodes.emplace_back(f, nodes);
  }
}

}  // namespace

SweepResult sweep_shape(const TopoDS_Shape& shape, const SweepOptions& options) {
  if ((options.source >= 0) != (options.target >= 0)) {
    throw InputError("give both the source and the target face, or neither");
  }
  if (options.layers < 0) throw InputError("layers must be 0 (from the size) or more, not " + std::to_string(options.layers));
  const ShapeIndex index(shape);
  for (int f : {options.source, options.target}) {
    if (f >= index.face_count()) {
      throw InputError(face_name(f) + " does not exist; the shape has faces 0.." + std::to_string(index.face_count() - 1));
    }
  }
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  if (solids.Extent() == 0) throw InputError("the shape has no solid to sweep (only faces or shells)");
  const double diagonal = shape_diagonal(shape);
  const double tol = std::max(1e-6 * diagonal, 1e-9);
  SweepResult result;
  std::map<int, ShapeMesh> cap_meshes;  // each swept solid's caps, by shape face
  bool given_used = options.source < 0;
  for (int k = 1; k <= solids.Extent(); ++k) {
    const int solid = k - 1;
    const std::vector<int> solid_faces = faces_of(index, solids(k));
    SweepOptions for_solid = options;
    const bool holds_given = options.source >= 0 &&
                             std::count(solid_faces.begin(), solid_faces.end(), options.source) > 0;
    if (options.source >= 0 && !holds_given) for_solid.source = for_solid.target = -1;
    std::string refusal;
    std::optional<SolidFaces> faces;  // read once for the searches below
    // The first route that fits, with the caps `o` gives if any (then not a full turn).
    const auto route = [&](const SweepOptions& o, bool given) {
    SolidCaps caps;
    try {
      if (!faces) faces.emplace(index, solid_faces);
      caps = find_caps(index, *faces, o, tol);
    } catch (const Standard_Failure& e) {
      caps.why_not = std::string("OpenCASCADE failed on its faces (") +
                     (e.GetMessageString() ? e.GetMessageString() : "no message") + ")";
    }
    if (caps.source < 0 && !given && faces) {
      // Not capped: perhaps a full turn about an axis.
      try {
        SolidCaps turn = full_revolution(index, solids(k), *faces, tol, diagonal);
        if (!turn.profile.IsNull()) {
          caps = turn;
        } else {
          caps.why_not += "; nor a full revolution: " + turn.why_not;
        }
      } catch (const Standard_Failure&) {
        caps.why_not += "; nor a full revolution: OpenCASCADE failed on its section";
      }
    }
    if (caps.source < 0 && caps.profile.IsNull() && faces) {
      // No exact motion: perhaps a one-to-one sweep between caps of any shape.
      try {
        ProjectedCaps general = find_projected_caps(index, solid_faces, o.source, o.target);
        if (general.source >= 0) {
          caps.source = general.source;
          caps.target = general.target;
          caps.projected = std::move(general);
        } else {
          caps.why_not += "; nor a one-to-one sweep: " + general.why_not;
        }
      } catch (const Standard_Failure&) {
        caps.why_not += "; nor a one-to-one sweep: OpenCASCADE failed on its faces";
      }
    }
    return caps;
    };
    SolidCaps caps = route(for_solid, holds_given);
    if (!holds_given && caps.source >= 0 && caps.profile.IsNull() && cap_meshes.count(caps.target) &&
        !cap_meshes.count(caps.source)) {
      // Its target is a cap another solid swept: sweep from it instead, to share it.
      SweepOptions turned = for_solid;
      turned.source = caps.target;
      turned.target = caps.source;
      SolidCaps other = route(turned, true);
      if (other.source >= 0) caps = std::move(other);
    }
    if (caps.source < 0 && caps.profile.IsNull()) {
      if (holds_given) {
        throw InputError(face_name(options.source) + " and " + face_name(options.target) +
                         " are not the caps of a sweep: " + caps.why_not);
      }
      refusal = "solid " + std::to_string(solid) + " is not sweepable: " + caps.why_not;
    } else {
      given_used = given_used || holds_given;
      // A refused solid leaves nothing in the mesh.
      const HexMesh& m = result.mesh;
      const std::size_t nodes = m.nodes.size(), hexes = m.hexes.size(), sets = m.face_nodes.size(),
                        swept = m.solids.size();
      try {
        sweep_solid(shape, index, solid, solid_faces, caps, for_solid, tol, result.mesh, result, cap_meshes);
      } catch (const FacesRefusedError& e) {
        refusal = "solid " + std::to_string(solid) + ": its source face was not meshed: " + e.what();
      } catch (const InputError& e) {
        const std::string what = e.what();
        refusal = what.rfind("solid ", 0) == 0 ? what : "solid " + std::to_string(solid) + ": " + what;
      } catch (const Standard_Failure& e) {
        refusal = "solid " + std::to_string(solid) + ": OpenCASCADE failed on it (" +
                  std::string(e.GetMessageString() ? e.GetMessageString() : "no message") + ")";
      }
      if (!refusal.empty()) {
        result.mesh.nodes.resize(nodes);
        result.mesh.hexes.resize(hexes);
        result.mesh.scaled_jacobian.resize(hexes);
        if (result.mesh.mid_nodes.size() > hexes) result.mesh.mid_nodes.resize(hexes);
        if (result.mesh.jacobian_ratio.size() > hexes) result.mesh.jacobian_ratio.resize(hexes);
        result.mesh.face_nodes.resize(sets);
        result.mesh.solids.resize(swept);
      }
    }
    if (refusal.empty()) continue;
    if (!options.keep_going) throw InputError(refusal);
    result.mesh.refused.push_back({solid, refusal});
  }
  if (!given_used) throw InputError(face_name(options.source) + " is on no solid of the shape");
  merge_shared_face_nodes(result.mesh);
  if (result.mesh.solids.empty()) {
    throw InputError("no solid could be swept; the first refused: " + result.mesh.refused.front().reason);
  }
  return result;
}

}  // namespace tquad
