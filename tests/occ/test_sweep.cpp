// sweep_shape on extrusions built here: hexahedra that fill the solid exactly (their
// volumes sum to the solid's), none inverted, as many as the source's quads times the
// layers, caps and sides with their nodes; solids that are not extrusions refused
// with the reason, and kept out of the mesh.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <TopTools_ListOfShape.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepOffsetAPI_MakePipe.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeWedge.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <BRep_Builder.hxx>
#include <GC_MakeCircle.hxx>
#include <GProp_GProps.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax1.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <utility>

#include "core/input_error.h"
#include "occ/model/shape_index.h"
#include "occ/sweep/sweep.h"

namespace tquad {
namespace {

double volume_of(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props);
  return props.Mass();
}

double hexes_volume(const HexMesh& mesh, const SweptSolid& solid) {
  double sum = 0;
  for (std::int64_t k = solid.first_hex; k < solid.first_hex + solid.hex_count; ++k) {
    std::array<Vec3, 8> p;
    for (int i = 0; i < 8; ++i) p[i] = mesh.nodes[mesh.hexes[k][i]];
    sum += hex_volume(p);
  }
  return sum;
}

// A 60 x 40 plate, 8 thick, with two holes through it, extruded along z (or `dir`).
TopoDS_Shape holed_plate(const gp_Vec& dir = gp_Vec(0, 0, 8)) {
  BRepBuilderAPI_MakeWire outer;
  const gp_Pnt c[4] = {{0, 0, 0}, {60, 0, 0}, {60, 40, 0}, {0, 40, 0}};
  for (int i = 0; i < 4; ++i) outer.Add(BRepBuilderAPI_MakeEdge(c[i], c[(i + 1) % 4]).Edge());
  BRepBuilderAPI_MakeFace face(outer.Wire());
  for (double x : {18.0, 42.0}) {
    const gp_Circ circle(gp_Ax2(gp_Pnt(x, 20, 0), gp_Dir(0, 0, 1)), 6);
    BRepBuilderAPI_MakeWire hole(BRepBuilderAPI_MakeEdge(circle).Edge());
    face.Add(TopoDS::Wire(hole.Wire().Reversed()));
  }
  return BRepPrimAPI_MakePrism(face.Face(), dir).Shape();
}

// The volume of the solid with its holes' walls (the faces that are not planes, of
// radius `radius` across the caps, `normal_height` between them) replaced by the
// polygons of their nodes: each such polygon of n sides leaves its circle's segments
// in the solid.
double polygonal_volume(const TopoDS_Shape& shape, const SweepResult& r, double radius, double normal_height) {
  const ShapeIndex index(shape);
  const SweptSolid& s = r.mesh.solids[0];
  double volume = volume_of(shape);
  for (const auto& [face, nodes] : r.mesh.face_nodes) {
    if (BRepAdaptor_Surface(index.face(face)).GetType() == GeomAbs_Plane) continue;
    const double n = static_cast<double>(nodes.size()) / (s.layers + 1);
    volume += (M_PI - 0.5 * n * std::sin(2 * M_PI / n)) * radius * radius * normal_height;
  }
  return volume;
}

// Every quad face of the hexahedra is in one (the boundary) or two (inside) of them,
// and the boundary is the two caps' quads and each layer's quads along the source's
// rim: a conforming quad mesh of the solid's faces.
// Each quad face of the hexahedra (its corners, sorted) and how many hold it.
std::map<std::array<NodeId, 4>, int> quad_face_uses(const HexMesh& mesh) {
  constexpr int kFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::map<std::array<NodeId, 4>, int> faces;
  for (const Hex& h : mesh.hexes) {
    for (const auto& f : kFaces) {
      std::array<NodeId, 4> key{h[f[0]], h[f[1]], h[f[2]], h[f[3]]};
      std::sort(key.begin(), key.end());
      ++faces[key];
    }
  }
  return faces;
}

void expect_conforming(const HexMesh& mesh) {
  const std::map<std::array<NodeId, 4>, int> faces = quad_face_uses(mesh);
  long long boundary = 0;
  for (const auto& [key, count] : faces) {
    ASSERT_LE(count, 2) << "a quad face in " << count << " hexahedra";
    boundary += count == 1;
  }
  long long expected = 0;
  for (const SweptSolid& s : mesh.solids) {
    const long long per_layer = s.hex_count / s.layers;
    std::map<std::pair<NodeId, NodeId>, int> rim;  // the source quads' edges
    for (std::int64_t k = s.first_hex; k < s.first_hex + s.hex_count; ++k) {
      const Hex& h = mesh.hexes[k];
      if ((k - s.first_hex) % s.layers != 0) continue;  // each quad's first layer
      for (int i = 0; i < 4; ++i) ++rim[std::minmax(h[i], h[(i + 1) % 4])];
    }
    long long rim_edges = 0;
    for (const auto& [edge, count] : rim) rim_edges += count == 1;
    expected += (s.source >= 0 ? 2 * per_layer : 0) + s.layers * rim_edges;  // a full turn has no caps
  }
  EXPECT_EQ(boundary, expected);
}

void expect_valid_sweep(const TopoDS_Shape& shape, const SweepResult& r, double normal_height = 0) {
  ASSERT_EQ(r.mesh.solids.size(), 1u);
  const SweptSolid& s = r.mesh.solids[0];
  EXPECT_EQ(r.mesh.hexes.size(), static_cast<std::size_t>(s.hex_count));
  EXPECT_EQ(s.hex_count % s.layers, 0);
  for (double sj : r.mesh.scaled_jacobian) ASSERT_GT(sj, 1e-6);
  expect_conforming(r.mesh);
  const double expected = normal_height > 0 ? polygonal_volume(shape, r, 6.0, normal_height) : volume_of(shape);
  EXPECT_NEAR(hexes_volume(r.mesh, s), expected, 1e-9 * volume_of(shape));
  // Every node is in a hexahedron, and each cap's nodes are a layer's.
  std::set<NodeId> used;
  for (const Hex& h : r.mesh.hexes) used.insert(h.begin(), h.end());
  EXPECT_EQ(used.size(), r.mesh.nodes.size());
}

TEST(Sweep, AnExtrudedPlateWithHolesFillsItsSolidWithHexahedra) {
  const TopoDS_Shape plate = holed_plate();
  SweepOptions options;
  options.face.size = 4.0;
  const SweepResult r = sweep_shape(plate, options);
  expect_valid_sweep(plate, r, 8.0);
  const SweptSolid& s = r.mesh.solids[0];
  EXPECT_EQ(s.layers, 2);  // 8 / 4
  EXPECT_NEAR(s.height, 8.0, 1e-9);
  // The caps are the faces with the holes: the most edges.
  ASSERT_EQ(r.mesh.face_nodes.size(), 8u);  // 2 caps, 4 sides, 2 hole walls
  const std::size_t per_layer = r.mesh.nodes.size() / (s.layers + 1);
  EXPECT_EQ(r.mesh.face_nodes[0].second.size(), per_layer);
  EXPECT_EQ(r.mesh.face_nodes[1].second.size(), per_layer);
  for (std::size_t k = 2; k < r.mesh.face_nodes.size(); ++k) {
    const auto& [face, nodes] = r.mesh.face_nodes[k];
    EXPECT_GE(nodes.size(), 2u * (s.layers + 1)) << "side face " << face;
    EXPECT_EQ(nodes.size() % (s.layers + 1), 0u) << "side face " << face;
  }
  // Given layers are kept.
  options.layers = 5;
  const SweepResult five = sweep_shape(plate, options);
  EXPECT_EQ(five.mesh.solids[0].layers, 5);
  EXPECT_EQ(five.mesh.hexes.size() * 2, r.mesh.hexes.size() * 5);
}

TEST(Sweep, AnObliqueExtrusionIsSweptAlongItsVector) {
  const TopoDS_Shape plate = holed_plate(gp_Vec(3, -2, 10));
  SweepOptions options;
  options.face.size = 5.0;
  const SweepResult r = sweep_shape(plate, options);
  expect_valid_sweep(plate, r, 10.0);
  EXPECT_NEAR(r.mesh.solids[0].height, std::sqrt(9.0 + 4.0 + 100.0), 1e-9);
}

TEST(Sweep, GivenCapsAreUsedAndWrongOnesNamed) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 20, 30).Shape();
  SweepOptions options;
  options.face.size = 5.0;
  const SweepResult any = sweep_shape(box, options);
  expect_valid_sweep(box, any);
  // Faces 0 and 1 of a box are its x = 0 and x = 10 sides.
  options.source = 0;
  options.target = 1;
  const SweepResult along_x = sweep_shape(box, options);
  expect_valid_sweep(box, along_x);
  EXPECT_EQ(along_x.mesh.solids[0].source, 0);
  EXPECT_EQ(along_x.mesh.solids[0].layers, 2);
  options.target = 2;  // a neighbour, not the opposite face
  try {
    sweep_shape(box, options);
    FAIL() << "faces 0 and 2 accepted as caps";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face 0 and face 2 are not the caps"), std::string::npos) << e.what();
  }
  options.target = -1;
  EXPECT_THROW(sweep_shape(box, options), InputError);  // the source alone
  options.source = 7;
  options.target = 0;
  EXPECT_THROW(sweep_shape(box, options), InputError);  // no face 7
}

