// reuse_unchanged_face (face_route.h): a refinement round takes over a face none of
// whose edges changed, renumbered, and it is the mesh meshing it again would give.
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopExp_Explorer.hxx>

#include <set>

#include "occ/intervals/edge_discretization.h"
#include "occ/face/face_route.h"

namespace tquad {
namespace {

struct Discretized {
  std::vector<EdgeNodes> edges;
  std::vector<Vec3> nodes;
};

Discretized discretized(const ShapeIndex& index, const std::vector<int>& segments) {
  Discretized d;
  d.edges = discretize_edges(index, segments, d.nodes);
  return d;
}

std::set<int> edges_of_face(const ShapeIndex& index, int f) {
  std::set<int> edges;
  for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) edges.insert(index.edge_index(it.Current()));
  return edges;
}

TEST(EdgeSpacings, KeptSpacingsGiveTheNodesAFreshDiscretizationGives) {
  // A cylinder's curved edges (the arc-length spacing is not uniform in parameter).
  const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(5, 12).Shape();
  const ShapeIndex index(cylinder);
  EdgeSpacings kept;
  std::vector<int> segments(index.edge_count(), 6);
  std::vector<Vec3> first_nodes;
  discretize_edges(index, segments, first_nodes, &kept);
  segments[0] = 10;  // one edge asked again at another count, the others at the same
  std::vector<Vec3> kept_nodes, fresh_nodes;
  const std::vector<EdgeNodes> from_kept = discretize_edges(index, segments, kept_nodes, &kept);
  const std::vector<EdgeNodes> fresh = discretize_edges(index, segments, fresh_nodes);
  ASSERT_EQ(kept_nodes.size(), fresh_nodes.size());
  for (std::size_t i = 0; i < fresh_nodes.size(); ++i) EXPECT_TRUE(kept_nodes[i] == fresh_nodes[i]) << "node " << i;
  ASSERT_EQ(from_kept.size(), fresh.size());
  for (std::size_t e = 0; e < fresh.size(); ++e) {
    EXPECT_EQ(from_kept[e].params, fresh[e].params) << "edge " << e;
    EXPECT_EQ(from_kept[e].nodes, fresh[e].nodes) << "edge " << e;
    if (!fresh[e].degenerate) EXPECT_EQ(kept.last[e].segments, segments[e]) << "edge " << e;
  }
}

TEST(FaceReuse, AnUnchangedFaceIsTakenOverRenumberedAndEqualsMeshingItAgain) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 20, 30).Shape();
  const ShapeIndex index(box);
  const ShapeMeshOptions options;
  std::vector<int> segments(index.edge_count(), 4);
  const Discretized before = discretized(index, segments);
  // A face without edge 0, whose nodes come first: more segments there shift the
  // ids of every other edge's nodes.
  int f = 0;
  while (edges_of_face(index, f).count(0)) ++f;
  const FaceOutcome first = mesh_one_face(index, f, before.edges, before.nodes, options, 2.5);
  ASSERT_TRUE(first.ok) << first.reason;

  const std::set<int> own = edges_of_face(index, f);
  segments[0] = 6;
  const Discretized after = discretized(index, segments);
  FaceOutcome taken = first;
  ASSERT_TRUE(reuse_unchanged_face(index, f, before.edges, before.nodes, after.edges, after.nodes, taken));
  const FaceOutcome again = mesh_one_face(index, f, after.edges, after.nodes, options, 2.5);
  ASSERT_TRUE(again.ok);
  EXPECT_EQ(taken.mesh.boundary_nodes, again.mesh.boundary_nodes);
  EXPECT_EQ(taken.boundary.nodes, again.boundary.nodes);
  EXPECT_EQ(taken.mesh.quads, again.mesh.quads);
  ASSERT_EQ(taken.mesh.interior.size(), again.mesh.interior.size());
  for (std::size_t i = 0; i < again.mesh.interior.size(); ++i) {
    EXPECT_TRUE(taken.mesh.interior[i] == again.mesh.interior[i]) << "interior node " << i;
  }
  bool shifted = false;  // the renumbering did something
  for (std::size_t i = 0; i < first.mesh.boundary_nodes.size(); ++i) {
    shifted = shifted || first.mesh.boundary_nodes[i] != taken.mesh.boundary_nodes[i];
  }
  EXPECT_TRUE(shifted) << "edge 0's new nodes should shift face " << f << "'s node ids";

  // One of its own edges changed: meshed again, the outcome left as it was.
  segments[*own.begin()] = 6;
  const Discretized changed = discretized(index, segments);
  FaceOutcome refused_reuse = first;
  EXPECT_FALSE(reuse_unchanged_face(index, f, before.edges, before.nodes, changed.edges, changed.nodes, refused_reuse));
  EXPECT_EQ(refused_reuse.mesh.boundary_nodes, first.mesh.boundary_nodes);

  // A refusal is never taken over.
  FaceOutcome refusal;
  refusal.reason = "refused";
  EXPECT_FALSE(reuse_unchanged_face(index, f, before.edges, before.nodes, after.edges, after.nodes, refusal));
}

}  // namespace
}  // namespace tquad
