// remove_doublets: merge the two quads around an interior node that lies in only two.
//
// Such a node (a doublet) has both its edges shared by the same two quads, so each of
// them has a straight or reflex angle there, which no node move can fix (one quad
// gains what the other loses, so at best both keep a straight angle, of scaled
// Jacobian 0). Removing the node and merging its quads removes one node and one
// quad, so nodes = 1 + quads + boundary_edges / 2 - holes still holds. A merge is
// kept only if the merged quad's worst corner is no worse than the two quads' worst,
// unless `even_if_worse`: then a merged quad with a reflex corner at an interior node
// is left for smoothing to open (the caller compares).
#pragma once

#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

// Whether some node of the `nodes`, not one of [0, fixed), lies in exactly two quads.
// Most meshes have none.
bool has_doublet(const std::vector<Quad>& quads, int fixed, std::size_t nodes);

// Nodes [0, fixed) stay. param, position and normal are per node as in smooth_mesh
// (smoothing.h); removed nodes are dropped from them and the quads renumbered (kept
// nodes keep their order). Returns the number of nodes removed; `refused` (if given)
// receives the number of doublets left because merging them would be worse.
int remove_doublets(std::vector<Quad>& quads, int fixed, std::vector<Vec3>& param, std::vector<Vec3>& position,
                    std::vector<Vec3>& normal, bool even_if_worse = false, int* refused = nullptr);

}  // namespace tquad
