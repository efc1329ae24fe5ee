// assign_even_intervals: make every meshed face's boundary total even by changing
// edge counts by one, the only global constraint of quad meshing (paper, section 1).
//
// Changing an edge's count flips the parity of the (at most two) faces it bounds.
// Odd faces are paired along shortest paths of the face-adjacency graph and every
// edge on the path changes by one, so faces inside the path flip twice and stay even.
// An odd face with no odd partner in reach uses an edge of its own that bounds no
// other meshed face. A closed shell always has an even number of odd faces.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "occ/intervals/edge_discretization.h"
#include "occ/model/face_wire_edges.h"
#include "occ/model/shape_index.h"

namespace tquad {

struct IntervalChange {
  int edge;
  int from, to;
};

// segments: per edge (0 for edges not meshed; a seam edge counts twice in its face).
// meshed: per face. lengths and size choose +1 or -1 (the smaller relative change).
// Returns the changes made; throws InputError naming a face whose parity cannot be
// fixed.
// minimum: per edge (or empty), a count the change may not go below.
std::vector<IntervalChange> assign_even_intervals(const ShapeIndex& index,
                                                  const std::vector<char>& meshed,
                                                  const std::vector<double>& lengths, double size,
                                                  std::vector<int>& segments,
                                                  const std::vector<int>& minimum = {});

// As assign_even_intervals, where each of `chains` (edges kept equal) changes as one
// unit: it flips the parity of the faces holding an odd number of its edges; and
// each of `paired` (two edges of different chains or none, the long sides of a
// band) changes as one unit too, instead of each edge on its own.
std::vector<IntervalChange> make_faces_even(const ShapeIndex& index, const std::vector<char>& meshed,
                                            const std::vector<double>& lengths, double size,
                                            std::vector<int>& segments, const std::vector<int>& minimum,
                                            const std::vector<std::vector<int>>& chains,
                                            const std::vector<std::pair<int, int>>& paired = {});

// Sum of the edge counts along a face's wires (seams twice, degenerate edges 0).
int face_boundary_total(const ShapeIndex& index, int face, const std::vector<int>& segments);

// Raises `floor` (per edge) to kThreeCurveSideMinimum on every edge of a meshed face
// bounded by three edges (one wire; degenerate edges, a pole at a corner, aside), so
// such a face is three quads or more. A quarter disk with its centre collapsed and
// counts 1, 4, 1 (a cylinder's quarter end cap at the default size: the arc raised by
// its neighbour) is three quads, one with a corner of 157.5 degrees on the arc (scaled
// Jacobian 0.38); with 2, 4, 2 it is a 2 x 2 grid.
void raise_three_edge_face_floors(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<int>& floor);

// Raises `floor` on both edges of every loop (outer or hole) of a meshed face made
// of two edges (poles aside), so the loop has 4 segments or more: two curves get 2
// each, a curve closed by a line (a D) 3 and the line 1, so that no corner of the
// loop's quad lies in the middle of the line (180 degrees: a D of 2 and 2 was one
// degenerate quad). Two shallow arcs, as a boolean leaves between two overlapping
// holes or a hole and a fillet, are otherwise one segment each at a size larger than
// them, and a face (or hole) of 2 segments cannot be meshed: such a lens, shorter
// than the size, was refused.
void raise_two_edge_loop_floors(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<int>& floor);

// The whole shape's edge counts chosen together: opposite edges of every face bounded
// by four edges, and the outer and inner circle of a ring face (two wires of one edge
// each), are joined into chains (as in mapped meshing), each chain gets the
// one count that best fits all its edges' length / size (at least every floor), so
// those faces are mapped grids (T0, the best elements) and even by construction;
// bands one segment wide get equal long sides (band_balance.h); the other faces are
// then made even by make_faces_even, changing whole chains or single edges. An edge
// merged into another (ShapeIndex::merged_into) is chained to it unconditionally.
struct IntervalReport {
  std::vector<IntervalChange> changes;  // against the counts given
  int chains = 0;                       // chains of two or more edges
  int chained_edges = 0;
  int balanced_bands = 0;               // faces one segment wide given equal long sides
  int balanced_rings = 0;               // faces of two loops given equal totals (ring_balance.h)
  int quartered_pole_rims = 0;          // disks around a pole given a multiple of 4 (pole_rims.h)
};

// `wires`: the faces' wires (the same shape as `index`); `kept`: edge spacings the
// narrow bands' provisional discretization takes and keeps (discretize_edges), or none.
IntervalReport assign_shape_intervals(const ShapeIndex& index, const std::vector<char>& meshed,
                                      const std::vector<double>& lengths, double size, std::vector<int>& segments,
                                      const std::vector<int>& floor, FaceWireEdges& wires,
                                      EdgeSpacings* kept = nullptr);

}  // namespace tquad
