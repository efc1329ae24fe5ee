// splice_touching_loops: a domain whose hole touches another loop at a shared point.
//
// A hole that meets the outer loop (or another hole) at one boundary point, a CAD
// vertex both wires pass through, leaves the region between them connected: its
// boundary is one closed walk that passes that point twice, not disjoint simple loops,
// and check_planar_domain refuses it ("the boundary crosses or touches itself"). The
// hole is spliced into the loop it touches at that point: walking the loop up to the
// point, once around the hole, and on from the point. The point is then kept twice,
// each copy the corner of its own wedge of the region, and each copy is moved into its
// wedge (along its bisector) by kPinchNudge of its shorter neighbouring segment, so the
// loop is simple again and decomposes as usual. The mesh's quads at the two copies
// meet again at the one shared node (the caller maps both copies to it), where the
// nudge is undone: it moves only the chart, never a node in space.
//
// Only the first shared point of two loops is spliced: a hole touching its outer loop
// at two points cuts the region in two, which stays refused.
#pragma once

#include <vector>

#include "core/decomposition/planar_domain.h"

namespace tquad {

// Of the shorter segment next to a pinched copy.
constexpr double kPinchNudge = 0.05;

struct SplicedDomain {
  PlanarDomain domain;
  // Spliced point i is point source[i] of the given domain (in its node numbering).
  std::vector<int> source;
  int splices = 0;
};

// `ids[i]`: an identity of the given domain's point i (its shared node); two points of
// different loops with one identity are one point where the loops touch. Loops keep
// their orientation (the domain lies to the left); a hole spliced into the outer loop
// leaves the domain with one hole fewer. Nothing changes (splices 0) when no two loops
// share a point.
SplicedDomain splice_touching_loops(const PlanarDomain& domain, const std::vector<long long>& ids);

}  // namespace tquad
