// check_disk_mesh: the structural properties every mesh of a disk-like boundary must
// have, checked without geometry tolerances. Used by the tests and by the CLI before
// it writes anything (never a silent bad mesh).
#pragma once

#include <string>
#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

// Returns "" when the mesh is valid, else what is wrong, for a mesh whose first
// `boundary_points` nodes are the boundary loop in order:
//   - node indices in range, four distinct nodes per quad;
//   - conforming and consistently oriented: each directed edge in at most one quad,
//     each interior edge in exactly two (once per direction), and the edges in one
//     quad only are exactly the boundary segments i -> i+1;
//   - every node finite and used; no two nodes at the same position;
//   - V = 1 + F + E/2 (Euler's formula for a disk of quads).
std::string check_disk_mesh(const QuadMesh& mesh, int boundary_points);

// The same for a domain with holes: the first nodes are the loops one after the other
// (loop_sizes[0] outer points, then each hole's), and
// V = 1 + F + E/2 - holes.
std::string check_domain_mesh(const QuadMesh& mesh, const std::vector<int>& loop_sizes);

}  // namespace tquad
