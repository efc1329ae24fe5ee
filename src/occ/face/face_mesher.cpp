#include "occ/face/face_mesher.h"
#include "core/cancellation.h"

#include <BRepAdaptor_Surface.hxx>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <Precision.hxx>
#include <gp_Lin.hxx>
#include <Extrema_ExtPS.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <BRep_Tool.hxx>

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>

#include "core/decomposition/breadth_first_placement.h"
#include "core/templates/disk_o_grid.h"
#include "core/geometry/mean_plane.h"
#include "core/decomposition/planar_domain.h"
#include "core/templates/pole_sector_mesh.h"
#include "core/templates/tip_strip.h"
#include "core/face_refusal.h"
#include "core/input_error.h"
#include "core/geometry/planar_self_intersection.h"
#include "core/mesh/quality.h"
#include "occ/model/occ_vec.h"

namespace tquad {

namespace {


// The quads of a template mesh in the face's local numbering, reversed when the loop
// runs clockwise around the outer normal.
void take_quads(const QuadMesh& mesh, bool reverse, FaceMeshResult& out) {
  out.quads = mesh.quads;
  if (reverse) for (Quad& q : out.quads) std::swap(q[1], q[3]);
  out.template_tree = mesh.template_tree;
}

// Quads with a corner inverted against the face's outer normal at the quad's centre,
// in space: uv[i] and xyz[i] are local node i's parameters and position.
// `param` holds the mesh's own coordinates: (u, v), or polar (x, y) around a pole,
// where a quad's centre is taken before going back to (u, v) (a quad across the seam
// has corners at u near 0 and near the period).
// Local positions and parameters: the loop's nodes, then the interior ones.
std::vector<Vec3> local_positions(const FaceBoundary& b, const std::vector<Vec3>& nodes,
                                  const std::vector<Vec3>& interior) {
  std::vector<Vec3> xyz;
  for (NodeId id : b.nodes) xyz.push_back(nodes[id]);
  xyz.insert(xyz.end(), interior.begin(), interior.end());
  return xyz;
}

// A disk meshed around a pole (polar (x, y), the pole at the origin) has no node
// there unless one is put there: otherwise a quad spans the pole (a cone's tip cut
// off well below the apex). The interior node nearest the origin moves onto it,
// unless that inverts a quad.
void put_a_node_on_the_pole(QuadMesh& mesh, int boundary_points) {
  const int count = static_cast<int>(mesh.nodes.size());
  if (count <= boundary_points) return;
  int nearest = boundary_points;
  for (int i = boundary_points; i < count; ++i) {
    if (norm(mesh.nodes[i]) < norm(mesh.nodes[nearest])) nearest = i;
  }
  const std::vector<Vec3> loop(mesh.nodes.begin(), mesh.nodes.begin() + boundary_points);
  const Vec3 up = newell_normal(loop);
  const long long before = summarize_quality(mesh, up).inverted;
  const Vec3 kept = mesh.nodes[nearest];
  mesh.nodes[nearest] = Vec3{0, 0, 0};
  const QualitySummary after = summarize_quality(mesh, up);
  if (after.inverted > before || after.collapsed > 0) mesh.nodes[nearest] = kept;
}

// A mesh built in the face's parameter space (the loop's points first), placed on the
// surface and checked; `start`: when building it began.
FaceMeshResult place_parameter_mesh(const TopoDS_Face& face, const FaceBoundary& b, const std::vector<Vec3>& nodes,
                                    QuadMesh uv_mesh, std::chrono::steady_clock::time_point start) {
  if (b.polar && b.polar->angle >= 2 * M_PI) put_a_node_on_the_pole(uv_mesh, static_cast<int>(b.nodes.size()));
  FaceMeshResult out;
  out.boundary_nodes = b.nodes;
  take_quads(uv_mesh, !runs_counter_clockwise(b, face), out);
  out.template_seconds = seconds_since(start);
  const auto placing = std::chrono::steady_clock::now();
  const BRepAdaptor_Surface surface(face);
  const std::size_t n = b.nodes.size();
  out.interior.reserve(uv_mesh.nodes.size() - n);
  // Around a pole the mesh was built in polar (x, y): back to (u, v) first.
  for (std::size_t i = n; i < uv_mesh.nodes.size(); ++i) {
    const Vec3 uv = b.polar ? polar_to_uv(*b.polar, uv_mesh.nodes[i]) : uv_mesh.nodes[i];
    out.interior.push_back(to_vec3(surface.Value(uv.x, uv.y)));
  }
  out.placement_seconds = seconds_since(placing);
  check_on_surface(face, surface, uv_mesh.nodes, b.polar, local_positions(b, nodes, out.interior), out);
  return out;
}

FaceMeshResult mesh_in_parameter_space(const TopoDS_Face& face, const FaceBoundary& b,
                                       const std::vector<int>& corners, const std::vector<Vec3>& nodes,
                                       const MeshOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  return place_parameter_mesh(face, b, nodes, mesh_boundary(BoundaryLoop{b.uv, corners}, options), start);
}

// The face's outer loop in space, each node once. A loop through a seam meets the
// seam's nodes twice: in space it folds onto itself, which is refused.
std::vector<Vec3> loop_in_space(const FaceBoundary& b, const std::vector<Vec3>& nodes) {
  std::vector<NodeId> sorted = b.nodes;
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end()) {
    throw FaceRefusalError(RefusalCode::not_supported, "the boundary passes twice through node " + std::to_string(*twice) +
                                                           " (a seam); a face with both a seam and a pole is not supported yet");
  }
  std::vector<Vec3> loop;
  for (NodeId id : b.nodes) loop.push_back(nodes[id]);
  return loop;
}

// Whether a mesh of the loop in space, its quads counter-clockwise about the loop's
// Newell normal, turns the other way around the face's outer normal: the outer
// normals along the loop, summed (zero where singular), against that normal. The
// first node's alone was wrong where it is a pole: a fillet's B-spline closing on a
// point has du x dv zero there, and its mesh came out almost wholly inverted.
bool reversed_against_rim(const TopoDS_Face& face, const FaceBoundary& b, const std::vector<Vec3>& loop) {
  const BRepAdaptor_Surface surface(face);
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  Vec3 outer;
  for (const Vec3& uv : b.uv) outer += outer_normal(surface, reversed, uv);
  return dot(newell_normal(loop), outer) < 0;
}

// A mesh of the face's outer loop in space (its loop nodes first, in loop order) put
// on the surface, its quads reversed when `reverse`: each interior node at its
// closest point there; `start`: when building the mesh began.
FaceMeshResult place_space_mesh(const TopoDS_Face& face, const FaceBoundary& b, const std::vector<Vec3>& loop,
                                const std::vector<Vec3>& nodes, const QuadMesh& mesh, bool reverse,
                                std::chrono::steady_clock::time_point start) {
  FaceMeshResult out;
  out.boundary_nodes = b.nodes;
  out.used_projection = true;
  out.template_seconds = seconds_since(start);
  const auto placing = std::chrono::steady_clock::now();
  const BRepAdaptor_Surface surface(face);
  take_quads(mesh, reverse, out);

  // Closest points on the surface, each search started from the (u, v) of an edge
  // neighbour already placed, breadth first from the boundary: OpenCASCADE's Newton
  // step converges from there. Started from the previous node in creation order
  // (across a template's rows), it often failed into the global search (a grid over
  // the surface, then projections on iso-curves), which then took most of the face
  // meshing's time.
  TopLoc_Location location;  // the surface is stored in the face's local frame
  const Handle(Geom_Surface) geom = BRep_Tool::Surface(face, location);
  ShapeAnalysis_Surface analysis(geom);
  const double tolerance = BRep_Tool::Tolerance(face);
  const gp_Trsf to_local = location.Transformation().Inverted();
  const gp_Trsf to_global = location.Transformation();
  std::vector<Vec3> uv = b.uv;
  uv.resize(mesh.nodes.size(), b.uv[0]);  // a node in no quad (none expected) starts from node 0
  out.interior.resize(mesh.nodes.size() - loop.size());
  std::vector<char> placed(mesh.nodes.size(), 0);
  const auto place = [&](NodeId node, NodeId start_from) {
    const Vec3& q = mesh.nodes[node];
    const gp_Pnt local = gp_Pnt(q.x, q.y, q.z).Transformed(to_local);
    const gp_Pnt2d p = analysis.NextValueOfUV(gp_Pnt2d(uv[start_from].x, uv[start_from].y), local, tolerance);
    uv[node] = {p.X(), p.Y(), 0.0};
    out.interior[node - loop.size()] = to_vec3(geom->Value(p.X(), p.Y()).Transformed(to_global));
    placed[node] = 1;
  };
  for (const PlacementStep& step : breadth_first_placement(mesh.nodes, mesh.quads, loop.size())) {
    place(step.node, step.start_from);
  }
  for (std::size_t i = loop.size(); i < mesh.nodes.size(); ++i) {
    if (!placed[i]) place(static_cast<NodeId>(i), 0);
  }
  out.placement_seconds = seconds_since(placing);
  check_on_surface(face, surface, uv, std::nullopt, local_positions(b, nodes, out.interior), out);
  return out;
}

FaceMeshResult mesh_in_space(const TopoDS_Face& face, const FaceBoundary& b, const std::vector<int>& corners,
                             const std::vector<Vec3>& nodes, const MeshOptions& options) {
  const std::vector<Vec3> loop = loop_in_space(b, nodes);
  const auto start = std::chrono::steady_clock::now();
  return place_space_mesh(face, b, loop, nodes, mesh_boundary(BoundaryLoop{loop, corners}, options),
                          reversed_against_rim(face, b, loop), start);
}

}  // namespace

