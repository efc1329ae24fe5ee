// o_grid_decomposition: the decomposition of a domain with one hole into two
// four-sided patches (an O-grid in two halves). Two straight cuts join the hole's rim
// to the outer loop at roughly opposite places: from rim point r and from the rim
// point half the rim away, each to the nearest outer point whose cut stays inside the
// domain. Each half has the outer piece opposite the rim piece and cut opposite cut,
// so a ring of equal counts meshes as a mapped grid. It is one case of the face
// decomposition (face_decomposition.h): same patches, cut counts and patch meshing.
#pragma once

#include <optional>

#include "core/decomposition/face_decomposition.h"

namespace tquad {

// `rim_point`: where the first cut leaves the hole (an index into loops[1]). Empty
// when the domain does not have exactly one hole, or no two distinct inside cuts
// exist from those rim points.
std::optional<FaceDecomposition> o_grid_decomposition(const PlanarDomain& domain, int rim_point);

}  // namespace tquad