TEST(Sweep, SolidsThatAreNotExtrusionsAreRefusedWithTheReason) {
  const TopoDS_Shape sphere = BRepPrimAPI_MakeSphere(5).Shape();
  SweepOptions options;
  try {
    sweep_shape(sphere, options);
    FAIL() << "a sphere swept";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("solid 0 is not sweepable"), std::string::npos) << e.what();
  }
  // A box with a corner scooped out by a ball: no direction has caps and straight sides.
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 10, 10).Shape();
  const TopoDS_Shape cut = BRepAlgoAPI_Cut(box, BRepPrimAPI_MakeSphere(gp_Pnt(10, 10, 10), 4).Shape()).Shape();
  try {
    sweep_shape(cut, options);
    FAIL() << "a box with a scooped corner swept";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not sweepable"), std::string::npos) << e.what();
  }
  // With keep_going the extrusion beside them is swept, and they are listed.
  TopoDS_Compound both;
  BRep_Builder builder;
  builder.MakeCompound(both);
  builder.Add(both, BRepBuilderAPI_Transform(sphere, gp_Trsf()).Shape());
  gp_Trsf away;
  away.SetTranslation(gp_Vec(100, 0, 0));
  builder.Add(both, BRepBuilderAPI_Transform(holed_plate(), away).Shape());
  options.keep_going = true;
  options.face.size = 4.0;
  const SweepResult r = sweep_shape(both, options);
  ASSERT_EQ(r.mesh.solids.size(), 1u);
  EXPECT_EQ(r.mesh.solids[0].solid, 1);
  ASSERT_EQ(r.mesh.refused.size(), 1u);
  EXPECT_EQ(r.mesh.refused[0].solid, 0);
  EXPECT_NE(r.mesh.refused[0].reason.find("not sweepable"), std::string::npos) << r.mesh.refused[0].reason;
  for (double sj : r.mesh.scaled_jacobian) EXPECT_GT(sj, 1e-6);
  // Only the sphere: nothing swept is an error, keep_going or not.
  EXPECT_THROW(sweep_shape(sphere, options), InputError);
  // Faces alone are no solid.
  EXPECT_THROW(sweep_shape(BRepBuilderAPI_MakeFace(gp_Pln(), 0, 1, 0, 1).Face(), options), InputError);
}