std::optional<FaceMeshResult> mesh_disk_in_space(const TopoDS_Face& face, const FaceBoundary& b,
                                                 const std::vector<Vec3>& nodes, const MeshOptions& options) {
  if (b.inner_wires > 0 || b.polar) return std::nullopt;
  const std::vector<Vec3> loop = loop_in_space(b, nodes);
  const std::optional<MeanPlane> plane = MeanPlane::of_loop(loop);
  if (!plane) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  // The loop seen on its mean plane, counter-clockwise there (MeanPlane), its CAD
  // vertices marked so that a sharp one is no disk.
  PlanarDomain domain;
  DomainLoop& outer = domain.loops.emplace_back();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 local = plane->local(loop[i]);
    outer.points.push_back({local.x, local.y, 0.0});
  }
  outer.vertex.assign(loop.size(), 0);
  for (int start_index : b.edge_start) outer.vertex[start_index] = 1;
  std::optional<QuadMesh> disk = mesh_disk_o_grid(domain, options);
  if (!disk) return std::nullopt;
  // Each interior node where the line through its point of the plane, along the
  // plane's normal, meets the face: a dome's closest points to its base plane would
  // all lie on its rim. The face must lie over its plane (one hit each).
  // The quads run counter-clockwise about the plane's normal; the face's outer normal
  // where they land says which way they must turn (along the rim it may lie in the
  // plane: a hemisphere's).
  IntCurvesFace_ShapeIntersector hits;
  hits.Load(face, Precision::Confusion());
  const BRepAdaptor_Surface surface(face);
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  double facing = 0;
  for (std::size_t i = 0; i < disk->nodes.size(); ++i) {
    if (i < loop.size()) {
      disk->nodes[i] = loop[i];
      continue;
    }
    const Vec3 p = plane->point_at(disk->nodes[i].x, disk->nodes[i].y, 0.0);
    hits.Perform(gp_Lin(gp_Pnt(p.x, p.y, p.z), gp_Dir(plane->normal.x, plane->normal.y, plane->normal.z)),
                 -RealLast(), RealLast());
    if (!hits.IsDone() || hits.NbPnt() != 1) return std::nullopt;
    disk->nodes[i] = to_vec3(hits.Pnt(1));
    facing += dot(outer_normal(surface, reversed, {hits.UParameter(1), hits.VParameter(1), 0.0}), plane->normal);
  }
  return place_space_mesh(face, b, loop, nodes, *disk, facing < 0, start);
}

