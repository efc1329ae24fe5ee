// flip_lopsided_sharp_corners: a boundary node at a sharp corner (at most 150
// degrees) that lies in two quads, one of them with a poor corner there (scaled
// Jacobian under kFlatCornerBelow), shares an angle one quad could take whole. No
// node move mends it where the face is thin at the corner: a face ending in a narrow
// tip cut off by a short edge had its corner node of about 100 degrees in two quads,
// one with nearly all of it and one with a sliver of a few degrees (poor even after
// smoothing), the inner node between them having no room to move in the thin tip.
//
// The two quads make a hexagon around their shared inner edge (from the corner to an
// inner node); cut along one of the other two diagonals instead, the corner node
// lies in one quad, and the inner node in one quad fewer (kept only where it keeps
// three or more: no doublet). Of the two diagonals, the one whose two new quads'
// worst corner is the better where the nodes are now, or the other: which ends
// better only smoothing tells (of two faces mirroring each other, meshed the other
// way round, each ended better after smoothing with a different diagonal). Node and
// quad counts stay, so nodes = 1 + quads + boundary_edges / 2 - holes still holds.
// The new quads may be poor where the nodes are: the caller smooths after the flips
// and weighs the result against the mesh without them (as for flat_corner_turns.h).
#pragma once

#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

// A corner of at most this angle (radians) is flipped to one quad: a lone quad's
// corner there keeps a scaled Jacobian of at least sin(150 degrees) = 0.5, the bound
// flat_corner_turns.h mends from the other side.
constexpr double kSharpCornerUpTo = 150.0 * 3.14159265358979323846 / 180.0;

enum class FlipDiagonal { better_now, other };

// Nodes [0, fixed) are the boundary's. position and normal: per node (normal of unit
// length, or zero: the quad's own normal stands in). Returns the number of flips.
int flip_lopsided_sharp_corners(std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                                const std::vector<Vec3>& normal, FlipDiagonal diagonal);

}  // namespace tquad
