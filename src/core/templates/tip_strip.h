// mesh_tip_strip: a thin region between two sharp tips (a chamfer's sliver on a hex
// head, a lens between two nearly tangent curves) meshed as two rows of quads along
// it, with one kite at each tip.
//
// The loop runs from one tip to the other along chain A and back along chain B, each
// of n segments (n >= 3, counts equal). The interior nodes m_1 .. m_{n-1} sit between
// the chains' nodes a_i and b_i; the rows are the quads (a_i, a_i+1, m_i+1, m_i) and
// (b_i+1, b_i, m_i, m_i+1) for i = 1 .. n-2, and each tip's quad is (b_1, tip, a_1,
// m_1) (alike at the other tip). The tip is then the corner of one quad only: its
// CAD angle bounds the face's worst corner, whatever the layout, and every other quad
// is a trapezoid across the band. Templates on the same loop (T3 with the tips as
// corners, T5 between the chains, or a decomposition) fill the sliver with quads
// whose corners near the tips follow its narrowing and stay far from square.
//
// m_i is the middle of a_i and b_i, except at the tips: there m_1 moves along the band
// past the middle of a_1 b_1 until its corner is a third of what the tip's angle leaves
// of 360 degrees (on the line a_1 b_1 the kite would have a corner of 180 degrees), at
// most half way to m_2's middle (where the band widens fast, further would fold the
// row's first quad).
#pragma once

#include <optional>
#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

// The strip's mesh of the closed loop `points` (the points first, bit-exact, then
// m_1 .. m_{n-1}; quads in the loop's orientation), or nothing when it does not apply:
// tips out of range or equal, chains of unequal counts or under 3 segments, or a quad
// not convex in the loop's plane (the points' z is ignored: a (u, v) chart or a plane).
std::optional<QuadMesh> mesh_tip_strip(const std::vector<Vec3>& points, int tip_a, int tip_b);

}  // namespace tquad
