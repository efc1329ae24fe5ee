// smooth_mesh: better-shaped quads by moving interior nodes on their surface.
//
// The templates place nodes by transfinite maps (paper, eqs. 3 and 4) and the repair
// (untangle.h) only removes inverted corners, so thin or skewed quads remain where a
// patch's counts or corners suit the geometry poorly: collinear interior nodes of a
// transition, skewed quads along a cut. This pass moves each interior node in the
// mesh's own coordinates (a face's (u, v), or a plane), evaluates the surface there,
// and keeps a move only if the worst corner whose angle it decides (the scaled
// Jacobian against the surface normal at each corner's node, and in the quad's own
// plane) does not drop and no quad around it collapses. So the mesh's worst element
// never gets worse, and a node moves
// only where that helps its quads. Each pass visits nodes in index order
// (deterministic: the same mesh for any thread count). Folded corners are first
// unfolded by untangle_corner_areas (area_untangling.h), which the worst-corner rule
// below cannot do. Then:
//   - first the mean of its edge neighbours (Laplacian), whole, half or a quarter of
//     the way; the move is kept if it raises the worst corner there, or keeps it and
//     raises the sum of the quads' scaled Jacobians there (each quad's lowest corner,
//     the mean's measure), with a quarter weight on each corner the node decides;
//   - then, where the worst corner there is under search_below, the steepest ascent
//     of that worst corner (max_min_ascent.h): gradients by finite differences, a
//     step predicted to where another corner would become the worst, halved until
//     the move is kept; where it is under good_enough only, the steepest ascent of
//     that sum, the worst held (the gradient projected so that no corner at
//     the worst falls).
// Each corner is judged by the lower of its scaled Jacobian against the surface
// normals and in its quad's own plane.
#pragma once

#include <optional>

#include <functional>
#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

// Places node `node` at mesh coordinates `param`: its position and the surface's
// outer normal there (any length). Returns false where the surface is singular (a
// pole), where the node may not go. (The node is named for surfaces fitted per node,
// fitted_surface.h; a CAD face's surface is the same for all.)
using PlaceNode = std::function<bool(int node, const Vec3& param, Vec3& position, Vec3& normal)>;

struct SmoothingOptions {
  int passes = 12;
  // Corners under this get the steepest ascent (the Laplacian alone barely moves a
  // node whose neighbours are themselves badly placed).
  double search_below = 0.6;
  // Nodes whose corners around all reach this are left alone unless a neighbour moves;
  // below it that sum is raised, the worst held. High, because fair
  // corners between 0.8 and 0.98 are most of a mesh's corners: raising them lifts the
  // mean of nearly every part. With the passes' 12 (against 8 and 0.95): either
  // alone raised the means about half as much as both, for a few percent more
  // meshing time at most (most nodes stop moving within a few passes).
  double good_enough = 0.98;
};

struct SmoothingResult {
  long long untangling_moves = 0;  // moves that unfolded corners first (area_untangling.h)
  long long moves = 0;             // accepted node moves over all passes
  int passes = 0;       // passes run (they stop early when no node moves)
};

// Nodes [0, fixed) never move, nor do nodes whose normal is singular (a node put on
// a pole stays on it). param, position and normal hold each node's mesh
// coordinates, position and outer normal (zero where singular: the corners there are
// signed by the quad's own normal, the cross product of its diagonals); the moved
// nodes' entries are updated.
SmoothingResult smooth_mesh(const std::vector<Quad>& quads, int fixed, std::vector<Vec3>& param,
                            std::vector<Vec3>& position, std::vector<Vec3>& normal, const PlaceNode& place,
                            const SmoothingOptions& options = {});

// smooth_mesh of a mesh already smoothed but for a local change: only the nodes
// marked in `region` move (the change and a few rings of nodes around it). A layout
// changed around one boundary corner (flat_corner_turns.h, sharp_corner_flips.h) is
// smoothed so at the cost of its neighbourhood: smoothing the whole face for each
// such layout made the smoothing several times slower on faces with many of them.
// Folds are unfolded (area_untangling.h) among the quads touching the region and by
// its nodes alone: a flipped layout is mostly folded where the smoothed nodes are
// (a thin tip keeps its poor corner when such layouts are passed over), and
// unfolding the whole face's quads was slow for each layout on a large face (a fold
// at a cusp, elsewhere, that it failed to undo each time).
SmoothingResult smooth_mesh_near(const std::vector<Quad>& quads, int fixed, std::vector<Vec3>& param,
                                 std::vector<Vec3>& position, std::vector<Vec3>& normal, const PlaceNode& place,
                                 std::vector<bool> region, const SmoothingOptions& options = {});

// A planar mesh (normal +z) cleaned and smoothed in place: doublets merged
// (doublets.h), then smooth_mesh with nodes [0, fixed) kept. Returns the smoothing's
// result; `merged` receives the doublets removed.
SmoothingResult smooth_planar_mesh(QuadMesh& mesh, int fixed, int& merged, const SmoothingOptions& options = {});

// The same for a planar region in any plane: boundary nodes [0, fixed) on the plane
// with unit normal `normal`, quads counter-clockwise around it. Smoothed in the
// plane's own frame; the boundary nodes keep their coordinates bit for bit.
SmoothingResult smooth_mesh_in_plane(QuadMesh& mesh, int fixed, const Vec3& normal, int& merged,
                                     const SmoothingOptions& options = {});

// A boundary region's mesh (boundary_points first) smoothed: in its plane when the
// loop is planar (plane_normal set), on the surface its templates' mesh spans
// (fitted_surface.h) when it is a curved 3D loop, which has no surface of its own
// (left as meshed if its projection on its mean plane crosses itself); a quad alone at a reflex
// boundary point first split in five (reflex_corners.h); then checked again
// (check_disk_mesh; a failure is std::logic_error, the mesher's fault). The boundary
// route of the CLI and the Python module (boundary_region.h) calls this.
void smooth_region(QuadMesh& mesh, int boundary_points, const std::optional<Vec3>& plane_normal);

}  // namespace tquad
