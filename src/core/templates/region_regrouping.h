// regroup_curves: the fallback for regions below the templates' minimums
// (docs/design.md, "Regions below the templates' minimums"). T3 cannot split a
// one-edge curve, and T5 cannot split a curve of fewer than 4 edges without leaving
// a one-edge side. Such a region is meshed with
// another number of curves, chosen from the counts alone:
//   - three curves with a one-edge curve: merge it into a neighbour, giving two curves,
//     when both are then >= 4 edges (the most balanced merge); otherwise split the
//     longest curve, giving four curves;
//   - two curves with one under 4 edges: split each curve in two (a one-edge curve
//     stays whole and the other is split in three), giving four curves.
// A regrouped region loses a corner (merge) or gains one at a node that may be on a
// straight stretch of boundary (split); the quad at such a corner has an angle near
// 180 degrees, which the quality report shows.
#pragma once

#include <vector>

#include "core/templates/template_catalogue.h"

namespace tquad {

// Corner positions, as edge offsets along the loop from the region's first corner,
// that the templates should use, ascending (the first is not 0 when the merge drops
// the region's first corner). Returns {0, n0, n0 + n1, ...} (the region's own
// corners) when no regrouping is needed.
std::vector<int> regroup_curves(const CurveCounts& counts);

// Counts of the curves between consecutive corner offsets of a loop of total edges
// (the last curve wraps around to the first offset).
CurveCounts counts_from_offsets(const std::vector<int>& offsets, int total_edges);

}  // namespace tquad
