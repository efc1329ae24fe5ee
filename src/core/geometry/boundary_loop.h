// BoundaryLoop: the paper's discrete input (section 2), a closed polyline of 3D points
// in order around the region and the indices of its 2, 3 or 4 corner points. Curve k
// runs from corner k to corner k+1 (cyclically); segment i joins point i to point i+1.
#pragma once

#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

// Coordinates beyond this magnitude are refused: squares and cross products of them
// stay far inside double's range.
constexpr double kMaxCoordinate = 1e12;

// A segment shorter than this fraction of the loop's bounding-box diagonal joins two
// points that coincide but for rounding: refused as degenerate. A fuzzed loop whose
// segment was one unit in the last place long made a T3 split's parameter exactly 1
// and its centre NaN.
constexpr double kShortestSegmentFraction = 1e-12;

struct BoundaryLoop {
  std::vector<Vec3> points;
  std::vector<int> corners;
};

// Number of segments of each curve, in curve order (corners sorted ascending).
std::vector<int> curve_segment_counts(const std::vector<int>& sorted_corners, int point_count);

// Throws InputError naming the point, segment or curve at fault when the loop cannot
// be meshed: fewer than 4 points, odd segment count, corner count not 2..4, corner
// out of range or repeated, non-finite coordinate, zero-length segment, a planar
// boundary that crosses itself or folds back.
// Returns the corners sorted ascending.
std::vector<int> validate_boundary(const BoundaryLoop& loop);

}  // namespace tquad
