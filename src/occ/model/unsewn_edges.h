// unsewn_edge_pairs: where a file's faces touch without sharing their edge.
//
// A STEP file may hold faces that meet along a curve but each with an edge of its own
// there (the faces were not sewn). Each face is then meshed on its own edge, so the
// two meshes meet without sharing nodes: the mesh has a crack there that a solver
// sees as a free boundary. Such pairs are found here
// and reported (a warning and the report's `unsewn_edge_pairs`), never silently.
#pragma once

#include <vector>

#include "occ/model/shape_index.h"

namespace tquad {

struct UnsewnEdgePair {
  int first = 0, second = 0;  // edge indices, first < second
  double tolerance = 0;       // the distance within which they were found to coincide
};

// Pairs of free edges (each on one face only, not a seam, not degenerated) whose end
// points and mid points coincide within the edges' tolerances; in edge order.
std::vector<UnsewnEdgePair> unsewn_edge_pairs(const ShapeIndex& index);

}  // namespace tquad
