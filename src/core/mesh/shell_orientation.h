// orient_shells: every face's quads turned so that faces meeting at an edge agree on
// their normals, as a shell element's top and bottom and a pressure's side need.
//
// Two quads of different faces that share a mesh edge agree when they run along it in
// opposite directions (each quad lists its corners counterclockwise about its normal).
// Faces joined by such edges form a component; within it one face fixes every other
// face's turn by breadth-first propagation. Which way a component faces:
//  - it holds an anchored face (a face of a solid, whose orientation the CAD's solid
//    gives as outward): that face's, and anchored faces are never turned;
//  - it is closed (every mesh edge on its faces' boundaries has a partner) and holds no
//    anchored face: outward, the side that makes its enclosed volume positive;
//  - otherwise (an open shell, a set of faces): the orientation of the larger area.
// An edge three or more faces share (a non-manifold junction) relates none of them.
// Where the propagation meets a face already given the other turn (a one-sided shell,
// such as a Moebius band, or two anchored faces that disagree) the pair is reported
// and the face keeps its first turn.
#pragma once

#include <utility>
#include <vector>

#include "core/mesh/shape_mesh.h"

namespace tquad {

struct ShellOrientation {
  std::vector<int> turned_faces;  // shape face numbers whose quads were reversed, ascending
  // Pairs of shape face numbers (lower first, ascending) that meet along an edge and
  // could not be given normals that agree there.
  std::vector<std::pair<int, int>> conflicts;
};

// Turns the quads (and second-order middle nodes) of faces in `mesh` as above. Nodes
// numbered below `boundary_nodes` are the only ones that may lie on a face's boundary
// (the shape's edge and vertex nodes; faces' interior nodes come after them).
// `anchored[k]` (or empty: none) for mesh.faces[k]. Per-quad measures stay as they are:
// each is taken against the normal its face is given, which turns with the quads.
ShellOrientation orient_shells(ShapeMesh& mesh, NodeId boundary_nodes, const std::vector<char>& anchored);

}  // namespace tquad