Vec3 outer_normal(const BRepAdaptor_Surface& surface, bool reversed, const Vec3& uv) {
  Vec3 point;
  return outer_normal(surface, reversed, uv, point);
}

Vec3 outer_normal(const BRepAdaptor_Surface& surface, bool reversed, const Vec3& uv, Vec3& point) {
  gp_Pnt p;
  gp_Vec du, dv;
  surface.D1(uv.x, uv.y, p, du, dv);
  point = to_vec3(p);
  if (singular_normal(du, dv)) return Vec3{};
  gp_Vec n = du.Crossed(dv);
  if (reversed) n.Reverse();
  return to_vec3(n);
}

void check_on_surface(const TopoDS_Face& face, const BRepAdaptor_Surface& surface, const std::vector<Vec3>& param,
                      const std::optional<PolarMap>& polar, const std::vector<Vec3>& xyz, std::vector<Vec3> normals,
                      FaceMeshResult& out) {
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  const auto to_uv = [&](const Vec3& p) { return polar ? polar_to_uv(*polar, p) : p; };
  const bool planar = surface.GetType() == GeomAbs_Plane;
  const double u_period = !polar && surface.IsUPeriodic() ? surface.UPeriod() : 0;
  const double v_period = !polar && surface.IsVPeriodic() ? surface.VPeriod() : 0;
  out.param = param;
  out.polar = polar;
  // Each corner is checked against the normal at its own node, so a quad warped on a
  // strongly curved face is judged where its corners are; where the surface is
  // singular at the node (a pole), the normal at the quad's centre stands in, and
  // where it is singular there too, the quad's own (the diagonals' cross product).
  long long inverted = 0, bad = 0, collapsed = 0, off_surface = 0;
  double worst = 1.0, worst_own = 1.0;
  out.scaled_jacobian.clear();
  out.scaled_jacobian.reserve(out.quads.size());
  for (const Quad& q : out.quads) {
    poll_cancellation(16);
    const std::array<Vec3, 4> corner{xyz[q[0]], xyz[q[1]], xyz[q[2]], xyz[q[3]]};
    Vec3 centre, centre_param, mean_normal;
    for (int i = 0; i < 4; ++i) {
      centre += 0.25 * corner[i];
      // On a periodic surface a quad may straddle the seam: each corner's (u, v) is
      // taken within half a period of the first corner's, so the centre lies in the quad.
      Vec3 p = param[q[i]];
      if (u_period > 0) p.x -= u_period * std::round((p.x - param[q[0]].x) / u_period);
      if (v_period > 0) p.y -= v_period * std::round((p.y - param[q[0]].y) / v_period);
      centre_param += 0.25 * p;
      mean_normal += normals[q[i]];
    }
    std::optional<Vec3> centre_normal;  // evaluated only where a node's normal is singular
    double quad_worst = 1.0;
    for (int i = 0; i < 4; ++i) {
      Vec3 normal = normals[q[i]];
      if (norm(normal) == 0) {
        if (!centre_normal) centre_normal = outer_normal(surface, reversed, to_uv(centre_param));
        normal = *centre_normal;
      }
      if (norm(normal) == 0) normal = cross(corner[2] - corner[0], corner[3] - corner[1]);
      quad_worst = std::min(quad_worst, corner_scaled_jacobian(corner, i, normal));
    }
    worst = std::min(worst, quad_worst);
    worst_own = std::min(worst_own, own_scaled_jacobian(corner));
    out.scaled_jacobian.push_back(quad_worst);
    inverted += quad_worst < -kSurfaceInvertedBelow ? 1 : 0;
    bad += is_bad_quad(corner, quad_worst) ? 1 : 0;
    collapsed += is_collapsed(corner) ? 1 : 0;
    // How far the quad's centre lies off the surface (at its parameters' centre),
    // along its corners' mean normal, against its longer diagonal: a quad cutting
    // across the surface it stands for (a tangential offset, as near a pole, does not
    // count).
    const double mean_length = norm(mean_normal);
    if (mean_length > 0 && !planar) {  // on a plane the corners' centre lies on it
      const gp_Pnt p = surface.Value(to_uv(centre_param).x, to_uv(centre_param).y);
      const double off = std::abs(dot(centre - to_vec3(p), mean_normal)) / mean_length;
      const double diagonal = std::max(distance(corner[0], corner[2]), distance(corner[1], corner[3]));
      off_surface += off > kOffSurfaceRatio * diagonal ? 1 : 0;
    }
  }
  out.inverted = inverted;
  out.bad = bad;
  out.collapsed = collapsed;
  out.off_surface = off_surface;
  out.worst_corner = worst;
  out.worst_own = worst_own;
  out.normal = std::move(normals);
}