// A profile in the xz plane (x from r0 to r0 + 10, z from 0 to 10, a hole of radius 2
// in its middle) turned by `angle` about the z axis.
TopoDS_Shape revolved(double angle, double r0 = 10.0) {
  BRepBuilderAPI_MakeWire outer;
  const gp_Pnt c[4] = {{r0, 0, 0}, {r0 + 10, 0, 0}, {r0 + 10, 0, 10}, {r0, 0, 10}};
  for (int i = 0; i < 4; ++i) outer.Add(BRepBuilderAPI_MakeEdge(c[i], c[(i + 1) % 4]).Edge());
  BRepBuilderAPI_MakeFace face(outer.Wire());
  const gp_Circ circle(gp_Ax2(gp_Pnt(r0 + 5, 0, 5), gp_Dir(0, 1, 0)), 2);
  // The outer wire runs clockwise about +y (the face's normal is -y): the hole's
  // circle about +y already runs the other way round.
  face.Add(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle).Edge()).Wire());
  return BRepPrimAPI_MakeRevol(face.Face(), gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), angle).Shape();
}

TEST(Sweep, PartialRevolutionsAreSweptByTheExactRotation) {
  for (double degrees : {90.0, 180.0, 270.0}) {
    SCOPED_TRACE(std::to_string(degrees) + " degrees");
    const double angle = degrees * M_PI / 180;
    const TopoDS_Shape ring = revolved(angle);
    Bnd_Box box;
    BRepBndLib::Add(ring, box);
    SweepOptions options;
    options.face.size = std::sqrt(box.SquareExtent()) / 50;  // the size the 1% below holds at
    const SweepResult r = sweep_shape(ring, options);
    ASSERT_EQ(r.mesh.solids.size(), 1u);
    const SweptSolid& s = r.mesh.solids[0];
    EXPECT_TRUE(s.rotation);
    EXPECT_NEAR(std::abs(s.angle), angle, 1e-9);
    EXPECT_NEAR(std::abs(s.vector.z), 1.0, 1e-12);
    EXPECT_NEAR(std::hypot(s.point.x, s.point.y), 0.0, 1e-9);
    // The longest path (radius 20) over the size.
    EXPECT_EQ(s.layers, static_cast<int>(std::lround(20 * angle / options.face.size)));
    for (double sj : r.mesh.scaled_jacobian) ASSERT_GT(sj, 0.2);
    expect_conforming(r.mesh);
    // Each layer is the one before it turned by angle / layers about z: the same radius
    // and height, the polar angle one step on.
    const double step = angle / s.layers;
    for (const Hex& h : r.mesh.hexes) {
      for (int i = 0; i < 4; ++i) {
        const Vec3 a = r.mesh.nodes[h[i]], b = r.mesh.nodes[h[i + 4]];
        ASSERT_NEAR(std::hypot(a.x, a.y), std::hypot(b.x, b.y), 1e-9 * 30);
        ASSERT_NEAR(a.z, b.z, 1e-9 * 30);
        const double turned = std::remainder(std::atan2(b.y, b.x) - std::atan2(a.y, a.x), 2 * M_PI);
        ASSERT_NEAR(std::abs(turned), step, 1e-9);
      }
    }
    // Chords inside the arcs and a polygon inside the hole: within 1% of the volume.
    EXPECT_NEAR(hexes_volume(r.mesh, s), volume_of(ring), 0.01 * volume_of(ring));
  }
}

