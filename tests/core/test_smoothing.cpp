// Smoothing, doublets and hole rings (smoothing.h, doublets.h, hole_rings.h): examples,
// and a property check over the generated planar domains of the face decomposition
// tests: after cleaning and smoothing, every mesh is still valid, keeps its boundary
// points bit-exact, satisfies nodes = 1 + quads + boundary_edges / 2 - holes, and its
// worst corner is no lower than before. The gain is printed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "case_stride.h"
#include "core/repair/area_untangling.h"
#include "core/decomposition/decomposed_mesher.h"
#include "core/repair/doublets.h"
#include "core/decomposition/hole_rings.h"
#include "core/geometry/max_min_ascent.h"
#include "core/mesh/mesh_validation.h"
#include "core/mesh/quality.h"
#include "core/repair/reflex_corners.h"
#include "core/repair/smoothing.h"
#include "domain_generators.h"

namespace tquad {
namespace {

using testing::circle_hole;
using testing::loop_sizes;

const Vec3 kUp{0, 0, 1};

DomainLoop square_loop(double x0, double y0, double x1, double y1, int per_side) {
  DomainLoop loop;
  const Vec3 c[4] = {{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}};
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < per_side; ++k) {
      loop.points.push_back(c[i] + (static_cast<double>(k) / per_side) * (c[(i + 1) % 4] - c[i]));
      loop.vertex.push_back(k == 0);
    }
  }
  return loop;
}

// Quads around each node.
std::vector<int> quads_per_node(const QuadMesh& mesh) {
  std::vector<int> count(mesh.nodes.size(), 0);
  for (const Quad& q : mesh.quads) for (NodeId n : q) ++count[n];
  return count;
}

TEST(Doublets, TwoQuadsAroundOneInteriorNodeBecomeOne) {
  // A unit square cut along its diagonal through a node at its centre: both quads
  // have a straight angle there.
  std::vector<Quad> quads{{4, 0, 1, 2}, {4, 2, 3, 0}};
  std::vector<Vec3> position{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}};
  std::vector<Vec3> param = position, normal(5, kUp);
  EXPECT_EQ(remove_doublets(quads, 4, param, position, normal), 1);
  ASSERT_EQ(quads.size(), 1u);
  EXPECT_EQ(quads[0], (Quad{0, 1, 2, 3}));
  EXPECT_EQ(position.size(), 4u);
  EXPECT_EQ(param.size(), 4u);
  // A fixed node is never removed.
  std::vector<Quad> kept{{4, 0, 1, 2}, {4, 2, 3, 0}};
  std::vector<Vec3> p2{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}}, u2 = p2, n2(5, kUp);
  EXPECT_EQ(remove_doublets(kept, 5, u2, p2, n2), 0);
  EXPECT_EQ(kept.size(), 2u);
}

TEST(Smoothing, MovesAnInteriorNodeOffAStraightAngleAndNeverLowersTheWorst) {
  // A 2 x 2 grid of quads whose middle node sits on the straight line between two
  // edge midpoints' diagonal: moved, the corners around it improve.
  QuadMesh mesh;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}, {0, 2, 0}, {0, 1, 0}, {1.9, 1.8, 0}};
  mesh.quads = {{0, 1, 8, 7}, {1, 2, 3, 8}, {8, 3, 4, 5}, {7, 8, 5, 6}};
  const double before = summarize_quality(mesh, kUp).scaled_jacobian.min;
  int merged = 0;
  const SmoothingResult r = smooth_planar_mesh(mesh, 8, merged);
  EXPECT_EQ(merged, 0);
  // (1.9, 1.8) folds the corner at (2, 1): the untangling moves it first.
  EXPECT_GT(r.untangling_moves, 0);
  const double after = summarize_quality(mesh, kUp).scaled_jacobian.min;
  EXPECT_GT(after, before);
  EXPECT_GT(after, 0.95) << "the middle node goes to the centre";
  for (int i = 0; i < 8; ++i) EXPECT_EQ(mesh.nodes[i].z, 0.0);
}

