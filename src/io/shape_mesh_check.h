// check_shape_mesh: what every mesh writer relies on in a ShapeMesh, checked before a
// byte is written (so a bad mesh never becomes a wrong file):
//   - every node's coordinates are finite (a binary writer would copy a NaN as it is);
//   - every quad's node indices are in [0, nodes.size());
//   - the face records are in quad order and own every quad exactly once: the first
//     starts at quad 0, each next one starts where the previous ended, the last ends at
//     quads.size() (a record may own 0 quads);
//   - face indices are >= 0 and unique; a refused face is >= 0 and not also meshed;
//   - the per-quad quality arrays are empty or hold one value per quad;
//   - at second order, one entry of mid_nodes per quad, valid indices, and one middle
//     node per mesh edge: the same from every quad of the edge, neither a corner nor
//     another edge's middle.
#pragma once

#include "core/mesh/shape_mesh.h"

namespace tquad {

// Throws std::invalid_argument (a std::logic_error: a bad ShapeMesh is a bug of the
// code that built it, not a user's input error) saying which quad or record is wrong.
void check_shape_mesh(const ShapeMesh& mesh);

}  // namespace tquad
