// ShapeMesh: the mesh of several faces (a CAD shape, or one boundary region as face 0)
// in one node array, so faces that share boundary nodes are conforming. This is what
// the file writers and the report take.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/face_refusal.h"
#include "core/mesh/quad_mesh.h"

namespace tquad {

// What --corners best did on a face: corner sets tried beyond the natural choice, and
// the natural and chosen meshes' worst and mean scaled Jacobian (after smoothing).
struct CornerSearch {
  int tried = 0;
  bool changed = false;  // a searched set beat the natural choice
  // Not asked for: the given corners left an inverted quad (boundary_region.h).
  bool after_inverted = false;
  double natural_worst = 0, natural_mean = 0, chosen_worst = 0, chosen_mean = 0;
};

struct FaceMesh {
  int face = 0;               // index of the face in the shape (0-based)
  std::string template_tree;  // e.g. "T2[T0,T0,T1[T0,T0,T0,T0]]"
  std::int64_t first_quad = 0;
  std::int64_t quad_count = 0;
  std::optional<CornerSearch> corner_search;  // set by --corners best, or after an inverted quad
  std::string route;  // the face route that made its mesh (face_route.cpp's registry); empty for a boundary
};

struct RefusedFace {
  int face = 0;
  std::string reason;  // names the face (0-based) and what failed; no command-line advice
  RefusalCode code = RefusalCode::cannot_mesh;
  std::vector<int> vertices;  // shape vertices on the face's outer wire, in its order
};

struct ShapeMesh {
  std::vector<Vec3> nodes;
  std::vector<Quad> quads;
  std::vector<FaceMesh> faces;  // in quad order: face k owns quads [first, first + count)
  std::vector<RefusedFace> refused_faces;
  // Per quad (or empty): the scaled Jacobian with each corner signed by the surface's
  // outer normal at that corner (face_mesher.h, check_on_surface), the one measure of
  // inverted quads on curved faces; the quality report takes it when present.
  std::vector<double> scaled_jacobian;
  // Per quad (or empty): the Lee-Lo shape metric (quality.h), for the user to look at.
  std::vector<double> lee_lo;
  // Second order (or empty: first order): per quad, the node in the middle of each of
  // its edges, edge i running from corner i to corner i + 1; the nodes themselves are
  // in `nodes` with the corners.
  std::vector<Quad> mid_nodes;

  bool second_order() const { return !mid_nodes.empty(); }
  int nodes_per_element() const { return second_order() ? 8 : 4; }

  // Quad k's nodes in the order of VTK's quadratic quad, CalculiX's S8 and Gmsh's
  // 8-node quadrangle alike: the four corners, then the middles of edges 0-1, 1-2,
  // 2-3 and 3-0; its four corners alone at first order. A value (the writers call it
  // for every element: no allocation).
  struct ElementNodes {
    std::array<NodeId, 8> ids{};
    int count = 4;
    const NodeId* begin() const { return ids.data(); }
    const NodeId* end() const { return ids.data() + count; }
  };
  ElementNodes element_nodes(std::size_t k) const {
    ElementNodes e;
    std::copy(quads[k].begin(), quads[k].end(), e.ids.begin());
    if (second_order()) {
      std::copy(mid_nodes[k].begin(), mid_nodes[k].end(), e.ids.begin() + 4);
      e.count = 8;
    }
    return e;
  }
};

// One boundary region as a shape of one face (face 0), moving the mesh's arrays.
inline ShapeMesh single_face_mesh(QuadMesh&& mesh) {
  ShapeMesh shape;
  shape.nodes = std::move(mesh.nodes);
  shape.quads = std::move(mesh.quads);
  shape.faces.push_back({0, mesh.template_tree, 0, static_cast<std::int64_t>(shape.quads.size()), std::nullopt, ""});
  return shape;
}

}  // namespace tquad
