// mesh_mapped_ring: a ring (one hole) whose outer loop and hole have the same number
// of segments, meshed as one structured grid around the hole: no cut, every node of
// both loops in two quads.
//
// The O-grid cuts a ring in two halves at its nearest points, and the halves' counts
// then differ by the twist between the loops: on a ring one quad thick that puts a
// transition where there is no room (a thin cylinder band got a poor worst quad so).
// Here hole point i is paired with outer point i + k, the offset k with the least
// summed squared distance, and the rows between them are straight interpolations, as
// many as the mean pair distance over the loops' mean spacing.
#pragma once

#include <optional>

#include "core/decomposition/planar_domain.h"
#include "core/mesh/quad_mesh.h"

namespace tquad {

// The mesh (the domain's points first, bit-exact), or nothing when the domain is not
// a ring with equal loop counts or the grid would not tile it (a quad not
// counter-clockwise, or the quads' areas not summing to the ring's).
std::optional<QuadMesh> mesh_mapped_ring(const PlanarDomain& domain);

}  // namespace tquad