void check_on_surface(const TopoDS_Face& face, const BRepAdaptor_Surface& surface, const std::vector<Vec3>& param,
                      const std::optional<PolarMap>& polar, const std::vector<Vec3>& xyz, FaceMeshResult& out) {
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  std::vector<Vec3> normals;
  if (surface.GetType() == GeomAbs_Plane && !param.empty()) {
    // A plane's derivatives are its axes at every (u, v): one normal for all nodes
    // (the same bits as evaluating it at each; most CAD faces are planes).
    normals.assign(param.size(), outer_normal(surface, reversed, polar ? polar_to_uv(*polar, param[0]) : param[0]));
  } else {
    normals.resize(param.size());
    for (std::size_t i = 0; i < param.size(); ++i) {
      poll_cancellation(16);
      normals[i] = outer_normal(surface, reversed, polar ? polar_to_uv(*polar, param[i]) : param[i]);
    }
  }
  check_on_surface(face, surface, param, polar, xyz, std::move(normals), out);
}

bool better_face_mesh(const FaceMeshResult& a, const FaceMeshResult& b) {
  if (a.bad != b.bad) return a.bad < b.bad;
  if (a.inverted != b.inverted) return a.inverted < b.inverted;
  if (a.collapsed != b.collapsed) return a.collapsed < b.collapsed;
  return a.worst_corner > b.worst_corner;
}

