// balance_rings: a face bounded by two loops (an annulus: a washer, a tube's end, a
// shoulder), or by one wire around a seam (a band of a cylinder or a cone cut open
// along its seam: its rims are the wire's runs between the seam's two passes), gets
// equal segment totals on both rims where their lengths are near enough to chain
// (count_fitting.h). Then the one-hole O-grid's halves, or the band, are mapped
// grids; with unequal totals a thin ring, one or two quads across, has no room for
// the templates' transitions and fills with quads at a straight angle (scaled
// Jacobian 0).
//
// Totals change by whole units, the chains (which keeps their faces mapped) or free
// edges: each step takes the unit that closes the gap at the least cost
// (count_cost; between equal costs, the least square of it, so that the steps spread
// over the units), never below an edge's floor, and first the units whose edges all
// stay near their goals (strays_from_goal).
#pragma once

#include <vector>

#include "occ/model/face_wire_edges.h"
#include "occ/model/shape_index.h"

namespace tquad {

// segments: per edge, changed in place; chains: edges kept equal; goal and floor: per
// edge; extent: per edge, its length over the size. Rims are near enough by their
// goals (floors for curvature count: a small hole's rim against its washer's outer
// rim) or by their extents: a refinement round raises the floors of one rim's edges
// (a gear's teeth doubled), and its rim must stay balanced against the other.
// Returns the number of rings balanced.
int balance_rings(FaceWireEdges& wires, const std::vector<char>& meshed, const std::vector<double>& goal,
                  const std::vector<double>& extent, const std::vector<int>& floor, std::vector<int>& segments,
                  const std::vector<std::vector<int>>& chains);

}  // namespace tquad