// A 4 x 4 grid on the unit square: boundary nodes 0..11 counter-clockwise from
// (0, 0), interior nodes 12..15 at (1/4 + k/2 ...) below.
struct Grid {
  std::vector<Vec3> nodes;
  std::vector<Quad> quads;
};
Grid four_by_four() {
  Grid g;
  int id[5][5];
  for (int i = 0; i <= 4; ++i) {
    for (int j = 0; j <= 4; ++j) id[i][j] = -1;
  }
  // Boundary first, counter-clockwise.
  for (int k = 0; k < 4; ++k) id[k][0] = static_cast<int>(g.nodes.size()), g.nodes.push_back({k / 4.0, 0, 0});
  for (int k = 0; k < 4; ++k) id[4][k] = static_cast<int>(g.nodes.size()), g.nodes.push_back({1, k / 4.0, 0});
  for (int k = 4; k > 0; --k) id[k][4] = static_cast<int>(g.nodes.size()), g.nodes.push_back({k / 4.0, 1, 0});
  for (int k = 4; k > 0; --k) id[0][k] = static_cast<int>(g.nodes.size()), g.nodes.push_back({0, k / 4.0, 0});
  for (int i = 1; i < 4; ++i) {
    for (int j = 1; j < 4; ++j) id[i][j] = static_cast<int>(g.nodes.size()), g.nodes.push_back({i / 4.0, j / 4.0, 0});
  }
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) g.quads.push_back({id[i][j], id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]});
  }
  return g;
}

TEST(AreaUntangling, UnfoldsAGridWhoseInteriorNodesWereThrownAcrossIt) {
  Grid g = four_by_four();
  const int fixed = 16;
  // Interior nodes mirrored through the centre: every interior corner folds.
  for (int n = fixed; n < static_cast<int>(g.nodes.size()); ++n) g.nodes[n] = Vec3{1, 1, 0} - g.nodes[n];
  g.nodes[fixed + 4] = {0.9, 0.1, 0};  // the centre node thrown to a corner
  const std::vector<Vec3> boundary(g.nodes.begin(), g.nodes.begin() + fixed);
  ASSERT_GT(inverted_corners(g.quads, g.nodes, 1.0), 0);
  int placed = 0;
  const AreaUntanglingResult r = untangle_corner_areas(g.quads, fixed, g.nodes, 1.0, [&](int n, const Vec3&) {
    EXPECT_GE(n, fixed);
    ++placed;
    return true;
  });
  EXPECT_GT(r.inverted_before, 0);
  EXPECT_EQ(r.inverted_after, 0);
  EXPECT_EQ(inverted_corners(g.quads, g.nodes, 1.0), 0);
  EXPECT_EQ(placed, r.moves);
  for (int n = 0; n < fixed; ++n) EXPECT_TRUE(g.nodes[n] == boundary[n]) << n;
}

TEST(AreaUntangling, RefusedPlacesAreNotTakenAndAFoldItCannotUndoIsLeftAsItWas) {
  Grid g = four_by_four();
  const int fixed = 16;
  g.nodes[fixed + 4] = {0.9, 0.1, 0};
  const std::vector<Vec3> before = g.nodes;
  // Every place refused: nothing moves.
  AreaUntanglingResult r = untangle_corner_areas(g.quads, fixed, g.nodes, 1.0, [](int, const Vec3&) { return false; });
  EXPECT_EQ(r.moves, 0);
  EXPECT_EQ(r.inverted_after, r.inverted_before);
  for (std::size_t n = 0; n < g.nodes.size(); ++n) EXPECT_TRUE(g.nodes[n] == before[n]) << n;
  // A boundary node pushed inside the grid (fixed, so the fold stays): the nodes
  // that moved trying go back.
  g.nodes[2] = {0.5, 0.6, 0};
  const std::vector<Vec3> folded = g.nodes;
  r = untangle_corner_areas(g.quads, fixed, g.nodes, 1.0, [](int, const Vec3&) { return true; });
  EXPECT_GT(r.inverted_after, 0);
  EXPECT_LE(r.inverted_after, r.inverted_before);
  if (r.inverted_after == r.inverted_before) {
    for (std::size_t n = 0; n < g.nodes.size(); ++n) EXPECT_TRUE(g.nodes[n] == folded[n]) << n;
  }
}

