// Refused faces come with a code and the face's vertices, so front ends (the FreeCAD
// workbench above all) act on records instead of parsing messages; without
// keep_going the job stops with FacesRefusedError carrying the same records.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Circle.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Circ.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/input_error.h"
#include "generated_parts.h"
#include "occ/intervals/edge_discretization.h"
#include "occ/model/shape_index.h"
#include "occ/shape_mesher.h"

namespace tquad {
namespace {

// A box and, apart from it, a drilled cone (generated_parts.h): the cone's side
// face (a pole and a hole) is one the mesher does not handle; the other faces mesh.
TopoDS_Shape box_and_drilled_cone() {
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  builder.Add(compound, BRepPrimAPI_MakeBox(10.0, 10.0, 10.0).Shape());
  builder.Add(compound, drilled_cone(30.0, 0.0, 0.0));
  return compound;
}

// The cone's side face: the one face after the box's six with a degenerate edge.
int cone_face(const TopoDS_Shape& shape) {
  const ShapeIndex index(shape);
  for (int f = 6; f < index.face_count(); ++f) {
    for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) {
      if (BRep_Tool::Degenerated(TopoDS::Edge(it.Current()))) return f;
    }
  }
  return -1;
}

TEST(FaceRefusals, KeepGoingListsTheRefusedFaceWithItsCodeAndVertices) {
  const TopoDS_Shape shape = box_and_drilled_cone();
  ShapeMeshOptions options;
  options.keep_going = true;
  const ShapeMeshResult result = mesh_shape(shape, options);
  const ShapeIndex index(shape);
  ASSERT_EQ(result.mesh.faces.size(), static_cast<std::size_t>(index.face_count() - 1));
  ASSERT_EQ(result.mesh.refused_faces.size(), 1u);
  const RefusedFace& refused = result.mesh.refused_faces[0];
  EXPECT_EQ(refused.face, cone_face(shape));
  EXPECT_EQ(refused.code, RefusalCode::not_supported) << refused.reason;
  EXPECT_STREQ(refusal_code_name(refused.code), "not_supported");
  EXPECT_EQ(refused.reason.find("--"), std::string::npos) << "no command-line advice: " << refused.reason;
  // The cone face's wires pass through vertices of the cone only, which come after
  // the box's eight; its tip is one of them.
  std::vector<int> vertices = refused.vertices;
  ASSERT_FALSE(vertices.empty());
  for (int v : vertices) EXPECT_GE(v, 8);
  bool tip = false;
  for (int v : vertices) tip = tip || BRep_Tool::Pnt(index.vertex(v)).Distance(gp_Pnt(30.0, 0.0, 0.0)) < 1e-9;
  EXPECT_TRUE(tip) << "the cone's tip is among the refused face's vertices";
}

TEST(FaceRefusals, WithoutKeepGoingTheErrorCarriesTheRecords) {
  const TopoDS_Shape shape = box_and_drilled_cone();
  try {
    mesh_shape(shape, ShapeMeshOptions{});
    ADD_FAILURE() << "a refused face did not stop the job";
  } catch (const FacesRefusedError& e) {
    ASSERT_EQ(e.refused().size(), 1u);
    EXPECT_EQ(e.refused()[0].face, cone_face(shape));
    EXPECT_EQ(e.refused()[0].code, RefusalCode::not_supported);
    const std::string message = e.what();
    EXPECT_NE(message.find("1 face(s) refused"), std::string::npos) << message;
    EXPECT_EQ(message.find("--keep-going"), std::string::npos) << "each front end words its own advice: " << message;
  }
}

// A 10 mm box whose first edge's 3D curve is a parabola through the same ends with
// its middle pole 1e5 away, as a damaged file's B-spline pole; its two faces'
// surfaces are as before.
TopoDS_Shape box_with_a_stray_edge(int& stray) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10.0, 10.0, 10.0).Shape();
  const ShapeIndex index(box);
  stray = 0;
  const TopoDS_Edge edge = TopoDS::Edge(index.edge(stray));
  TopoDS_Vertex first, last;
  TopExp::Vertices(edge, first, last, true);
  const gp_Pnt a = BRep_Tool::Pnt(first), b = BRep_Tool::Pnt(last);
  TColgp_Array1OfPnt poles(1, 3);
  poles(1) = a;
  poles(2) = gp_Pnt(0.5 * (a.X() + b.X()) + 1e5, 0.5 * (a.Y() + b.Y()) + 1e5, 0.5 * (a.Z() + b.Z()));
  poles(3) = b;
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0;
  knots(2) = 1;
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities(1) = multiplicities(2) = 3;
  BRep_Builder builder;
  builder.UpdateEdge(edge, new Geom_BSplineCurve(poles, knots, multiplicities, 2), 1e-7);
  builder.Range(edge, 0.0, 1.0, true);
  return box;
}

