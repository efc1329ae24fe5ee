// check_planar_self_intersection: refuse a planar boundary loop that crosses or
// touches itself, or folds back on itself. Non-planar (3D) loops are not checked:
// their projections may legitimately overlap.
#pragma once

#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

// Throws InputError naming the two segments that meet. Cost: O(n) on average (a
// uniform grid of segment bounding boxes), O(n^2) at worst.
void check_planar_self_intersection(const std::vector<Vec3>& loop_points);

// Newell's normal of a closed loop: its direction is the loop's orientation normal and
// its length twice the projected area.
Vec3 newell_normal(const std::vector<Vec3>& loop_points);

// Unit normal of the loop's plane (oriented by the loop) when all its points lie on
// one plane within 1e-9 of its size; false otherwise (fewer than 3 points included).
bool planar_normal(const std::vector<Vec3>& loop_points, Vec3& unit_normal);

struct PlanarSegment {
  Vec3 a, b;  // x, y used
};

// A pair (i < j) of segments that meet, other than pairs that `neighbours(i, j)`
// says share an end by construction; empty when none do. O(n) on average (a uniform
// grid of bounding boxes).
std::optional<std::pair<int, int>> find_segment_crossing(const std::vector<PlanarSegment>& segments,
                                                         const std::function<bool(int, int)>& neighbours);

}  // namespace tquad
