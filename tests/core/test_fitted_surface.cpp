// The surface a curved 3D loop's mesh spans (fitted_surface.h): each interior node's
// quadric fit reproduces a quadric surface and a plane, keeps the node where it
// was, exists only where the loop's projection is a simple polygon; and a curved
// loop's mesh smoothed on it keeps its nodes on the surface the templates made.
#include <gtest/gtest.h>

#include <cmath>

#include "boundary_generators.h"
#include "core/geometry/fitted_surface.h"
#include "core/geometry/mean_value_surface.h"
#include "core/templates/mesher.h"
#include "core/mesh/quality.h"
#include "core/repair/smoothing.h"

namespace tquad {
namespace {

// A structured grid of (cells + 1)^2 nodes over [-1, 1]^2 on z = height(x, y): its
// boundary first (counter-clockwise), then the interior, and its quads.
template <typename Height>
QuadMesh grid_on(int cells, Height height) {
  QuadMesh mesh;
  std::vector<int> id((cells + 1) * (cells + 1), -1);
  const auto at = [&](int i, int j) { return j * (cells + 1) + i; };
  const auto add = [&](int i, int j) {
    const double x = -1 + 2.0 * i / cells, y = -1 + 2.0 * j / cells;
    id[at(i, j)] = static_cast<int>(mesh.nodes.size());
    mesh.nodes.push_back({x, y, height(x, y)});
  };
  for (int i = 0; i < cells; ++i) add(i, 0);
  for (int j = 0; j < cells; ++j) add(cells, j);
  for (int i = cells; i > 0; --i) add(i, cells);
  for (int j = cells; j > 0; --j) add(0, j);
  for (int j = 1; j < cells; ++j) for (int i = 1; i < cells; ++i) add(i, j);
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      mesh.quads.push_back({id[at(i, j)], id[at(i + 1, j)], id[at(i + 1, j + 1)], id[at(i, j + 1)]});
    }
  }
  return mesh;
}

// Symmetric under (x, y) -> (-x, -y): the grid's boundary has Newell normal +z, so the
// fits' frame is the (x, y) plane.
double saddle(double x, double y) { return 0.3 * x * x - 0.2 * x * y - 0.1 * y * y + 1; }

TEST(FittedSurface, ReproducesAQuadricAndKeepsEachNode) {
  const int cells = 8, boundary = 4 * cells;
  const QuadMesh mesh = grid_on(cells, saddle);
  const std::optional<MeanPlane> plane = MeanPlane::of_loop({mesh.nodes.begin(), mesh.nodes.begin() + boundary});
  ASSERT_TRUE(plane);
  FittedSurface surface(*plane, boundary);
  surface.fit_nodes(mesh.nodes, mesh.quads);
  for (int node = boundary; node < static_cast<int>(mesh.nodes.size()); ++node) {
    const Vec3 local = surface.plane().local(mesh.nodes[node]), start{local.x, local.y, 0};
    Vec3 position, normal;
    ASSERT_TRUE(surface.place(node, start, position, normal));
    EXPECT_NEAR(distance(position, mesh.nodes[node]), 0, 1e-12);
    // Moved half an edge, still on the quadric, with its normal.
    ASSERT_TRUE(surface.place(node, start + Vec3{0.1, -0.07, 0}, position, normal));
    EXPECT_NEAR(position.z, saddle(position.x, position.y), 1e-9);
    const Vec3 expected{-(0.6 * position.x - 0.2 * position.y), -(-0.2 * position.x - 0.2 * position.y), 1};
    EXPECT_NEAR(norm(cross(normal, expected)) / (norm(normal) * norm(expected)), 0, 1e-9);
    EXPECT_GT(dot(normal, expected), 0);  // oriented as the loop (counter-clockwise about +z)
  }
}

TEST(FittedSurface, NoPlaneWhereTheLoopsProjectionCrossesItself) {
  // A trefoil knot: its projection on any plane crosses itself.
  std::vector<Vec3> knot;
  for (int i = 0; i < 90; ++i) {
    const double t = 2 * M_PI * i / 90;
    knot.push_back({std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t)});
  }
  EXPECT_FALSE(MeanPlane::of_loop(knot));  // so no fitted surface either
}

// The membrane through a grid's boundary (grid_on) at its interior node `node`:
// position and normal there, and the normal the position's finite differences give.
struct MembraneAt {
  Vec3 position, normal, expected_normal;
};

template <typename Height>
MembraneAt membrane_of_grid(Height height, int node) {
  const int cells = 8, boundary = 4 * cells;
  const QuadMesh mesh = grid_on(cells, height);
  const std::vector<Vec3> loop(mesh.nodes.begin(), mesh.nodes.begin() + boundary);
  const std::optional<MeanPlane> plane = MeanPlane::of_loop(loop);
  EXPECT_TRUE(plane);
  const MeanValueSurface surface(*plane, loop);
  Vec3 unused, on_loop{plane->local(loop[3]).x, plane->local(loop[3]).y, 0};
  EXPECT_FALSE(surface.place(on_loop, unused, unused));  // on the loop: no normal
  const Vec3 local = plane->local(mesh.nodes[boundary + node]), p{local.x, local.y, 0};
  MembraneAt at;
  EXPECT_TRUE(surface.place(p, at.position, at.normal));
  const double h = 1e-6;
  Vec3 along_x, along_y;
  EXPECT_TRUE(surface.place(p + Vec3{h, 0, 0}, along_x, unused));
  EXPECT_TRUE(surface.place(p + Vec3{0, h, 0}, along_y, unused));
  at.expected_normal = cross((1 / h) * (along_x - at.position), (1 / h) * (along_y - at.position));
  return at;
}

