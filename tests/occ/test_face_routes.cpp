// The face-route registry (face_route.h): each route is one row, offered in a fixed
// order, and the mesh a face keeps names the route that made it.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
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
                                          "polar disk",  "pole sector",            "disk in space",
                                          "disk O-grid", "decomposition"};
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

}  // namespace
}  // namespace tquad
