// assign_even_intervals: make every meshed face's boundary total even by changing
// edge counts by one, the only global constraint of quad meshing (paper, section 1).
//
// Changing an edge's count flips the parity of the (at most two) faces it bounds.
// Odd faces are paired along shortest paths of the face-adjacency graph and every
// edge on the path changes by one, so faces inside the path flip twice and stay even.
// An odd face with no odd partner in reach uses an edge of its own that bounds no
// other meshed face. A closed shell always has an even number of odd faces.
#pragma once

#include <string>
#include <vector>

#include "occ/shape_index.h"

namespace tquad {

struct IntervalChange {
  int edge;
  int from, to;
};

// segments: per edge (0 for edges not meshed; a seam edge counts twice in its face).
// meshed: per face. lengths and size choose +1 or -1 (the smaller relative change).
// Returns the changes made; throws InputError naming a face whose parity cannot be
// fixed.
std::vector<IntervalChange> assign_even_intervals(const ShapeIndex& index,
                                                  const std::vector<char>& meshed,
                                                  const std::vector<double>& lengths, double size,
                                                  std::vector<int>& segments);

// Sum of the edge counts along a face's wires (seams twice, degenerate edges 0).
int face_boundary_total(const ShapeIndex& index, int face, const std::vector<int>& segments);

}  // namespace tquad