TEST(ReflexCorners, AQuadAloneAtAReflexPointIsSplitInFiveAndSmoothedValid) {
  // An arrowhead of four boundary points, (1, 1) reflex, meshed as its own single
  // quad: that quad is inverted at (1, 1) whatever moves. Split in five and smoothed,
  // every quad is valid and the boundary is kept.
  QuadMesh mesh;
  mesh.nodes = {{0, 0, 0}, {3, 1, 0}, {0, 2, 0}, {1, 1, 0}};
  mesh.quads = {{0, 1, 2, 3}};
  EXPECT_EQ(summarize_quality(mesh, kUp).inverted, 1);
  const std::vector<Vec3> boundary = mesh.nodes;
  ASSERT_NO_THROW(smooth_region(mesh, 4, kUp));
  EXPECT_EQ(mesh.quads.size(), 5u);
  EXPECT_EQ(mesh.nodes.size(), 1 + mesh.quads.size() + 4 / 2);
  EXPECT_EQ(check_disk_mesh(mesh, 4), "");
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(mesh.nodes[i] == boundary[i]) << i;
  const QualitySummary q = summarize_quality(mesh, kUp);
  EXPECT_EQ(q.inverted, 0);
  EXPECT_GT(q.scaled_jacobian.min, 0.0);
  // A convex quad is left alone.
  QuadMesh square;
  square.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.quads = {{0, 1, 2, 3}};
  EXPECT_EQ(split_reflex_corner_quads(square, 4, kUp), 0);
  EXPECT_EQ(square.quads.size(), 1u);
}

TEST(HoleRings, AHoleGetsMappedRingsAndNoFanOnItsRim) {
  PlanarDomain d;
  d.loops.push_back(square_loop(0, 0, 10, 6, 15));
  d.loops.push_back(circle_hole({5, 3}, 1.0, 24));
  const RingedDomain ringed = ring_holes(d);
  EXPECT_EQ(ringed.rings, kHoleRingLayers);
  EXPECT_EQ(ringed.ring_quads.size(), 24u * kHoleRingLayers);
  const QuadMesh mesh = mesh_planar_domain(d, 10.0 / 15);
  ASSERT_EQ(check_domain_mesh(mesh, loop_sizes(d)), "");
  const std::vector<int> around = quads_per_node(mesh);
  const int rim = d.offset(1);
  for (int i = 0; i < 24; ++i) EXPECT_EQ(around[rim + i], 2) << "rim node " << i << " lies in a fan";
  EXPECT_EQ(summarize_quality(mesh, kUp).inverted, 0);
}

TEST(HoleRings, AFineRimGetsGradedRingsOutToTheOutlinesSpacing) {
  // A 100 x 60 outline of spacing 5 and a hole of radius 10 of spacing about 0.5 (a
  // local size on it): rings each kRingGrowth times as thick as the one inside, more
  // than the two a uniform rim gets, and a mesh whose rim nodes lie in no fan.
  PlanarDomain d;
  d.loops.push_back(square_loop(0, 0, 100, 60, 16));
  d.loops.push_back(circle_hole({50, 30}, 10.0, 126));
  const RingedDomain ringed = ring_holes(d);
  EXPECT_GT(ringed.rings, kHoleRingLayers);
  EXPECT_LE(ringed.rings, kMaxHoleRingLayers);
  // Ring k's nodes: ring_nodes[(k - 1) n + i]; along the x axis from the centre, each
  // ring's thickness over the one inside it is the growth rate.
  const int n = 126;
  std::vector<double> radius{10.0};
  for (int k = 0; k < ringed.rings; ++k) {
    const Vec3& p = ringed.ring_nodes[static_cast<std::size_t>(k) * n];
    radius.push_back(std::hypot(p.x - 50, p.y - 30));
  }
  for (std::size_t k = 2; k < radius.size(); ++k) {
    EXPECT_NEAR((radius[k] - radius[k - 1]) / (radius[k - 1] - radius[k - 2]), kRingGrowth, 0.02) << k;
  }
  const QuadMesh mesh = mesh_planar_domain(d, 5.0);
  ASSERT_EQ(check_domain_mesh(mesh, loop_sizes(d)), "");
  const std::vector<int> around = quads_per_node(mesh);
  for (int i = 0; i < n; ++i) EXPECT_EQ(around[d.offset(1) + i], 2) << "rim node " << i << " lies in a fan";
  EXPECT_EQ(summarize_quality(mesh, kUp).inverted, 0);
}

TEST(HoleRings, NoRingWhereTheHoleNearlyTouchesTheOutline) {
  PlanarDomain d;
  d.loops.push_back(square_loop(0, 0, 4, 4, 8));
  d.loops.push_back(circle_hole({2, 0.75}, 0.5, 8));  // 0.25 from the bottom side
  const RingedDomain ringed = ring_holes(d);
  EXPECT_EQ(ringed.rings, 0);
  const QuadMesh mesh = mesh_planar_domain(d, 0.5);
  ASSERT_EQ(check_domain_mesh(mesh, loop_sizes(d)), "");
}

