// triangulate_polygon_with_holes: a triangulation of a polygon with holes that uses
// only the polygon's own vertices (no Steiner point), with well-shaped triangles where
// the vertices allow: the face decomposition's coarse cut of a face into patches
// (face_decomposition.h).
//
// Method: each hole is joined to the outer ring by its shortest bridge that stays
// inside the domain (holes with the rightmost vertex first), giving one weakly simple
// ring; ears are cut from it, the best-shaped valid ear first (largest smallest
// angle); then diagonals are flipped while that raises the smaller of the two
// triangles' smallest angles (Lawson's flips, which on a convex pair tend to the
// constrained Delaunay triangulation). Cost O(n^2) to O(n^3) in the vertex count;
// the decomposition calls it on tens to hundreds of coarse vertices.
#pragma once

#include <array>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

// Vertex v of loop l has id = (number of vertices in loops before l) + v.
using CoarseTriangle = std::array<int, 3>;

// loops[0]: the outer polygon, counter-clockwise; loops[1..]: holes, clockwise; each
// loop has at least 3 vertices. Returns triangles counter-clockwise, as vertex ids.
// Every loop edge (consecutive vertices, in loop order) is a side of exactly one
// triangle and every other triangle side of exactly two.
// Throws TriangulationFailure when the polygon is not simple enough to triangulate
// with its own vertices (crossing loops, touching holes, collinear runs with no ear).
// `avoid(a, b, c)`: ears (a, b, c) cut only when no other ear is left.
using EarFilter = std::function<bool(int a, int b, int c)>;
std::vector<CoarseTriangle> triangulate_polygon_with_holes(const std::vector<std::vector<Vec3>>& loops,
                                                           const EarFilter& avoid = {});

struct TriangulationFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Smallest interior angle of the triangle (radians; 0 when degenerate).
double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace tquad
