#include "core/mesh_validation.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <vector>

namespace tquad {

namespace {

std::uint64_t edge_key(NodeId a, NodeId b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

std::string check_quads(const QuadMesh& mesh) {
  const auto n = static_cast<NodeId>(mesh.nodes.size());
  for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
    const Quad& q = mesh.quads[k];
    for (int i = 0; i < 4; ++i) {
      if (q[i] < 0 || q[i] >= n) return "quad " + std::to_string(k) + " has a node index out of range";
      for (int j = 0; j < i; ++j) {
        if (q[i] == q[j]) return "quad " + std::to_string(k) + " repeats node " + std::to_string(q[i]);
      }
    }
  }
  return "";
}

// Loop l holds boundary nodes [start[l], start[l+1]); its segments run i -> i+1 and
// last -> first.
bool is_boundary_segment(NodeId a, NodeId b, const std::vector<int>& start) {
  for (std::size_t l = 0; l + 1 < start.size(); ++l) {
    if (a < start[l] || a >= start[l + 1]) continue;
    return b == (a + 1 < start[l + 1] ? a + 1 : start[l]);
  }
  return false;
}

std::string check_edges(const QuadMesh& mesh, const std::vector<int>& start) {
  const int boundary_points = start.back();
  std::vector<std::uint64_t> directed;
  directed.reserve(mesh.quads.size() * 4);
  for (const Quad& q : mesh.quads) {
    for (int i = 0; i < 4; ++i) directed.push_back(edge_key(q[i], q[(i + 1) % 4]));
  }
  std::sort(directed.begin(), directed.end());
  const auto repeated = std::adjacent_find(directed.begin(), directed.end());
  if (repeated != directed.end()) {
    return "edge " + std::to_string(*repeated >> 32) + "-" + std::to_string(*repeated & 0xffffffffu) +
           " is used twice in the same direction (overlapping or flipped quads)";
  }
  long long boundary_found = 0;
  for (std::uint64_t e : directed) {
    const auto a = static_cast<NodeId>(e >> 32), b = static_cast<NodeId>(e & 0xffffffffu);
    if (std::binary_search(directed.begin(), directed.end(), edge_key(b, a))) continue;
    if (!is_boundary_segment(a, b, start)) {
      return "edge " + std::to_string(a) + "-" + std::to_string(b) +
             " belongs to one quad only but is not a boundary segment (the mesh has a hole or a crack)";
    }
    ++boundary_found;
  }
  if (boundary_found != boundary_points) {
    return std::to_string(boundary_points - boundary_found) + " boundary segments belong to no quad";
  }
  return "";
}

std::string check_nodes(const QuadMesh& mesh) {
  std::vector<char> used(mesh.nodes.size(), 0);
  for (const Quad& q : mesh.quads) for (NodeId id : q) used[id] = 1;
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (!used[i]) return "node " + std::to_string(i) + " belongs to no quad";
  }
  std::vector<NodeId> order(mesh.nodes.size());
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](NodeId i) { const Vec3& p = mesh.nodes[i]; return std::tie(p.x, p.y, p.z); };
  std::sort(order.begin(), order.end(), [&](NodeId a, NodeId b) { return key(a) < key(b); });
  for (std::size_t i = 1; i < order.size(); ++i) {
    if (mesh.nodes[order[i]] == mesh.nodes[order[i - 1]]) {
      return "nodes " + std::to_string(order[i - 1]) + " and " + std::to_string(order[i]) +
             " are at the same position";
    }
  }
  return "";
}

}  // namespace

std::string check_disk_mesh(const QuadMesh& mesh, int boundary_points) {
  return check_domain_mesh(mesh, {boundary_points});
}

std::string check_domain_mesh(const QuadMesh& mesh, const std::vector<int>& loop_sizes) {
  std::vector<int> start{0};
  for (int size : loop_sizes) start.push_back(start.back() + size);
  const int boundary_points = start.back();
  const int holes = static_cast<int>(loop_sizes.size()) - 1;
  std::string problem = check_quads(mesh);
  if (problem.empty()) problem = check_edges(mesh, start);
  if (problem.empty()) problem = check_nodes(mesh);
  if (problem.empty()) {
    const long long expected = 1 + static_cast<long long>(mesh.quads.size()) + boundary_points / 2 - holes;
    if (static_cast<long long>(mesh.nodes.size()) != expected) {
      problem = "the mesh has " + std::to_string(mesh.nodes.size()) + " nodes; a domain with " +
                std::to_string(holes) + " holes, " + std::to_string(mesh.quads.size()) + " quads and " +
                std::to_string(boundary_points) + " boundary edges has " + std::to_string(expected);
    }
  }
  return problem;
}

}  // namespace tquad
