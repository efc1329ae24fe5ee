// The eight-node (serendipity) quadrilateral: corners 0..3, then the middles of edges
// 0-1, 1-2, 2-3 and 3-0 (the order of VTK's quadratic quad and CalculiX's S8), and
// whether its map from the reference square is one-to-one.
#pragma once

#include <array>

#include "core/mesh/shape_mesh.h"
#include "core/geometry/vec3.h"

namespace tquad {

// The smallest scaled Jacobian of the element's map from [-1, 1]^2: at the corners,
// the edge middles, the centre and the 2 x 2 Gauss points, (x_xi x x_eta) . n /
// (|x_xi| |x_eta|) with n the unit normal of the corners' quad (the cross product of
// its diagonals). 1 for a square with straight edges; at or below 0 where a curved
// edge folds the element (a middle node bent past the opposite side of a thin quad),
// which solvers refuse (CalculiX: "nonpositive jacobian").
double quadratic_quad_min_scaled_jacobian(const std::array<Vec3, 8>& nodes);

// Quad k of a second-order mesh: its corners' then its middles' positions.
std::array<Vec3, 8> element_positions(const ShapeMesh& mesh, std::size_t k);

// A middle node on a curved edge can fold a thin quad (the curve bulging past the
// opposite side). Each such quad's middles go back to their chords' middles, shared
// with the quads on the other side of those edges; with straight edges a quad is as
// valid as its corners (valid corners give a positive Jacobian all over), so a few
// passes end it. Returns how many middles were moved.
long long straighten_folded_quads(ShapeMesh& mesh);

}  // namespace tquad
