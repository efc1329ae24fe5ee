// untangle_corner_areas: frees a mesh of inverted corners by moving interior nodes in
// its own 2D coordinates (a face's (u, v), or a plane) to where the smallest signed
// corner area around them is largest.
//
// The smoother (smoothing.h) keeps a move only when the worst scaled Jacobian around a
// node does not drop, which cannot bring an inverted corner back: the scaled Jacobian
// of a folded corner hardly changes under small moves (it stays near -1), so the
// search sees no gain. Signed areas do: with one node moving, every corner area around
// it is an affine function of its position, so the best position is a small linear
// program, max t subject to t <= area_i(x, y), solved exactly at a vertex of three
// tight constraints (the optimization-based untangling of Freitag and Plassmann,
// 2000). Four steep walls keep the node within its neighbours' bounding box.
//
// Nodes visited: those of quads with a corner area at or below zero and of the quads
// around them, in index order, pass after pass until no corner is inverted or no node
// moves (the same mesh for any thread count). When some corner stays inverted, every
// node goes back where it was: a fold the linear programs cannot undo (one held by
// fixed boundary nodes) spread over more quads is worse than the fold left alone.
#pragma once

#include <functional>
#include <vector>

#include "core/mesh/quad_mesh.h"
#include "core/geometry/vec3.h"

namespace tquad {

struct AreaUntanglingResult {
  int inverted_before = 0;  // corners with a signed area <= 0 (in the 2D coordinates)
  int inverted_after = 0;
  long long moves = 0;
};

// Nodes [0, fixed) never move. `param` holds each node's 2D coordinates (z ignored);
// `orientation` is +1 when the quads run counter-clockwise in them, -1 when clockwise.
// `place(node, p)` is asked before node moves to p; returning false refuses the move
// (a pole, a point off the surface), and it may update the caller's other per-node
// data when it returns true.
AreaUntanglingResult untangle_corner_areas(const std::vector<Quad>& quads, int fixed, std::vector<Vec3>& param,
                                           double orientation,
                                           const std::function<bool(int node, const Vec3& p)>& place);

// Corners of `quads` whose signed area in `param` (times orientation) is <= 0.
int inverted_corners(const std::vector<Quad>& quads, const std::vector<Vec3>& param, double orientation);

}  // namespace tquad
