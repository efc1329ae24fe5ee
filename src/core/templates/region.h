// Region: a closed loop of mesh nodes grouped into 2, 3 or 4 curves, the unit the
// templates decompose. curves[k] runs from corner k to corner k+1 and includes both;
// curves[k].back() == curves[k+1].front(). The loop is counter-clockwise in the
// orientation of the input boundary, and so is every subregion the templates make.
#pragma once

#include <vector>

#include "core/mesh/quad_mesh.h"
#include "core/templates/template_catalogue.h"

namespace tquad {

struct Region {
  std::vector<std::vector<NodeId>> curves;

  CurveCounts counts() const {
    CurveCounts c;
    for (const auto& curve : curves) c.push_back(static_cast<int>(curve.size()) - 1);
    return c;
  }
};

// Nodes first..last (inclusive) of a curve, in order.
inline std::vector<NodeId> piece(const std::vector<NodeId>& curve, int first, int last) {
  return std::vector<NodeId>(curve.begin() + first, curve.begin() + last + 1);
}

inline std::vector<NodeId> reversed(const std::vector<NodeId>& curve) {
  return std::vector<NodeId>(curve.rbegin(), curve.rend());
}

}  // namespace tquad
