// mesh_face: one face's quads from its boundary loop.
//
// The template mesh is built in the face's (u, v) parameter space, where the edges'
// pcurves give the boundary, and every interior node is the surface evaluated once at
// its (u, v): nodes lie on the face by construction. Where the (u, v) loop is not a
// clean polygon (a pcurve crossing itself, a seam shifted by a period), the mesh is
// built from the 3D loop instead (paper, section 3: the 3D mapping) and each interior
// node is projected onto the surface, warm-started from the previous node's (u, v).
#pragma once

#include <BRepAdaptor_Surface.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/templates/mesher.h"
#include "core/mesh/shape_mesh.h"
#include "occ/face/face_boundary.h"
#include "occ/model/shape_index.h"

namespace tquad {

struct FaceMeshResult {
  // Local node numbering: i < boundary_nodes.size() is boundary_nodes[i] (a shared
  // node: the outer loop, then a hole's rim), else interior[i - size].
  std::vector<NodeId> boundary_nodes;
  std::vector<Quad> quads;
  std::vector<Vec3> interior;
  std::string template_tree;
  std::string route;             // the face route that made it (face_route.cpp's registry)
  bool used_projection = false;  // the 3D fallback was used
  long long inverted = 0;        // quads still inverted after repair
  // Quads unfit for analysis (is_bad_quad): inverted, degenerate, folded or collapsed.
  // A face keeps none unless the user allows them (ShapeMeshOptions::allow_inverted).
  long long bad = 0;
  long long collapsed = 0;       // collapsed quads (is_collapsed), counted in `bad` too
  long long off_surface = 0;     // quads cutting across the surface (kOffSurfaceRatio)
  double worst_corner = 1.0;     // lowest scaled Jacobian against the outer normal
  double worst_own = 1.0;        // lowest own_scaled_jacobian of its quads (quality.h)
  std::vector<double> scaled_jacobian;  // per quad, its corners signed by the outer normal
  // Each local node's mesh coordinates, as check_on_surface measured them: (u, v), or
  // polar (x, y) around `polar`'s pole.
  std::vector<Vec3> param;
  // Each local node's outer normal there (outer_normal: zero where singular), as
  // check_on_surface measured them.
  std::vector<Vec3> normal;
  std::optional<PolarMap> polar;
  double template_seconds = 0;   // building the template mesh (core)
  double placement_seconds = 0;  // putting its interior nodes on the surface
  double meshing_seconds = 0;    // the face's routes before smoothing, every candidate
  double smoothing_seconds = 0;  // smoothing the chosen mesh on the surface
  std::optional<CornerSearch> corner_search;  // set by --corners best
};

// Whether the surface's normal direction at a point is not to be trusted: S_u and
// S_v within about half a degree of parallel (the collapsed corner of a Bezier patch
// falls well inside that), or one of them vanishing against the other (a pole, where
// the ratio falls to rounding noise).
inline bool singular_normal(const gp_Vec& du, const gp_Vec& dv) {
  const double a = du.Magnitude(), b = dv.Magnitude();
  return du.Crossed(dv).Magnitude() <= 1e-2 * a * b || std::min(a, b) <= 1e-9 * std::max(a, b);
}

// The face's outer normal at (u, v) (not unit length), zero where the surface is
// singular (a pole, a collapsed side: its direction is noise there).
Vec3 outer_normal(const BRepAdaptor_Surface& surface, bool reversed, const Vec3& uv);
// The point at uv and outer_normal there, from one evaluation of the surface.
Vec3 outer_normal(const BRepAdaptor_Surface& surface, bool reversed, const Vec3& uv, Vec3& point);

// A quad whose centre lies farther than this many of its diagonals off the surface
// (along the normal at the centre of its corners' parameters) cuts across the surface
// it stands for.
constexpr double kOffSurfaceRatio = 0.25;

// Measures a face's quads on its surface, into out: the scaled Jacobian of each quad
// with every corner signed by the outer normal at that corner's node (at the quad's
// centre where the surface is singular at the node), its lowest (worst_corner), the
// quads below -kSurfaceInvertedBelow (inverted), the bad ones (is_bad_quad), the
// collapsed ones and those off the surface. param: each local node's mesh coordinates, (u, v) or polar (x, y) when
// `polar`; xyz: each local node's position. `surface`: the face's, from the caller
// (each adaptor made computes the face's (u, v) bounds, a pass over every pcurve).
void check_on_surface(const TopoDS_Face& face, const BRepAdaptor_Surface& surface, const std::vector<Vec3>& param,
                      const std::optional<PolarMap>& polar, const std::vector<Vec3>& xyz, FaceMeshResult& out);
// The same with each node's outer normal known (outer_normal at its param), as the
// smoother keeps them: no evaluation of the surface at the nodes again.
void check_on_surface(const TopoDS_Face& face, const BRepAdaptor_Surface& surface, const std::vector<Vec3>& param,
                      const std::optional<PolarMap>& polar, const std::vector<Vec3>& xyz, std::vector<Vec3> normals,
                      FaceMeshResult& out);

// Whether mesh a beats mesh b of the same face: fewer bad quads (is_bad_quad), then
// fewer inverted ones, then fewer collapsed ones (triangles in effect), then a better
// worst corner.
bool better_face_mesh(const FaceMeshResult& a, const FaceMeshResult& b);

// The sum and the mean of a face mesh's per-quad scaled Jacobian (0 for no quad).
double scaled_jacobian_sum(const FaceMeshResult& m);
double mean_scaled_jacobian(const FaceMeshResult& m);

// A mesh's lowest corner by either normal: the surface's or the quad's own (a quad
// warped on a curved face can be fair against the one and poor against the other).
inline double lowest_corner(const FaceMeshResult& m) { return std::min(m.worst_corner, m.worst_own); }

// better_face_mesh, and at the same worst corner (within 1e-9) the higher mean: the
// order --corners best keeps ("the best worst element, then the best mean").
bool better_worst_then_mean(const FaceMeshResult& a, const FaceMeshResult& b);

// Quads come counter-clockwise around the face's outer normal. Throws InputError with
// the reason when neither route meshes the face; a mesh with inverted quads is
// returned (counted in `inverted`) for the caller to weigh against other corners.
FaceMeshResult mesh_face(const ShapeIndex& index, int face, const FaceBoundary& boundary,
                         const std::vector<int>& corners, const std::vector<Vec3>& nodes,
                         const MeshOptions& options);

// A disk around a pole (boundary.polar) meshed as a square and four mapped patches
// in polar (x, y) (disk_o_grid.h), a node put on the pole; nothing when the face is not
// polar or the O-grid does not fit.
std::optional<FaceMeshResult> mesh_polar_disk(const TopoDS_Face& face, const FaceBoundary& boundary,
                                              const std::vector<Vec3>& nodes, const MeshOptions& options);

// A disk in space (one loop, no hole, no seam: a lune of a sphere between its poles,
// a face closing on a pole with no seam) seen on its loop's mean plane and meshed as
// the disk's O-grid (core/templates/disk_o_grid.h), every interior node then lifted along the
// plane's normal onto the face: no quad gets a corner of 180 degrees on a smooth rim
// or at a pole on it, as corners of templates there would. Nothing when the loop's
// projection is no simple polygon, no such disk (a sharp CAD vertex), or the face
// does not lie over the plane once.
std::optional<FaceMeshResult> mesh_disk_in_space(const TopoDS_Face& face, const FaceBoundary& boundary,
                                                 const std::vector<Vec3>& nodes, const MeshOptions& options);

// A cone's tip flattened into its sector (pole_sector) and meshed in two halves
// (core/templates/pole_sector_mesh.h); nothing when the halves do not fit.
std::optional<FaceMeshResult> mesh_pole_sector(const TopoDS_Face& face, const PoleSector& sector,
                                               const std::vector<Vec3>& nodes, const MeshOptions& options);

// A thin face between two sharp tips meshed as the tip strip (core/templates/tip_strip.h)
// in (u, v); nothing when tip_strip_tips finds none.
std::optional<FaceMeshResult> mesh_face_tip_strip(const TopoDS_Face& face, const FaceBoundary& boundary,
                                                  const std::vector<Vec3>& nodes);

// The loop positions of a tip strip's two tips, or nothing: a hole, a pole or a
// degenerate edge, not exactly two CAD vertices turning by kStripTipTurn or more either
// way (at a cusp the turn's sign is rounding noise), chains between them of unequal
// counts or under 3 segments, or a band wider than kStripWidth mean segments (in
// space) where a row crosses it (a_i to b_i): the strip's two rows would be long and
// flat there, which the scaled Jacobian ranking the candidates does not see.
constexpr double kStripTipTurn = 2.0 * M_PI / 3;  // an angle of 60 degrees or less inside
constexpr double kStripWidth = 3.0;
std::optional<std::pair<int, int>> tip_strip_tips(const FaceBoundary& boundary, const std::vector<Vec3>& nodes);

// "at vertices 3, 7, 8, 12" (or "node n" for a corner where no wire edge starts).
std::string corner_text(const FaceBoundary& boundary, const std::vector<int>& corners);

}  // namespace tquad
