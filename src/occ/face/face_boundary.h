// FaceBoundary: the outer wire of a face as one closed loop of shared mesh nodes, with
// each node's (u, v) on the face's surface (from the edges' pcurves, which share the
// 3D curve's parameter) and the wire's vertices with their turning angles.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "occ/intervals/edge_discretization.h"
#include "occ/model/shape_index.h"

namespace tquad {

// Polar coordinates around a pole of a face periodic in u: theta = 2 pi (u - u_ref) /
// period, r = |v - pole_v| / radius, and (x, y) = (r cos theta, -side r sin theta),
// side = +1 when the face lies at v > pole_v. The sign keeps the (u, v) orientation:
// (u, v) -> (theta, r) has Jacobian sign `side`, (theta, r) -> (r cos, r sin) sign -1.
//
// With `angle` under 2 pi the map is a sector instead (pole_sector): theta = angle
// ((u - u_ref) / period - 1/2), so the seam's two sides lie at -angle / 2 and
// +angle / 2, and the pole is the sector's apex.
struct PolarMap {
  double u_ref = 0, period = 1, pole_v = 0, radius = 1, side = 1;
  double angle = 2 * M_PI;
};

// A closed loop of shared nodes with their (u, v): an inner wire (a hole's rim).
struct NodeLoop {
  std::vector<NodeId> nodes;
  std::vector<Vec3> uv;
  std::vector<int> edge_start;  // loop position where each wire edge begins
  std::vector<int> edge_index;  // shape edge index of each wire edge
};

struct FaceBoundary {
  std::vector<NodeId> nodes;   // around the outer wire; the loop closes on itself
  std::vector<Vec3> uv;        // (u, v, 0) of each loop node
  std::vector<int> edge_start;      // loop position where each wire edge begins
  std::vector<int> start_vertex;    // shape vertex index at each edge_start
  std::vector<int> edge_index;      // shape edge index of each wire edge
  std::vector<char> is_seam;        // the wire edge is the face's seam (met twice)
  std::vector<double> turn;         // signed turning angle there (radians, > 0 convex)
  std::vector<double> arc_length;   // 3D length along the loop to each node (size + 1)
  int inner_wires = 0;
  std::vector<NodeLoop> holes;      // the inner wires, each walked like the outer one
  bool has_degenerate_edge = false;
  double pole_v = 0;                // v of the (first) degenerate edge, if any
  std::optional<PolarMap> polar;    // set by around_pole: uv (holes' too) then hold polar (x, y)
  // Polar: the surface turns a full turn around its pole (kSmoothPoleAngle: a sphere's
  // pole, not a cone's tip), so the pole is an ordinary point of the face, which may
  // be decomposed and meshed in polar (x, y) with no node there.
  bool smooth_pole = false;
};

// Around a pole where the surface turns by this or more it is smooth: a sphere's pole
// turns 2 pi, a cone's tip 2 pi sin(half-angle), under this below 78.5 degrees.
constexpr double kSmoothPoleAngle = 0.98 * 2 * M_PI;

// Signed area of a (u, v) loop (positive: counter-clockwise).
double signed_uv_area(const std::vector<Vec3>& uv);

// Whether the loop runs counter-clockwise around the face's outer normal.
bool runs_counter_clockwise(const FaceBoundary& boundary, const TopoDS_Face& face);

// A face with a seam and a pole (a cone's side, a sphere cap) is a disk seen from the
// pole: the seam is only a cut of its parametrization.
bool is_disk_around_pole(const FaceBoundary& boundary);

// The loop without its seam edges, in polar (x, y) around the pole: a planar disk the
// templates mesh directly; the pole itself becomes an ordinary interior point. Throws
// InputError when the face is not periodic in u.
FaceBoundary around_pole(const FaceBoundary& boundary, const TopoDS_Face& face, int face_index,
                         const std::vector<Vec3>& nodes);

// A cone's tip (or any pole where the surface turns less than kSectorAngleBelow
// around it) flattened: the face cut along its seam is a sector of the angle the
// surface turns around the pole (2 pi sin(half-angle) for a cone; measured from the
// surface near the pole), radius along v. Its loop keeps the seam's nodes on both
// sides and the pole's node as the apex. For a cone the sector is its development,
// so quads keep their shape on the surface. Nothing when the face is not such (no single apex node, a
// sharp vertex on the rim, the angle too wide). mesh_sector_in_halves
// (core/templates/pole_sector_mesh.h) meshes it.
struct PoleSector {
  FaceBoundary boundary;  // uv holds the sector's (x, y); polar set, its angle under 2 pi
  // Loop positions: the loop runs apex -> rim_start (the seam's first side) -> rim_end
  // (the rim) -> apex (the seam's second side).
  int apex = 0, rim_start = 0, rim_end = 0;
};
// Two quads meet the apex. On a cone their corners there are 2a (half-angle a), the
// disk's four 2 asin(sin a sin 45 deg): the sector's are the better up to a near 55
// degrees (a sector of 295 degrees); wider, only the disk is tried. In between both
// are, and the better mesh stays.
constexpr double kSectorAngleBelow = 300.0 * M_PI / 180.0;
constexpr double kSectorRimTurn = 20.0 * M_PI / 180.0;  // a sharper rim vertex: no sector
std::optional<PoleSector> pole_sector(const FaceBoundary& boundary, const TopoDS_Face& face);

// Whether a degenerate edge (one 3D point) of the face is a pole, the one test every
// route and count rule asks: its pcurve runs along a line the surface collapses on
// (a sphere's or a cone's: the full u period). An exporter also marks an edge shorter
// than its vertex tolerance degenerate where the surface does not collapse; its
// pcurve spans under 1/1000 of the face's (u, v) box in both directions: a point of
// the chart, which the face's loop passes through like any vertex.
bool is_pole_edge(const TopoDS_Edge& edge, const TopoDS_Face& face);

// How far the surface of a face with a pole (is_pole_edge) turns around it, in
// radians, measured next to the pole: 2 pi sin(half-angle) on a cone, 2 pi on a
// sphere; 0 when the face has no pole or is not periodic in u.
double face_pole_angle(const TopoDS_Face& face);

// (u, v) of a polar (x, y).
Vec3 polar_to_uv(const PolarMap& map, const Vec3& xy);

// Throws std::runtime_error when a pcurve is missing.
FaceBoundary face_boundary(const ShapeIndex& index, int face, const std::vector<EdgeNodes>& edges,
                           const std::vector<Vec3>& nodes);

}  // namespace tquad
