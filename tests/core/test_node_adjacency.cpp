// SlottedLists (node_adjacency.h) holds the same lists in the same order as
// CompressedLists, for nodes with fewer than four, four, and more items (irregular
// nodes of the template meshes, and a fan of quads around one node).
#include <gtest/gtest.h>

#include <vector>

#include "boundary_generators.h"
#include "core/templates/mesher.h"
#include "core/mesh/node_adjacency.h"

namespace tquad {
namespace {

std::vector<int> slotted(const SlottedLists& lists, NodeId n) {
  std::vector<int> items;
  lists.for_each(n, [&](int item) { items.push_back(item); });
  return items;
}

std::vector<int> compressed(const CompressedLists& lists, NodeId n) {
  return {lists.items.begin() + lists.offsets[n], lists.items.begin() + lists.offsets[n + 1]};
}

void expect_same_lists(std::size_t nodes, const std::vector<Quad>& quads, int& nodes_with_more) {
  const SlottedLists slots = slotted_quads_around_nodes(nodes, quads);
  const CompressedLists lists = quads_around_nodes(nodes, quads);
  for (NodeId n = 0; n < static_cast<NodeId>(nodes); ++n) {
    const std::vector<int> expected = compressed(lists, n);
    ASSERT_EQ(slotted(slots, n), expected) << "node " << n;
    EXPECT_EQ(slots.first(n), expected.empty() ? -1 : expected.front());
    nodes_with_more += expected.size() > 4 ? 1 : 0;
  }
}

TEST(SlottedLists, SameListsAsCompressedListsOnTemplateMeshes) {
  int nodes_with_more = 0, meshes = 0;
  for (int index = 0; index < 300; ++index) {
    QuadMesh mesh;
    try {
      mesh = mesh_boundary(testing::generated_case(index).loop);
    } catch (const std::exception&) {
      continue;
    }
    ++meshes;
    expect_same_lists(mesh.nodes.size(), mesh.quads, nodes_with_more);
  }
  EXPECT_GT(meshes, 200);
  EXPECT_GT(nodes_with_more, 0);  // the overflow list was exercised
}

TEST(SlottedLists, AFanOfQuadsAroundOneNode) {
  // Node 0 in the middle of 9 quads (0, 2k+1, 2k+2, (2k+3) mod 18), node 19 of none.
  std::vector<Quad> quads;
  for (int k = 0; k < 9; ++k) quads.push_back({0, 2 * k + 1, 2 * k + 2, (2 * k + 3) % 18});
  int nodes_with_more = 0;
  expect_same_lists(20, quads, nodes_with_more);
  EXPECT_EQ(nodes_with_more, 1);
  EXPECT_EQ(slotted_quads_around_nodes(20, quads).first(19), -1);
}

}  // namespace
}  // namespace tquad
