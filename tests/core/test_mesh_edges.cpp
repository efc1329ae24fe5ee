// MeshEdges (mesh_edges.h): every undirected edge of a quad mesh once, found from
// both of its quads, the edges of no quad not found.
#include <gtest/gtest.h>

#include <set>

#include "boundary_generators.h"
#include "core/mesh/mesh_edges.h"
#include "core/templates/mesher.h"

namespace tquad {
namespace {

TEST(MeshEdges, EachEdgeOnceFromEitherSide) {
  for (int index = 0; index < 200; ++index) {
    QuadMesh mesh;
    try {
      mesh = mesh_boundary(testing::generated_case(index).loop);
    } catch (const std::exception&) {
      continue;
    }
    const MeshEdges edges(mesh.nodes.size(), mesh.quads);
    std::set<std::pair<NodeId, NodeId>> distinct;
    std::set<std::size_t> numbers;
    for (const Quad& q : mesh.quads) {
      for (int i = 0; i < 4; ++i) {
        const NodeId a = q[i], b = q[(i + 1) % 4];
        distinct.insert(std::minmax(a, b));
        const std::size_t e = edges.index(a, b);
        ASSERT_NE(e, MeshEdges::npos);
        EXPECT_EQ(edges.index(b, a), e);
        numbers.insert(e);
      }
    }
    EXPECT_EQ(edges.count(), distinct.size());
    EXPECT_EQ(numbers.size(), distinct.size());
    EXPECT_LT(*numbers.rbegin(), edges.count());
    // A diagonal is no edge.
    EXPECT_EQ(edges.index(mesh.quads[0][0], mesh.quads[0][2]), MeshEdges::npos);
  }
}

}  // namespace
}  // namespace tquad
