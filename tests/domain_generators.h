// Planar domain generators for the face decomposition tests: orthogonal outlines (L,
// T, U, H, combs), star-shaped and other non-convex polygons, with 0 to 20 holes
// (circles, squares, slots), sampled with uniform or graded spacing. Every domain is
// valid: simple loops, holes inside the outline and apart from each other, an even
// boundary total.
#pragma once

#include <string>
#include <vector>

#include "core/decomposition/planar_domain.h"

namespace tquad::testing {

struct GeneratedDomain {
  PlanarDomain domain;
  double size = 0;  // the target edge length the boundary was sampled with
  std::string description;
};

// The i-th domain of a reproducible family.
GeneratedDomain generated_domain(int index);

// Each loop's point count, as check_domain_mesh takes them.
std::vector<int> loop_sizes(const PlanarDomain& domain);

// A polygon through `corners` (in their order), each side in `per_side` equal
// segments, the corners CAD vertices.
DomainLoop polygon_loop(const std::vector<Vec3>& corners, int per_side);

// A circle of n points around `centre`, clockwise (a hole), no CAD vertex.
DomainLoop circle_hole(Vec3 centre, double radius, int n);

}  // namespace tquad::testing
