// The order of one-by-one node placement (breadth_first_placement.h), on the meshes of
// generated boundaries: every interior node exactly once, each started from an edge
// neighbour placed before it, the nearest of those.
#include <gtest/gtest.h>

#include <set>

#include "boundary_generators.h"
#include "core/decomposition/breadth_first_placement.h"
#include "core/templates/mesher.h"
#include "core/mesh/node_adjacency.h"

namespace tquad {
namespace {

using testing::GeneratedCase;
using testing::generated_case;
using testing::square_boundary;

void expect_valid_order(const QuadMesh& mesh, std::size_t boundary_count, const std::string& what) {
  const std::vector<PlacementStep> steps = breadth_first_placement(mesh.nodes, mesh.quads, boundary_count);
  ASSERT_EQ(steps.size(), mesh.nodes.size() - boundary_count) << what;
  std::set<std::pair<NodeId, NodeId>> edges;
  for (const Quad& q : mesh.quads) {
    for (int i = 0; i < 4; ++i) {
      edges.insert({q[i], q[(i + 1) % 4]});
      edges.insert({q[(i + 1) % 4], q[i]});
    }
  }
  std::vector<char> placed(mesh.nodes.size(), 0);
  for (std::size_t i = 0; i < boundary_count; ++i) placed[i] = 1;
  for (const PlacementStep& s : steps) {
    ASSERT_GE(s.node, static_cast<NodeId>(boundary_count)) << what;
    ASSERT_FALSE(placed[s.node]) << what << ": node " << s.node << " placed twice";
    ASSERT_TRUE(edges.count({s.node, s.start_from})) << what << ": " << s.start_from << " is no neighbour of " << s.node;
    ASSERT_TRUE(placed[s.start_from]) << what << ": node " << s.node << " starts from an unplaced node";
    const double chosen = norm(mesh.nodes[s.start_from] - mesh.nodes[s.node]);
    for (const auto& [a, b] : edges) {
      if (a == s.node && placed[b]) {
        EXPECT_LE(chosen, norm(mesh.nodes[b] - mesh.nodes[s.node])) << what << ": node " << s.node;
      }
    }
    placed[s.node] = 1;
  }
}

TEST(BreadthFirstPlacement, EveryInteriorNodeOnceFromItsNearestPlacedNeighbour) {
  for (int index = 0; index < 300; ++index) {
    const GeneratedCase c = generated_case(index);
    QuadMesh mesh;
    try {
      mesh = mesh_boundary(c.loop);
    } catch (const std::exception&) {
      continue;  // refused boundaries have their own tests
    }
    expect_valid_order(mesh, c.loop.points.size(), c.description);
  }
}

TEST(BreadthFirstPlacement, NoInteriorNodesNoSteps) {
  const QuadMesh mesh = mesh_boundary(square_boundary(1, 1, 1, 1));
  EXPECT_TRUE(breadth_first_placement(mesh.nodes, mesh.quads, mesh.nodes.size()).empty());
}

}  // namespace
}  // namespace tquad
