#include "occ/model/face_sewing.h"

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Builder.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>

#include "occ/model/shape_index.h"
#include "occ/model/unsewn_edges.h"

namespace tquad {

SewnShape sew_faces(const TopoDS_Shape& shape) {
  const ShapeIndex index(shape);
  SewnShape result{shape, index.edge_count(), index.edge_count()};
  double tolerance = 0;
  for (const UnsewnEdgePair& pair : unsewn_edge_pairs(index)) tolerance = std::max(tolerance, pair.tolerance);
  if (!(tolerance > 0)) return result;  // no unsewn pair: nothing to sew
  BRepBuilderAPI_Sewing sewing(tolerance);
  sewing.Add(shape);
  sewing.Perform();
  TopoDS_Compound sewn;
  BRep_Builder builder;
  builder.MakeCompound(sewn);
  for (int f = 0; f < index.face_count(); ++f) {
    const TopoDS_Shape& face = index.face(f);
    builder.Add(sewn, sewing.IsModifiedSubShape(face) ? sewing.ModifiedSubShape(face) : face);
  }
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(sewn, TopAbs_EDGE, edges);
  result.shape = sewn;
  result.edges_after = edges.Extent();
  return result;
}

}  // namespace tquad