TEST(Sweep, SecondOrderPutsEdgeMiddlesOnTheGeometryAndThePaths) {
  const TopoDS_Shape ring = revolved(M_PI / 2);
  SweepOptions options;
  options.face.size = 2.0;
  options.face.order = 2;
  const SweepResult r = sweep_shape(ring, options);
  ASSERT_TRUE(r.mesh.second_order());
  ASSERT_EQ(r.mesh.mid_nodes.size(), r.mesh.hexes.size());
  const SweptSolid& s = r.mesh.solids[0];
  const double half_step = M_PI / 2 / s.layers / 2;
  for (std::size_t k = 0; k < r.mesh.hexes.size(); ++k) {
    ASSERT_GT(r.mesh.jacobian_ratio[k], 0.0) << "hexahedron " << k;
    for (int i = 0; i < 4; ++i) {
      // The middle of the edge from corner i to corner i + 4: on the corner's arc,
      // half a layer on.
      const Vec3 a = r.mesh.nodes[r.mesh.hexes[k][i]], m = r.mesh.nodes[r.mesh.mid_nodes[k][8 + i]];
      ASSERT_NEAR(std::hypot(a.x, a.y), std::hypot(m.x, m.y), 1e-9);
      ASSERT_NEAR(a.z, m.z, 1e-9);
      ASSERT_NEAR(std::abs(std::remainder(std::atan2(m.y, m.x) - std::atan2(a.y, a.x), 2 * M_PI)), half_step, 1e-9);
      // A layer's edge middle is the source's (on its face's curve or surface), turned.
      const Vec3 b = r.mesh.nodes[r.mesh.hexes[k][(i + 1) % 4]], mb = r.mesh.nodes[r.mesh.mid_nodes[k][i]];
      ASSERT_LT(distance(mb, 0.5 * (a + b)), 0.5 * distance(a, b));
    }
  }
  // Each side face's node set holds its edge middles too: the hole's wall (a piece of
  // torus, the one face neither plane nor cylinder) has every node at distance 2 from
  // the hole's centre circle.
  const ShapeIndex index(ring);
  int tori = 0;
  for (const auto& [face, nodes] : r.mesh.face_nodes) {
    const GeomAbs_SurfaceType type = BRepAdaptor_Surface(index.face(face)).GetType();
    if (type == GeomAbs_Plane || type == GeomAbs_Cylinder) continue;
    ++tori;
    EXPECT_GT(nodes.size(), 3u * (s.layers + 1));
    for (NodeId n : nodes) {
      const Vec3 p = r.mesh.nodes[n];
      ASSERT_NEAR(std::hypot(std::hypot(p.x, p.y) - 15.0, p.z - 5.0), 2.0, 1e-6) << "node " << n;
    }
  }
  EXPECT_EQ(tori, 1);
}

