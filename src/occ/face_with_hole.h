// mesh_face_with_hole: a face with one inner wire (a plate with a hole, a flange).
//
// Two bridges, straight in (u, v), join the hole's rim to the outer wire at roughly
// opposite places and cut the face into two hole-free regions. Each region is a
// four-curve region whose corners are the bridges' ends (an O-grid half: the outer
// part opposite the rim part, bridge opposite bridge), meshed by the templates in
// (u, v) like any face; the bridges' nodes are shared by both halves. Several bridge
// places are tried (from eight points of the rim to their nearest outer nodes); the
// one whose mesh has the fewest inverted quads, then the best worst corner, is kept.
// The face's template tree reads "H2[tree of one half,tree of the other]".
#pragma once

#include <TopoDS_Face.hxx>

#include "core/mesher.h"
#include "occ/face_boundary.h"
#include "occ/face_mesher.h"

namespace tquad {

// Throws InputError when no bridge pair gives two valid regions.
FaceMeshResult mesh_face_with_hole(const TopoDS_Face& face, int face_index, const FaceBoundary& boundary,
                                   const std::vector<Vec3>& nodes, double edge_size,
                                   const MeshOptions& options);

}  // namespace tquad
