// QuadMesh: the mesher's output for one region.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

using NodeId = std::int32_t;
using Quad = std::array<NodeId, 4>;

struct QuadMesh {
  // #nodes positions. The first points of a boundary input are the boundary points
  // themselves, in input order and bit-exact; interior nodes follow.
  std::vector<Vec3> nodes;
  // #quads node indices, counter-clockwise in the boundary loop's orientation.
  std::vector<Quad> quads;
  // The template tree, e.g. "T2[T0,T0,T1[T0,T0,T0,T0]]".
  std::string template_tree;
  // The interior cuts the templates made (node-index polylines): the boundaries
  // between subregions, drawn thicker in figures.
  std::vector<std::vector<NodeId>> subregion_cuts;
  // Corner indices (into the boundary points) the root template actually used: equal
  // to the input corners unless the region was regrouped (see region_regrouping.h).
  std::vector<int> corners_used;
};

}  // namespace tquad
