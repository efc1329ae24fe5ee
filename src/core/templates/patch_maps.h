// The transfinite maps the templates use to place interior points and cuts.
#pragma once

#include <array>

#include "core/geometry/curve_geometry.h"

namespace tquad {

// QuadPatchMap: bilinear transfinite projector of four curves (paper, eq. 1). Curves
// in loop order: s0 bottom (u from 0 to 1), s1 right (v up), s2 top (run from right
// to left), s3 left (run down). F interpolates the four curves exactly.
class QuadPatchMap {
 public:
  QuadPatchMap(const CurveGeometry& s0, const CurveGeometry& s1, const CurveGeometry& s2,
               const CurveGeometry& s3)
      : s_{&s0, &s1, &s2, &s3} {}
  Vec3 operator()(double u, double v) const;

 private:
  std::array<const CurveGeometry*, 4> s_;
};

// Barycentric coordinates of a three-curve region: l[i] is the weight of corner Vi,
// the start of curve si. A point at parameter t on s0 is (1-t, t, 0), on s1
// (0, 1-t, t), on s2 (t, 0, 1-t).
using Barycentric = std::array<double, 3>;

// TriPatchMap: trilinear transfinite projector of three curves (paper, eq. 2, the
// Barnhill-Birkhoff-Gordon triangle: the mean of three projectors along lines of
// constant l0, l1, l2, less the linear interpolant of the corners). Interpolates the
// three curves exactly.
class TriPatchMap {
 public:
  TriPatchMap(const CurveGeometry& s0, const CurveGeometry& s1, const CurveGeometry& s2)
      : s_{&s0, &s1, &s2} {}
  Vec3 operator()(const Barycentric& l) const;

 private:
  std::array<const CurveGeometry*, 3> s_;
};

}  // namespace tquad
