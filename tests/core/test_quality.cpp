// Quality metrics on shapes whose values are known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "core/mesh/quality.h"

namespace tquad {
namespace {

const Vec3 kUp{0, 0, 1};

// The same double, bit for bit (NaN included).
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(Quality, OnePassGivesTheSeparateMeasuresBitForBit) {
  // Random quads, planar and not, with coincident corners and zero normals mixed in.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  std::uniform_int_distribution<int> kind(0, 5);
  int collapsed = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = {coordinate(rng), coordinate(rng), trial % 2 ? coordinate(rng) : 0.0};
    if (kind(rng) == 0) p[2] = p[1];                                  // a zero-length side
    if (kind(rng) == 0) p[3] = p[0] + 1e-5 * (p[3] - p[0]);           // a collapsed side
    Vec3 normal = trial % 3 == 0 ? Vec3{0, 0, 1} : cross(p[2] - p[0], p[3] - p[1]);
    if (kind(rng) == 0) normal = {0, 0, 0};
    const QuadQuality q = quad_quality(p, normal);
    ASSERT_TRUE(same_bits(q.lee_lo, lee_lo_quality(p, normal))) << trial;
    ASSERT_TRUE(same_bits(q.scaled_jacobian, scaled_jacobian(p, normal))) << trial;
    ASSERT_EQ(q.collapsed, is_collapsed(p)) << trial;
    collapsed += q.collapsed ? 1 : 0;
  }
  EXPECT_GT(collapsed, 100);
}

TEST(Quality, PlanarCornersAreTheGeneralOnesSignedByUp) {
  // Quads of a plane z = c: random ones, and on a small integer grid (straight
  // corners, zero-length sides and inverted quads come often there).
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  std::uniform_int_distribution<int> grid(-2, 2);
  const std::array<Vec3, 4> up = {kUp, kUp, kUp, kUp};
  int straight = 0, degenerate_side = 0, inverted = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double z = trial % 3 == 0 ? 0.0 : coordinate(rng);
    std::array<Vec3, 4> p;
    for (Vec3& v : p) {
      v = trial % 2 ? Vec3{coordinate(rng), coordinate(rng), z}
                    : Vec3{double(grid(rng)), double(grid(rng)), z};
    }
    const QuadCorners general = quad_corners(p, up), planar = planar_quad_corners(p);
    for (int i = 0; i < 4; ++i) {
      ASSERT_EQ(planar.jacobian[i], general.jacobian[i]) << trial << " corner " << i;
      ASSERT_EQ(planar.own_jacobian[i], general.own_jacobian[i]) << trial << " corner " << i;
      straight += general.jacobian[i] == 0 ? 1 : 0;
      degenerate_side += general.jacobian[i] == -1 ? 1 : 0;
      inverted += general.jacobian[i] < 0 && general.jacobian[i] > -1 ? 1 : 0;
    }
    ASSERT_EQ(planar.collapsed, general.collapsed) << trial;
    ASSERT_TRUE(same_bits(planar.edge_ratio, general.edge_ratio)) << trial;
  }
  EXPECT_GT(straight, 100);
  EXPECT_GT(degenerate_side, 100);
  EXPECT_GT(inverted, 1000);
}

TEST(Quality, LeeLoIsTheProductOfItsSortedCornerMeasures) {
  // Lee-Lo from its definition (quality.h), the corners' alphas sorted by std::sort,
  // against quality.cpp's sorting by minima and maxima; inverted and degenerate quads
  // included (a4 <= 0: a4 / a1).
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  std::uniform_int_distribution<int> grid(-2, 2);
  int non_positive = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = trial % 2 ? Vec3{coordinate(rng), coordinate(rng), 0} : Vec3{double(grid(rng)), double(grid(rng)), 0};
    std::array<double, 4> alpha;
    for (int i = 0; i < 4; ++i) {
      const Vec3 &prev = p[(i + 3) % 4], &here = p[i], &next = p[(i + 1) % 4];
      const double squares = dot(next - here, next - here) + dot(prev - here, prev - here) + dot(next - prev, next - prev);
      const double twice_area = dot(cross(next - here, prev - here), kUp);
      alpha[i] = squares > 0 ? std::sqrt(3.0) * twice_area / squares : 0.0;
    }
    std::sort(alpha.begin(), alpha.end(), [](double a, double b) { return a > b; });
    double expected;
    if (alpha[3] <= 0) {
      expected = alpha[0] > 0 ? std::max(-1.0, alpha[3] / alpha[0]) : -1.0;
      ++non_positive;
    } else {
      expected = alpha[2] * alpha[3] / (alpha[0] * alpha[1]);
    }
    ASSERT_NEAR(lee_lo_quality(p, kUp), expected, 1e-12) << trial;
  }
  EXPECT_GT(non_positive, 1000);
}