TEST(Smoothing, GeneratedDomainsStayValidAndTheirWorstNeverDrops) {
  constexpr int kDomains = 5040;
  long long merged_total = 0, raised = 0;
  double sum_before = 0, sum_after = 0, mean_before = 0, mean_after = 0;
  for (int i : testing::cases(kDomains)) {
    SCOPED_TRACE(testing::case_trace(i));
    const testing::GeneratedDomain g = testing::generated_domain(i);
    QuadMesh mesh = mesh_planar_domain(g.domain, g.size);
    const QualitySummary before = summarize_quality(mesh, kUp);
    int merged = 0;
    smooth_planar_mesh(mesh, g.domain.point_count(), merged);
    merged_total += merged;
    ASSERT_EQ(check_domain_mesh(mesh, loop_sizes(g.domain)), "") << g.description;
    int k = 0;
    for (const DomainLoop& loop : g.domain.loops) {
      for (const Vec3& p : loop.points) ASSERT_TRUE(mesh.nodes[k++] == p) << g.description << ": point moved";
    }
    const QualitySummary after = summarize_quality(mesh, kUp);
    ASSERT_GE(after.scaled_jacobian.min, before.scaled_jacobian.min - 1e-12) << g.description;
    EXPECT_LE(after.inverted, before.inverted) << g.description;
    raised += after.scaled_jacobian.min > before.scaled_jacobian.min + 1e-9 ? 1 : 0;
    sum_before += before.scaled_jacobian.min;
    sum_after += after.scaled_jacobian.min;
    mean_before += before.scaled_jacobian.avg;
    mean_after += after.scaled_jacobian.avg;
  }
  std::printf("[ quality  ] smoothing %d decomposed domains: mean of per-mesh minimums %.3f -> %.3f "
              "(raised in %lld), mean scaled Jacobian %.3f -> %.3f, %lld doublets merged\n",
              kDomains, sum_before / kDomains, sum_after / kDomains, raised, mean_before / kDomains,
              mean_after / kDomains, merged_total);
  if (testing::whole_set()) EXPECT_GT(sum_after, sum_before);
}

TEST(Smoothing, APlanarMeshSmoothsBitForBitAsTheGeneralRouteDoes) {
  // A planar mesh without doublets or folds is smoothed in its one node array
  // (smooth_planar_mesh); the general route, with mesh coordinates, positions and
  // normals apart and each move placed by a PlaceNode, must give the same nodes.
  int compared = 0, moved = 0;
  for (int i = 0; i < 300; ++i) {
    const testing::GeneratedDomain g = testing::generated_domain(i);
    const QuadMesh meshed = mesh_planar_domain(g.domain, g.size);
    const int fixed = g.domain.point_count();
    if (has_doublet(meshed.quads, fixed, meshed.nodes.size()) || summarize_quality(meshed, kUp).inverted > 0) {
      continue;  // those take the general route anyway
    }
    QuadMesh fast = meshed;
    int merged = 0;
    smooth_planar_mesh(fast, fixed, merged);
    std::vector<Vec3> param = meshed.nodes, position = meshed.nodes, normal(meshed.nodes.size(), kUp);
    const PlaceNode in_plane = [](int, const Vec3& p, Vec3& at, Vec3& n) {
      at = p;
      n = kUp;
      return true;
    };
    const SmoothingResult general = smooth_mesh(meshed.quads, fixed, param, position, normal, in_plane);
    ASSERT_EQ(fast.nodes.size(), position.size()) << g.description;
    for (std::size_t n = 0; n < position.size(); ++n) {
      ASSERT_TRUE(fast.nodes[n] == position[n]) << g.description << ": node " << n;
    }
    ++compared;
    moved += general.moves > 0 ? 1 : 0;
  }
  std::printf("[ smoothing] %d planar meshes smoothed alike both ways (%d with nodes moved)\n", compared, moved);
  EXPECT_GT(compared, 150);
  EXPECT_GT(moved, 150);
}

