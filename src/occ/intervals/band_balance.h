// balance_narrow_bands: a face whose chosen corners make it a band one or two
// segments wide (two opposite sides of at most kNarrowBand segments each) gets equal
// counts on its two long sides, so it is a mapped grid. One quad across has no room
// for a transition at all (the templates' T1 and T2 need two rows); two quads across
// a fillet bent 90 degrees had room, but the transition folded a quad (a negative
// scaled Jacobian against the quad's own normal on a toroidal fillet). The shorter
// long side's longest edge takes the difference: a free edge alone, or a chained edge
// with its whole chain (so the chain's faces stay mapped). Ends of 1 and 2 segments
// are made equal likewise, or the band stays odd and the parity fix changes one of
// its edges (a long side, which then needs a transition, its quads far worse than the
// mapped grid's). Sides are counted as the segments stand when the band is looked
// at, so two bands sharing an edge see each other's changes, and a band that a later
// one unbalanced is balanced again in a further pass.
#pragma once

#include <utility>
#include <vector>

#include "occ/intervals/edge_discretization.h"
#include "occ/model/shape_index.h"

namespace tquad {

// Bands this many segments wide or less get equal long sides.
constexpr int kNarrowBand = 2;

// segments: per edge, changed in place; chains: edges kept equal. Returns the number
// of faces balanced.
// kept: spacings to take and keep (discretize_edges), or none.
// paired: when given, receives for every band with equal long sides (balanced here or
// already) the longest unchained edge of each long side, so that the parity fix can
// change both at once and keep the band mapped (each edge in one pair at most).
int balance_narrow_bands(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<int>& segments,
                           const std::vector<std::vector<int>>& chains, EdgeSpacings* kept = nullptr,
                           std::vector<std::pair<int, int>>* paired = nullptr);

}  // namespace tquad
