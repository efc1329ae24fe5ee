// Second-order quads: a node in the middle of every quad edge, on the geometry.
//
// On a CAD edge the middle node is the edge's curve at the middle parameter of the
// segment, made once per segment, so the faces on both sides share it (conforming,
// and on the curve: a hole's rim stays round). Inside a face it is the surface at the
// middle of the two nodes' mesh coordinates ((u, v), or polar (x, y) around a pole),
// shared by the two quads of that edge. Where a curved middle would fold a thin quad,
// the quad's edges are made straight.
#pragma once

#include <vector>

#include "core/mesh/shape_mesh.h"
#include "occ/intervals/edge_discretization.h"
#include "occ/face/face_mesher.h"
#include "occ/model/shape_index.h"

namespace tquad {

// Fills mesh.mid_nodes (one entry per quad) and appends the middle nodes to
// mesh.nodes. `face_meshes[r]` is the result whose quads are mesh.faces[r]'s, in the
// same order (local numbering: FaceMeshResult); `edges` the CAD edges' nodes, whose
// ids `node_id` turns into the mesh's (-1: a node the mesh dropped). The
// order of the new nodes follows the quads, so the output does not depend on threads.
// A quad that its curved middles would fold (quadratic_quad.h: a scaled Jacobian at
// or below 0 somewhere) gets straight edges instead; returns how many middles were
// put back on their chords that way.
long long add_mid_edge_nodes(const ShapeIndex& index, const std::vector<EdgeNodes>& edges,
                             const std::vector<NodeId>& node_id,
                             const std::vector<const FaceMeshResult*>& face_meshes, ShapeMesh& mesh);

}  // namespace tquad
