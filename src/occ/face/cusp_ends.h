// Cusp ends: where two edges of a face meet at a small angle and part as they go (a
// sliver face tapering to a tip, a crescent's horns), the quad in the tip has there
// the angle between the chords from the tip to the edges' first nodes, and its scaled
// Jacobian is at most the sine of that angle. Between curves that part, the angle
// grows with the chords' length, so such an edge end gets a first segment as long as
// the target size allows, whatever the edge's count (refinements and the interval
// assignment raise counts: a sliver's edges were cut into segments well under the
// target size, leaving a tip chord angle of a fraction of a degree).
#pragma once

#include <vector>

#include "occ/model/shape_index.h"

namespace tquad {

// The lengths of an edge's segments at its first and last vertex (along its FORWARD
// orientation) where that end is a cusp end; 0 where it is not.
struct CuspEnds {
  double first = 0.0;
  double last = 0.0;
  double edge_length = 0.0;  // the edge's arc length, where an end is a cusp end
  bool any() const { return first > 0.0 || last > 0.0; }
};

// Per edge (`lengths`: each edge's arc length, 0 for the unusable and degenerate ones,
// which are never graded; `sizes`: each edge's target size, the global one or a local
// size's there). An end's segment is min(size, length / 3), and the end is a
// cusp end when, in some face, it and another edge of that face leave their common
// vertex so that the chords to the points at a quarter of that length make less than
// kCuspAngle and the chords to the points at that length make at least kPartingRatio
// times as much (straight edges meeting at a sharp corner do not part: no gain there).
std::vector<CuspEnds> cusp_ends(const ShapeIndex& index, const std::vector<double>& sizes,
                                const std::vector<double>& lengths);
// The same with one size for every edge.
std::vector<CuspEnds> cusp_ends(const ShapeIndex& index, double size, const std::vector<double>& lengths);

}  // namespace tquad
