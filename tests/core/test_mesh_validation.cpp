// The structural mesh check (mesh_validation.h) on meshes broken on purpose: each
// fault must be found and named. The property tests only show it accepts valid meshes.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>

#include "core/mesh/mesh_validation.h"

namespace tquad {
namespace {

// A 2 x 2 grid on the unit square: boundary nodes 0..7 counter-clockwise from the
// origin, node 8 in the middle, four quads counter-clockwise.
QuadMesh grid_2x2() {
  QuadMesh mesh;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}, {0, 2, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.quads = {{0, 1, 8, 7}, {1, 2, 3, 8}, {8, 3, 4, 5}, {7, 8, 5, 6}};
  return mesh;
}

// A square ring: outer loop 0..3 counter-clockwise, hole loop 4..7 clockwise.
QuadMesh square_ring() {
  QuadMesh mesh;
  mesh.nodes = {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0}, {1, 1, 0}, {1, 2, 0}, {2, 2, 0}, {2, 1, 0}};
  mesh.quads = {{0, 1, 7, 4}, {1, 2, 6, 7}, {2, 3, 5, 6}, {3, 0, 4, 5}};
  return mesh;
}

bool names(const std::string& problem, const std::string& part) {
  return problem.find(part) != std::string::npos;
}

TEST(MeshValidation, AcceptsValidMeshes) {
  EXPECT_EQ(check_disk_mesh(grid_2x2(), 8), "");
  EXPECT_EQ(check_domain_mesh(square_ring(), {4, 4}), "");
}

TEST(MeshValidation, FindsANodeIndexOutOfRange) {
  QuadMesh mesh = grid_2x2();
  mesh.quads[2][1] = 9;
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "quad 2 has a node index out of range"));
  mesh.quads[2][1] = -1;
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "quad 2 has a node index out of range"));
}

TEST(MeshValidation, FindsAQuadRepeatingANode) {
  QuadMesh mesh = grid_2x2();
  mesh.quads[1] = {1, 2, 3, 1};
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "quad 1 repeats node 1"));
}

TEST(MeshValidation, FindsOverlappingQuads) {
  QuadMesh mesh = grid_2x2();
  mesh.quads.push_back(mesh.quads[3]);
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "edge 5-6 is used twice in the same direction"));
}

TEST(MeshValidation, FindsAFlippedQuad) {
  QuadMesh mesh = grid_2x2();
  std::swap(mesh.quads[0][1], mesh.quads[0][3]);  // 0, 7, 8, 1: clockwise
  // Its side on the loop runs backwards (found first), and its inner sides run as
  // its neighbours' do.
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "edge 1-0 belongs to one quad only"));
  mesh.quads[0] = {1, 0, 7, 8};  // the same quad, starting elsewhere
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "edge 1-0 belongs to one quad only"));
}

TEST(MeshValidation, FindsACrack) {
  QuadMesh mesh = grid_2x2();
  // Quad 2 gets its own copy of the middle node: edges 3-8' and 8'-5 border one quad.
  mesh.nodes.push_back({1.0, 1.0, 1.0});
  mesh.quads[2][0] = 9;
  const std::string problem = check_disk_mesh(mesh, 8);
  EXPECT_TRUE(names(problem, "belongs to one quad only but is not a boundary segment")) << problem;
}

TEST(MeshValidation, FindsABoundarySegmentInTheWrongDirection) {
  QuadMesh mesh = grid_2x2();
  // Every quad turned clockwise: interior edges still pair up, boundary edges run
  // against the loop.
  for (Quad& q : mesh.quads) std::swap(q[1], q[3]);
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "belongs to one quad only but is not a boundary segment"));
}

TEST(MeshValidation, FindsBoundarySegmentsNoQuadHas) {
  QuadMesh mesh = square_ring();
  mesh.quads.push_back({4, 7, 6, 5});  // the hole filled: its loop borders no quad alone
  EXPECT_TRUE(names(check_domain_mesh(mesh, {4, 4}), "4 boundary segments belong to no quad"));
}

TEST(MeshValidation, FindsAnUnusedNode) {
  QuadMesh mesh = grid_2x2();
  mesh.nodes.push_back({5, 5, 0});
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "node 9 belongs to no quad"));
}

TEST(MeshValidation, FindsCoincidentNodesIncludingSignedZeros) {
  QuadMesh mesh = grid_2x2();
  mesh.nodes[8] = mesh.nodes[3];
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "nodes 3 and 8 are at the same position"));
  mesh = grid_2x2();
  mesh.nodes[8] = {-0.0, 0.0, -0.0};  // equal to node 0 at (0, 0, 0)
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "nodes 0 and 8 are at the same position"));
}

TEST(MeshValidation, FindsANonFiniteNode) {
  // A NaN equals nothing, so the coincidence test alone would let two NaN nodes pass
  // (a fuzzed T3 split once put its centre and cuts there).
  QuadMesh mesh = grid_2x2();
  mesh.nodes[8].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "node 8 has a coordinate that is NaN or infinite"));
  mesh = grid_2x2();
  mesh.nodes[8].z = -std::numeric_limits<double>::infinity();
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "node 8 has a coordinate that is NaN or infinite"));
}

TEST(MeshValidation, FindsANodeCountNoDiskHas) {
  // The grid and, apart from it, a cube's closed surface: every edge is in two quads
  // or on the loop, every node used, none coincident; only V = 1 + F + E/2 fails
  // (17 nodes where 1 + 10 + 4 = 15).
  QuadMesh mesh = grid_2x2();
  for (int z = 0; z < 2; ++z) {
    for (const auto& [x, y] : {std::pair(5, 5), std::pair(6, 5), std::pair(6, 6), std::pair(5, 6)}) {
      mesh.nodes.push_back({double(x), double(y), double(z)});
    }
  }
  // Cube nodes 9..12 at z = 0, 13..16 at z = 1; outward faces.
  mesh.quads.insert(mesh.quads.end(), {{9, 12, 11, 10}, {13, 14, 15, 16}, {9, 10, 14, 13},
                                       {10, 11, 15, 14}, {11, 12, 16, 15}, {12, 9, 13, 16}});
  EXPECT_TRUE(names(check_disk_mesh(mesh, 8), "the mesh has 17 nodes")) << check_disk_mesh(mesh, 8);
}

}  // namespace
}  // namespace tquad
