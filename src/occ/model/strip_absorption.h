// Strip absorption: a face narrower than the contraction bound everywhere becomes
// no quads, its two long sides one mesh edge.
//
// A strip (two long sides within kContractedEdgeRatio x size of each other, joined
// at its ends by edges shorter than that, or meeting at a vertex) is what an exporter
// leaves of a tiny fillet or of a boolean's near-coincident faces. Meshed, it is a
// row of rectangles far thinner than long, and its ends keep the faces beside them
// from contracting those short end edges (edge_contraction.h): each such neighbour
// then has a side far shorter than its quads, and a quad there is a triangle in
// effect (is_collapsed). Absorbed, the strip is like an edge: its ends are contracted
// and its long sides share one row of nodes (the kept side's, the merged side's
// (u, v) chart still its own), so the faces on either side meet conforming, with a
// gap no wider than the bound. Meshers remove such small features by a length
// tolerance in the same way.
//
// Only a strip whose sides bound no common face besides it, of one wire with no
// seam, is absorbed; and only when both its ends are contracted (absorb_strips
// checks the vertex groups after contraction).
#pragma once

#include <vector>

#include "occ/model/shape_index.h"

namespace tquad {

struct AbsorbedStrip {
  int face = -1;
  int kept = -1, merged = -1;  // the long sides: merged takes kept's nodes
  bool reversed = false;       // their FORWARD orientations run opposite ways
  double width = 0.0;          // the largest distance found between the two sides
};

// The faces of `meshed` that are strips at element size `size` (the bound is
// kContractedEdgeRatio x size). lengths: each edge's arc length; usable: per edge,
// or empty for all.
std::vector<AbsorbedStrip> strips_to_absorb(const ShapeIndex& index, const std::vector<char>& meshed,
                                            const std::vector<double>& lengths, const std::vector<char>& usable,
                                            double size);

// Contracts the short edges (edges_to_contract, the strips exempt from its strip
// test) and absorbs the strips whose ends that contraction joined; a strip whose
// ends stay apart (an end edge another face keeps) is not absorbed and the
// contraction is done again without it. Returns the strips absorbed, and the edges
// contracted in `contracted`.
std::vector<AbsorbedStrip> contract_and_absorb(ShapeIndex& index, std::vector<AbsorbedStrip> strips,
                                               const std::vector<double>& lengths, const std::vector<char>& usable,
                                               double size, std::vector<int>& contracted);

}  // namespace tquad