TEST(Quality, RectanglesScoreOne) {
  for (double w : {1.0, 0.2, 5.0}) {
    const std::array<Vec3, 4> q{Vec3{0, 0, 0}, Vec3{w, 0, 0}, Vec3{w, 1, 0}, Vec3{0, 1, 0}};
    EXPECT_NEAR(lee_lo_quality(q, kUp), 1.0, 1e-12) << w;
    EXPECT_NEAR(scaled_jacobian(q, kUp), 1.0, 1e-12) << w;
  }
}

TEST(Quality, ATriangleInEffectIsCollapsedAndAThinRectangleIsNot) {
  // A side 1e-5 long facing one of 1: every corner is about 90 or 45 degrees, yet the
  // Jacobian determinant at the short side is 1e-5 of the one facing it.
  const std::array<Vec3, 4> wedge{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1e-5, 0}};
  EXPECT_GT(scaled_jacobian(wedge, kUp), 0.5);
  EXPECT_TRUE(is_collapsed(wedge));
  EXPECT_TRUE(quad_corners(wedge, {kUp, kUp, kUp, kUp}).collapsed);
  EXPECT_TRUE(is_bad_quad(wedge, scaled_jacobian(wedge, kUp)));
  // A rectangle 1e-5 wide (a strip face far narrower than the size): its Jacobian is
  // the same at every corner, and it is the only mesh such a face has.
  const std::array<Vec3, 4> strip{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1e-5, 0}, Vec3{0, 1e-5, 0}};
  EXPECT_FALSE(is_collapsed(strip));
  EXPECT_FALSE(planar_quad_corners(strip).collapsed);
  EXPECT_FALSE(is_bad_quad(strip, scaled_jacobian(strip, kUp)));
  // Tapering to a tenth of its width across its length: not collapsed either.
  const std::array<Vec3, 4> taper{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1e-4, 0}, Vec3{0, 1e-5, 0}};
  EXPECT_FALSE(is_collapsed(taper));
}

TEST(Quality, ParallelogramScoresItsAngle) {
  const double angle = M_PI / 3;  // 60 degrees
  const Vec3 s{std::cos(angle), std::sin(angle), 0};
  const std::array<Vec3, 4> q{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 0, 0} + s, s};
  EXPECT_NEAR(scaled_jacobian(q, kUp), std::sin(angle), 1e-12);
  // Unit rhombus: corner triangles at 60 degrees are equilateral (alpha 1), at 120
  // degrees have edges 1, 1, sqrt(3) and alpha = 2 sqrt(3) (sqrt(3)/4) / 5 = 0.6.
  EXPECT_NEAR(lee_lo_quality(q, kUp), (0.6 * 0.6) / (1.0 * 1.0), 1e-12);
}

TEST(Quality, InvertedAndDegenerateQuadsScoreAtMostZero) {
  const std::array<Vec3, 4> clockwise{Vec3{0, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 0}, Vec3{1, 0, 0}};
  EXPECT_LT(scaled_jacobian(clockwise, kUp), 0);
  EXPECT_LT(lee_lo_quality(clockwise, kUp), 0);
  const std::array<Vec3, 4> straight_corner{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{2, 0, 0}, Vec3{1, 1, 0}};
  EXPECT_NEAR(scaled_jacobian(straight_corner, kUp), 0.0, 1e-12);
  EXPECT_LE(lee_lo_quality(straight_corner, kUp), 0.0);
  const std::array<Vec3, 4> bow_tie{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 0}};
  EXPECT_LT(scaled_jacobian(bow_tie, kUp), 0);
}

TEST(Quality, SummaryCountsInvertedQuadsAndComputesStatistics) {
  QuadMesh mesh;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  mesh.quads = {{0, 1, 2, 3}, {1, 2, 5, 4}};  // the second is clockwise
  const QualitySummary s = summarize_quality(mesh, kUp);
  EXPECT_EQ(s.inverted, 1);
  EXPECT_NEAR(s.scaled_jacobian.max, 1.0, 1e-12);
  EXPECT_NEAR(s.scaled_jacobian.min, -1.0, 1e-12);
  EXPECT_NEAR(s.scaled_jacobian.avg, 0.0, 1e-12);
  EXPECT_NEAR(s.scaled_jacobian.std, 1.0, 1e-12);
}

}  // namespace
}  // namespace tquad
