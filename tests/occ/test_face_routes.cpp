// The face-route registry (face_route.h): each route is one row, offered in a fixed
// order, and the mesh a face keeps names the route that made it.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <gp_Ax2.hxx>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/mesh/quality.h"
#include "occ/face/face_route.h"
#include "occ/model/shape_index.h"
#include "occ/shape_mesher.h"

namespace tquad {
namespace {

// The routes of the kept meshes, by face.
std::map<int, std::string> routes_of(const TopoDS_Shape& shape) {
  ShapeMeshOptions options;
  const ShapeMeshResult result = mesh_shape(shape, options);
  EXPECT_TRUE(result.mesh.refused_faces.empty());
  std::map<int, std::string> routes;
  for (const FaceMesh& f : result.mesh.faces) routes[f.face] = f.route;
  return routes;
}

std::set<std::string> route_set(const std::map<int, std::string>& routes) {
  std::set<std::string> out;
  for (const auto& [face, route] : routes) out.insert(route);
  return out;
}

TEST(FaceRoutes, TheRegistryListsEachRouteOnceInItsOrder) {
  const std::vector<std::string> names = face_route_names();
  const std::vector<std::string> expected{"cube sphere", "mapped ring and O-grid", "templates on corners",
                                          "tip strip",   "polar disk",             "pole sector",
                                          "disk in space", "disk O-grid",          "decomposition"};
  EXPECT_EQ(names, expected);
}

TEST(FaceRoutes, EachFaceNamesTheRouteOfItsMesh) {
  // A box: every face a mapped grid on its own four corners.
  for (const auto& [face, route] : routes_of(BRepPrimAPI_MakeBox(10, 20, 30).Shape())) {
    EXPECT_EQ(route, "templates on corners") << "box face " << face;
  }
  // A full sphere: one face closed around two poles.
  EXPECT_EQ(route_set(routes_of(BRepPrimAPI_MakeSphere(10).Shape())), std::set<std::string>{"cube sphere"});
  // A cylinder: its end disks are O-grids.
  const std::map<int, std::string> cylinder = routes_of(BRepPrimAPI_MakeCylinder(10, 30).Shape());
  EXPECT_EQ(std::count_if(cylinder.begin(), cylinder.end(), [](const auto& r) { return r.second == "disk O-grid"; }),
            2);
  // A cone to its apex: the tip's disk around the pole.
  const std::set<std::string> cone = route_set(routes_of(BRepPrimAPI_MakeCone(10.0, 0.0, 20.0).Shape()));
  EXPECT_TRUE(cone.count("pole sector") || cone.count("polar disk"));
  // A plate with one hole: its faces with the hole a ring or O-grid; with three, the
  // decomposition.
  const TopoDS_Shape plate = BRepPrimAPI_MakeBox(100, 60, 10).Shape();
  const auto hole = [](double x, double y) {
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, -1), gp_Dir(0, 0, 1)), 8, 12).Shape();
  };
  const TopoDS_Shape one = BRepAlgoAPI_Cut(plate, hole(50, 30)).Shape();
  EXPECT_EQ(route_set(routes_of(one)).count("mapped ring and O-grid"), 1u);
  TopoDS_Shape three = BRepAlgoAPI_Cut(plate, hole(20, 30)).Shape();
  three = BRepAlgoAPI_Cut(three, hole(50, 30)).Shape();
  three = BRepAlgoAPI_Cut(three, hole(80, 30)).Shape();
  // (The decomposition's mesh may be the one with its patches' corners searched.)
  const std::set<std::string> decomposed = route_set(routes_of(three));
  EXPECT_TRUE(std::any_of(decomposed.begin(), decomposed.end(),
                          [](const std::string& r) { return r.rfind("decomposition", 0) == 0; }));
}

// A hex head chamfered by a 30-degree cone (a nut's or a cap screw's): the cone's six
// faces each lie between the chamfer circle and two hyperbolas on the flats, with
// tips of a few degrees where the circle meets them. With the circle at 1.04 times the
// flats' distance, its arcs and the hyperbolas below them get equal counts, and each
// cone face is meshed by the tip strip: two rows of quads along it.
TEST(FaceRoutes, AChamferedHexHeadsConeFacesAreTipStrips) {
  const double flat = 5.0, corner = flat / std::cos(M_PI / 6), height = 5.0, chamfer_radius = 5.2;
  BRepBuilderAPI_MakePolygon hexagon;
  // Corners off the cone's seam (at angle 0), which would cut one cone face in two.
  for (int k = 0; k < 6; ++k) {
    const double angle = (k + 0.5) * M_PI / 3;
    hexagon.Add(gp_Pnt(corner * std::cos(angle), corner * std::sin(angle), 0));
  }
  hexagon.Close();
  const TopoDS_Shape prism =
      BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(hexagon.Wire()).Face(), gp_Vec(0, 0, height)).Shape();
  const double drop = std::tan(M_PI / 6);  // the cone falls 30 degrees from the top face
  const double base_radius = chamfer_radius + height / drop;
  const TopoDS_Shape cone = BRepPrimAPI_MakeCone(base_radius, chamfer_radius, height).Shape();
  const TopoDS_Shape head = BRepAlgoAPI_Common(prism, cone).Shape();
  ShapeMeshOptions options;
  const ShapeMeshResult result = mesh_shape(head, options);
  ASSERT_TRUE(result.mesh.refused_faces.empty());
  const ShapeIndex index(head);
  int cone_faces = 0;
  for (const FaceMesh& f : result.mesh.faces) {
    if (BRepAdaptor_Surface(index.face(f.face)).GetType() != GeomAbs_Cone) continue;
    ++cone_faces;
    EXPECT_EQ(f.route, "tip strip") << "face " << f.face << ": " << f.template_tree;
    // Two rows between the tips: 2n - 2 quads for a loop of 2n segments (the edges
    // of one quad only).
    std::map<std::pair<NodeId, NodeId>, int> uses;
    double worst = 1;
    for (std::int64_t q = f.first_quad; q < f.first_quad + f.quad_count; ++q) {
      const Quad& quad = result.mesh.quads[q];
      for (int i = 0; i < 4; ++i) ++uses[std::minmax(quad[i], quad[(i + 1) % 4])];
      const std::array<Vec3, 4> p{result.mesh.nodes[quad[0]], result.mesh.nodes[quad[1]], result.mesh.nodes[quad[2]],
                                  result.mesh.nodes[quad[3]]};
      worst = std::min(worst, own_scaled_jacobian(p));
    }
    const auto loop = std::count_if(uses.begin(), uses.end(), [](const auto& u) { return u.second == 1; });
    EXPECT_EQ(f.quad_count, loop - 2) << "face " << f.face;
    EXPECT_GT(worst, 0.0) << "face " << f.face;
  }
  EXPECT_EQ(cone_faces, 6);
}

}  // namespace
}  // namespace tquad

