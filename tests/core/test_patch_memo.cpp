// PatchMeshMemo: the same patch input gives the mesh mesh_boundary gives, computed once.
#include <gtest/gtest.h>

#include <cstring>

#include "boundary_generators.h"
#include "core/input_error.h"
#include "core/decomposition/patch_memo.h"

namespace tquad {
namespace {

bool same_mesh(const QuadMesh& a, const QuadMesh& b) {
  return a.quads == b.quads && a.nodes.size() == b.nodes.size() &&
         std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(Vec3)) == 0 &&
         a.template_tree == b.template_tree;
}

TEST(PatchMeshMemo, GivesMeshBoundarysMeshOncePerInput) {
  PatchMeshMemo memo;
  const BoundaryLoop square = testing::square_boundary(6, 4, 8, 2);
  const BoundaryLoop triangle = testing::triangle_boundary(4, 6, 4);
  const QuadMesh& first = memo.mesh(square, {});
  EXPECT_TRUE(same_mesh(first, mesh_boundary(square, {})));
  EXPECT_EQ(&memo.mesh(square, {}), &first);  // kept, not meshed again

  const QuadMesh& other = memo.mesh(triangle, {});
  EXPECT_NE(&other, &first);
  EXPECT_TRUE(same_mesh(other, mesh_boundary(triangle, {})));
  EXPECT_EQ(&memo.mesh(square, {}), &first);  // references stay valid as entries grow

  MeshOptions no_repair;
  no_repair.untangle = false;
  EXPECT_NE(&memo.mesh(square, no_repair), &first);  // other options: another entry

  BoundaryLoop moved = square;
  moved.points[1].x = std::nextafter(moved.points[1].x, 1.0);  // one bit
  EXPECT_NE(&memo.mesh(moved, {}), &first);
}

TEST(PatchMeshMemo, ALoopTheTemplatesRefuseThrowsEachTime) {
  PatchMeshMemo memo;
  BoundaryLoop odd = testing::square_boundary(3, 4, 4, 4);  // 15 segments
  EXPECT_THROW(memo.mesh(odd, {}), InputError);
  EXPECT_THROW(memo.mesh(odd, {}), InputError);
}

}  // namespace
}  // namespace tquad
