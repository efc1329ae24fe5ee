// Edges far shorter than the size are contracted to one node (edge_contraction.h), so
// no quad beside them is a triangle in effect; where an edge cannot be contracted
// (the end of a strip face), the strip is absorbed (strip_absorption.h) when it is
// as narrow as that everywhere.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "core/mesh/quality.h"
#include "occ/model/edge_contraction.h"
#include "occ/intervals/edge_discretization.h"
#include "occ/model/shape_index.h"
#include "occ/shape_mesher.h"
#include "occ/model/strip_absorption.h"

namespace tquad {
namespace {

TopoDS_Face polygon_face(const std::vector<gp_Pnt>& points) {
  BRepBuilderAPI_MakePolygon polygon;
  for (const gp_Pnt& p : points) polygon.Add(p);
  polygon.Close();
  return BRepBuilderAPI_MakeFace(polygon.Wire(), true).Face();
}

// A 10 x 10 square with one corner cut off by an edge `cut` * sqrt(2) long.
TopoDS_Face cut_square(double cut) {
  return polygon_face({gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0), gp_Pnt(10, 10 - cut, 0), gp_Pnt(10 - cut, 10, 0),
                       gp_Pnt(0, 10, 0)});
}

long long collapsed_quads(const ShapeMesh& mesh) {
  long long count = 0;
  for (const Quad& q : mesh.quads) {
    count += is_collapsed({mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]], mesh.nodes[q[3]]}) ? 1 : 0;
  }
  return count;
}

double closest_nodes(const ShapeMesh& mesh) {
  double closest = INFINITY;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    for (std::size_t j = i + 1; j < mesh.nodes.size(); ++j) closest = std::min(closest, distance(mesh.nodes[i], mesh.nodes[j]));
  }
  return closest;
}

TEST(EdgeContraction, AnEdgeFarShorterThanTheSizeBecomesOneNode) {
  ShapeMeshOptions options;
  options.size = 1.0;
  // 0.0014 long, under 0.004 of the size: contracted, and the quads around the cut
  // corner are whole quads.
  const ShapeMeshResult tiny = mesh_shape(cut_square(1e-3), options);
  ASSERT_TRUE(tiny.mesh.refused_faces.empty());
  ASSERT_EQ(tiny.contracted_edges.size(), 1u);
  EXPECT_EQ(collapsed_quads(tiny.mesh), 0);
  EXPECT_GT(closest_nodes(tiny.mesh), 0.1);  // its two ends are one node
  // 0.014 long, over the bound: kept, with a node at each end, and the quad beside it
  // is not collapsed (its Jacobian ratio is about 0.014).
  const ShapeMeshResult small = mesh_shape(cut_square(1e-2), options);
  ASSERT_TRUE(small.mesh.refused_faces.empty());
  EXPECT_TRUE(small.contracted_edges.empty());
  EXPECT_EQ(collapsed_quads(small.mesh), 0);
  EXPECT_NEAR(closest_nodes(small.mesh), 1e-2 * std::sqrt(2.0), 1e-9);
}

TEST(EdgeContraction, AChainOfShortEdgesIsNotJoinedFurtherThanTheBound) {
  // Ten collinear edges 0.001 long along the top of a 10 x 10 square: 0.01 in all,
  // over the bound (0.004) at size 1.
  std::vector<gp_Pnt> points{gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0), gp_Pnt(10, 10, 0)};
  for (int k = 0; k <= 10; ++k) points.push_back(gp_Pnt(5.0 - 1e-3 * k, 10, 0));
  points.push_back(gp_Pnt(0, 10, 0));
  const TopoDS_Face face = polygon_face(points);
  const ShapeIndex index(face);
  std::vector<double> lengths;
  edge_segment_counts(index, 1.0, lengths);
  const std::vector<int> contracted = edges_to_contract(index, lengths, {}, 1.0);
  EXPECT_FALSE(contracted.empty());
  EXPECT_LT(contracted.size(), 10u);
  // Joined vertices, grouped: no group spans the bound.
  ShapeIndex joined(face);
  joined.contract_edges(contracted);
  for (int u = 0; u < index.vertex_count(); ++u) {
    for (int v = u + 1; v < index.vertex_count(); ++v) {
      if (joined.vertex_index(index.vertex(u)) != joined.vertex_index(index.vertex(v))) continue;
      EXPECT_LT(BRep_Tool::Pnt(index.vertex(u)).Distance(BRep_Tool::Pnt(index.vertex(v))), kContractedEdgeRatio) << u << " " << v;
    }
  }
  ShapeMeshOptions options;
  options.size = 1.0;
  const ShapeMeshResult result = mesh_shape(face, options);
  EXPECT_TRUE(result.mesh.refused_faces.empty());
  EXPECT_EQ(result.contracted_edges, contracted);
}

