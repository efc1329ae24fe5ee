// Boundary generators for the tests: closed polylines sampled from 2, 3 or 4 parametric
// curves, with chosen counts and spacing, in the plane or curved in 3D.
#pragma once

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "core/geometry/boundary_loop.h"

namespace tquad::testing {

using Curve = std::function<Vec3(double)>;  // t in [0, 1]

enum class Spacing { Uniform, Graded, Random };

// Parameters 0 = t_0 < ... < t_n = 1 of n segments: uniform, geometrically graded
// (each segment `ratio` times the previous), or random sizes within a factor 3.
std::vector<double> spacing_params(int n, Spacing kind, double ratio, std::mt19937& rng);

// Samples each curve with its count of segments (the last point of a curve is the
// first of the next, so it is not repeated); corners are the curves' first points.
BoundaryLoop sample_loop(const std::vector<Curve>& curves, const std::vector<int>& counts,
                         const std::vector<std::vector<double>>& params);

// Straight segment from a to b, and a circular arc from a to b bulging to the left of
// a->b by sagitta * |b - a| (negative: to the right) in the plane z = a.z.
Curve line(Vec3 a, Vec3 b);
Curve arc(Vec3 a, Vec3 b, double sagitta);

// Curves with the same counts on the unit square (loop A, C, B, D so that A is
// opposite B and C opposite D, as in the paper's Table 1) and on the equilateral
// triangle of side 1 (A, B, C).
BoundaryLoop square_boundary(int A, int B, int C, int D);
BoundaryLoop triangle_boundary(int A, int B, int C);

struct GeneratedCase {
  BoundaryLoop loop;
  std::string description;
  bool convex_planar = false;  // planar, convex, corners at the true corners
  bool planar = false;
};

// The i-th case of a reproducible family covering 2, 3 and 4 curves, 1..40 segments
// per curve (even total), uniform, graded and random spacing, convex and mildly
// non-convex planar shapes, and curved 3D boundaries.
GeneratedCase generated_case(int index);

}  // namespace tquad::testing
