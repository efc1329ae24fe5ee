// decompose_domain: a face's planar domain (any outline, any number of holes) cut into
// patches of 3 and 4 curves that the templates mesh with any even count: the domain
// decomposition the paper leaves to its user (abstract, section 1).
//
// Method (coarse triangulation and pairing; docs/design.md, "Face decomposition"):
//  1. Coarse vertices on every loop: the CAD vertices where the boundary turns
//     sharply (they must stay patch corners), then more points so that no piece of
//     boundary between two coarse vertices turns by more than 60 degrees (a circle
//     gets 6) or is longer than twice the gap in front of it (the local feature
//     size), each new piece keeping 2 segments or more, and every loop has at least 3.
//     A reflex corner much nearer to a point in front of it than to its neighbours (a
//     thin junction) makes that point a coarse vertex too, so a short cut can join them;
//     so does any coarse vertex facing a point across a band thinner than the segments
//     there (DecompositionOptions::cross_thin_bands), so cuts cross the band.
//  2. A triangulation of the polygon of coarse vertices (coarse_triangulation.h).
//     Its diagonals are the cuts, straight in the chart. A cut that meets the real
//     boundary (a piece bulging across its chord), or leaves it at a sliver angle,
//     adds a coarse vertex in that piece and the triangulation is made again. In the
//     end every boundary point can be a coarse vertex, where the cuts are true
//     diagonals of the boundary polygon; only when even that fails (nearly collinear
//     points that the ear test and the cut test judge differently) is the domain
//     refused.
//  3. Triangles are paired across cuts into four-sided patches, greedily by the shape
//     of the merged quadrilateral (its corners measured on the real boundary pieces),
//     when every corner lies between 25 and 155 degrees (or when the quadrilateral
//     beats a sliver triangle, DecompositionOptions::merge_sliver_pairs); unpaired triangles stay
//     three-sided patches (T3/T4). Greedy rather than Boost.Graph's
//     maximum_weighted_matching, which in Boost 1.74 can crash or not terminate on
//     some graphs (boostorg/graph issues 199, 223, 399).
//
// The same domain always gives the same decomposition (no randomness, no threads).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/decomposition/planar_domain.h"