TEST(Sweep, RevolutionsThatTouchTheirAxisAreRefused) {
  SweepOptions options;
  options.face.size = 2.0;
  try {
    const SweepResult r = sweep_shape(revolved(M_PI / 2, 0.0), options);
    FAIL() << "a profile on the axis swept: " << r.mesh.hexes.size() << " hexahedra";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("touches the axis of its revolution"), std::string::npos) << e.what();
  }
  // A ball: every face turns about an axis, but its profile (a half disk) touches it.
  try {
    sweep_shape(BRepPrimAPI_MakeSphere(5).Shape(), options);
    FAIL() << "a ball swept";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("touches the axis"), std::string::npos) << e.what();
  }
}

TEST(Sweep, AFullRevolutionIsItsProfileTurnedAllTheWayRound) {
  // The profile with a hole turned a full turn: no caps, so its section by a half-plane
  // through the axis is meshed and turned, the last layer joined to the first.
  const TopoDS_Shape ring = revolved(2 * M_PI);
  Bnd_Box box;
  BRepBndLib::Add(ring, box);
  SweepOptions options;
  options.face.size = std::sqrt(box.SquareExtent()) / 50;
  const SweepResult r = sweep_shape(ring, options);
  ASSERT_EQ(r.mesh.solids.size(), 1u);
  const SweptSolid& s = r.mesh.solids[0];
  EXPECT_EQ(s.source, -1);
  EXPECT_TRUE(s.rotation);
  EXPECT_NEAR(std::abs(s.angle), 2 * M_PI, 1e-12);
  EXPECT_EQ(s.layers, static_cast<int>(std::lround(2 * M_PI * 20 / options.face.size)));
  for (double sj : r.mesh.scaled_jacobian) ASSERT_GT(sj, 0.2);
  expect_conforming(r.mesh);
  // Every node in a hexahedron and none twice: the layers close on the first.
  std::set<NodeId> used;
  for (const Hex& h : r.mesh.hexes) used.insert(h.begin(), h.end());
  EXPECT_EQ(used.size(), r.mesh.nodes.size());
  EXPECT_EQ(r.mesh.nodes.size() % s.layers, 0u);
  EXPECT_NEAR(hexes_volume(r.mesh, s), volume_of(ring), 0.01 * volume_of(ring));
  // Each of its five faces (outer and inner walls, top, bottom, the hole's torus) has
  // its nodes, in every layer.
  EXPECT_EQ(r.mesh.face_nodes.size(), 5u);
  for (const auto& [face, nodes] : r.mesh.face_nodes) {
    EXPECT_EQ(nodes.size() % s.layers, 0u) << "face " << face;
    EXPECT_GE(nodes.size(), 2u * s.layers) << "face " << face;
  }
}