TEST(Smoothing, NearALocalChangeOnlyTheRegionMoves) {
  // The generated domains smoothed from the templates' nodes with only the nodes of
  // the first quads' (a region) allowed to move: every node outside stays bit for
  // bit, some inside move, and the worst corner never drops.
  int with_moves = 0;
  for (int i = 0; i < 100; ++i) {
    const testing::GeneratedDomain g = testing::generated_domain(i);
    const QuadMesh meshed = mesh_planar_domain(g.domain, g.size);
    const int fixed = g.domain.point_count();
    if (has_doublet(meshed.quads, fixed, meshed.nodes.size())) continue;
    std::vector<Vec3> param = meshed.nodes, position = meshed.nodes, normal(meshed.nodes.size(), kUp);
    const PlaceNode in_plane = [](int, const Vec3& p, Vec3& at, Vec3& n) {
      at = p;
      n = kUp;
      return true;
    };
    std::vector<bool> region(meshed.nodes.size(), false);
    for (std::size_t q = 0; q < meshed.quads.size() / 4; ++q) for (NodeId n : meshed.quads[q]) region[n] = true;
    const double before = summarize_quality(meshed, kUp).scaled_jacobian.min;
    const SmoothingResult result = smooth_mesh_near(meshed.quads, fixed, param, position, normal, in_plane, region);
    for (std::size_t n = 0; n < position.size(); ++n) {
      if (!region[n]) ASSERT_TRUE(position[n] == meshed.nodes[n]) << g.description << ": node " << n;
    }
    QuadMesh smoothed = meshed;
    smoothed.nodes = position;
    EXPECT_GE(summarize_quality(smoothed, kUp).scaled_jacobian.min, before - 1e-12) << g.description;
    with_moves += result.moves > 0 ? 1 : 0;
  }
  EXPECT_GT(with_moves, 20);
}

// The steepest ascent of a minimum: with one rate, along its gradient; with two that
// pull apart, the direction where both rise equally (the bisector here); with rates
// that no direction raises together, none.
TEST(MaxMinAscent, OneRateRisesAlongItsGradient) {
  const Ascent ascent = max_min_ascent({Vec3{3, 4, 0}});
  EXPECT_NEAR(ascent.direction.x, 0.6, 1e-12);
  EXPECT_NEAR(ascent.direction.y, 0.8, 1e-12);
  EXPECT_NEAR(ascent.rate, 5.0, 1e-12);
}

TEST(MaxMinAscent, TwoRatesRiseTogetherBetweenTheirGradients) {
  // g1 . d and g2 . d are equal along (1, 1)/sqrt(2); along either gradient the
  // other rate is 0.
  const Ascent ascent = max_min_ascent({Vec3{1, 0, 0}, Vec3{0, 1, 0}});
  EXPECT_NEAR(ascent.direction.x, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(ascent.direction.y, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(ascent.rate, std::sqrt(0.5), 1e-12);
  // A third rate that the bisector lowers moves the answer to where all three
  // rise (d.y > 5 d.x > 0), and none of them rises slower than the rate given.
  const Ascent three = max_min_ascent({Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{-1, 0.2, 0}});
  EXPECT_GT(three.rate, 0.0);
  for (const Vec3& g : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{-1, 0.2, 0}}) {
    EXPECT_GE(g.x * three.direction.x + g.y * three.direction.y, three.rate - 1e-12);
  }
}

TEST(MaxMinAscent, OpposedRatesGiveNoAscent) {
  // At a maximum of the minimum: every direction lowers one of them.
  EXPECT_LE(max_min_ascent({Vec3{1, 0, 0}, Vec3{-1, 0, 0}}).rate, 0.0);
  EXPECT_LE(max_min_ascent({Vec3{1, 0, 0}, Vec3{-0.5, 0.8, 0}, Vec3{-0.5, -0.8, 0}}).rate, 0.0);
  EXPECT_LE(max_min_ascent({}).rate, 0.0);
  EXPECT_LE(max_min_ascent({Vec3{0, 0, 0}}).rate, 0.0);
}

// The ascent's answer is the best direction: no direction of a fine sweep does
// better on random gradient sets.
TEST(MaxMinAscent, NoSweptDirectionDoesBetter) {
  unsigned state = 12345;
  const auto next = [&] {
    state = state * 1103515245u + 12345u;
    return ((state >> 8) & 0xffff) / 32768.0 - 1.0;
  };
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<Vec3> gradients;
    const int count = 1 + trial % 6;
    for (int i = 0; i < count; ++i) gradients.push_back({next(), next(), 0.0});
    const Ascent ascent = max_min_ascent(gradients);
    double best_swept = -INFINITY;
    for (int k = 0; k < 3600; ++k) {
      const double angle = k * 2 * M_PI / 3600;
      double rate = INFINITY;
      for (const Vec3& g : gradients) rate = std::min(rate, g.x * std::cos(angle) + g.y * std::sin(angle));
      best_swept = std::max(best_swept, rate);
    }
    if (best_swept > 0) {
      EXPECT_GE(ascent.rate, best_swept - 1e-9) << "trial " << trial;
    } else {
      EXPECT_LE(ascent.rate, 1e-3) << "trial " << trial;
    }
  }
}

}  // namespace
}  // namespace tquad
