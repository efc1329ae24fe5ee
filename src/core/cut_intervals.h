// assign_cut_intervals: the number of edges on each cut of a face decomposition.
//
// The boundary's counts are fixed (shared with the neighbouring faces); each cut gets
// the count nearest its length / size, at least 1 (2 on a three-sided patch), and then the parity of every patch
// is made even, which the templates need: patches are visited leaves-first along a
// spanning tree of the patch graph (patches joined by cuts), and an odd patch changes
// its cut towards its parent by one (+1 or -1, whichever stays nearer the goal). The
// patches' totals sum to the boundary total plus twice the cuts, so the root is even
// exactly when the boundary total is.
#pragma once

#include <vector>

#include "core/face_decomposition.h"

namespace tquad {

// Throws InputError when the domain's boundary total is odd.
std::vector<int> assign_cut_intervals(const PlanarDomain& domain, const FaceDecomposition& decomposition,
                                      double size);

}  // namespace tquad
