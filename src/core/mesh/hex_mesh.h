// HexMesh: hexahedra swept from quads (occ/sweep/sweep.h), with what the writers and
// the report need: the solids swept and refused, and each CAD face's nodes.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/vec3.h"
#include "core/mesh/quad_mesh.h"

namespace tquad {

// Eight nodes as VTK's hexahedron (type 12) and CalculiX's C3D8 order them: a bottom
// face 0-3, the top face 4-7 above it (node i + 4 above node i), 0-1-2-3 turning
// counter-clockwise seen from the top, so every corner's Jacobian is positive.
using Hex = std::array<NodeId, 8>;

struct SweptSolid {
  int solid = 0;             // the shape's solid (0-based, in TopExp order)
  int source = 0, target = 0;  // its caps (shape face indices, 0-based)
  int layers = 0;            // hexahedra from source to target
  double height = 0.0;       // the longest path of a source node
  // The motion from source to target: a translation by `vector`, or a rotation by
  // `angle` (radians, right-handed) about the axis through `point` along `vector`;
  // or, `projected`, no exact motion: layers placed by the general route
  // (occ/sweep/projected_sweep.h), vector, point and angle unused.
  bool rotation = false;
  bool projected = false;
  Vec3 vector, point;
  double angle = 0.0;
  std::int64_t first_hex = 0, hex_count = 0;
};

struct RefusedSolid {
  int solid = 0;
  std::string reason;  // names the solid and the faces that block it
};

struct HexMesh {
  std::vector<Vec3> nodes;
  std::vector<Hex> hexes;
  std::vector<SweptSolid> solids;  // in hex order
  std::vector<RefusedSolid> refused;
  // Per CAD face of a swept solid (shape face index), its nodes, ascending: the
  // caps' and the sides' (a side's are its source edge's nodes in every layer).
  std::vector<std::pair<int, std::vector<NodeId>>> face_nodes;
  std::vector<double> scaled_jacobian;  // per hex (hex_scaled_jacobian)
  // Second order (or empty): per hexahedron, the node in the middle of each edge, in
  // VTK's (type 25) and CalculiX's (C3D20) order: edges 0-1, 1-2, 2-3, 3-0, 4-5, 5-6,
  // 6-7, 7-4, 0-4, 1-5, 2-6, 3-7; the nodes themselves are in `nodes`.
  std::vector<std::array<NodeId, 12>> mid_nodes;
  // Second order: per hexahedron, the smallest Jacobian determinant at its 27
  // integration points over the largest (hex20_jacobian_ratio).
  std::vector<double> jacobian_ratio;
  // CAD faces that two swept solids share whose nodes there differ (a side face of
  // both, meshed by each): the mesh does not conform across them (merge_shared_face_nodes).
  std::vector<int> unshared_faces;

  bool second_order() const { return !mid_nodes.empty(); }
  int nodes_per_element() const { return second_order() ? 20 : 8; }
  // Hexahedron k's nodes: its 8 corners, then (second order) its 12 edge middles. A
  // value (the writers call it for every element: no allocation).
  struct ElementNodes {
    std::array<NodeId, 20> ids{};
    std::size_t count = 8;
    const NodeId* begin() const { return ids.data(); }
    const NodeId* end() const { return ids.data() + count; }
    std::size_t size() const { return count; }
    NodeId operator[](std::size_t i) const { return ids[i]; }
  };
  ElementNodes element_nodes(std::size_t k) const {
    ElementNodes e;
    std::copy(hexes[k].begin(), hexes[k].end(), e.ids.begin());
    if (second_order()) {
      std::copy(mid_nodes[k].begin(), mid_nodes[k].end(), e.ids.begin() + 8);
      e.count = 20;
    }
    return e;
  }
};

// Joins the nodes of a CAD face listed by two or more solids (face_nodes) that lie at
// the same point (bitwise: a solid swept from a cap another one left copies its
// nodes), so the solids share them, and drops the copies; a face whose later lists
// have nodes the first lacks goes to unshared_faces.
void merge_shared_face_nodes(HexMesh& mesh);

// The worst of the eight corners' scaled Jacobians: the determinant of the three
// unit edge vectors leaving each corner (Knupp's hexahedron metric); 1 for a cube,
// at or below 0 for an inverted or degenerate corner.
double hex_scaled_jacobian(const std::array<Vec3, 8>& p);

// The 20-node (serendipity) hexahedron's Jacobian determinant at its 3 x 3 x 3 Gauss
// points: the smallest over the largest. Above 0 when the element is valid everywhere
// it is integrated, whatever its corners' Jacobians say; 1 for an undistorted one.
double hex20_jacobian_ratio(const std::array<Vec3, 20>& p);

// The hexahedron's volume (six tetrahedra from node 0's diagonal), for tests and
// checks; exact for hexahedra whose faces are planar.
double hex_volume(const std::array<Vec3, 8>& p);

}  // namespace tquad
