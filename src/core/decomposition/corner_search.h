// mesh_boundary_best_corners: a boundary region meshed with the corner set, among its
// given corners and other sharp points, that gives the best worst (then mean) scaled
// Jacobian. The paper shows (Figures 9 and 10, Table 3) that a region meshed with 3 or
// 2 curves can beat its natural 4, and leaves the choice to its user.
//
// Candidates: the given corners and the points where the loop turns at least 5
// degrees, the kBoundarySearchCandidates sharpest; every set of 2, 3 or 4 of them,
// the kBoundarySearchSets whose corners turn closest to what their count asks (90
// degrees for 4, 120 for 3, 180 for 2) first. Sets are compared before smoothing; the
// best and the given set are then both smoothed (smooth_region) and the better kept,
// so the result is never worse than the given corners'. Deterministic.
#pragma once

#include <optional>
#include <vector>

#include "core/geometry/boundary_loop.h"
#include "core/templates/mesher.h"
#include "core/mesh/shape_mesh.h"
#include "core/geometry/vec3.h"

namespace tquad {

constexpr int kBoundarySearchCandidates = 8;
constexpr int kBoundarySearchSets = 40;

// A point where curves may meet: its loop position and how much the loop turns there.
struct CornerCandidate {
  int position = 0;
  double turn = 0;  // radians
};

// Every set of 2, 3 or 4 of the (at most 16) candidates, positions sorted, except the
// sets in `excluded`; the `limit` whose corners turn closest to what their count asks
// (2 pi / count: 90 degrees for 4, 120 for 3, 180 for 2, summed) first, ties in
// enumeration order. The one ranking of corner sets, for boundary files and faces.
std::vector<std::vector<int>> ranked_corner_sets(std::vector<CornerCandidate> candidates,
                                                 const std::vector<std::vector<int>>& excluded, int limit);

struct CornerSearchResult {
  QuadMesh mesh;
  std::vector<int> corners;  // the corners used, sorted
  CornerSearch search;
};

// `plane_normal`: the loop's plane when planar (quality signed by it, the meshes
// smoothed in it when `smooth`), else std::nullopt (each quad's own normal; the
// meshes smoothed on the surface they span when `smooth`). Throws InputError as
// mesh_boundary does when the given corners cannot be meshed. `given_smoothed`: the
// given corners' mesh already smoothed by smooth_region (the boundary route has it),
// taken instead of smoothing it again.
CornerSearchResult mesh_boundary_best_corners(const BoundaryLoop& loop, const MeshOptions& options,
                                              const std::optional<Vec3>& plane_normal, bool smooth,
                                              const QuadMesh* given_smoothed = nullptr);

// A patch of a face decomposition searched alike (MeshOptions::search_patch_corners):
// `given` is its mesh with its given corners (in the z = 0 plane, counter-clockwise,
// as the decomposition's patches are). Where given's worst corner is under
// kPatchSearchBelow, the first kPatchSearchSets candidate sets are meshed as above and
// the one that beats given before smoothing returned; else (or when none does) a copy
// of given. Nothing is smoothed: the face is, whole, and the caller compares it with
// its mesh without the search then. Patches searched from 0.5 instead raised fewer
// means; 12 sets instead of 40 halve the search's meshing time with worst quads as
// good or better (both judged before smoothing); 6 lose some of the gains.
constexpr double kPatchSearchBelow = 0.8;
constexpr int kPatchSearchSets = 12;
QuadMesh mesh_patch_best_corners(const BoundaryLoop& loop, const MeshOptions& options, const QuadMesh& given);

}  // namespace tquad