// Each quad side's count of quads using it: 2 everywhere on a closed mesh.
std::map<std::pair<NodeId, NodeId>, int> side_uses(const ShapeMesh& mesh) {
  std::map<std::pair<NodeId, NodeId>, int> uses;
  for (const Quad& q : mesh.quads) {
    for (int k = 0; k < 4; ++k) ++uses[std::minmax(q[k], q[(k + 1) % 4])];
  }
  return uses;
}

bool closed(const ShapeMesh& mesh) {
  const auto uses = side_uses(mesh);
  return std::all_of(uses.begin(), uses.end(), [](const auto& u) { return u.second == 2; });
}

// A 10 x 10 square with one corner cut by `cut` * sqrt(2), extruded 3 high, meshed at
// size 1 (contraction bound 0.004).
TopoDS_Shape cut_prism(double cut) { return BRepPrimAPI_MakePrism(cut_square(cut), gp_Vec(0, 0, 3)).Shape(); }
ShapeMeshResult mesh_at_size_one(const TopoDS_Shape& shape) {
  ShapeMeshOptions options;
  options.size = 1.0;
  return mesh_shape(shape, options);
}

TEST(StripAbsorption, AStripNarrowerThanTheBoundIsAbsorbedAndTheSolidStaysClosed) {
  // A square cut by an edge 1.4e-6 long, extruded: the cut's side face is a strip
  // that wide. Meshed, its ends would stay (a strip folds onto itself when they are
  // contracted) and each cap would keep a quad beside them that is a triangle in
  // effect. Absorbed, the strip has no quads, its long sides share one row of nodes,
  // its ends are contracted on both caps, and the prism's mesh is closed.
  const TopoDS_Shape prism = cut_prism(1e-6);
  const ShapeMeshResult result = mesh_at_size_one(prism);
  EXPECT_TRUE(result.mesh.refused_faces.empty());
  ASSERT_EQ(result.absorbed_strips.size(), 1u);
  const AbsorbedStrip& strip = result.absorbed_strips.front();
  EXPECT_NEAR(strip.width, 1e-6 * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(result.contracted_edges.size(), 2u);
  EXPECT_EQ(collapsed_quads(result.mesh), 0);
  EXPECT_TRUE(closed(result.mesh));
  const ShapeIndex index(prism);
  EXPECT_EQ(result.mesh.faces.size(), static_cast<std::size_t>(index.face_count() - 1));
  for (const FaceMesh& f : result.mesh.faces) EXPECT_NE(f.face, strip.face);
  // No quad of the faces beside it cuts across their surfaces (their merged side's
  // nodes lie within the strip's width of them).
  EXPECT_EQ(result.off_surface, 0);
}

TEST(StripAbsorption, AStripWiderThanTheBoundIsMeshed) {
  // The same with a cut 0.014 wide, over the bound (0.004 at size 1): a row of thin
  // rectangles, every face meshed, closed.
  const TopoDS_Shape prism = cut_prism(1e-2);
  const ShapeMeshResult result = mesh_at_size_one(prism);
  EXPECT_TRUE(result.mesh.refused_faces.empty());
  EXPECT_TRUE(result.absorbed_strips.empty());
  EXPECT_EQ(result.mesh.faces.size(), static_cast<std::size_t>(ShapeIndex(prism).face_count()));
  EXPECT_EQ(collapsed_quads(result.mesh), 0);
  EXPECT_TRUE(closed(result.mesh));
}

TEST(StripAbsorption, ATinyFilletIsAbsorbedAtEverySizeItIsNarrowerThanTheBound) {
  // A 10 x 6 x 4 box with one edge rounded by a radius 1e-4 (a quarter cylinder
  // 1.6e-4 wide, with arcs that short at its ends): absorbed at sizes 0.5 to 2 (bound
  // 0.002 to 0.008), meshed as a strip at 0.02 (bound 8e-5). Either way the mesh is
  // closed and no quad is collapsed.
  BRepPrimAPI_MakeBox box(10, 6, 4);
  BRepFilletAPI_MakeFillet fillet(box.Shape());
  TopExp_Explorer it(box.Shape(), TopAbs_EDGE);
  fillet.Add(1e-4, TopoDS::Edge(it.Current()));
  const TopoDS_Shape rounded = fillet.Shape();
  for (double size : {0.5, 1.0, 2.0, 0.02}) {
    SCOPED_TRACE("size " + std::to_string(size));
    ShapeMeshOptions options;
    options.size = size;
    const ShapeMeshResult result = mesh_shape(rounded, options);
    EXPECT_TRUE(result.mesh.refused_faces.empty());
    EXPECT_EQ(result.absorbed_strips.size(), size > 0.1 ? 1u : 0u);
    EXPECT_EQ(collapsed_quads(result.mesh), 0);
    EXPECT_TRUE(closed(result.mesh));
  }
}

}  // namespace
}  // namespace tquad
