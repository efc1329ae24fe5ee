// mesh_face_decomposed: a face of any outline with any number of holes, meshed by the
// face decomposition of core (decomposed_mesher.h) in a chart of its (u, v) space.
//
// The chart is (u, v) scaled by the surface's mean first derivatives |S_u| and |S_v|
// over the face (and mirrored when the outer loop runs clockwise in (u, v)), so that
// lengths and angles there are close to the surface's on cylinders, cones and
// unevenly parametrized B-splines: the decomposition measures angles and lengths. The
// mesh's interior nodes are the surface evaluated at their (u, v). The CAD vertices
// are the boundary points the decomposition may keep as sharp corners.
#pragma once

#include <TopoDS_Face.hxx>

#include "core/mesher.h"
#include "occ/face_boundary.h"
#include "occ/face_mesher.h"

namespace tquad {

// `vertex_nodes`: shared nodes below this id are CAD vertices. Throws InputError
// (naming the face) for a face with a pole, or when the decomposition fails.
FaceMeshResult mesh_face_decomposed(const TopoDS_Face& face, int face_index, const FaceBoundary& boundary,
                                    const std::vector<Vec3>& nodes, int vertex_nodes, double edge_size,
                                    const MeshOptions& options);

}  // namespace tquad
