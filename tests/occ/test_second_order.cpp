// Second-order quads (mid_edge_nodes.h): one node in the middle of every quad edge,
// shared by the two quads of that edge (also across faces), on the curve of a CAD edge
// (a hole's rim stays round) and on the surface inside a face.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>

#include <cmath>
#include <map>
#include <set>
#include <string>

#include "core/input_error.h"
#include "core/mesh/quadratic_quad.h"
#include "occ/shape_mesher.h"
#include "occ/read/shape_reader.h"

namespace tquad {
namespace {

// Every quad edge has one middle node, the same from both quads; the nodes are the
// corners and the middles, each once.
void expect_conforming_middles(const ShapeMesh& mesh) {
  ASSERT_EQ(mesh.mid_nodes.size(), mesh.quads.size());
  std::map<std::pair<NodeId, NodeId>, NodeId> middle_of;
  std::set<NodeId> corners, middles;
  for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
    for (int i = 0; i < 4; ++i) {
      const NodeId a = mesh.quads[k][i], b = mesh.quads[k][(i + 1) % 4];
      const NodeId m = mesh.mid_nodes[k][i];
      const auto [it, added] = middle_of.emplace(std::minmax(a, b), m);
      EXPECT_EQ(it->second, m) << "quad " << k << " edge " << i << ": another middle node than its neighbour's";
      corners.insert(a);
      middles.insert(m);
    }
  }
  for (NodeId m : middles) EXPECT_EQ(corners.count(m), 0u) << "node " << m << " is a corner and a middle";
  EXPECT_EQ(middles.size(), middle_of.size());
  EXPECT_EQ(mesh.nodes.size(), corners.size() + middles.size());
}

TEST(SecondOrder, CylinderMiddlesOnItsSurfacesAndRims) {
  constexpr double radius = 5.0, height = 10.0;
  ShapeMeshOptions options;
  options.size = 1.5;
  options.order = 2;
  const ShapeMesh mesh = mesh_shape(BRepPrimAPI_MakeCylinder(radius, height).Shape(), options).mesh;
  expect_conforming_middles(mesh);
  int on_rims = 0;
  for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
    for (int i = 0; i < 4; ++i) {
      const Vec3& a = mesh.nodes[mesh.quads[k][i]];
      const Vec3& b = mesh.nodes[mesh.quads[k][(i + 1) % 4]];
      const Vec3& m = mesh.nodes[mesh.mid_nodes[k][i]];
      const double r = std::hypot(m.x, m.y);
      const bool on_cap = std::abs(m.z) < 1e-12 || std::abs(m.z - height) < 1e-12;
      EXPECT_TRUE(on_cap || std::abs(r - radius) < 1e-9) << "a middle node off the surface: r " << r << ", z " << m.z;
      EXPECT_LE(r, radius + 1e-9);
      const bool rim_edge = std::abs(std::hypot(a.x, a.y) - radius) < 1e-9 &&
                            std::abs(std::hypot(b.x, b.y) - radius) < 1e-9 && std::abs(a.z - b.z) < 1e-12;
      if (rim_edge) {
        ++on_rims;
        EXPECT_NEAR(r, radius, 1e-9) << "a rim's middle node is on the circle, not on the chord";
      }
    }
  }
  EXPECT_GT(on_rims, 0);
}

TEST(SecondOrder, PlateWithHoleKeepsTheHoleRound) {
  // 100 x 60 with a hole of diameter 20 at (50, 30), as four faces around it.
  const TopoDS_Shape plate = read_shape(std::string(TQUAD_SOURCE_DIR) + "/resources/shapes/plate_with_hole.brep");
  ShapeMeshOptions options;
  options.size = 4.0;
  options.order = 2;
  const ShapeMesh mesh = mesh_shape(plate, options).mesh;
  expect_conforming_middles(mesh);
  int rim_middles = 0;
  for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
    for (int i = 0; i < 4; ++i) {
      const auto r = [&](NodeId n) { return std::hypot(mesh.nodes[n].x - 50.0, mesh.nodes[n].y - 30.0); };
      if (std::abs(r(mesh.quads[k][i]) - 10.0) < 1e-9 && std::abs(r(mesh.quads[k][(i + 1) % 4]) - 10.0) < 1e-9) {
        ++rim_middles;
        EXPECT_NEAR(r(mesh.mid_nodes[k][i]), 10.0, 1e-9);
      }
    }
  }
  EXPECT_GT(rim_middles, 8);
}

TEST(SecondOrder, ThinRingQuadsDoNotFold) {
  // A ring 0.1 wide on a radius of 10: its rims' segments bulge (sagitta about 0.7)
  // far past the ring's width, but both rims bend alike, so the quads stay valid.
  const gp_Ax2 axis(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  const TopoDS_Wire outer = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(axis, 10.0)));
  TopoDS_Wire inner = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(axis, 9.9)));
  inner.Reverse();
  BRepBuilderAPI_MakeFace ring(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), outer);
  ring.Add(inner);
  ShapeMeshOptions options;
  options.size = 4.0;
  options.order = 2;
  const ShapeMeshResult result = mesh_shape(ring.Face(), options);
  const ShapeMesh& mesh = result.mesh;
  expect_conforming_middles(mesh);
  for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
    std::array<Vec3, 8> p;
    for (int i = 0; i < 4; ++i) {
      p[i] = mesh.nodes[mesh.quads[k][i]];
      p[4 + i] = mesh.nodes[mesh.mid_nodes[k][i]];
    }
    EXPECT_GT(quadratic_quad_min_scaled_jacobian(p), 0.0) << "quad " << k << " folds";
  }
}

TEST(SecondOrder, FirstOrderHasNoMiddlesAndOtherOrdersAreRefused) {
  ShapeMeshOptions options;
  options.size = 2.0;
  const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(5.0, 10.0).Shape();
  const ShapeMesh first = mesh_shape(cylinder, options).mesh;
  EXPECT_FALSE(first.second_order());
  options.order = 2;
  const ShapeMesh second = mesh_shape(cylinder, options).mesh;
  EXPECT_EQ(second.quads, first.quads) << "the same quads, with middles added";
  EXPECT_TRUE(std::equal(first.nodes.begin(), first.nodes.end(), second.nodes.begin()));
  options.order = 3;
  EXPECT_THROW(mesh_shape(cylinder, options), InputError);
}

}  // namespace
}  // namespace tquad
