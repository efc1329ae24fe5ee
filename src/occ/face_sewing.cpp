#include "occ/face_sewing.h"

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>

namespace tquad {

namespace {

int count_edges(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  return edges.Extent();
}

// The largest tolerance of the edges on one face only (not seams, not degenerated)
// and of their vertices; 0 when there is no such edge.
double widest_free_edge_tolerance(const TopoDS_Shape& shape) {
  TopTools_IndexedDataMapOfShapeListOfShape faces_of_edge;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, faces_of_edge);
  double widest = 0;
  for (int i = 1; i <= faces_of_edge.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(faces_of_edge.FindKey(i));
    if (faces_of_edge(i).Extent() != 1 || BRep_Tool::Degenerated(edge)) continue;
    if (BRep_Tool::IsClosed(edge, TopoDS::Face(faces_of_edge(i).First()))) continue;  // a seam
    TopoDS_Vertex first, last;
    TopExp::Vertices(edge, first, last);
    widest = std::max(widest, BRep_Tool::Tolerance(edge));
    if (!first.IsNull()) widest = std::max(widest, BRep_Tool::Tolerance(first));
    if (!last.IsNull()) widest = std::max(widest, BRep_Tool::Tolerance(last));
  }
  return widest;
}

}  // namespace

SewnShape sew_faces(const TopoDS_Shape& shape) {
  SewnShape result{shape, count_edges(shape), 0};
  result.edges_after = result.edges_before;
  const double tolerance = 4 * widest_free_edge_tolerance(shape);
  if (!(tolerance > 0)) return result;
  BRepBuilderAPI_Sewing sewing(tolerance);
  sewing.Add(shape);
  sewing.Perform();
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopoDS_Compound sewn;
  BRep_Builder builder;
  builder.MakeCompound(sewn);
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Shape& face = faces(i);
    builder.Add(sewn, sewing.IsModifiedSubShape(face) ? sewing.ModifiedSubShape(face) : face);
  }
  result.shape = sewn;
  result.edges_after = count_edges(sewn);
  return result;
}

}  // namespace tquad