TEST(FaceRefusals, AnEdgeStrayingFarOutOfTheFacesBoxIsUnusable) {
  // A random edit of an IGES file moved a B-spline edge's pole 400 km out of a shape
  // 2.6 m across; the command worked 84 s before its arc-length spacing failed the
  // whole job. Its B-spline faces' box (BRepBndLib takes their surfaces) did not hold it;
  // a planar face's box takes its edges, so here the faces' box is given: the box
  // the 10 mm cube's faces span.
  const Box3 faces_box{{0, 0, 0}, {10, 10, 10}};
  const ShapeIndex whole(BRepPrimAPI_MakeBox(10.0, 10.0, 10.0).Shape());
  EXPECT_TRUE(unusable_edges(whole, faces_box).empty());
  int stray = 0;
  const ShapeIndex index(box_with_a_stray_edge(stray));
  const auto unusable = unusable_edges(index, faces_box);
  ASSERT_EQ(unusable.size(), 1u);
  EXPECT_EQ(unusable.begin()->first, stray);
  EXPECT_EQ(unusable.begin()->second, "strays 7.07e+04 out of the shape's bounding box, which is 17.3 across");
}

TEST(FaceRefusals, AVertexWhoseToleranceBridgesAWideGapMakesItsEdgesUnusable) {
  // A random edit of a part's STEP file moved a vertex's point 1e6 away; OpenCASCADE's
  // healing widened the vertex's tolerance to reach its edges, and the part was
  // meshed with a spike to that point. Here one corner of the 10 mm cube gets a
  // tolerance of 2 (12% of its 17.3 across): its three edges are unusable; the same
  // cube with 0.1 (0.6%) keeps them all.
  const TopoDS_Shape cube = BRepPrimAPI_MakeBox(10.0, 10.0, 10.0).Shape();
  const ShapeIndex index(cube);
  const Box3 box{{0, 0, 0}, {10, 10, 10}};
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(cube, TopAbs_VERTEX, vertices);
  const TopoDS_Vertex corner = TopoDS::Vertex(vertices(1));
  BRep_Builder builder;
  builder.UpdateVertex(corner, 0.1);
  EXPECT_TRUE(unusable_edges(index, box).empty());
  builder.UpdateVertex(corner, 2.0);
  const auto unusable = unusable_edges(index, box);
  ASSERT_EQ(unusable.size(), 3u);
  const gp_Pnt p = BRep_Tool::Pnt(corner);
  char at[64];
  std::snprintf(at, sizeof at, "(%g, %g, %g)", p.X(), p.Y(), p.Z());
  for (const auto& [edge, why] : unusable) {
    EXPECT_EQ(why, std::string("ends at the vertex at ") + at +
                       ", whose tolerance 2 is over 1% of the shape's 17.3 across: the edges there do not meet");
  }
}

TEST(FaceRefusals, AHoleWhoseEdgesDoNotJoinIsDamaged) {
  // A plate 20 across with a hole of one circle edge whose two ends are two vertices
  // at one point (as a boolean left on a generated part, where OpenCASCADE's wire
  // explorer gave no edge of it and the face was refused as "a hole of only 0
  // segments", as if a smaller size would help). Walked, the hole would close on its
  // first vertex and leave the second alone: a crack.
  const gp_Circ circle(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 3.0);
  BRep_Builder builder;
  TopoDS_Vertex start, end;
  builder.MakeVertex(start, gp_Pnt(3, 0, 0), 1e-7);
  builder.MakeVertex(end, gp_Pnt(3, 0, 0), 1e-7);
  TopoDS_Edge rim;  // (BRepBuilderAPI_MakeEdge refuses to build it)
  builder.MakeEdge(rim, new Geom_Circle(circle), 1e-7);
  builder.Add(rim, start.Oriented(TopAbs_FORWARD));
  builder.Add(rim, end.Oriented(TopAbs_REVERSED));
  builder.Range(rim, 0.0, 2 * M_PI);
  TopoDS_Wire hole;
  builder.MakeWire(hole);
  builder.Add(hole, rim.Reversed());
  TopoDS_Face plate = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakePolygon(gp_Pnt(-10, -10, 0), gp_Pnt(10, -10, 0),
                                                                         gp_Pnt(10, 10, 0), gp_Pnt(-10, 10, 0), true)
                                                  .Wire())
                          .Face();
  plate.Free(true);  // built faces are frozen against changes
  builder.Add(plate, hole);
  ShapeMeshOptions options;
  options.keep_going = true;
  try {
    const ShapeMeshResult result = mesh_shape(plate, options);
    ADD_FAILURE() << "the plate was meshed";
  } catch (const InputError& e) {  // its only face refused: nothing meshed
    const std::string what = e.what();
    EXPECT_NE(what.find("a wire closed by two vertices"), std::string::npos) << what;
  }
}

TEST(FaceRefusals, EveryCodeHasItsOwnName) {
  const RefusalCode codes[] = {RefusalCode::cannot_mesh, RefusalCode::inverted_quads, RefusalCode::too_coarse,
                               RefusalCode::not_supported, RefusalCode::damaged, RefusalCode::internal};
  std::vector<std::string> names;
  for (RefusalCode code : codes) names.push_back(refusal_code_name(code));
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
}

}  // namespace
}  // namespace tquad
