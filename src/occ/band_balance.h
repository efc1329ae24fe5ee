// balance_one_quad_bands: a face whose chosen corners make it a band one segment wide
// (two opposite sides of one segment each) can only be meshed with one quad per
// segment along it, so its two long sides need equal counts: an all-quad mesh one
// quad wide has no room for a transition (the templates' T1 and T2 need two rows).
// The shorter long side's longest edge takes the difference: a free edge alone, or a
// chained edge with its whole chain (so the chain's faces stay mapped).
#pragma once

#include <vector>

#include "occ/shape_index.h"

namespace tquad {

// segments: per edge, changed in place; chains: edges kept equal. Returns the number
// of faces balanced.
int balance_one_quad_bands(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<int>& segments,
                           const std::vector<std::vector<int>>& chains);

}  // namespace tquad