// Lofts and pipes: the general route (projected_sweep.h).

// A square of side `side` centred on the z axis at height z, turned by `degrees`.
TopoDS_Wire square(double side, double z, double degrees) {
  BRepBuilderAPI_MakePolygon polygon;
  const double a = degrees * M_PI / 180, h = side / 2;
  const double corners[4][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
  for (const auto& c : corners) {
    polygon.Add(gp_Pnt(c[0] * std::cos(a) - c[1] * std::sin(a), c[0] * std::sin(a) + c[1] * std::cos(a), z));
  }
  polygon.Close();
  return polygon.Wire();
}

TopoDS_Shape loft(const TopoDS_Wire& bottom, const TopoDS_Wire& top, bool ruled) {
  BRepOffsetAPI_ThruSections sections(true, ruled);
  sections.AddWire(bottom);
  sections.AddWire(top);
  sections.Build();
  return sections.Shape();
}

double diagonal_of(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return std::sqrt(box.SquareExtent());
}

// One solid swept by the general route at D / 50: no hexahedron inverted, the boundary
// conforming, the volume within 1% of the solid's, the target's nodes on its face.
SweepResult expect_projected_sweep(const TopoDS_Shape& shape, int order = 1) {
  SweepOptions options;
  options.face.size = diagonal_of(shape) / 50;
  options.face.order = order;
  const SweepResult r = sweep_shape(shape, options);
  EXPECT_EQ(r.mesh.solids.size(), 1u);
  if (r.mesh.solids.size() != 1) return r;
  const SweptSolid& s = r.mesh.solids[0];
  EXPECT_TRUE(s.projected);
  EXPECT_GE(s.layers, 1);
  for (double sj : r.mesh.scaled_jacobian) EXPECT_GT(sj, 1e-6);
  for (double ratio : r.mesh.jacobian_ratio) EXPECT_GT(ratio, 1e-6);
  expect_conforming(r.mesh);
  EXPECT_NEAR(hexes_volume(r.mesh, s), volume_of(shape), 0.01 * volume_of(shape));
  const ShapeIndex index(shape);
  const double tol = 1e-6 * diagonal_of(shape);
  for (const auto& [face, nodes] : r.mesh.face_nodes) {
    if (face != s.target && face != s.source) continue;
    for (std::size_t k = 0; k < nodes.size(); k += 7) {
      const Vec3& p = r.mesh.nodes[nodes[k]];
      BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(gp_Pnt(p.x, p.y, p.z)).Vertex(), index.face(face));
      EXPECT_LE(d.Value(), tol) << "a node of cap face " << face;
    }
  }
  return r;
}

TEST(Sweep, TwistedAndScaledLoftsAreSweptByProjection) {
  for (const bool ruled : {true, false}) {
    for (const double turn : {0.0, 30.0, 60.0}) {
      SCOPED_TRACE(std::string(ruled ? "ruled" : "smooth") + " loft turned " + std::to_string(turn));
      expect_projected_sweep(loft(square(20, 0, 0), square(12, 20, turn), ruled));
    }
  }
  // Outlines whose edges lie on each other's lines and circles (a notched plate; a
  // barrel cut by two arcs of one circle): each boundary node goes up its own edge's
  // side, not up a side whose edge's line or circle passes through it.
  const auto scaled = [](const TopoDS_Wire& w, double scale, double z) {
    gp_Trsf t;
    t.SetScale(gp_Pnt(0, 0, 0), scale);
    gp_Trsf up;
    up.SetTranslation(gp_Vec(0, 0, z));
    return TopoDS::Wire(BRepBuilderAPI_Transform(w, up * t, true).Shape());
  };
  BRepBuilderAPI_MakePolygon notched;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {-15, -10}, {15, -10}, {15, 10}, {5, 10}, {5, 0}, {-5, 0}, {-5, 10}, {-15, 10}}) {
    notched.Add(gp_Pnt(x, y, 0));
  }
  notched.Close();
  SCOPED_TRACE("notched outline");
  expect_projected_sweep(loft(notched.Wire(), scaled(notched.Wire(), 0.6, 20), true));
  const gp_Circ round(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), std::hypot(4.0, 12.0));
  BRepBuilderAPI_MakeWire barrel;
  barrel.Add(BRepBuilderAPI_MakeEdge(round, gp_Pnt(4, 12, 0), gp_Pnt(-4, 12, 0)).Edge());
  barrel.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(-4, 12, 0), gp_Pnt(-4, -12, 0)).Edge());
  barrel.Add(BRepBuilderAPI_MakeEdge(round, gp_Pnt(-4, -12, 0), gp_Pnt(4, -12, 0)).Edge());
  barrel.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(4, -12, 0), gp_Pnt(4, 12, 0)).Edge());
  SCOPED_TRACE("barrel outline");
  expect_projected_sweep(loft(barrel.Wire(), scaled(barrel.Wire(), 0.6, 20), true));
  // Circles of two radii, off axis: a slanted truncated cone.
  const gp_Circ bottom(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 10);
  const gp_Circ top(gp_Ax2(gp_Pnt(4, 0, 15), gp_Dir(0, 0, 1)), 5);
  const auto circle_wire = [](const gp_Circ& c) { return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(c).Edge()).Wire(); };
  SCOPED_TRACE("slanted cone");
  expect_projected_sweep(loft(circle_wire(bottom), circle_wire(top), true), 2);
}

