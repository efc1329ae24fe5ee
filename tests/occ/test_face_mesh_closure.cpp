// face_mesh_closure_problem (face_mesh_closure.h): a face's mesh closes on the face's
// own edges, seams inside it.
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>

#include "occ/intervals/edge_discretization.h"
#include "occ/face/face_mesh_closure.h"
#include "occ/face/face_route.h"

namespace tquad {
namespace {

struct MeshedFace {
  ShapeIndex index;
  std::vector<EdgeNodes> edges;
  FaceOutcome outcome;
};

// Face f of `shape` meshed alone with 4 segments on every edge.
void mesh_face_of(const TopoDS_Shape& shape, int f, MeshedFace& out) {
  std::vector<Vec3> nodes;
  out.edges = discretize_edges(out.index, std::vector<int>(out.index.edge_count(), 4), nodes);
  out.outcome = mesh_one_face(out.index, f, out.edges, nodes, ShapeMeshOptions{}, 1.0);
  ASSERT_TRUE(out.outcome.ok) << out.outcome.reason;
}

TEST(FaceMeshClosure, AMeshedFaceClosesOnItsEdges) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 10, 10).Shape();
  MeshedFace m{ShapeIndex(box), {}, {}};
  mesh_face_of(box, 0, m);
  EXPECT_EQ(face_mesh_closure_problem(m.index, 0, m.edges, m.outcome.mesh), "");
  // A cylinder's side: its seam's segments are inside the mesh, in two quads each.
  const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(5, 10).Shape();
  MeshedFace c{ShapeIndex(cylinder), {}, {}};
  mesh_face_of(cylinder, 0, c);
  EXPECT_EQ(face_mesh_closure_problem(c.index, 0, c.edges, c.outcome.mesh), "");
}

TEST(FaceMeshClosure, AMissingQuadOrAQuadTwiceIsFound) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 10, 10).Shape();
  MeshedFace m{ShapeIndex(box), {}, {}};
  mesh_face_of(box, 0, m);
  FaceMeshResult missing = m.outcome.mesh;
  ASSERT_EQ(missing.quads.size(), 16u);
  missing.quads.erase(missing.quads.begin() + 5);  // an inner quad of the 4 x 4 grid or a border one
  const std::string hole = face_mesh_closure_problem(m.index, 0, m.edges, missing);
  EXPECT_NE(hole.find("face 0: "), std::string::npos) << hole;
  EXPECT_TRUE(hole.find("(a crack)") != std::string::npos || hole.find("is in no quad") != std::string::npos) << hole;
  FaceMeshResult twice = m.outcome.mesh;
  twice.quads.push_back(twice.quads.front());
  const std::string folded = face_mesh_closure_problem(m.index, 0, m.edges, twice);
  EXPECT_NE(folded.find("quads"), std::string::npos) << folded;
  EXPECT_NE(folded, "");
}

}  // namespace
}  // namespace tquad