TEST(MeanValueSurface, ReproducesAPlaneAndHasTheNormalOfItsHeights) {
  // Mean value interpolation reproduces linear heights (a plane) exactly.
  const auto tilted = [](double x, double y) { return 0.3 * x - 0.2 * y + 1; };
  const MembraneAt flat = membrane_of_grid(tilted, 10);
  EXPECT_NEAR(flat.position.z, tilted(flat.position.x, flat.position.y), 1e-12);
  EXPECT_NEAR(norm(cross(flat.normal, Vec3{-0.3, 0.2, 1})) / norm(flat.normal), 0, 1e-9);
  // Round a saddle, its normal (analytic derivatives) is that of its heights.
  for (int node : {0, 10, 24, 48}) {
    const MembraneAt at = membrane_of_grid(saddle, node);
    EXPECT_NEAR(norm(cross(at.normal, at.expected_normal)) / (norm(at.normal) * norm(at.expected_normal)), 0, 1e-5);
    EXPECT_GT(dot(at.normal, at.expected_normal), 0);
  }
}

// The largest distance of a mesh's interior nodes from the sphere of radius 1.
double off_sphere(const QuadMesh& mesh, int boundary) {
  double worst = 0;
  for (std::size_t i = boundary; i < mesh.nodes.size(); ++i) worst = std::max(worst, std::abs(norm(mesh.nodes[i]) - 1));
  return worst;
}

TEST(FittedSurface, CurvedLoopsMeshIsSmoothedOnTheTemplatesSurface) {
  // A sphere octant's boundary, arcs of 12, 8 and 8 edges (as the shipped
  // sphere_octant_t3.json): smoothed, the nodes stay as close to the sphere as the
  // templates put them (their surface is not the sphere), and the worst quad gets
  // better.
  std::vector<Vec3> points;
  const int counts[3] = {12, 8, 8};
  for (int arc = 0; arc < 3; ++arc) {
    for (int i = 0; i < counts[arc]; ++i) {
      const double t = M_PI / 2 * i / counts[arc], c = std::cos(t), s = std::sin(t);
      points.push_back(arc == 0 ? Vec3{c, s, 0} : arc == 1 ? Vec3{0, c, s} : Vec3{s, 0, c});
    }
  }
  const int n = static_cast<int>(points.size());
  QuadMesh mesh = mesh_boundary({points, {0, counts[0], counts[0] + counts[1]}});
  const double meshed_off = off_sphere(mesh, n);
  const QualitySummary before = summarize_quality(mesh, std::nullopt);
  ASSERT_NO_THROW(smooth_region(mesh, n, std::nullopt));
  const QualitySummary after = summarize_quality(mesh, std::nullopt);
  std::printf("[ quality  ] sphere octant, 12, 8, 8: worst %.3f -> %.3f, mean %.3f -> %.3f; off the sphere "
              "%.4f -> %.4f\n", before.scaled_jacobian.min, after.scaled_jacobian.min, before.scaled_jacobian.avg,
              after.scaled_jacobian.avg, meshed_off, off_sphere(mesh, n));
  EXPECT_GT(after.scaled_jacobian.min, before.scaled_jacobian.min);
  EXPECT_LT(off_sphere(mesh, n), meshed_off * 1.1);
  for (int i = 0; i < n; ++i) EXPECT_TRUE(mesh.nodes[i] == points[i]);
}

TEST(FittedSurface, LopsidedCurvedLoopIsUntangledOnIt) {
  // Generated case 3622, a lopsided three-curve loop (counts 25, 1, 12) wrapped on a
  // cylinder, keeps an inverted quad as meshed; smoothed, none.
  const testing::GeneratedCase c = testing::generated_case(3622);
  ASSERT_FALSE(c.planar);
  QuadMesh mesh = mesh_boundary(c.loop);
  const QualitySummary before = summarize_quality(mesh, std::nullopt);
  ASSERT_GT(before.inverted, 0);
  const int n = static_cast<int>(c.loop.points.size());
  ASSERT_NO_THROW(smooth_region(mesh, n, std::nullopt));
  const QualitySummary after = summarize_quality(mesh, std::nullopt);
  std::printf("[ quality  ] %s: worst %.4f, %lld inverted -> worst %.4f, %lld inverted\n", c.description.c_str(),
              before.scaled_jacobian.min, before.inverted, after.scaled_jacobian.min, after.inverted);
  EXPECT_EQ(after.inverted, 0);
  for (int i = 0; i < n; ++i) EXPECT_TRUE(mesh.nodes[i] == c.loop.points[i]);
}

}  // namespace
}  // namespace tquad
