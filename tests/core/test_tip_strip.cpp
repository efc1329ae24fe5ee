// The tip strip (core/templates/tip_strip.h): thin lenses between two sharp tips,
// generated over many shapes, counts and orientations, meshed as two rows and a kite
// at each tip, every quad convex; loops it does not fit are declined.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <utility>

#include "core/templates/tip_strip.h"

namespace tquad {
namespace {

struct Lens {
  std::vector<Vec3> points;
  int tip_a = 0, tip_b = 0, n = 0;
};

// A lens over x in [0, 1]: chain A above (y = top(x)), chain B below (y = -bottom(x)),
// both n segments with the same, unevenly spread, abscissas (jittered a little on
// one chain), the tips' angles between about 3 and 60 degrees; then turned, scaled
// and, for odd seeds, run clockwise.
Lens generated_lens(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Lens lens;
  lens.n = 3 + static_cast<int>(unit(random) * 22);
  const double top = 0.01 + 0.25 * unit(random), bottom = 0.01 + 0.25 * unit(random);
  const double power = 0.6 + 0.8 * unit(random);  // how blunt the lens is
  const double spread = 0.6 * unit(random);       // uneven spacing
  const auto x_at = [&](int i) {
    const double t = static_cast<double>(i) / lens.n;
    return t + spread * std::sin(M_PI * t) * (t - 0.5) * 0.5;
  };
  const auto height = [&](double x, double h) { return h * std::pow(std::sin(M_PI * x), power); };
  std::vector<Vec3> loop;
  for (int i = 0; i < lens.n; ++i) {  // chain A: from tip 0 along the top
    const double x = x_at(i);
    loop.push_back({x, height(x, top), 0});
  }
  for (int i = lens.n; i > 0; --i) {  // chain B: from tip 1 back along the bottom
    const double jitter = (i == lens.n) ? 0.0 : 0.2 / lens.n * (unit(random) - 0.5);
    const double x = x_at(i) + jitter;
    loop.push_back({x, -height(x, bottom), 0});
  }
  loop[lens.n] = {1, 0, 0};
  // Along the top left to right, back along the bottom: clockwise; mirrored, counter-clockwise.
  for (Vec3& p : loop) p.y = -p.y;
  const double angle = 2 * M_PI * unit(random), scale = 0.1 + 10 * unit(random);
  for (Vec3& p : loop) {
    p = {scale * (std::cos(angle) * p.x - std::sin(angle) * p.y) + 3,
         scale * (std::sin(angle) * p.x + std::cos(angle) * p.y) - 1, 0};
  }
  const int shift = static_cast<int>(unit(random) * loop.size());
  std::rotate(loop.begin(), loop.begin() + shift, loop.end());
  lens.tip_a = (static_cast<int>(loop.size()) - shift) % static_cast<int>(loop.size());
  lens.tip_b = (lens.tip_a + lens.n) % static_cast<int>(loop.size());
  if (seed % 2 == 1) {
    std::reverse(loop.begin(), loop.end());
    const int count = static_cast<int>(loop.size());
    lens.tip_a = count - 1 - lens.tip_a;
    lens.tip_b = count - 1 - lens.tip_b;
  }
  lens.points = loop;
  return lens;
}

double loop_area2(const std::vector<Vec3>& p) {
  double s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 &a = p[i], &b = p[(i + 1) % p.size()];
    s += a.x * b.y - b.x * a.y;
  }
  return s;
}

class TipStripOf : public ::testing::TestWithParam<unsigned> {};

TEST_P(TipStripOf, TwoRowsAndAKiteAtEachTipEveryQuadConvexTheLoopKept) {
  const Lens lens = generated_lens(GetParam());
  const int count = static_cast<int>(lens.points.size());
  const std::optional<QuadMesh> mesh = mesh_tip_strip(lens.points, lens.tip_a, lens.tip_b);
  ASSERT_TRUE(mesh) << "n " << lens.n;
  ASSERT_EQ(mesh->quads.size(), static_cast<std::size_t>(2 * lens.n - 2));
  ASSERT_EQ(mesh->nodes.size(), static_cast<std::size_t>(count + lens.n - 1));
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(mesh->nodes[i].x, lens.points[i].x);
    EXPECT_EQ(mesh->nodes[i].y, lens.points[i].y);
  }
  const double sign = loop_area2(lens.points) > 0 ? 1.0 : -1.0;
  std::map<std::pair<NodeId, NodeId>, int> directed;
  std::map<NodeId, int> quads_at;
  for (const Quad& q : mesh->quads) {
    for (int i = 0; i < 4; ++i) {
      ++directed[{q[i], q[(i + 1) % 4]}];
      ++quads_at[q[i]];
      const Vec3 &prev = mesh->nodes[q[(i + 3) % 4]], &here = mesh->nodes[q[i]], &next = mesh->nodes[q[(i + 1) % 4]];
      const Vec3 e = next - here, f = prev - here;
      EXPECT_GT(sign * (e.x * f.y - e.y * f.x) / (norm(e) * norm(f)), 0.0) << "quad corner at node " << q[i];
    }
  }
  // The loop's segments once each, the loop's way; every inner edge twice, both ways.
  for (int i = 0; i < count; ++i) {
    const NodeId from = i, to = (i + 1) % count;
    EXPECT_EQ(directed[std::make_pair(from, to)], 1) << "segment " << i;
    EXPECT_EQ(directed.count({to, from}), 0u) << "segment " << i;
  }
  for (const auto& [edge, uses] : directed) {
    EXPECT_EQ(uses, 1);
    const bool on_loop = edge.first < count && edge.second < count;
    if (!on_loop) EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << edge.first << "-" << edge.second;
  }
  // Each tip is the corner of one quad.
  EXPECT_EQ(quads_at[lens.tip_a], 1);
  EXPECT_EQ(quads_at[lens.tip_b], 1);
}

INSTANTIATE_TEST_SUITE_P(GeneratedLenses, TipStripOf, ::testing::Range(0u, 200u));

TEST(TipStrip, LoopsItDoesNotFitAreDeclined) {
  const Lens lens = generated_lens(4);
  const int count = static_cast<int>(lens.points.size());
  EXPECT_FALSE(mesh_tip_strip(lens.points, lens.tip_a, lens.tip_a));
  EXPECT_FALSE(mesh_tip_strip(lens.points, lens.tip_a, count));
  EXPECT_FALSE(mesh_tip_strip(lens.points, -1, lens.tip_b));
  // Chains of unequal counts.
  EXPECT_FALSE(mesh_tip_strip(lens.points, lens.tip_a, (lens.tip_b + 2) % count));
  // Two segments a chain: no row between the kites.
  const std::vector<Vec3> diamond{{0, 0, 0}, {1, 0.1, 0}, {2, 0, 0}, {1, -0.1, 0}};
  EXPECT_FALSE(mesh_tip_strip(diamond, 0, 2));
  // A loop folded so that a quad would turn the wrong way.
  std::vector<Vec3> bent = {{0, 0, 0}, {1, 0.05, 0}, {2, 0.05, 0}, {3, 0, 0}, {2, -0.05, 0}, {1, 3, 0}};
  EXPECT_FALSE(mesh_tip_strip(bent, 0, 3));
}

}  // namespace
}  // namespace tquad
