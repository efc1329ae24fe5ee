// face_mesh_closure_problem: a face's mesh closes on the face's own edges.
//
// Every mesh edge in one quad only is a segment of one of the face's edges (seams,
// met twice, aside: their segments lie inside the mesh), each such segment is in
// exactly one quad, and no mesh edge is in more than two (two edges of one segment
// between the same nodes, a seam given as two edges, make one mesh edge in two). The routes check their
// meshes against the loops they were given; this checks the loops too. A face around
// a pole whose seam passed through a hole was given a loop that jumped from the rim
// to the hole across the face: its mesh passed every other check and left a crack of
// four open edges in a closed solid.
#pragma once

#include <string>
#include <vector>

#include "occ/intervals/edge_discretization.h"
#include "occ/face/face_mesher.h"
#include "occ/model/shape_index.h"

namespace tquad {

// Empty when the mesh closes on the face's edges; else what is wrong, naming a mesh
// edge by its shared nodes.
std::string face_mesh_closure_problem(const ShapeIndex& index, int face, const std::vector<EdgeNodes>& edges,
                                      const FaceMeshResult& mesh);

}  // namespace tquad
