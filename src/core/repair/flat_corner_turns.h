// turn_flat_boundary_corners: a boundary node that lies in one quad alone, where the
// boundary is nearly straight, is a corner of nearly 180 degrees of that quad. No node
// move mends it: the node and its two neighbours along the boundary are shared with
// the next face and stay (a corner a degree or two short of 180 has a scaled
// Jacobian near 0).
//
// The quad and a neighbour across one of its two inner edges make a hexagon; cut
// along the diagonal from the boundary node instead, the node lies in two quads and
// its angle is shared between them. The neighbour along the boundary on that side
// gives up a quad: where it then lies in one quad alone at a straight boundary too,
// the same turn is made there, and so on along the boundary (a chain of at most
// kMaxChain turns) until a node that can spare a quad or whose corner is not flat (a
// corner of the face); a chain that finds none is undone. Of the two directions, the
// shorter chain is kept. Node and quad counts stay, so nodes = 1 + quads +
// boundary_edges / 2 - holes still holds, and no inner node is left in two quads (a
// doublet). The new quads may be folded where the nodes are: the caller smooths after
// the turns and weighs the result against the mesh without them.
#pragma once

#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

// Boundary corners under this scaled Jacobian (about 150 degrees and more) are turned.
constexpr double kFlatCornerBelow = 0.5;
// The longest chain of turns along a boundary.
constexpr int kMaxChain = 8;

// Whether some boundary node (of [0, fixed)) lies in one quad alone at a corner under
// kFlatCornerBelow: one count of the boundary nodes' quads, so that most meshes, which
// have none, cost no more.
bool has_flat_lone_corner(const std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                          const std::vector<Vec3>& normal);

// Nodes [0, fixed) are the boundary's. position and normal: per node (normal of unit
// length, or zero: the quad's own normal stands in). Returns the number of turns.
int turn_flat_boundary_corners(std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                               const std::vector<Vec3>& normal);

}  // namespace tquad