double scaled_jacobian_sum(const FaceMeshResult& m) {
  double sum = 0;
  for (double v : m.scaled_jacobian) sum += v;
  return sum;
}

double mean_scaled_jacobian(const FaceMeshResult& m) {
  if (m.scaled_jacobian.empty()) return 0.0;
  return scaled_jacobian_sum(m) / static_cast<double>(m.scaled_jacobian.size());
}

bool better_worst_then_mean(const FaceMeshResult& a, const FaceMeshResult& b) {
  if (a.bad != b.bad || a.inverted != b.inverted || a.collapsed != b.collapsed ||
      std::abs(a.worst_corner - b.worst_corner) > 1e-9) {
    return better_face_mesh(a, b);
  }
  return mean_scaled_jacobian(a) > mean_scaled_jacobian(b);
}

FaceMeshResult mesh_face(const ShapeIndex& index, int face_index, const FaceBoundary& boundary,
                         const std::vector<int>& corners, const std::vector<Vec3>& nodes,
                         const MeshOptions& options) {
  const TopoDS_Face& face = index.face(face_index);
  const std::string name = "face " + std::to_string(face_index);
  if (boundary.nodes.size() < 4) {
    throw FaceRefusalError(RefusalCode::too_coarse, name + " has only " + std::to_string(boundary.nodes.size()) +
                                                        " boundary segments; a smaller element size gives it more");
  }
  // A degenerate edge (a pole) is one point in space but a segment in (u, v): the
  // parameter-space mesh would collapse quads there, so such a face takes the 3D route,
  // where the pole is a single loop node. A route that leaves inverted quads gives way
  // to the other when that one does better.
  std::string uv_problem = "a degenerate edge (pole) collapses quads in (u, v)";
  std::optional<FaceMeshResult> best;
  if (!boundary.has_degenerate_edge || boundary.polar) {
    try {
      best = mesh_in_parameter_space(face, boundary, corners, nodes, options);
    } catch (const InputError& e) {
      uv_problem = e.what();
    }
  }
  // On a plane the (u, v) chart is the plane's own Euclidean frame, so the 3D route
  // would build the same template mesh again, up to a rigid motion, and repair it the
  // same way: it is tried only where (u, v) failed outright.
  const bool plane = BRepAdaptor_Surface(face).GetType() == GeomAbs_Plane;
  if (!best || (best->bad > 0 && !plane)) {
    try {
      FaceMeshResult in_space = mesh_in_space(face, boundary, corners, nodes, options);
      if (!best || better_face_mesh(in_space, *best)) best = std::move(in_space);
    } catch (const InputError& e) {
      if (!best) throw InputError(name + " cannot be meshed: in (u, v): " + uv_problem + "; in 3D: " + e.what());
    }
  }
  return *best;
}

