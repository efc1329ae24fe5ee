// align_narrow_bands: the nodes of a band's two long sides face each other.
//
// A band one or two segments wide (two opposite sides of at most kNarrowBand
// segments: band_balance.h gives its long sides equal counts) and narrower than half
// its segments (kNarrowEnd) is a mapped grid whose quads join node i of one long side
// to node i of the other. Each side is cut by its own arc length, so where the sides
// differ in length or start offset (a tapered strip, a helical groove's flank, a band
// between a circle and a row of tooth arcs) node i of one lies far along from node i
// of the other, and across a band much narrower than its segments that shear
// flattens or folds the quads. Here a long side that is one edge (the follower) takes
// its inner nodes where the other side's (the leader's) nodes project onto its curve,
// so the grid's lines cross the band. The leader's edges stay as they are and are
// never followers afterwards (an edge moves at most once, for one band); a projection
// that is not in order along the follower, or leaves a segment under kShortestShare
// of the even one, leaves the follower as it was.
//
// A thin ring (a face with one hole whose two loops have equal node counts,
// ring_balance.h) is aligned the same way before any band: when one loop is a single
// closed edge (a circle around a hexagonal socket, a washer between two circles),
// its inner nodes move to where the other loop's nodes project onto it, so that the
// mapped ring's quads (mapped_ring.h) run straight across the ring. Its vertex stays,
// facing the other loop's nearest node; the other loop's edges are frozen.
#pragma once

#include <vector>

#include "occ/intervals/edge_discretization.h"
#include "occ/model/face_wire_edges.h"
#include "occ/model/shape_index.h"

namespace tquad {

// A follower keeps every segment at least this share of its even one: shorter ones
// would crowd the face on its other side. Low, because a leader side often ends in a
// short edge of its own, whose nodes the follower must face too (or the band's quads
// there lean across the whole short edge).
constexpr double kShortestShare = 0.05;
// A band is narrow when every leader node lies nearer the follower's curve than this
// share of the long sides' mean segment: wider, its quads have room to lean, and
// moving a shared edge's nodes would only unsettle the faces on its other side.
constexpr double kNarrowEnd = 0.5;

// Moves followers' inner nodes in `edges` and `nodes` (and their spacing in `kept`,
// when given, so that the next round starts from it). Returns the number of bands and
// rings aligned.
int align_narrow_bands(const ShapeIndex& index, const std::vector<char>& meshed, std::vector<EdgeNodes>& edges,
                       std::vector<Vec3>& nodes, EdgeSpacings* kept);

// Per face, 1 where the face is a ring that align_narrow_bands may align at these
// counts: two loops of equal totals in `segments`, one a single edge, and every
// vertex of the other within kNarrowEnd of a mean segment (from `lengths`) of that
// edge's curve. Interval assignment keeps such rings balanced (interval_assignment.h).
std::vector<char> alignable_ring_faces(FaceWireEdges& wires, const std::vector<char>& meshed,
                                       const std::vector<double>& lengths, const std::vector<int>& segments);

}  // namespace tquad
