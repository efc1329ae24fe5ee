// FaceBoundary: the outer wire of a face as one closed loop of shared mesh nodes, with
// each node's (u, v) on the face's surface (from the edges' pcurves, which share the
// 3D curve's parameter) and the wire's vertices with their turning angles.
#pragma once

#include <string>
#include <vector>

#include "occ/edge_discretization.h"
#include "occ/shape_index.h"

namespace tquad {

struct FaceBoundary {
  std::vector<NodeId> nodes;   // around the outer wire; the loop closes on itself
  std::vector<Vec3> uv;        // (u, v, 0) of each loop node
  std::vector<int> edge_start;      // loop position where each wire edge begins
  std::vector<int> start_vertex;    // shape vertex index at each edge_start
  std::vector<double> turn;         // signed turning angle there (radians, > 0 convex)
  std::vector<double> arc_length;   // 3D length along the loop to each node (size + 1)
  int inner_wires = 0;
  bool has_degenerate_edge = false;
};

// Signed area of a (u, v) loop (positive: counter-clockwise).
double signed_uv_area(const std::vector<Vec3>& uv);

// Whether the loop runs counter-clockwise around the face's outer normal.
bool runs_counter_clockwise(const FaceBoundary& boundary, const TopoDS_Face& face);

// Throws std::runtime_error when a pcurve is missing.
FaceBoundary face_boundary(const ShapeIndex& index, int face, const std::vector<EdgeNodes>& edges,
                           const std::vector<Vec3>& nodes);

}  // namespace tquad
