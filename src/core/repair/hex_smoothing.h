// smooth_hexahedra: Laplacian smoothing of hexahedra's free nodes that never makes the
// worst hexahedron around a node worse ("smart" Laplacian: a move is kept only when the
// smallest scaled Jacobian of the node's hexahedra does not drop), so a valid mesh
// stays valid and an inverted one untangles where averaging helps.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry/vec3.h"
#include "core/mesh/hex_mesh.h"

namespace tquad {

struct HexSmoothingNode {
  NodeId node = 0;                    // into the nodes
  std::vector<NodeId> neighbours;     // the nodes it is joined to by a hexahedron's edge
  std::vector<std::int64_t> hexes;    // the hexahedra it is a corner of
};

// Up to `passes` passes over `free` (in order), each node moved to its neighbours'
// mean when that keeps or raises the smallest scaled Jacobian of its hexahedra; stops
// early after a pass that moves nothing. Returns the moves kept.
long long smooth_hexahedra(std::vector<Vec3>& nodes, const std::vector<Hex>& hexes,
                           const std::vector<HexSmoothingNode>& free, int passes);

}  // namespace tquad
