// mesh_mapped_grid: template T0, the structured grid of a four-curve region whose
// opposite curves have equal counts, by discrete transfinite interpolation (paper,
// eq. 1, in the discrete form of Haber et al.): node (i, j) sits at parameters (u, v)
// where the line joining the i-th nodes of bottom and top meets the line joining the
// j-th nodes of left and right, with every curve parametrized by its own arc length.
// This reproduces graded boundary spacing inside the region.
#pragma once

#include "core/mesh/mesh_builder.h"
#include "core/templates/region.h"

namespace tquad {

// region: four curves with counts (n, m, n, m). Adds (n-1)(m-1) nodes and n m quads.
void mesh_mapped_grid(const Region& region, MeshBuilder& builder);

}  // namespace tquad
