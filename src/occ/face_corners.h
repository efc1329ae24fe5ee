// choose_face_corners: where the curves of a face's boundary loop begin (2, 3 or 4
// loop positions), for the templates.
//   - one edge (a disk): two curves, split at the node opposite its vertex;
//   - otherwise the wire's vertices that turn by at least 20 degrees (convex); when
//     more than 4, the 4 closest to 90 degrees whose opposite curves have the most
//     similar lengths; tangent joins (fillets) are not corners;
//   - fewer than 2 such vertices: the first vertices of the wire (up to 4), or for a
//     smooth closed loop two opposite nodes.
// `requested` (shape vertex indices, --corners) overrides the choice.
#pragma once

#include <vector>

#include "occ/face_boundary.h"

namespace tquad {

// Throws InputError naming the face and vertex when a requested vertex is not on the
// face's outer wire, or fewer than 2 / more than 4 are requested.
std::vector<int> choose_face_corners(const FaceBoundary& boundary, int face,
                                     const std::vector<int>& requested);

}  // namespace tquad
