// Edge contraction: edges far shorter than the element size become one node.
//
// A quad with such an edge as a side is a triangle in effect (is_collapsed: its
// Jacobian ratio is about the edge's length over the size), whatever the face's mesh;
// no grading of a template mesh brings the quads beside it down to its length. So
// the edge is contracted, as meshers skip model edges under a length tolerance: its
// two vertices become one mesh node (the group's first vertex), and the edge is no
// side of any face and gets no segment. The faces keep their other edges, and their
// nodes still lie on the CAD model within the edge's length.
//
// Not contracted: an edge closed on a face (a seam), one whose ends are one vertex,
// and one across a strip, a face narrower there than the edge bound (its two sides
// beside the edge run closer than that: a mapped strip of thin rectangles is that
// face's mesh, and contracting its ends would fold it onto itself). Nor one whose
// wire would keep fewer than two edges, nor one that would join vertices further
// apart than the bound (a chain of short edges along a curve). A short edge left out
// whose two ends are joined through others all the same is contracted with them.
#pragma once

#include <vector>

#include "occ/model/shape_index.h"

namespace tquad {

// Edges shorter than this fraction of the element size are contracted: the quad
// beside such an edge would have a Jacobian ratio near kCollapsedAreaRatio.
constexpr double kContractedEdgeRatio = 4e-3;

// The edges to contract at element size `size`. lengths: each edge's arc length
// (edge_segment_counts); usable: per edge, or empty for all; strips: per face, or
// empty for none, the faces absorbed as strips (strip_absorption.h), which do not
// keep their end edges from contracting.
std::vector<int> edges_to_contract(const ShapeIndex& index, const std::vector<double>& lengths,
                                   const std::vector<char>& usable, double size,
                                   const std::vector<char>& strips = {});

}  // namespace tquad
