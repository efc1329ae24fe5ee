// The corner search of a decomposition's patches (MeshOptions::search_patch_corners,
// mesh_patch_best_corners in corner_search.h): a poor patch gets other corners, a
// good one keeps its mesh, no patch ends worse than its given corners' mesh, and
// domains meshed with it stay valid.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "boundary_generators.h"
#include "core/decomposition/corner_search.h"
#include "core/decomposition/decomposed_mesher.h"
#include "core/input_error.h"
#include "core/mesh/mesh_validation.h"
#include "core/decomposition/patch_memo.h"
#include "core/mesh/quality.h"
#include "domain_generators.h"

namespace tquad {
namespace {

const Vec3 kUp{0, 0, 1};

bool same_mesh(const QuadMesh& a, const QuadMesh& b) {
  return a.quads == b.quads && a.nodes.size() == b.nodes.size() &&
         std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(Vec3)) == 0 &&
         a.template_tree == b.template_tree;
}

// The patch's points first, bit for bit, and nodes = 1 + quads + edges / 2.
void expect_patch_mesh(const BoundaryLoop& loop, const QuadMesh& mesh) {
  ASSERT_GE(mesh.nodes.size(), loop.points.size());
  EXPECT_EQ(std::memcmp(mesh.nodes.data(), loop.points.data(), loop.points.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(mesh.nodes.size(), 1 + mesh.quads.size() + loop.points.size() / 2);
}

// The unit square with 6, 2, 6 and 2 segments given two corners, at opposite
// corners: two curves, each turning 90 degrees in its middle.
BoundaryLoop square_given_two_corners() {
  BoundaryLoop loop = testing::square_boundary(6, 6, 2, 2);
  loop.corners = {0, 8};
  return loop;
}

TEST(PatchCornerSearch, CornersInsideCurvesGiveWayToBetterOnes) {
  const BoundaryLoop loop = square_given_two_corners();
  const QuadMesh given = mesh_boundary(loop, {});
  const QualitySummary before = summarize_quality(given, kUp);
  ASSERT_LT(before.scaled_jacobian.min, kPatchSearchBelow) << "the case must be a poor patch";
  const QuadMesh searched = mesh_patch_best_corners(loop, {}, given);
  expect_patch_mesh(loop, searched);
  const QualitySummary after = summarize_quality(searched, kUp);
  std::printf("[ quality  ] square given two corners: %.3f (%s) -> %.3f (%s)\n", before.scaled_jacobian.min,
              given.template_tree.c_str(), after.scaled_jacobian.min, searched.template_tree.c_str());
  EXPECT_EQ(after.inverted, 0);
  EXPECT_GT(after.scaled_jacobian.min, before.scaled_jacobian.min + 0.1);
}

TEST(PatchCornerSearch, AGoodPatchKeepsItsMesh) {
  const BoundaryLoop square = testing::square_boundary(6, 6, 4, 4);
  const QuadMesh given = mesh_boundary(square, {});
  ASSERT_GE(summarize_quality(given, kUp).scaled_jacobian.min, kPatchSearchBelow);
  EXPECT_TRUE(same_mesh(mesh_patch_best_corners(square, {}, given), given));
}

TEST(PatchCornerSearch, TheMemoSearchesWhenAskedAndKeepsBothMeshes) {
  const BoundaryLoop loop = square_given_two_corners();
  MeshOptions searching;
  searching.search_patch_corners = true;
  PatchMeshMemo memo;
  const QuadMesh& searched = memo.mesh(loop, searching);
  EXPECT_TRUE(same_mesh(searched, mesh_patch_best_corners(loop, {}, mesh_boundary(loop, {}))));
  EXPECT_FALSE(same_mesh(searched, mesh_boundary(loop, {})));
  const QuadMesh& given = memo.mesh(loop, {});
  EXPECT_TRUE(same_mesh(given, mesh_boundary(loop, {})));
  EXPECT_EQ(&memo.mesh(loop, searching), &searched);  // kept, not searched again
  EXPECT_EQ(&memo.mesh(loop, {}), &given);
}

TEST(PatchCornerSearch, NoPlanarBoundaryEndsWorseThanItsGivenCorners) {
  // Every 20th generated boundary that is planar (in the z = 0 plane, as patches are;
  // the generator draws them counter-clockwise there).
  int searched = 0, improved = 0;
  for (int i = 0; i < 12000; i += 20) {
    const testing::GeneratedCase c = testing::generated_case(i);
    if (!c.planar) continue;
    QuadMesh given;
    try {
      given = mesh_boundary(c.loop, {});
    } catch (const InputError&) {
      continue;  // the search starts from a mesh of the given corners
    }
    ++searched;
    const QuadMesh found = mesh_patch_best_corners(c.loop, {}, given);
    expect_patch_mesh(c.loop, found);
    ASSERT_EQ(check_disk_mesh(found, static_cast<int>(c.loop.points.size())), "") << c.description;
    const QualitySummary a = summarize_quality(given, kUp), b = summarize_quality(found, kUp);
    ASSERT_LE(b.inverted, a.inverted) << c.description;
    if (b.inverted == a.inverted) ASSERT_GE(b.scaled_jacobian.min, a.scaled_jacobian.min - 1e-9) << c.description;
    if (b.scaled_jacobian.min > a.scaled_jacobian.min + 1e-9) ++improved;
  }
  std::printf("[ quality  ] patch corner search: %d planar boundaries, %d with a better worst corner\n", searched,
              improved);
  EXPECT_GT(searched, 250);
  EXPECT_GT(improved, 0);
}

// Not monotone for a whole domain (each patch is, before the domain's own repair and
// its choice among decomposition variants): the CAD route compares the face's meshes
// with and without the search and keeps the better, smoothed.
TEST(PatchCornerSearch, GeneratedDomainsMeshedWithItStayValid) {
  MeshOptions searching;
  searching.search_patch_corners = true;
  int better = 0, worse = 0, domains = 0;
  for (int i = 0; i < 5040; i += 40) {
    const testing::GeneratedDomain g = testing::generated_domain(i);
    QuadMesh plain, searched;
    ASSERT_NO_THROW(plain = mesh_planar_domain(g.domain, g.size)) << g.description;
    ASSERT_NO_THROW(searched = mesh_planar_domain(g.domain, g.size, searching)) << g.description;
    ASSERT_EQ(check_domain_mesh(searched, testing::loop_sizes(g.domain)), "") << g.description;
    int k = 0;
    for (const DomainLoop& loop : g.domain.loops) {
      for (const Vec3& p : loop.points) ASSERT_TRUE(searched.nodes[k++] == p) << g.description << ": point moved";
    }
    const QualitySummary a = summarize_quality(plain, kUp), b = summarize_quality(searched, kUp);
    EXPECT_EQ(b.inverted, 0) << g.description;
    ++domains;
    if (b.scaled_jacobian.min > a.scaled_jacobian.min + 1e-9) ++better;
    if (b.scaled_jacobian.min < a.scaled_jacobian.min - 1e-9) ++worse;
  }
  std::printf("[ quality  ] domains with searched patches: %d, worst corner better on %d, worse on %d\n", domains,
              better, worse);
  EXPECT_GT(better, 0);
}

}  // namespace
}  // namespace tquad