TEST(Sweep, ALoftWithAHoleThroughItKeepsTheHole) {
  const TopoDS_Shape tapered = loft(square(20, 0, 0), square(16, 20, 20), true);
  const TopoDS_Shape holed =
      BRepAlgoAPI_Cut(tapered, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -5), gp_Dir(0, 0, 1)), 3, 30).Shape()).Shape();
  const SweepResult r = expect_projected_sweep(holed);
  ASSERT_EQ(r.mesh.face_nodes.size(), 7u);  // 2 caps, 4 sides, the hole's wall
}

TEST(Sweep, APipeAlongACurveIsSweptByProjection) {
  TColgp_Array1OfPnt through(1, 4);
  through(1) = gp_Pnt(0, 0, 0);
  through(2) = gp_Pnt(2, 0, 15);
  through(3) = gp_Pnt(10, 0, 30);
  through(4) = gp_Pnt(25, 0, 38);
  const Handle(Geom_BSplineCurve) path = GeomAPI_PointsToBSpline(through).Curve();
  const TopoDS_Wire spine = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(path).Edge()).Wire();
  const TopoDS_Face profile = BRepBuilderAPI_MakeFace(square(6, 0, 0)).Face();
  BRepOffsetAPI_MakePipe pipe(spine, profile);
  pipe.Build();
  ASSERT_TRUE(pipe.IsDone());
  expect_projected_sweep(pipe.Shape());
}

TEST(Sweep, SidesThatAreNotFourSidedOrStackedAreNamed) {
  // A pyramid's sides are triangles.
  const TopoDS_Shape pyramid = BRepPrimAPI_MakeWedge(10, 10, 10, 5, 5, 5, 5).Shape();
  SweepOptions options;
  try {
    sweep_shape(pyramid, options);
    FAIL() << "a pyramid swept";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("faces that are not four-sided"), std::string::npos) << e.what();
  }
}

TEST(Sweep, SidesStackedAlongTheSweepGetTheirShareOfTheLayers) {
  // A loft through three squares: each side is two faces, one above the other.
  BRepOffsetAPI_ThruSections three(true, true);
  three.AddWire(square(20, 0, 0));
  three.AddWire(square(16, 10, 10));
  three.AddWire(square(12, 30, 20));
  three.Build();
  const SweepResult r = expect_projected_sweep(three.Shape());
  ASSERT_EQ(r.mesh.solids.size(), 1u);
  const SweptSolid& s = r.mesh.solids[0];
  EXPECT_EQ(r.mesh.face_nodes.size(), 10u);  // 2 caps, 8 sides
  // The upper sides are twice as long: about two thirds of the layers.
  EXPECT_GE(s.layers, 3);
  // A plate with a countersunk hole: the hole's wall is a cone above a cylinder, the
  // outer sides one face each.
  const TopoDS_Shape plate = BRepPrimAPI_MakeBox(gp_Pnt(-20, -20, 0), 40, 40, 10).Shape();
  const TopoDS_Shape bore = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -1), gp_Dir(0, 0, 1)), 4, 12).Shape();
  const TopoDS_Shape sink = BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(0, 0, 6), gp_Dir(0, 0, 1)), 4, 8, 4).Shape();
  const TopoDS_Shape countersunk = BRepAlgoAPI_Cut(BRepAlgoAPI_Cut(plate, bore).Shape(), sink).Shape();
  SCOPED_TRACE("countersunk plate");
  const SweepResult c = expect_projected_sweep(countersunk);
  ASSERT_EQ(c.mesh.face_nodes.size(), 8u);  // 2 caps, 4 sides, the bore and the cone
}

