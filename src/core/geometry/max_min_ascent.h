// max_min_ascent: the direction that raises the smallest of several linear rates.
//
// The smoother raises the worst of the corners around a node, a minimum of smooth
// functions of the node's position, so the worst corner's gradient alone can lower
// a corner just above it. Near a minimum shared by several corners the steepest
// ascent of the minimum is the unit direction d maximizing min_i g_i . d over the
// gradients g_i of the corners at (or near) it, as in Freitag and Ollivier-Gooch's
// max-min angle smoothing (1997). In the plane that maximum is reached along some
// g_i or where two rates are equal (d perpendicular to g_i - g_j), so those
// candidates are enough.
#pragma once

#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

struct Ascent {
  Vec3 direction;     // unit, in the (x, y) plane (z = 0); zero when none rises
  double rate = 0.0;  // min_i g_i . direction: > 0 when every rate rises
};

// Over the gradients' (x, y) parts; `gradients` may be empty (then no ascent).
Ascent max_min_ascent(const std::vector<Vec3>& gradients);

}  // namespace tquad
