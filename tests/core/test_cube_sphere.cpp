// The cube sphere (core/templates/cube_sphere.h): a closed, consistently oriented all-quad mesh
// of the unit sphere for every even m, whose seam is the meridian through +x.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "core/templates/cube_sphere.h"
#include "core/mesh/quality.h"

namespace tquad {
namespace {

class CubeSphereOf : public ::testing::TestWithParam<int> {};

TEST_P(CubeSphereOf, IsAClosedOutwardMeshWithItsSeamOnTheMeridian) {
  const int m = GetParam();
  const CubeSphere s = cube_sphere(m);
  ASSERT_EQ(s.quads.size(), static_cast<std::size_t>(6 * m * m));
  ASSERT_EQ(s.nodes.size(), static_cast<std::size_t>(6 * m * m + 2));
  // Every directed edge once, and its reverse once: closed and consistently oriented.
  std::map<std::pair<NodeId, NodeId>, int> directed;
  for (const Quad& q : s.quads) {
    for (int i = 0; i < 4; ++i) ++directed[{q[i], q[(i + 1) % 4]}];
  }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << "edge " << edge.first << "-" << edge.second;
  }
  // V - E + F = 2.
  EXPECT_EQ(static_cast<long long>(s.nodes.size()) - static_cast<long long>(directed.size() / 2) +
                static_cast<long long>(s.quads.size()),
            2);
  // Outward: every corner positive against the radial normal, the worst that of the
  // cube's corners (three quads of 120 degrees) or better.
  for (const Quad& q : s.quads) {
    const std::array<Vec3, 4> p{s.nodes[q[0]], s.nodes[q[1]], s.nodes[q[2]], s.nodes[q[3]]};
    const Vec3 outward = p[0] + p[1] + p[2] + p[3];
    EXPECT_GT(scaled_jacobian(p, outward), std::sin(2 * M_PI / 3) - 1e-3);
    EXPECT_GT(own_scaled_jacobian(p), std::sin(2 * M_PI / 3) - 1e-3);
  }
  // The seam: 2m + 1 nodes on y = 0, x >= 0, from the south pole to the north pole
  // in equal angles.
  ASSERT_EQ(s.seam.size(), static_cast<std::size_t>(2 * m + 1));
  for (std::size_t t = 0; t < s.seam.size(); ++t) {
    const Vec3& p = s.nodes[s.seam[t]];
    EXPECT_NEAR(p.y, 0.0, 1e-15);
    EXPECT_GE(p.x, -1e-15);
    EXPECT_NEAR(std::asin(std::clamp(p.z, -1.0, 1.0)), -M_PI / 2 + M_PI * t / (2.0 * m), 1e-12) << "seam node " << t;
  }
}

INSTANTIATE_TEST_SUITE_P(EvenCounts, CubeSphereOf, ::testing::Values(2, 4, 6, 8, 12, 20, 32));

TEST(CubeSphere, OddOrTooFewSegmentsAreRefused) {
  for (int m : {-2, 0, 1, 3, 7}) EXPECT_THROW(cube_sphere(m), std::invalid_argument) << m;
}

}  // namespace
}  // namespace tquad
