// Topological equivalence (paper, section 1): two regions with the same curve counts
// get identical connectivity, whatever their geometry; only node positions differ.
// For two-curve regions this holds once T5's cut count is fixed (MeshOptions).
#include <gtest/gtest.h>

#include <random>

#include "boundary_generators.h"
#include "core/templates/mesher.h"

namespace tquad {
namespace {

using testing::arc;
using testing::line;
using testing::sample_loop;
using testing::spacing_params;
using testing::Spacing;

BoundaryLoop shape_with_counts(const std::vector<int>& counts, int variant) {
  std::mt19937 rng(variant);
  std::vector<testing::Curve> curves;
  if (counts.size() == 4) {
    const Vec3 p[2][4] = {{{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {0, 1, 0}},
                          {{0, 0, 1}, {1, -0.5, 2}, {1.6, 1.5, 0}, {-0.3, 1.2, 0.4}}};
    for (int i = 0; i < 4; ++i) curves.push_back(line(p[variant][i], p[variant][(i + 1) % 4]));
  } else if (counts.size() == 3) {
    const Vec3 p[2][3] = {{{0, 0, 0}, {1, 0, 0}, {0.5, 0.9, 0}}, {{0, 0, 0}, {4, 1, 0}, {-1, 2, 0}}};
    for (int i = 0; i < 3; ++i) curves.push_back(line(p[variant][i], p[variant][(i + 1) % 3]));
  } else {
    const double bulge = variant == 0 ? 0.5 : 0.2;
    curves = {arc({-1, 0, 0}, {1, 0, 0}, -bulge), arc({1, 0, 0}, {-1, 0, 0}, -0.7)};
  }
  std::vector<std::vector<double>> params;
  for (int n : counts) {
    params.push_back(spacing_params(n, variant == 0 ? Spacing::Uniform : Spacing::Random, 1.0, rng));
  }
  return sample_loop(curves, counts, params);
}

TEST(TopologicalEquivalence, SameCountsGiveIdenticalConnectivity) {
  const std::vector<std::vector<int>> cases = {
      {4, 8, 4, 6}, {7, 3, 12, 2}, {1, 9, 1, 1}, {20, 20, 20, 20},
      {10, 8, 4},   {10, 4, 4},    {3, 9, 6},    {1, 5, 6},  {17, 17, 2},
      {12, 12},     {9, 15},       {40, 6},      {1, 5}};
  MeshOptions options;
  options.t5_cut_edges = 4;
  for (const auto& counts : cases) {
    const QuadMesh a = mesh_boundary(shape_with_counts(counts, 0), options);
    const QuadMesh b = mesh_boundary(shape_with_counts(counts, 1), options);
    std::string name;
    for (int c : counts) name += std::to_string(c) + " ";
    EXPECT_EQ(a.template_tree, b.template_tree) << name;
    EXPECT_EQ(a.quads, b.quads) << name;
    EXPECT_EQ(a.nodes.size(), b.nodes.size()) << name;
    EXPECT_NE(a.nodes[a.nodes.size() - 1].x, b.nodes[b.nodes.size() - 1].x) << name
        << " (the two geometries should differ)";
  }
}

}  // namespace
}  // namespace tquad