TEST(Sweep, SolidsSharingACapShareItsNodes) {
  // Two plates with holes, one on the other, as two solids sharing the face between.
  const TopoDS_Shape lower = holed_plate();
  gp_Trsf up;
  up.SetTranslation(gp_Vec(0, 0, 8));
  const TopoDS_Shape upper = BRepBuilderAPI_Transform(holed_plate(), up).Shape();
  BRepAlgoAPI_BuilderAlgo fuse;
  TopTools_ListOfShape arguments;
  arguments.Append(lower);
  arguments.Append(upper);
  fuse.SetArguments(arguments);
  fuse.Build();
  ASSERT_TRUE(fuse.IsDone());
  SweepOptions options;
  options.face.size = 4.0;
  for (int order : {1, 2}) {
    SCOPED_TRACE("order " + std::to_string(order));
    options.face.order = order;
    const SweepResult r = sweep_shape(fuse.Shape(), options);
    ASSERT_EQ(r.mesh.solids.size(), 2u);
    EXPECT_TRUE(r.mesh.unshared_faces.empty());
    for (double sj : r.mesh.scaled_jacobian) ASSERT_GT(sj, 1e-6);
    // No two nodes at one point: the face between is one layer of nodes.
    std::set<std::array<double, 3>> points;
    for (const Vec3& p : r.mesh.nodes) points.insert({p.x, p.y, p.z});
    EXPECT_EQ(points.size(), r.mesh.nodes.size());
    // Its quads are each in two hexahedra, one of each solid.
    long long between = 0;
    for (const auto& [key, count] : quad_face_uses(r.mesh)) {
      ASSERT_LE(count, 2);
      const bool at_eight = std::all_of(key.begin(), key.end(), [&](NodeId n) { return std::abs(r.mesh.nodes[n].z - 8) < 1e-9; });
      if (at_eight) {
        EXPECT_EQ(count, 2);
        ++between;
      }
    }
    EXPECT_EQ(between, r.mesh.solids[0].hex_count / r.mesh.solids[0].layers);
    if (order == 1) {  // the polygons of the holes' nodes: corners only
      EXPECT_NEAR(hexes_volume(r.mesh, r.mesh.solids[0]) + hexes_volume(r.mesh, r.mesh.solids[1]),
                  2 * polygonal_volume(holed_plate(), sweep_shape(holed_plate(), options), 6.0, 8.0), 1e-6);
    }
  }
}

TEST(Sweep, HexahedronMeasures) {
  std::array<Vec3, 8> cube{Vec3{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  EXPECT_NEAR(hex_scaled_jacobian(cube), 1.0, 1e-12);
  EXPECT_NEAR(hex_volume(cube), 1.0, 1e-12);
  std::array<Vec3, 8> flipped = cube;
  std::swap(flipped[1], flipped[3]);
  std::swap(flipped[5], flipped[7]);
  EXPECT_LT(hex_scaled_jacobian(flipped), 0);
  EXPECT_NEAR(hex_volume(flipped), -1.0, 1e-12);
  std::array<Vec3, 8> sheared = cube;
  for (int i = 4; i < 8; ++i) sheared[i].x += 1;  // 45 degrees
  EXPECT_NEAR(hex_scaled_jacobian(sheared), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(hex_volume(sheared), 1.0, 1e-12);
}

}  // namespace
}  // namespace tquad