namespace tquad {
namespace {

// A face mesh as the chooser sees it: its quads' scaled Jacobians and their lowest.
FaceMeshResult measured(std::vector<double> jacobians) {
  FaceMeshResult m;
  m.quads.assign(jacobians.size(), Quad{0, 1, 2, 3});
  m.worst_corner = *std::min_element(jacobians.begin(), jacobians.end());
  m.scaled_jacobian = std::move(jacobians);
  return m;
}

TEST(FaceRoutes, TheLowestCornerIsTakenByEitherNormal) {
  FaceMeshResult warped = measured({0.6, 0.9});
  EXPECT_EQ(lowest_corner(warped), 0.6);
  warped.worst_own = 0.2;
  EXPECT_EQ(lowest_corner(warped), 0.2);
}

TEST(FaceRoutes, AFaceTakesItsHigherMeanMeshOnlyWhereThePartsWorstHolds) {
  std::vector<FaceOutcome> outcomes(6);
  for (FaceOutcome& o : outcomes) o.ok = true;
  // Face 0 holds the part's worst corner, 0.2, and most of its quads (part mean 0.82).
  outcomes[0].mesh = measured({0.2, 0.99, 0.99, 0.99, 0.99, 0.99, 0.99, 0.99, 0.99, 0.99, 0.99, 0.99, 0.99});
  // Face 1: its alternative stays above 0.2 and raises the part's mean: taken.
  outcomes[1].mesh = measured({0.5, 0.6});
  outcomes[1].higher_mean = measured({0.25, 0.95, 0.95});
  // Face 2: its alternative would make a new worst element for the part: not taken.
  outcomes[2].mesh = measured({0.5, 0.6});
  outcomes[2].higher_mean = measured({0.1, 0.99, 0.99, 0.99});
  // Face 3: a higher mean of its own (0.645 against 0.625), but its two quads more
  // add 1.33 to the sum, 0.665 each, under the part's mean: it would fall, not taken.
  outcomes[3].mesh = measured({0.95, 0.3});
  outcomes[3].higher_mean = measured({0.28, 0.7, 0.7, 0.9});
  // Face 4 is not part of the mesh (refused, or not asked for): left as it is.
  outcomes[4].mesh = measured({0.5, 0.6});
  outcomes[4].higher_mean = measured({0.3, 0.95});
  // Face 5: fair against the surface, but a quad warped under the part's worst by its
  // own normal: not taken.
  outcomes[5].mesh = measured({0.5, 0.6});
  outcomes[5].higher_mean = measured({0.3, 0.99, 0.99});
  outcomes[5].higher_mean->worst_own = 0.1;
  const std::vector<char> meshed{1, 1, 1, 1, 0, 1};

  const auto part = [&] {
    double sum = 0, worst = 1;
    long long count = 0;
    for (std::size_t f = 0; f < outcomes.size(); ++f) {
      if (!meshed[f]) continue;
      for (double v : outcomes[f].mesh.scaled_jacobian) sum += v;
      count += static_cast<long long>(outcomes[f].mesh.scaled_jacobian.size());
      worst = std::min(worst, lowest_corner(outcomes[f].mesh));
    }
    return std::pair<double, double>(worst, sum / static_cast<double>(count));
  };
  const auto [worst_before, mean_before] = part();
  EXPECT_EQ(take_higher_means(outcomes, meshed), 1);
  const auto [worst_after, mean_after] = part();
  EXPECT_EQ(worst_after, worst_before);
  EXPECT_GT(mean_after, mean_before);
  EXPECT_EQ(outcomes[1].mesh.scaled_jacobian.size(), 3u);
  EXPECT_EQ(outcomes[2].mesh.worst_corner, 0.5);
  EXPECT_EQ(outcomes[3].mesh.scaled_jacobian.size(), 2u);
  EXPECT_EQ(outcomes[4].mesh.scaled_jacobian.size(), 2u);
  EXPECT_EQ(outcomes[5].mesh.scaled_jacobian.size(), 2u);
  // Every alternative of a meshed face is dropped once decided.
  for (int f : {0, 1, 2, 3, 5}) EXPECT_FALSE(outcomes[f].higher_mean.has_value()) << "face " << f;
}

}  // namespace
}  // namespace tquad
