// sew_faces: the faces of a shape joined along the edges where they touch without
// sharing one (unsewn_edges.h), so those edges are cut once and the mesh is connected
// there.
//
// IGES files from many systems hold trimmed surfaces (type 144) with no topology
// between them: every face comes with edges of its own. Meshed so, each face's mesh
// ends on its own nodes and the mesh falls apart into faces (even a solid written to
// IGES by OpenCASCADE reads back with most of its shared edges unsewn). OpenCASCADE's
// sewing (BRepBuilderAPI_Sewing) merges such edges.
#pragma once

#include <TopoDS_Shape.hxx>

namespace tquad {

struct SewnShape {
  TopoDS_Shape shape;  // a compound of the sewn faces, in the shape's face order
  int edges_before = 0, edges_after = 0;
};

// Sews the unsewn edge pairs (unsewn_edges.h) within the widest distance they were
// found to coincide in, and returns the faces in their order in `shape` (the shape
// index's), so face numbers stay those of the file. A shape without an unsewn pair
// comes back as it is.
SewnShape sew_faces(const TopoDS_Shape& shape);

}  // namespace tquad
