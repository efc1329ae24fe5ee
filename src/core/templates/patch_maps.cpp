#include "core/templates/patch_maps.h"

namespace tquad {

Vec3 QuadPatchMap::operator()(double u, double v) const {
  const CurveGeometry &s0 = *s_[0], &s1 = *s_[1], &s2 = *s_[2], &s3 = *s_[3];
  const Vec3 bottom = s0.at(u), top = s2.at(1.0 - u);
  const Vec3 left = s3.at(1.0 - v), right = s1.at(v);
  const Vec3 p00 = s0.point(0), p10 = s1.point(0), p11 = s2.point(0), p01 = s3.point(0);
  return (1 - v) * bottom + v * top + (1 - u) * left + u * right -
         ((1 - u) * (1 - v) * p00 + u * (1 - v) * p10 + u * v * p11 + (1 - u) * v * p01);
}

Vec3 TriPatchMap::operator()(const Barycentric& l) const {
  const CurveGeometry &s0 = *s_[0], &s1 = *s_[1], &s2 = *s_[2];
  constexpr double kCorner = 1e-12;
  for (int i = 0; i < 3; ++i) {
    if (1.0 - l[i] < kCorner) return s_[i]->point(0);
  }
  const double l0 = l[0], l1 = l[1], l2 = l[2];
  // Lines of constant l2 meet s1 at s1(l2) and s2 at s2(1 - l2); likewise for l0, l1.
  const Vec3 along_l2 = (l1 / (1 - l2)) * s1.at(l2) + (l0 / (1 - l2)) * s2.at(1 - l2);
  const Vec3 along_l0 = (l2 / (1 - l0)) * s2.at(l0) + (l1 / (1 - l0)) * s0.at(1 - l0);
  const Vec3 along_l1 = (l0 / (1 - l1)) * s0.at(l1) + (l2 / (1 - l1)) * s1.at(1 - l1);
  const Vec3 corners = l0 * s0.point(0) + l1 * s1.point(0) + l2 * s2.point(0);
  return 0.5 * (along_l2 + along_l0 + along_l1 - corners);
}

}  // namespace tquad
