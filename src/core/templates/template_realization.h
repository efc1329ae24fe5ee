// Geometric realization of the decomposing templates: each function takes a region in
// its template's canonical form (see template_catalogue.h), adds the interior points
// and cuts, and returns the subregions in the order subregion_counts lists them.
//
// Where interior points go decides whether elements are valid (docs/design.md,
// "Placing interior points"). Interior points are placed with the region's own
// transfinite map (eq. 1 or 2) at parameters computed from 3D lengths (eqs. 3 and
// 4); cuts follow the map along straight lines of the parameter domain, so they bend
// with a curved region instead of cutting its chords.
#pragma once

#include <vector>

#include "core/mesh/mesh_builder.h"
#include "core/templates/region.h"
#include "core/templates/template_catalogue.h"

namespace tquad {

std::vector<Region> split_t1(const Region& canonical, MeshBuilder& builder);
std::vector<Region> split_t2(const Region& canonical, MeshBuilder& builder);
std::vector<Region> split_t3(const Region& canonical, MeshBuilder& builder);
std::vector<Region> split_t4(const Region& canonical, MeshBuilder& builder);
std::vector<Region> split_t5(const Region& canonical, MeshBuilder& builder,
                             const TemplateOptions& options);

// T5's cut length in edges as a real number: the distance between the nodes where
// split_t5 splits the two curves, over the mean boundary edge length.
double t5_cut_hint(const Region& two_curves, const std::vector<Vec3>& nodes);

}  // namespace tquad