namespace tquad {

// Points of loop `loop` from `first` forward (in loop order) to `last`.
struct BoundaryPiece {
  int loop = 0, first = 0, last = 0;
};

// A straight cut between two boundary points (domain node ids).
struct CutCurve {
  int from = 0, to = 0;
  double length = 0;
};

// A patch side lies on one boundary piece or one cut; a cut is walked from `to` to
// `from` when `reversed`.
struct PatchSide {
  bool is_cut = false;
  int index = 0;
  bool reversed = false;
};

// Sides counter-clockwise; side k begins at the patch's corner k.
struct DomainPatch {
  std::vector<PatchSide> sides;
};

struct FaceDecomposition {
  std::vector<BoundaryPiece> pieces;
  std::vector<CutCurve> cuts;
  std::vector<DomainPatch> patches;
  int corner_splits = 0;  // pieces split by DecompositionOptions::clear_corner_ears
  int sliver_pairs = 0;   // patches merged by DecompositionOptions::merge_sliver_pairs
  int neighbour_splits = 0;  // pieces split by DecompositionOptions::neighbours_across_corners
  int band_crossings = 0;    // points made coarse by DecompositionOptions::cross_thin_bands
  int reflex_extensions = 0;  // points made coarse by DecompositionOptions::extend_reflex_corners
  // Sliver ends left as they are by DecompositionOptions::keep_square_pairs.
  int square_pair_slivers = 0;
};

struct DecompositionOptions {
  // At a corner turning at least 60 degrees (interior angle 120 or less), another
  // loop's point inside the circle through the corner and its two coarse neighbours
  // makes the smallest-angle flips fan cuts into the corner: a 90-degree plate corner
  // ended in several patches, with quads of sliver corners.
  // With this set, the longer piece next to such a corner is split (up to 8 times
  // per corner) until that circle is empty, so the corner's ear stays one triangle.
  // It also moves cuts elsewhere, sometimes for the worse, so callers mesh both and
  // keep the better.
  bool clear_corner_ears = false;
  // Two triangles whose quadrilateral has a corner outside [25, 155] degrees are
  // still one patch when its worst corner beats the worst corner of one of them
  // (a thin flange meeting a plate: two slivers of under a degree across the junction
  // become a band with corners near 20 and 160 degrees), and a sliver diagonal of
  // such a pair splits no piece. It also changes the patches of other faces,
  // sometimes for the worse, so callers mesh both and keep the better.
  bool merge_sliver_pairs = true;
  // The gap in front of a piece also counts its neighbours' points straight in front
  // of it (within 30 degrees of its normal): across a sharp corner, the neighbour
  // runs back along the piece. Without it a loop of three pieces has no point in
  // front of any (all are the piece's or its neighbours'): a crescent or a triangle
  // with a cusp stays one thin patch, with a worse worst quad. It also moves cuts
  // elsewhere, sometimes for the worse, so callers mesh both and keep the better.
  bool neighbours_across_corners = true;
  // Where a coarse vertex faces a point of the boundary across a band narrower than
  // the segments at both (each side within 30 degrees of the other's normal), that
  // point is a coarse vertex too, so that cuts go straight across the band and its
  // quads stand upright: the flanges of an L-shaped face, about half a segment wide,
  // were cut at coarse vertices of each side placed apart, into T2s whose quads
  // leaned by half a segment or more. Callers mesh without it too where it added a
  // point, and keep the better.
  bool cross_thin_bands = true;
  // A reflex corner's two sides, continued straight into the domain, end at the
  // boundary point nearest to where they first meet it (within 20 degrees of the
  // continued side): that point is a coarse vertex, so that a cut can continue the
  // side and both patches at the corner get a corner near 90 degrees there. Without
  // it an L-shaped plate with rounded outer corners was cut from its reflex corner to
  // a rounded corner into two T2 patches with corners of 120 and 150 degrees. Callers
  // mesh without it too where it added a point, and keep the better.
  bool extend_reflex_corners = true;
  // A cut leaving the boundary at a sliver angle splits the piece there (so the cut
  // can start elsewhere), but the diagonal of a pair merged into a patch whose
  // corners all lie within 30 degrees of square is no cut: its slivers are left as
  // they are. Without it the thin rectangle at the foot of an L (a diagonal at about
  // 15 degrees) was split in two and its neighbours made triangles, for a lower mean
  // quality. It also moves cuts elsewhere, sometimes for the worse, so callers mesh
  // without it too and keep the better.
  bool keep_square_pairs = true;
  // A boundary point turning inwards (a reflex point) by at least this many degrees
  // is a coarse vertex, CAD vertex or not. 60, as for any point, on faces: 20 there
  // gave worse worst quads. The boundary route's fallback
  // (planar_loop_decomposition.h) takes 20: a side bent inwards by a little more than
  // that next to a cusp otherwise stays inside one patch, which the templates fold.
  double reflex_point_turn = 60.0;
};

// Throws InputError, naming the loop and point or segment, when a loop has fewer than
// 3 points, a coordinate that is not finite, two equal consecutive points, vertex
// flags that do not match its points, or the wrong orientation, or when boundary
// segments meet (a loop crossing itself, a hole crossing or touching another loop),
// or a hole lies outside the outer loop or inside another hole.
void check_planar_domain(const PlanarDomain& domain);

// The options worth a second mesh beside a decomposition `made` with `used`: `used`
// without each of merge_sliver_pairs, neighbours_across_corners, cross_thin_bands,
// extend_reflex_corners and keep_square_pairs that changed it
// (each can make a face better or worse; callers keep the better mesh). `made`
// null: the decomposition could not be made, so every such variant.
std::vector<DecompositionOptions> decomposition_variants(const DecompositionOptions& used, const FaceDecomposition* made);

// Checks the domain (check_planar_domain), then decomposes it.
FaceDecomposition decompose_domain(const PlanarDomain& domain, const DecompositionOptions& options = {});

// The domain node ids along a patch side, from its start to its end; `cut_nodes[c]`
// holds cut c's nodes from `from` to `to`.
std::vector<int> side_nodes(const PlanarDomain& domain, const FaceDecomposition& decomposition,
                            const PatchSide& side, const std::vector<std::vector<int>>& cut_nodes);

// The boundary segments (loop, segment from point segment to segment + 1) that the
// straight cut from point px of loop lx to point py of loop ly meets away from its
// ends; when it meets none but leaves the domain at an end, the two segments there.
// Empty: the cut lies inside the domain.
std::vector<std::pair<int, int>> cut_obstacles(const PlanarDomain& domain, int lx, int px, int ly, int py);

// Segments of a boundary piece.
int piece_segments(const PlanarDomain& domain, const BoundaryPiece& piece);

}  // namespace tquad
