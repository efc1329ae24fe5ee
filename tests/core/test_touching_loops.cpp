// splice_touching_loops (touching_loops.h) on generated domains: a jittered convex
// polygon with a triangular hole whose apex is one of the polygon's corners, pointing
// into it, at varied angles and point counts. Each spliced domain must be one simple
// loop that check_planar_domain accepts and the decomposition meshes validly (no
// inverted quad), its points the given ones except the two copies of the apex, each
// moved into its own wedge by at most kPinchNudge of its shorter segment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/decomposition/decomposed_mesher.h"
#include "core/decomposition/face_decomposition.h"
#include "core/mesh/mesh_validation.h"
#include "core/mesh/quality.h"
#include "core/decomposition/touching_loops.h"
#include "domain_generators.h"

namespace tquad {
namespace {

using testing::polygon_loop;

struct TouchingDomain {
  PlanarDomain domain;
  std::vector<long long> ids;  // the apex has one id on both loops
  int apex_outer = 0, apex_hole = 0;
};

TouchingDomain touching_domain(int seed) {
  std::mt19937 rng(static_cast<unsigned>(seed) * 7919u + 11u);
  std::uniform_real_distribution<double> unit(0, 1);
  const int sides = 4 + static_cast<int>(rng() % 5);
  std::vector<Vec3> corners;
  for (int i = 0; i < sides; ++i) {
    const double t = 2 * M_PI * (i + 0.3 * (unit(rng) - 0.5)) / sides;
    corners.push_back({10 * std::cos(t), 10 * std::sin(t), 0});
  }
  const int per_side = 2 + static_cast<int>(rng() % 4);
  TouchingDomain out;
  out.domain.loops.push_back(polygon_loop(corners, per_side));
  // The hole's apex is corner 0; its sides leave it inside the corner's wedge.
  const Vec3 apex = corners[0];
  const double out_angle = std::atan2(corners[1].y - apex.y, corners[1].x - apex.x);
  const double back_angle = std::atan2(corners[sides - 1].y - apex.y, corners[sides - 1].x - apex.x);
  double wedge = back_angle - out_angle;
  while (wedge <= 0) wedge += 2 * M_PI;
  const double f1 = 0.1 + 0.35 * unit(rng), f2 = 0.55 + 0.35 * unit(rng);
  const double length = 3 + 3 * unit(rng);
  const Vec3 p1{apex.x + length * std::cos(out_angle + f1 * wedge), apex.y + length * std::sin(out_angle + f1 * wedge), 0};
  const Vec3 p2{apex.x + length * std::cos(out_angle + f2 * wedge), apex.y + length * std::sin(out_angle + f2 * wedge), 0};
  int hole_per_side = 1 + static_cast<int>(rng() % 4);
  if ((sides * per_side + 3 * hole_per_side) % 2 != 0) ++hole_per_side;
  out.domain.loops.push_back(polygon_loop({apex, p2, p1}, hole_per_side));  // clockwise
  const int n = static_cast<int>(out.domain.loops[0].points.size());
  const int m = static_cast<int>(out.domain.loops[1].points.size());
  for (int i = 0; i < n + m; ++i) out.ids.push_back(i);
  out.ids[n] = 0;  // the hole's first point is the outer loop's first
  return out;
}

class SplicedTouchingHole : public ::testing::TestWithParam<int> {};

TEST_P(SplicedTouchingHole, IsOneSimpleLoopThatMeshesValidly) {
  const TouchingDomain t = touching_domain(GetParam());
  EXPECT_THROW(check_planar_domain(t.domain), InputError);
  const SplicedDomain s = splice_touching_loops(t.domain, t.ids);
  ASSERT_EQ(s.splices, 1);
  ASSERT_EQ(s.domain.loop_count(), 1);
  ASSERT_EQ(static_cast<int>(s.source.size()), t.domain.point_count());
  ASSERT_NO_THROW(check_planar_domain(s.domain));
  // Every given point once, the apex (0 and its hole copy) at its two copies.
  std::vector<int> sorted = s.source;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < t.domain.point_count(); ++i) EXPECT_EQ(sorted[i], i);
  const int n = static_cast<int>(t.domain.loops[0].points.size());
  const std::vector<Vec3>& spliced = s.domain.loops[0].points;
  const int count = static_cast<int>(spliced.size());
  for (int k = 0; k < count; ++k) {
    const int from = s.source[k];
    const Vec3 given = from < n ? t.domain.loops[0].points[from] : t.domain.loops[1].points[from - n];
    if (t.ids[from] != 0) {
      EXPECT_TRUE(spliced[k] == given) << "point " << from << " moved";
      continue;
    }
    const double shorter = std::min(distance(given, spliced[(k + count - 1) % count]),
                                    distance(given, spliced[(k + 1) % count]));
    EXPECT_GT(distance(spliced[k], given), 0.0);
    EXPECT_LE(distance(spliced[k], given), kPinchNudge * shorter * 1.5);
  }
  QuadMesh mesh;
  ASSERT_NO_THROW(mesh = mesh_planar_domain(s.domain, 1.5));
  ASSERT_EQ(check_domain_mesh(mesh, testing::loop_sizes(s.domain)), "") << mesh.template_tree;
  EXPECT_EQ(summarize_quality(mesh, Vec3{0, 0, 1}).inverted, 0) << mesh.template_tree;
}

INSTANTIATE_TEST_SUITE_P(GeneratedDomains, SplicedTouchingHole, ::testing::Range(0, 200));

TEST(SpliceTouchingLoops, LoopsSharingNoPointAreLeftAsTheyAre) {
  const PlanarDomain d = [] {
    PlanarDomain d;
    d.loops.push_back(polygon_loop({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}}, 2));
    d.loops.push_back(testing::circle_hole({2, 2, 0}, 1, 6));
    return d;
  }();
  std::vector<long long> ids(d.point_count());
  for (int i = 0; i < d.point_count(); ++i) ids[i] = i;
  const SplicedDomain s = splice_touching_loops(d, ids);
  EXPECT_EQ(s.splices, 0);
  ASSERT_EQ(s.domain.loop_count(), 2);
  for (int l = 0; l < 2; ++l) EXPECT_TRUE(s.domain.loops[l].points == d.loops[l].points);
}

}  // namespace
}  // namespace tquad
