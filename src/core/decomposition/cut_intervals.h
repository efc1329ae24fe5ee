// assign_cut_intervals: the number of edges on each cut of a face decomposition.
//
// The boundary's counts are fixed (shared with the neighbouring faces). Each cut's goal
// is its length / size, at least 1 (2 on a three-sided patch, and the turn minimum
// below on a curved surface). Opposite cuts of a
// four-sided patch are joined into chains (when their goals are within a factor 1.5),
// and a chain takes one count: the count of a boundary piece it faces when it can
// (the patch is then a mapped grid), else the best fit of its goals. Then every patch
// is made even, which the templates need: odd patches are paired along shortest paths
// of the patch graph, each step changing a whole chain by one (+1 or -1, whichever
// stays nearer the goals). Where chains cannot reach an odd patch, single cuts are
// changed instead: they always connect the patches on their two sides, and the
// patches' totals sum to the boundary total plus twice the cuts, an even number.
#pragma once

#include <vector>

#include "core/decomposition/face_decomposition.h"

namespace tquad {

// `turn_minimums`: per cut, the fewest segments that stand for its shape on the
// surface the domain charts (a cut straight in the chart may bend in space: across a
// torus groove's tube, a half circle 3.3 long wants 4 segments where a size of 3
// gives 1); empty in a plane. A cut's goal is at least its minimum.
// Throws InputError when the domain's boundary total is odd.
std::vector<int> assign_cut_intervals(const PlanarDomain& domain, const FaceDecomposition& decomposition,
                                      double size, const std::vector<int>& turn_minimums = {});

}  // namespace tquad
