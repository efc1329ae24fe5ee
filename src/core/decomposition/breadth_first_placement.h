// The order in which a mesh's interior nodes are placed one by one when each needs a
// starting guess from a node already placed (the closest-point search of a template
// mesh's nodes onto a CAD surface): breadth first from the boundary, each node
// started from its placed edge neighbour nearest to it.
#pragma once

#include <cstddef>
#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

struct PlacementStep {
  NodeId node;        // an interior node (index >= boundary_count)
  NodeId start_from;  // an edge neighbour placed before it (a boundary node or an earlier step's)
};

// Every interior node of `nodes` (the first boundary_count are the boundary, placed
// from the start) once, each after one of its edge neighbours; among the placed
// neighbours, start_from is the nearest by `nodes`' positions (ties: the lower index).
// Interior nodes in no quad cannot be reached and are left out.
std::vector<PlacementStep> breadth_first_placement(const std::vector<Vec3>& nodes, const std::vector<Quad>& quads,
                                                   std::size_t boundary_count);

}  // namespace tquad
