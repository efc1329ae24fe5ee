// split_reflex_corner_quads: a boundary point where a planar region turns reflex (an
// interior angle over 180 degrees) and that is the corner of one quad only leaves that
// quad inverted whatever its interior nodes do: its corner there is the region's
// reflex angle. (Most of the mildly non-convex generated boundaries that stayed
// inverted after smoothing were such.) Each such quad is replaced by five, an inner
// quad and four around it, so the reflex point becomes the corner of two quads; the
// four new nodes start a third of the way from each corner to the quad's centre and
// are left to the untangling and smoothing that follow. nodes = 1 + quads +
// boundary_edges / 2 still holds (four nodes and four quads more).
#pragma once

#include "core/mesh/quad_mesh.h"
#include "core/geometry/vec3.h"

namespace tquad {

// Boundary points are nodes [0, boundary_points); quads run counter-clockwise around
// `normal`. Returns the quads split.
int split_reflex_corner_quads(QuadMesh& mesh, int boundary_points, const Vec3& normal);

}  // namespace tquad
