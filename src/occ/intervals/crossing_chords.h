// edges_of_crossing_chords: where a face's discretized boundary crosses itself only
// because its segments are chords of curves coarser than the gap between them.
//
// A curved edge's chords cut inside its curve by their sagitta. Where another edge
// passes within that of it (a notch cut almost to an arc's top, a hole near a
// fillet), the loop of segments crosses itself although the face's edges do not,
// and every route refuses the face ("the boundary crosses or touches itself"). Finer
// segments on the curved edge cure it: a notch closer to an arc than its chords'
// sagitta is cleared once the arc has enough segments for their sagitta to fall under
// the gap. Two lines on a plane are their own chords: a crossing of theirs is the
// face's own and no count cures it; nor does any count part two segments meeting at
// one node (a hole touching the outer loop at a vertex).
#pragma once

#include <vector>

#include "occ/face/face_boundary.h"
#include "occ/model/shape_index.h"

namespace tquad {

// The shape edges of the first pair of the boundary's segments (its outer loop and
// holes, in (u, v)) that cross or touch, when one of the two edges at least is not a
// line on a plane and they share no node; empty when no other segments cross, when
// they are lines on a plane, or when the boundary is not a plain (u, v) loop (a pole,
// polar coordinates).
std::vector<int> edges_of_crossing_chords(const ShapeIndex& index, int face, const FaceBoundary& boundary);

}  // namespace tquad
