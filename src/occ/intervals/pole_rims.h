// quarter_pole_rims: a multiple of 4 segments on the rim of every disk around a pole.
//
// A face with a seam and a pole (a cone's side, a sphere cap) may be meshed as the
// disk's O-grid in polar coordinates (disk_o_grid.h). Its middle square has a grid
// node on the pole only when both its sides' counts are even, that is when the rim
// has a multiple of 4 segments; otherwise the node nearest the pole is moved onto it
// and the quads around it differ: the tip of a 60-degree cone had a worst corner of
// 0.80 there where four alike give 0.97. Changing a whole chain, or an edge outside
// chains, by 2 keeps every face's parity and every chain's faces mapped.
//
// Only where the surface turns around the pole by kQuarterRimFrom or more: sharper
// tips take the sector's halves (face_boundary.h, pole_sector), which need no
// multiple of 4, and a cone's tip turning less than that lost mean quality with its
// rim moved to a multiple of 4.
#pragma once

#include <cmath>
#include <vector>

#include "occ/model/shape_index.h"

namespace tquad {

constexpr double kQuarterRimFrom = 150.0 * M_PI / 180.0;

// A face closed around two poles (pole_to_pole.h) gets a multiple of 4 on its seam.
// goals: per edge, its length / size; floors: per edge, the least count. The change
// of each rim is the one of +2 or -2, on one of its units, that moves counts least
// from their goals. Returns the number of rims changed.
int quarter_pole_rims(const ShapeIndex& index, const std::vector<char>& meshed, const std::vector<double>& goals,
                      const std::vector<int>& floors, std::vector<int>& segments,
                      const std::vector<std::vector<int>>& chains);

}  // namespace tquad
