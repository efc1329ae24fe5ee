// A face's wires as shape edge indices, and a memo of them for the interval assignment.
#pragma once

#include <optional>
#include <vector>

#include "occ/model/shape_index.h"

namespace tquad {

// A face's wires as edge lists (the outer wire first), or nothing when an edge is
// degenerate (a pole).
using WireEdges = std::vector<std::vector<int>>;
std::optional<WireEdges> face_wire_edges(const ShapeIndex& index, int face);

// The edge that stands for a pole (is_pole_edge, face_boundary.h) in face_wires_with_poles.
inline constexpr int kPoleEdge = -1;

// A face's wires as edge lists in the order the wire explorer walks them (the outer
// wire first), poles as kPoleEdge, other degenerate edges (points of the chart) left
// out: the one walk face_wire_edges and the
// three-edge faces beside poles (interval_assignment.h) read.
WireEdges face_wires_with_poles(const ShapeIndex& index, int face);

// face_wire_edges of each face, computed when first asked and kept: a wire explorer
// computes the face's (u, v) bounds on cones and spline surfaces (a pass over every
// pcurve), and the interval assignment asks three times per face and round (a large
// share of the main thread's work on such faces). A face whose wires cannot be
// walked throws each time it is asked, as face_wire_edges does.
class FaceWireEdges {
 public:
  explicit FaceWireEdges(const ShapeIndex& index)
      : index_(index), known_(index.face_count(), 0), wires_(index.face_count()) {}
  const ShapeIndex& index() const { return index_; }
  const std::optional<WireEdges>& of(int face);

 private:
  const ShapeIndex& index_;
  std::vector<char> known_;
  std::vector<std::optional<WireEdges>> wires_;
};

}  // namespace tquad