std::optional<FaceMeshResult> mesh_polar_disk(const TopoDS_Face& face, const FaceBoundary& boundary,
                                              const std::vector<Vec3>& nodes, const MeshOptions& options) {
  if (!boundary.polar) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  // The disk's O-grid wants a counter-clockwise loop: a clockwise one (a concave cap,
  // its face reversed) is mirrored (x -> -x) for building and its nodes mirrored back,
  // which turns its quads the loop's way, as the templates give them (take_quads).
  const bool mirror = twice_signed_area(boundary.uv) < 0;
  PlanarDomain disk;
  disk.loops.push_back(DomainLoop{boundary.uv, {}});
  if (mirror) for (Vec3& p : disk.loops[0].points) p.x = -p.x;
  std::optional<QuadMesh> mesh = mesh_disk_o_grid(disk, options);
  if (!mesh) return std::nullopt;
  if (mirror) for (Vec3& p : mesh->nodes) p.x = -p.x;
  for (std::size_t i = 0; i < boundary.uv.size(); ++i) mesh->nodes[i] = boundary.uv[i];  // bit-exact
  return place_parameter_mesh(face, boundary, nodes, std::move(*mesh), start);
}

std::optional<FaceMeshResult> mesh_pole_sector(const TopoDS_Face& face, const PoleSector& sector,
                                               const std::vector<Vec3>& nodes, const MeshOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<QuadMesh> mesh =
      mesh_sector_in_halves(sector.boundary.uv, sector.apex, sector.rim_start, sector.rim_end, options);
  if (!mesh) return std::nullopt;
  return place_parameter_mesh(face, sector.boundary, nodes, std::move(*mesh), start);
}

std::optional<std::pair<int, int>> tip_strip_tips(const FaceBoundary& b, const std::vector<Vec3>& nodes) {
  if (b.inner_wires > 0 || b.polar || b.has_degenerate_edge) return std::nullopt;
  std::vector<int> tips;
  for (std::size_t k = 0; k < b.turn.size(); ++k) {
    if (std::abs(b.turn[k]) >= kStripTipTurn) tips.push_back(b.edge_start[k]);
  }
  const int count = static_cast<int>(b.nodes.size());
  if (tips.size() != 2) return std::nullopt;
  const int n = ((tips[1] - tips[0]) % count + count) % count;
  if (2 * n != count || n < 3) return std::nullopt;
  // The band's width where the strip's rows cross it: from a_i to b_i.
  const auto at = [&](int position) { return nodes[b.nodes[((position % count) + count) % count]]; };
  double length = 0, widest = 0;
  for (int i = 0; i < count; ++i) length += distance(at(i), at(i + 1));
  for (int i = 1; i < n; ++i) widest = std::max(widest, distance(at(tips[0] + i), at(tips[0] - i)));
  if (widest > kStripWidth * length / count) return std::nullopt;
  return std::pair(tips[0], tips[1]);
}

std::optional<FaceMeshResult> mesh_face_tip_strip(const TopoDS_Face& face, const FaceBoundary& b,
                                                  const std::vector<Vec3>& nodes) {
  const std::optional<std::pair<int, int>> tips = tip_strip_tips(b, nodes);
  if (!tips) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  std::optional<QuadMesh> mesh = mesh_tip_strip(b.uv, tips->first, tips->second);
  if (!mesh) return std::nullopt;
  return place_parameter_mesh(face, b, nodes, std::move(*mesh), start);
}

std::string corner_text(const FaceBoundary& b, const std::vector<int>& corners) {
  std::string text = "at vertices";
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const auto it = std::find(b.edge_start.begin(), b.edge_start.end(), corners[i]);
    text += (i ? ", " : " ") + (it == b.edge_start.end() ? "node " + std::to_string(b.nodes[corners[i]])
                                                          : std::to_string(b.start_vertex[it - b.edge_start.begin()]));
  }
  return text;
}

}  // namespace tquad
