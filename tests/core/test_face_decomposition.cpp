// Face decomposition (face_decomposition.h, decomposed_mesher.h): examples, and
// property checks over generated planar domains (domain_generators.h): orthogonal
// outlines, star-shaped polygons, 0 to 20 holes, uniform and graded spacing. Every
// mesh must be all-quad and conforming, keep the boundary points bit-exact, have no
// inverted quad and satisfy nodes = 1 + quads + boundary_edges / 2 - holes; meshes
// with a collapsed quad (a triangle in effect) are counted and bounded. The worst
// quality seen is printed.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <algorithm>

#include "case_stride.h"
#include "core/decomposition/cut_intervals.h"
#include "core/decomposition/decomposed_mesher.h"
#include "core/templates/disk_o_grid.h"
#include "core/templates/mapped_ring.h"
#include "core/input_error.h"
#include "core/mesh/mesh_validation.h"
#include "core/templates/o_grid.h"
#include "core/mesh/quality.h"
#include "domain_generators.h"

namespace tquad {
namespace {

using testing::circle_hole;
using testing::loop_sizes;
using testing::polygon_loop;

const Vec3 kUp{0, 0, 1};

void expect_valid(const PlanarDomain& d, const QuadMesh& mesh, const std::string& what) {
  ASSERT_EQ(check_domain_mesh(mesh, loop_sizes(d)), "") << what << " " << mesh.template_tree;
  int k = 0;
  for (const DomainLoop& loop : d.loops) {
    for (const Vec3& p : loop.points) ASSERT_TRUE(mesh.nodes[k++] == p) << what << ": boundary point moved";
  }
  const QualitySummary q = summarize_quality(mesh, kUp);
  EXPECT_EQ(q.inverted, 0) << what << " " << mesh.template_tree;
}

TEST(FaceDecomposition, SquareWithFourCircularHoles) {
  PlanarDomain d;
  d.loops.push_back(polygon_loop({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, 12));
  for (Vec3 c : {Vec3{1, 1}, Vec3{3, 1}, Vec3{3, 3}, Vec3{1, 3}}) d.loops.push_back(circle_hole(c, 0.4, 8));
  const QuadMesh mesh = mesh_planar_domain(d, 1.0 / 3);
  expect_valid(d, mesh, "square with four holes");
  EXPECT_EQ(mesh.template_tree.substr(0, 1), "D");
}

// Patches of the decomposition with a side that starts or ends at node 0 (the first
// point of the outer loop).
int patches_at_first_point(const FaceDecomposition& d) {
  int count = 0;
  for (const DomainPatch& patch : d.patches) {
    bool touches = false;
    for (const PatchSide& side : patch.sides) {
      if (side.is_cut) {
        touches = touches || d.cuts[side.index].from == 0 || d.cuts[side.index].to == 0;
      } else {
        const BoundaryPiece& piece = d.pieces[side.index];
        touches = touches || (piece.loop == 0 && (piece.first == 0 || piece.last == 0));
      }
    }
    count += touches ? 1 : 0;
  }
  return count;
}

TEST(FaceDecomposition, ClearedCornerEarsLeaveAPlateCornerToOnePatch) {
  // A plate with a hole near its corner (0, 0): the hole lies inside the circle
  // through the corner and its coarse neighbours, so the smallest-angle flips fan cuts
  // into the corner; with the ears cleared, one patch takes the corner whole.
  PlanarDomain d;
  d.loops.push_back(polygon_loop({{0, 0}, {10, 0}, {10, 8}, {0, 8}}, 20));
  d.loops.push_back(circle_hole({2.2, 2.2}, 0.8, 12));
  d.loops.push_back(circle_hole({7, 5}, 1.0, 12));
  const FaceDecomposition plain = decompose_domain(d);
  DecompositionOptions options;
  options.clear_corner_ears = true;
  const FaceDecomposition cleared = decompose_domain(d, options);
  EXPECT_EQ(plain.corner_splits, 0);
  EXPECT_GT(cleared.corner_splits, 0);
  std::printf("[ corner   ] patches at the plate corner: %d plain, %d with its ear cleared\n",
              patches_at_first_point(plain), patches_at_first_point(cleared));
  EXPECT_EQ(patches_at_first_point(cleared), 1);
  const QuadMesh mesh = mesh_decomposed_domain(d, cleared, assign_cut_intervals(d, cleared, 0.5), MeshOptions{});
  expect_valid(d, mesh, "plate with its corner ear cleared");
}

TEST(FaceDecomposition, LShapeIsCutAtItsReflexCorner) {
  PlanarDomain d;
  d.loops.push_back(polygon_loop({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 4));
  const FaceDecomposition decomposition = decompose_domain(d);
  EXPECT_GE(decomposition.cuts.size(), 1u);
  for (const DomainPatch& p : decomposition.patches) EXPECT_TRUE(p.sides.size() == 3 || p.sides.size() == 4);
  expect_valid(d, mesh_planar_domain(d, 0.25), "L shape");
}

// A loop through `corners` with `segments[i]` equal segments from corner i to the next.
DomainLoop segmented_loop(const std::vector<Vec3>& corners, const std::vector<int>& segments) {
  DomainLoop loop;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3 a = corners[i], b = corners[(i + 1) % corners.size()];
    for (int k = 0; k < segments[i]; ++k) {
      loop.points.push_back(a + (static_cast<double>(k) / segments[i]) * (b - a));
      loop.vertex.push_back(k == 0);
    }
  }
  return loop;
}

bool has_cut(const FaceDecomposition& d, int a, int b) {
  for (const CutCurve& c : d.cuts) if ((c.from == a && c.to == b) || (c.from == b && c.to == a)) return true;
  return false;
}

TEST(FaceDecomposition, ThinFlangeOnAPlateIsCutStraightAcrossItsJunctions) {
  // part.step face 22 in its chart: a flange 0.18 wide and 50.8 long (6 segments on its
  // free side) meeting a plate 15.9 wide at two reflex corners, 0.56 from the flange's
  // points 2 and 4. Cut there, the flange's ends and the plate are mapped grids; before,
  // a fan of slivers into point 3 left quads of 0.02.
  PlanarDomain d;
  d.loops.push_back(segmented_loop({{0, 0}, {0, 50.8}, {-0.182, 50.8}, {-0.182, 33.337}, {-121.776, 33.337},
                                    {-121.776, 17.462}, {-0.182, 17.462}, {-0.182, 0}},
                                   {6, 1, 2, 14, 2, 14, 2, 1}));
  const int top_reflex = 6 + 1 + 2, bottom_reflex = 6 + 1 + 2 + 14 + 2 + 14;
  const FaceDecomposition merged = decompose_domain(d);
  EXPECT_TRUE(has_cut(merged, bottom_reflex, 2));
  EXPECT_TRUE(has_cut(merged, top_reflex, 4));
  EXPECT_GT(merged.sliver_pairs, 0);
  const QuadMesh mesh = mesh_decomposed_domain(d, merged, assign_cut_intervals(d, merged, 8.5), MeshOptions{});
  expect_valid(d, mesh, "thin flange");
  DecompositionOptions options;
  options.merge_sliver_pairs = false;
  const FaceDecomposition unmerged = decompose_domain(d, options);
  const QuadMesh fan = mesh_decomposed_domain(d, unmerged, assign_cut_intervals(d, unmerged, 8.5), MeshOptions{});
  const double worst = summarize_quality(mesh, kUp).scaled_jacobian.min;
  const double fan_worst = summarize_quality(fan, kUp).scaled_jacobian.min;
  std::printf("[ flange   ] worst quad %.3f in %zu patches (%s); sliver triangles kept: %.3f in %zu patches\n", worst,
              merged.patches.size(), mesh.template_tree.c_str(), fan_worst, unmerged.patches.size());
  EXPECT_GT(worst, 0.3);
  EXPECT_GT(worst, fan_worst + 0.1);
}

// The mean scaled Jacobian of the quads all of whose nodes lie below y.
double mean_below(const QuadMesh& mesh, double y) {
  double sum = 0;
  int count = 0;
  const std::vector<double> sj = per_quad_quality(mesh.nodes, mesh.quads, kUp).scaled_jacobian;
  for (std::size_t q = 0; q < mesh.quads.size(); ++q) {
    bool below = true;
    for (NodeId n : mesh.quads[q]) below = below && mesh.nodes[n].y < y;
    if (below) sum += sj[q], ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

TEST(FaceDecomposition, ThinBandsAreCutStraightAcross) {
  // part.step face 17 in its chart, one side of it: a block with two flanges 4.8
  // wide, whose long sides have segments of 8.9 (the rim) and 8.0 (the window's edge).
  // The feature-size rule places coarse vertices on each side apart from the other's;
  // crossed, every cut in a flange goes to the nearest point across, leaning by at
  // most half a segment.
  PlanarDomain d;
  d.loops.push_back(segmented_loop({{0, -14.3}, {80, -14.3}, {80, 14.3}, {0, 14.3}, {0, 9.5}, {40, 9.5}, {40, -9.5},
                                    {0, -9.5}},
                                   {9, 4, 9, 1, 5, 2, 5, 1}));
  // The reflex corners' extensions (their own test) cut this block elsewhere: left
  // out here, so that the crossing alone is measured.
  DecompositionOptions options;
  options.extend_reflex_corners = false;
  const FaceDecomposition crossed = decompose_domain(d, options);
  options.cross_thin_bands = false;
  const FaceDecomposition plain = decompose_domain(d, options);
  EXPECT_GT(crossed.band_crossings, 0);
  EXPECT_EQ(plain.band_crossings, 0);
  // Cuts with both ends in a flange (y within 4.8 of a long side, left of the block),
  // and the most one of them leans.
  const auto flange_cuts = [&](const FaceDecomposition& decomposition, double& most_leaning) {
    int count = 0;
    most_leaning = 0;
    for (const CutCurve& cut : decomposition.cuts) {
      const Vec3 &a = d.loops[0].points[cut.from], &b = d.loops[0].points[cut.to];
      if (std::max(a.x, b.x) >= 40 || std::abs(a.y) < 9.4 || std::abs(b.y) < 9.4) continue;
      ++count;
      most_leaning = std::max(most_leaning, std::abs(a.x - b.x));
    }
    return count;
  };
  double most = 0, plain_most = 0;
  EXPECT_GT(flange_cuts(crossed, most), 2);
  flange_cuts(plain, plain_most);
  std::printf("[ bands    ] flange cuts lean by %.2f at most crossed, %.2f not\n", most, plain_most);
  EXPECT_LE(most, 0.5 * 80 / 9);
  const QuadMesh mesh = mesh_decomposed_domain(d, crossed, assign_cut_intervals(d, crossed, 8.5), MeshOptions{});
  const QuadMesh leaning = mesh_decomposed_domain(d, plain, assign_cut_intervals(d, plain, 8.5), MeshOptions{});
  expect_valid(d, mesh, "thin bands crossed");
  const double flange = mean_below(mesh, -9.4), leaning_flange = mean_below(leaning, -9.4);
  std::printf("[ bands    ] lower flange's mean quad %.3f crossed, %.3f not (%d points crossed)\n", flange,
              leaning_flange, crossed.band_crossings);
  EXPECT_GT(flange, leaning_flange + 0.05);
}

// Points of the quarter circle from `from` around `centre`, turning left by 90
// degrees, `segments` of them (the first included, the last not).
std::vector<Vec3> quarter_arc(const Vec3& centre, const Vec3& from, int segments) {
  std::vector<Vec3> points;
  const Vec3 radius = from - centre;
  for (int k = 0; k < segments; ++k) {
    const double a = 0.5 * M_PI * k / segments;
    points.push_back(centre + Vec3{radius.x * std::cos(a) - radius.y * std::sin(a),
                                   radius.x * std::sin(a) + radius.y * std::cos(a), 0});
  }
  return points;
}

TEST(FaceDecomposition, AReflexCornersSidesAreContinuedAcrossTheFace) {
  // part.step face 9: an L-shaped plate whose two outer corners away from the notch
  // are rounded (radius 6.35), segments of about 8.5. Its only sharp coarse
  // vertices are the four square corners and the reflex one; the feature size adds
  // none on the long top side. Without the extensions the one cut ran from the
  // reflex corner to the middle of a rounded corner, two T2 patches with corners of
  // 120 and 150 degrees. Continued, the notch's two sides split the L into three
  // mapped rectangles, and the foot's long thin rectangle (its diagonal at 14.5
  // degrees) stays one patch.
  PlanarDomain d;
  DomainLoop loop = segmented_loop({{22.225, 7.9375}, {22.225, 25.4}, {41.275, 25.4}}, {2, 2, 0});
  const auto append = [&](const std::vector<Vec3>& points, bool vertex_first) {
    for (std::size_t k = 0; k < points.size(); ++k) {
      loop.points.push_back(points[k]);
      loop.vertex.push_back(k == 0 && vertex_first);
    }
  };
  const auto line = [](const Vec3& a, const Vec3& b, int segments) {
    std::vector<Vec3> points;
    for (int k = 0; k < segments; ++k) points.push_back(a + (static_cast<double>(k) / segments) * (b - a));
    return points;
  };
  append(line({41.275, 25.4}, {41.275, 57.15}, 4), true);
  append(quarter_arc({34.925, 57.15}, {41.275, 57.15}, 2), true);
  append(line({34.925, 63.5}, {-34.925, 63.5}, 9), true);
  append(quarter_arc({-34.925, 57.15}, {-34.925, 63.5}, 2), true);
  append(line({-41.275, 57.15}, {-41.275, 7.9375}, 6), true);
  append(line({-41.275, 7.9375}, {22.225, 7.9375}, 7), true);
  d.loops.push_back(loop);
  DecompositionOptions before;
  before.extend_reflex_corners = false;
  before.keep_square_pairs = false;
  const FaceDecomposition extended = decompose_domain(d), plain = decompose_domain(d, before);
  EXPECT_EQ(extended.reflex_extensions, 2);
  EXPECT_EQ(plain.reflex_extensions, 0);
  EXPECT_EQ(extended.patches.size(), 3u);
  const QuadMesh mesh = mesh_decomposed_domain(d, extended, assign_cut_intervals(d, extended, 8.5), MeshOptions{});
  const QuadMesh old = mesh_decomposed_domain(d, plain, assign_cut_intervals(d, plain, 8.5), MeshOptions{});
  expect_valid(d, mesh, "L continued");
  const QualitySummary q = summarize_quality(mesh, kUp), q_old = summarize_quality(old, kUp);
  std::printf("[ reflex   ] L-shaped plate: %zu patches, quads min %.3f mean %.3f; without the extensions %zu "
              "patches, %.3f / %.3f\n",
              extended.patches.size(), q.scaled_jacobian.min, q.scaled_jacobian.avg, plain.patches.size(),
              q_old.scaled_jacobian.min, q_old.scaled_jacobian.avg);
  EXPECT_GT(q.scaled_jacobian.avg, 0.9);
  EXPECT_GT(q.scaled_jacobian.min, q_old.scaled_jacobian.min);
  EXPECT_GT(q.scaled_jacobian.avg, q_old.scaled_jacobian.avg + 0.1);
}

TEST(FaceDecomposition, VariantsLeaveOutEachOptionThatActedAndAllOfThemTogether) {
  // A decomposition where two options acted: one variant without each, and one
  // without both, so that the decomposition before either stays a candidate.
  FaceDecomposition made;
  made.reflex_extensions = 2;
  made.square_pair_slivers = 1;
  const std::vector<DecompositionOptions> variants = decomposition_variants({}, &made);
  ASSERT_EQ(variants.size(), 3u);
  EXPECT_FALSE(variants[0].extend_reflex_corners);
  EXPECT_TRUE(variants[0].keep_square_pairs);
  EXPECT_TRUE(variants[1].extend_reflex_corners);
  EXPECT_FALSE(variants[1].keep_square_pairs);
  EXPECT_FALSE(variants[2].extend_reflex_corners);
  EXPECT_FALSE(variants[2].keep_square_pairs);
  EXPECT_TRUE(variants[2].merge_sliver_pairs);  // it did not act: kept
  // One option alone: no third variant.
  made.square_pair_slivers = 0;
  EXPECT_EQ(decomposition_variants({}, &made).size(), 1u);
  // Nothing made yet: every option left out once, and all together.
  EXPECT_EQ(decomposition_variants({}, nullptr).size(), 6u);
}

TEST(FaceDecomposition, ACuspTrianglesLongSidesAreSplitForTheNeighbourAcrossTheCusp) {
  // A triangle with a 10-degree corner: its three pieces are all neighbours of each
  // other, so only the long sides' points across the cusp can be in front of them.
  PlanarDomain d;
  d.loops.push_back(segmented_loop({{0, 0}, {10, 0}, {10, 10 * std::tan(10 * M_PI / 180)}}, {20, 4, 20}));
  DecompositionOptions without;
  without.neighbours_across_corners = false;
  const FaceDecomposition split = decompose_domain(d), alone = decompose_domain(d, without);
  EXPECT_GT(split.neighbour_splits, 0);
  EXPECT_EQ(alone.neighbour_splits, 0);
  EXPECT_EQ(alone.patches.size(), 1u);
  EXPECT_GT(split.patches.size(), 1u);
  const QuadMesh mesh = mesh_planar_domain(d, 0.5);
  expect_valid(d, mesh, "cusp triangle");
  std::printf("[ cusp     ] %zu patches with the cusp's neighbours in front, %zu without; worst quad %.3f\n",
              split.patches.size(), alone.patches.size(), summarize_quality(mesh, kUp).scaled_jacobian.min);
}

TEST(FaceDecomposition, OGridOfARingIsTwoMappedHalves) {
  // A 24-edge square around a 16-edge circle: every rim place gives two four-sided
  // halves, outer piece opposite rim piece.
  PlanarDomain d;
  d.loops.push_back(polygon_loop({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}, 6));
  d.loops.push_back(circle_hole({0, 0}, 1.0, 16));
  for (int rim = 0; rim < 16; rim += 3) {
    const std::optional<FaceDecomposition> halves = o_grid_decomposition(d, rim);
    ASSERT_TRUE(halves.has_value()) << "rim point " << rim;
    ASSERT_EQ(halves->patches.size(), 2u);
    ASSERT_EQ(halves->cuts.size(), 2u);
    for (const DomainPatch& p : halves->patches) EXPECT_EQ(p.sides.size(), 4u);
    const QuadMesh mesh = mesh_decomposed_domain(d, *halves, assign_cut_intervals(d, *halves, 2.0 / 3), {});
    expect_valid(d, mesh, "ring, rim point " + std::to_string(rim));
    EXPECT_EQ(mesh.template_tree.substr(0, 2), "D2") << mesh.template_tree;
  }
  // No hole, or two: not an O-grid.
  PlanarDomain plain;
  plain.loops.push_back(d.loops[0]);
  EXPECT_FALSE(o_grid_decomposition(plain, 0).has_value());
}

TEST(DiskOGrid, ACircleIsASquareAndFourMappedPatchesAtEverySize) {
  // Corners on a smooth circle (two curves, T5) give a worst corner near
  // sin(360 / n degrees), halving with each refinement; the O-grid's stays put.
  for (int n : {8, 16, 32, 64, 128}) {
    PlanarDomain d;
    DomainLoop circle = circle_hole({0, 0}, 1.0, n);
    std::reverse(circle.points.begin(), circle.points.end());  // counter-clockwise
    d.loops.push_back(circle);
    const std::optional<QuadMesh> mesh = mesh_disk_o_grid(d);
    ASSERT_TRUE(mesh.has_value()) << n;
    expect_valid(d, *mesh, "circle of " + std::to_string(n));
    EXPECT_EQ(mesh->template_tree, "O5[T0,T0,T0,T0,T0]") << n;
    const double worst = summarize_quality(*mesh, kUp).scaled_jacobian.min;
    std::printf("[ quality  ] disk O-grid, circle of %d points: worst scaled Jacobian %.3f\n", n, worst);
    // The square's sides bowed towards the circle: its corners near 120 degrees on
    // both sides (0.87) rather than 90 and 135 (0.707).
    EXPECT_GT(worst, n >= 16 ? 0.83 : 0.75) << n;
  }
  // An ellipse (convex: bowed sides) and a wavy outline (not convex: straight sides)
  // give valid meshes too.
  for (double wave : {0.0, 0.15}) {
    PlanarDomain d;
    DomainLoop blob;
    const int n = 48;
    for (int i = 0; i < n; ++i) {
      const double t = 2 * M_PI * i / n, r = 1.0 + wave * std::cos(5 * t);
      blob.points.push_back({2.5 * r * std::cos(t), r * std::sin(t), 0.0});
    }
    blob.vertex.assign(n, 0);
    d.loops.push_back(blob);
    const std::optional<QuadMesh> mesh = mesh_disk_o_grid(d);
    ASSERT_TRUE(mesh.has_value()) << wave;
    expect_valid(d, *mesh, "blob, wave " + std::to_string(wave));
    EXPECT_GT(summarize_quality(*mesh, kUp).scaled_jacobian.min, 0.3) << wave;
  }
  // Not a disk: a hole, or a sharp corner.
  PlanarDomain ring;
  ring.loops.push_back(polygon_loop({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}, 4));
  EXPECT_FALSE(mesh_disk_o_grid(ring).has_value());
  ring.loops.push_back(circle_hole({0, 0}, 1.0, 8));
  EXPECT_FALSE(mesh_disk_o_grid(ring).has_value());
}

TEST(MappedRing, EqualLoopCountsGiveOneStructuredGridAroundTheHole) {
  // A 24-edge square around a 24-edge circle: no cut, every loop node in two quads.
  PlanarDomain d;
  d.loops.push_back(polygon_loop({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}, 6));
  d.loops.push_back(circle_hole({0.2, -0.1}, 1.0, 24));
  const std::optional<QuadMesh> mesh = mesh_mapped_ring(d);
  ASSERT_TRUE(mesh.has_value());
  expect_valid(d, *mesh, "ring of 24 and 24");
  EXPECT_EQ(mesh->template_tree.substr(0, 1), "R");
  std::vector<int> around(mesh->nodes.size(), 0);
  for (const Quad& q : mesh->quads) for (NodeId n : q) ++around[n];
  for (int i = 0; i < d.point_count(); ++i) EXPECT_EQ(around[i], 2) << "loop node " << i;
  // Unequal counts: not such a ring.
  d.loops[1] = circle_hole({0, 0}, 1.0, 16);
  EXPECT_FALSE(mesh_mapped_ring(d).has_value());
}

TEST(FaceDecomposition, EveryPatchTotalIsEvenAfterIntervalAssignment) {
  PlanarDomain d;
  d.loops.push_back(polygon_loop({{0, 0}, {5, 0}, {5, 3}, {0, 3}}, 7));  // 28 edges
  d.loops.push_back(circle_hole({2.5, 1.5}, 0.7, 10));
  const FaceDecomposition decomposition = decompose_domain(d);
  const std::vector<int> counts = assign_cut_intervals(d, decomposition, 0.37);
  for (const DomainPatch& p : decomposition.patches) {
    int total = 0;
    for (const PatchSide& s : p.sides) total += s.is_cut ? counts[s.index] : piece_segments(d, decomposition.pieces[s.index]);
    EXPECT_EQ(total % 2, 0);
  }
}

TEST(FaceDecomposition, CutsTakeAtLeastTheirTurnMinimumsAndStayEven) {
  // The same plate with a hole, each cut given a minimum from the surface's turning
  // along it (cut_intervals.h): 6 on every other cut, 1 on the rest. Every cut gets
  // at least its minimum, and every patch stays even.
  PlanarDomain d;
  d.loops.push_back(polygon_loop({{0, 0}, {5, 0}, {5, 3}, {0, 3}}, 7));
  d.loops.push_back(circle_hole({2.5, 1.5}, 0.7, 10));
  const FaceDecomposition decomposition = decompose_domain(d);
  ASSERT_GE(decomposition.cuts.size(), 2u);
  std::vector<int> minimums;
  for (std::size_t c = 0; c < decomposition.cuts.size(); ++c) minimums.push_back(c % 2 == 0 ? 6 : 1);
  const std::vector<int> plain = assign_cut_intervals(d, decomposition, 0.37);
  const std::vector<int> counts = assign_cut_intervals(d, decomposition, 0.37, minimums);
  int raised = 0;
  for (std::size_t c = 0; c < counts.size(); ++c) {
    EXPECT_GE(counts[c], minimums[c]) << "cut " << c;
    raised += counts[c] > plain[c];
  }
  EXPECT_GT(raised, 0);  // the minimums acted: the plain counts are under 6 somewhere
  for (const DomainPatch& p : decomposition.patches) {
    int total = 0;
    for (const PatchSide& s : p.sides) total += s.is_cut ? counts[s.index] : piece_segments(d, decomposition.pieces[s.index]);
    EXPECT_EQ(total % 2, 0);
  }
  expect_valid(d, mesh_decomposed_domain(d, decomposition, counts, MeshOptions{}), "plate with turn minimums");
}

TEST(FaceDecomposition, SameDomainSameDecomposition) {
  const testing::GeneratedDomain g = testing::generated_domain(40);
  const QuadMesh a = mesh_planar_domain(g.domain, g.size), b = mesh_planar_domain(g.domain, g.size);
  EXPECT_EQ(a.quads, b.quads);
  EXPECT_EQ(a.template_tree, b.template_tree);
}

TEST(FaceDecomposition, WrongOrientationAndOddTotalsAreRefused) {
  PlanarDomain d;
  d.loops.push_back(polygon_loop({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, 2));  // clockwise
  EXPECT_THROW(decompose_domain(d), InputError);
  PlanarDomain odd;
  odd.loops.push_back(polygon_loop({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 2));
  odd.loops[0].points.pop_back();
  odd.loops[0].vertex.pop_back();
  EXPECT_THROW(mesh_planar_domain(odd, 0.5), InputError);
}

TEST(FaceDecomposition, BrokenDomainsAreRefusedWithTheirFault) {
  const auto refused = [](const PlanarDomain& d, const std::string& words) {
    try {
      mesh_planar_domain(d, 0.25);
      ADD_FAILURE() << "accepted a domain that should fail with: " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  const DomainLoop square = polygon_loop({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, 4);
  PlanarDomain hole_outside{{square, circle_hole({3, 1}, 0.5, 8)}};
  refused(hole_outside, "hole 1 lies outside the outer loop");
  PlanarDomain crossing_hole{{square, circle_hole({2, 1}, 0.5, 8)}};
  refused(crossing_hole, "meets hole 1 segment");
  PlanarDomain overlapping_holes{{square, circle_hole({0.8, 1}, 0.4, 8), circle_hole({1.2, 1}, 0.4, 8)}};
  refused(overlapping_holes, "meets hole");
  PlanarDomain bow_tie{{polygon_loop({{0, 0}, {2, 2}, {2, 0}, {0, 2}}, 2)}};
  refused(bow_tie, "must run counter-clockwise");
  PlanarDomain with_nan{{square}};
  with_nan.loops[0].points[3].y = std::nan("");
  refused(with_nan, "point 3 is not a finite number");
  PlanarDomain repeated{{square}};
  repeated.loops[0].points[5] = repeated.loops[0].points[4];
  refused(repeated, "points 4 and 5 coincide");
}

TEST(FaceDecomposition, RandomLoopsAreMeshedOrRefusedNeverBroken) {
  // Random points in a square as the outer loop (often crossing itself), sometimes a
  // random hole: each is either refused with InputError or meshed validly.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(0, 1);
  int meshed = 0, refused = 0;
  for (int i = 0; i < 2000; ++i) {
    PlanarDomain d;
    const int n = 4 + 2 * static_cast<int>(rng() % 8);
    DomainLoop outer;
    for (int k = 0; k < n; ++k) {
      outer.points.push_back({coordinate(rng), coordinate(rng), 0});
      outer.vertex.push_back(1);
    }
    if (twice_signed_area(outer.points) < 0) std::reverse(outer.points.begin(), outer.points.end());
    d.loops.push_back(outer);
    if (i % 3 == 0) d.loops.push_back(circle_hole({coordinate(rng), coordinate(rng)}, 0.05, 6));
    QuadMesh mesh;
    try {
      mesh = mesh_planar_domain(d, 0.2);
    } catch (const InputError&) {
      ++refused;
      continue;
    }
    ++meshed;
    ASSERT_EQ(check_domain_mesh(mesh, loop_sizes(d)), "") << "random domain " << i;
  }
  std::printf("[ quality  ] random loops: %d meshed, %d refused as broken\n", meshed, refused);
  EXPECT_GT(meshed, 0);
  EXPECT_GT(refused, 0);
}

TEST(FaceDecomposition, GeneratedDomainsGiveValidMeshes) {
  constexpr int kDomains = 5040;  // 7 outlines x 21 hole counts x 2 spacings x 12
  double worst = 2, sum_min = 0;
  long long quads = 0, inverted_meshes = 0, collapsed_meshes = 0, collapsed = 0;
  std::string worst_where;
  const auto start = std::chrono::steady_clock::now();
  for (int i : testing::cases(kDomains)) {
    SCOPED_TRACE(testing::case_trace(i));
    const testing::GeneratedDomain g = testing::generated_domain(i);
    QuadMesh mesh;
    ASSERT_NO_THROW(mesh = mesh_planar_domain(g.domain, g.size)) << g.description;
    ASSERT_EQ(check_domain_mesh(mesh, loop_sizes(g.domain)), "") << g.description << " " << mesh.template_tree;
    int k = 0;
    for (const DomainLoop& loop : g.domain.loops) {
      for (const Vec3& p : loop.points) ASSERT_TRUE(mesh.nodes[k++] == p) << g.description << ": point moved";
    }
    const QualitySummary q = summarize_quality(mesh, kUp);
    if (q.collapsed > 0) {
      ++collapsed_meshes;
      collapsed += q.collapsed;
    }
    if (q.inverted > 0) {
      ++inverted_meshes;
      std::printf("[ quality  ] inverted quads left in %s\n", g.description.c_str());
    }
    if (q.scaled_jacobian.min < worst) { worst = q.scaled_jacobian.min; worst_where = g.description; }
    sum_min += q.scaled_jacobian.min;
    quads += static_cast<long long>(mesh.quads.size());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ quality  ] decomposed planar domains: %d meshes, %lld with inverted quads, %lld with "
              "collapsed quads (%lld quads); worst scaled Jacobian %.4f (%s), mean of per-mesh minimums "
              "%.3f; %lld quads in %.1f s\n",
              kDomains, inverted_meshes, collapsed_meshes, collapsed, worst, worst_where.c_str(),
              sum_min / kDomains, quads, seconds);
  EXPECT_EQ(inverted_meshes, 0);
  // Measured: 29 of 5,040 meshes have a quad with an edge under 1/1000 of its longest
  // (52 quads: two interior nodes of one T2 patch pulled almost together by the
  // per-patch repair; none without it). The goal is none; this guards against
  // regressions until then.
  EXPECT_LE(collapsed_meshes, 29);
}

}  // namespace
}  // namespace tquad
