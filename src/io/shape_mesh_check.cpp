#include "io/shape_mesh_check.h"

#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/mesh/mesh_edges.h"
#include "core/geometry/vec3.h"

namespace tquad {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("invalid ShapeMesh: " + what); }

void check_node_indices(const char* name, const std::vector<Quad>& rows, std::int64_t node_count) {
  for (std::size_t k = 0; k < rows.size(); ++k) {
    for (int i = 0; i < 4; ++i) {
      const NodeId id = rows[k][i];
      if (id < 0 || id >= node_count) {
        fail(std::string(name) + "[" + std::to_string(k) + "][" + std::to_string(i) + "] = " + std::to_string(id) +
             " is not a node index (" + std::to_string(node_count) + " nodes)");
      }
    }
  }
}

// Second order: one middle node per mesh edge, the same from every quad of the edge,
// and no middle is a corner or the middle of another edge.
void check_shared_middles(const ShapeMesh& mesh) {
  const MeshEdges edges(mesh.nodes.size(), mesh.quads);
  std::vector<NodeId> middle(edges.count(), -1);
  std::vector<char> used(mesh.nodes.size(), 0);  // 1: a corner, 2: a middle
  for (const Quad& q : mesh.quads) for (NodeId n : q) used[n] = 1;
  for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
    for (int i = 0; i < 4; ++i) {
      const NodeId m = mesh.mid_nodes[k][i];
      NodeId& known = middle[edges.index(mesh.quads[k][i], mesh.quads[k][(i + 1) % 4])];
      if (known == m) continue;
      const std::string where = "mid_nodes[" + std::to_string(k) + "][" + std::to_string(i) + "] = " + std::to_string(m);
      if (known >= 0) fail(where + ", but another quad of that edge has " + std::to_string(known));
      if (used[m]) fail(where + " is " + (used[m] == 1 ? "a corner" : "the middle of another edge"));
      known = m;
      used[m] = 2;
    }
  }
}

}  // namespace

void check_shape_mesh(const ShapeMesh& mesh) {
  const auto node_count = static_cast<std::int64_t>(mesh.nodes.size());
  for (const auto& [name, values] : {std::pair{"scaled_jacobian", &mesh.scaled_jacobian}, std::pair{"lee_lo", &mesh.lee_lo}}) {
    if (!values->empty() && values->size() != mesh.quads.size()) {
      fail(std::string(name) + " has " + std::to_string(values->size()) + " values for " +
           std::to_string(mesh.quads.size()) + " quads");
    }
  }
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    if (!is_finite(mesh.nodes[i])) fail("node " + std::to_string(i) + " has a coordinate that is NaN or infinite");
  }
  check_node_indices("quads", mesh.quads, node_count);
  if (mesh.second_order() && mesh.mid_nodes.size() != mesh.quads.size()) {
    fail("mid_nodes has " + std::to_string(mesh.mid_nodes.size()) + " entries for " +
         std::to_string(mesh.quads.size()) + " quads");
  }
  check_node_indices("mid_nodes", mesh.mid_nodes, node_count);
  if (mesh.second_order()) check_shared_middles(mesh);
  std::unordered_set<int> meshed;
  std::int64_t next = 0;
  for (std::size_t r = 0; r < mesh.faces.size(); ++r) {
    const FaceMesh& f = mesh.faces[r];
    const std::string name = "faces[" + std::to_string(r) + "] (face " + std::to_string(f.face) + ")";
    if (f.face < 0) fail(name + " has a negative face index");
    if (!meshed.insert(f.face).second) fail(name + ": face " + std::to_string(f.face) + " has two records");
    if (f.first_quad != next || f.quad_count < 0) {
      fail(name + " owns quads [" + std::to_string(f.first_quad) + ", +" + std::to_string(f.quad_count) +
           ") but the next unowned quad is " + std::to_string(next));
    }
    next += f.quad_count;
    if (next > static_cast<std::int64_t>(mesh.quads.size())) {
      fail(name + " owns quads up to " + std::to_string(next) + " of " + std::to_string(mesh.quads.size()));
    }
  }
  if (next != static_cast<std::int64_t>(mesh.quads.size())) {
    fail("the face records own " + std::to_string(next) + " of " + std::to_string(mesh.quads.size()) + " quads");
  }
  for (std::size_t r = 0; r < mesh.refused_faces.size(); ++r) {
    const int face = mesh.refused_faces[r].face;
    if (face < 0 || meshed.count(face) != 0) {
      fail("refused_faces[" + std::to_string(r) + "]: face " + std::to_string(face) +
           (face < 0 ? " is negative" : " is also meshed"));
    }
  }
}

}  // namespace tquad
