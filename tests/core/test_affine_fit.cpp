// AffineMap::fit over generated point sets: an affine map that the points determine
// (spread in 3D) is recovered from them exactly; one that they do not (points on a
// plane) still takes every point of that plane where the map does, and moves nothing
// off it along the plane's normal; a misfit leaves the least-squares residual (its
// sum is zero: the centroids match).
#include <gtest/gtest.h>

#include <random>

#include "case_stride.h"
#include "core/geometry/affine_fit.h"

namespace tquad {
namespace {

struct Affine {
  double m[3][3];
  Vec3 b;
  Vec3 operator()(const Vec3& x) const {
    return Vec3{m[0][0] * x.x + m[0][1] * x.y + m[0][2] * x.z, m[1][0] * x.x + m[1][1] * x.y + m[1][2] * x.z,
                m[2][0] * x.x + m[2][1] * x.y + m[2][2] * x.z} +
           b;
  }
};

Affine random_affine(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-2, 2);
  Affine a;
  for (auto& row : a.m) {
    for (double& v : row) v = u(rng);
  }
  a.b = Vec3{10 * u(rng), 10 * u(rng), 10 * u(rng)};
  return a;
}

TEST(AffineFit, RecoversTheMapOfPointsSpreadIn3D) {
  for (int i : testing::cases(500)) {
    SCOPED_TRACE(testing::case_trace(i));
    std::mt19937 rng(i);
    std::uniform_real_distribution<double> u(-50, 50);
    const Affine truth = random_affine(rng);
    std::vector<Vec3> a, b;
    for (int k = 0; k < 4 + i % 40; ++k) {
      a.push_back(Vec3{u(rng), u(rng), u(rng)});
      b.push_back(truth(a.back()));
    }
    const AffineMap fit = AffineMap::fit(a, b);
    const Vec3 probe{u(rng), u(rng), u(rng)};
    EXPECT_LT(distance(fit(probe), truth(probe)), 1e-8 * (1 + norm(truth(probe))));
  }
}

TEST(AffineFit, PointsOnAPlaneMapThatPlaneAndLeaveItsNormalOut) {
  for (int i : testing::cases(500)) {
    SCOPED_TRACE(testing::case_trace(i));
    std::mt19937 rng(1000 + i);
    std::uniform_real_distribution<double> u(-50, 50);
    const Affine truth = random_affine(rng);
    // A plane through a random point with two random directions.
    const Vec3 origin{u(rng), u(rng), u(rng)}, e1{u(rng), u(rng), u(rng)}, e2{u(rng), u(rng), u(rng)};
    const Vec3 normal = cross(e1, e2);
    if (norm(normal) < 1e-3 * norm(e1) * norm(e2)) continue;  // nearly parallel: no plane
    std::vector<Vec3> a, b;
    std::uniform_real_distribution<double> w(-1, 1);
    for (int k = 0; k < 3 + i % 30; ++k) {
      a.push_back(origin + w(rng) * e1 + w(rng) * e2);
      b.push_back(truth(a.back()));
    }
    const AffineMap fit = AffineMap::fit(a, b);
    const Vec3 on = origin + w(rng) * e1 + w(rng) * e2;
    EXPECT_LT(distance(fit(on), truth(on)), 1e-7 * (1 + norm(truth(on))));
    const Vec3 off = on + (w(rng) / norm(normal)) * normal * 30.0;
    EXPECT_LT(distance(fit(off), fit(on)), 1e-7 * (1 + norm(fit(on))));
  }
}

TEST(AffineFit, AMisfitLeavesResidualsThatSumToZero) {
  for (int i : testing::cases(200)) {
    SCOPED_TRACE(testing::case_trace(i));
    std::mt19937 rng(5000 + i);
    std::uniform_real_distribution<double> u(-50, 50), noise(-1, 1);
    const Affine truth = random_affine(rng);
    std::vector<Vec3> a, b;
    for (int k = 0; k < 8 + i % 20; ++k) {
      a.push_back(Vec3{u(rng), u(rng), u(rng)});
      b.push_back(truth(a.back()) + Vec3{noise(rng), noise(rng), noise(rng)});
    }
    const AffineMap fit = AffineMap::fit(a, b);
    Vec3 sum{0, 0, 0};
    double squares = 0, truth_squares = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      sum += b[k] - fit(a[k]);
      squares += dot(b[k] - fit(a[k]), b[k] - fit(a[k]));
      truth_squares += dot(b[k] - truth(a[k]), b[k] - truth(a[k]));
    }
    EXPECT_LT(norm(sum), 1e-8 * a.size() * 50);
    EXPECT_LE(squares, truth_squares * (1 + 1e-9));  // no worse than the map the points came from
  }
}

TEST(AffineFit, BadListsAreRefused) {
  EXPECT_THROW(AffineMap::fit({}, {}), std::invalid_argument);
  EXPECT_THROW(AffineMap::fit({Vec3{0, 0, 0}}, {}), std::invalid_argument);
  // One point: a translation.
  const AffineMap shift = AffineMap::fit({Vec3{1, 2, 3}}, {Vec3{4, 4, 4}});
  EXPECT_LT(distance(shift(Vec3{0, 0, 0}), Vec3{3, 2, 1}), 1e-12);
}

}  // namespace
}  // namespace tquad
