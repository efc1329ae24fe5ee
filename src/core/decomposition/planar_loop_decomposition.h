// mesh_planar_loop_decomposed: a planar boundary loop meshed as a face is, by the
// face decomposition (decomposed_mesher.h) in the loop's plane, its corners kept as
// patch corners, instead of by the templates on its 2, 3 or 4 curves. The boundary
// route (boundary_region.h) takes it where the templates' mesh, smoothed and with
// the searched corners, still has an inverted quad: a thin band folded along a side
// bent inwards, which no choice of curves unfolds, becomes patches of its own.
#pragma once

#include <optional>

#include "core/geometry/boundary_loop.h"
#include "core/templates/mesher.h"
#include "core/mesh/quad_mesh.h"
#include "core/geometry/vec3.h"

namespace tquad {

// `unit_normal`: the loop's plane normal, the loop counter-clockwise about it
// (planar_normal). The mesh keeps the loop's points first, bit-exact, its quads
// counter-clockwise about the normal; nothing when the decomposition refuses the
// loop.
std::optional<QuadMesh> mesh_planar_loop_decomposed(const BoundaryLoop& loop, const Vec3& unit_normal,
                                                    const MeshOptions& options);

}  // namespace tquad
