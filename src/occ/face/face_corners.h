// choose_face_corners: where the curves of a face's boundary loop begin (2, 3 or 4
// loop positions), for the templates.
//   - one edge (a disk): two curves, split at the node opposite its vertex;
//   - otherwise the wire's vertices that turn by at least 20 degrees (convex); when
//     more than 4, the 4 closest to 90 degrees whose opposite curves have the most
//     similar lengths; tangent joins (fillets) are not corners, but with fewer than
//     4 sharp vertices a fillet's arc that turns 60 degrees or more gives a corner
//     at its middle node;
//   - fewer than 2 such vertices: the first vertices of the wire (up to 4), or for a
//     smooth closed loop two opposite nodes.
// `requested` (shape vertex indices, --corners) overrides the choice.
#pragma once

#include <vector>

#include "occ/face/face_boundary.h"

namespace tquad {

// Throws InputError naming the face and vertex when a requested vertex is not on the
// face's outer wire, or fewer than 2 / more than 4 are requested.
// with_rounded: also take corners in fillets' arcs when fewer than 4 vertices are sharp.
std::vector<int> choose_face_corners(const FaceBoundary& boundary, int face,
                                     const std::vector<int>& requested, bool with_rounded);

// The corner sets worth trying, best guess first: the requested corners alone, or
// the sharp vertices' choice and, when it differs, the one with rounded corners.
std::vector<std::vector<int>> corner_choices(const FaceBoundary& boundary, int face,
                                             const std::vector<int>& requested);

// More corner sets for --corners best (the paper's Figures 9 and 10: a region meshed
// with 3 or 2 curves can beat its natural 4): sets of 2, 3 and 4 of the face's corner
// candidates (its vertices turning at least 5 degrees and its fillets' middles, the
// kSearchCandidates sharpest), those in `tried` left out, the kMaxSearchedSets whose
// corners turn closest to what their count asks (90 degrees for 4, 120 for 3, 180 for
// 2) first. Empty for a one-edge loop (a disk has its O-grid).
constexpr int kSearchCandidates = 8;
constexpr int kMaxSearchedSets = 24;
std::vector<std::vector<int>> searched_corner_choices(const FaceBoundary& boundary,
                                                      const std::vector<std::vector<int>>& tried);

}  // namespace tquad
