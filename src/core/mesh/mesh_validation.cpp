#include "core/mesh/mesh_validation.h"
#include "core/cancellation.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "core/mesh/node_adjacency.h"

namespace tquad {

namespace {

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

std::string edge_name(NodeId a, NodeId b) { return std::to_string(a) + "-" + std::to_string(b); }

// Linear in the mesh's size: sorting every directed edge, as this did before, took
// most of the check's time on large meshes, and the boundary route checks twice. Each
// quad side is listed at its lower node with the other node and its direction,
// (other << 1) | (runs from the higher node), so a node's short list holds every side
// between it and a higher neighbour.
std::string check_edges(const QuadMesh& mesh, const std::vector<int>& start) {
  const int boundary_points = start.back();
  const SlottedLists sides = SlottedLists::build(mesh.nodes.size(), [&](auto add) {
    for (const Quad& q : mesh.quads) {
      poll_cancellation(4);
      for (int i = 0; i < 4; ++i) {
        const NodeId a = q[i], b = q[(i + 1) % 4];
        add(std::min(a, b), (std::max(a, b) << 1) | (a > b ? 1 : 0));
      }
    }
  });
  std::vector<int> list;
  long long boundary_found = 0;
  for (NodeId low = 0; low < static_cast<NodeId>(mesh.nodes.size()); ++low) {
    list.clear();
    sides.for_each(low, [&](int side) { list.push_back(side); });
    std::sort(list.begin(), list.end());
    for (std::size_t k = 0; k < list.size();) {
      const NodeId high = list[k] >> 1;
      std::size_t end = k;
      while (end < list.size() && list[end] >> 1 == high) ++end;
      const auto from_to = [&](int side) { return side & 1 ? std::pair(high, low) : std::pair(low, high); };
      for (std::size_t j = k + 1; j < end; ++j) {
        if (list[j] == list[j - 1]) {
          const auto [a, b] = from_to(list[j]);
          return "edge " + edge_name(a, b) + " is used twice in the same direction (overlapping or flipped quads)";
        }
      }
      if (end - k == 1) {  // in one quad only: a boundary segment, in its direction
        const auto [a, b] = from_to(list[k]);
        if (!is_boundary_segment(a, b, start)) {
          return "edge " + edge_name(a, b) +
                 " belongs to one quad only but is not a boundary segment (the mesh has a hole or a crack)";
        }
        ++boundary_found;
      }
      k = end;
    }
  }
  if (boundary_found != boundary_points) {
    return std::to_string(boundary_points - boundary_found) + " boundary segments belong to no quad";
  }
  return "";
}

// A position's hash, equal for equal coordinates (-0 and +0 alike).
std::uint64_t position_hash(const Vec3& p) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (double c : {p.x + 0.0, p.y + 0.0, p.z + 0.0}) {
    std::uint64_t bits;
    std::memcpy(&bits, &c, sizeof bits);
    h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 31;
  }
  return h;
}

std::string check_nodes(const QuadMesh& mesh) {
  // A NaN node equals no other, so the coincidence test below would pass it.
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    if (!is_finite(mesh.nodes[i])) return "node " + std::to_string(i) + " has a coordinate that is NaN or infinite";
  }
  std::vector<char> used(mesh.nodes.size(), 0);
  for (const Quad& q : mesh.quads) for (NodeId id : q) used[id] = 1;
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (!used[i]) return "node " + std::to_string(i) + " belongs to no quad";
  }
  // Coincident nodes by an open-addressing hash table of node indices + 1 (0: empty),
  // at most half full: linear, where sorting the positions was slow on large meshes.
  std::size_t size = 2;
  while (size < 2 * mesh.nodes.size()) size *= 2;
  std::vector<NodeId> slots(size, 0);
  // Each node's first slot is a cache miss of a table larger than the caches: it is
  // asked for kAhead nodes early (the misses were a visible part of the check before).
  constexpr NodeId kAhead = 16;
  const auto count = static_cast<NodeId>(mesh.nodes.size());
  std::array<std::size_t, kAhead> first_slot{};
  for (NodeId i = 0; i < std::min(kAhead, count); ++i) first_slot[i] = position_hash(mesh.nodes[i]) & (size - 1);
  for (NodeId i = 0; i < count; ++i) {
    std::size_t slot = first_slot[i % kAhead];
    if (i + kAhead < count) {
      const std::size_t ahead = position_hash(mesh.nodes[i + kAhead]) & (size - 1);
      __builtin_prefetch(&slots[ahead]);
      first_slot[i % kAhead] = ahead;
    }
    for (; slots[slot] != 0; slot = (slot + 1) & (size - 1)) {
      const NodeId other = slots[slot] - 1;
      if (mesh.nodes[other] == mesh.nodes[i]) {
        return "nodes " + std::to_string(other) + " and " + std::to_string(i) + " are at the same position";
      }
    }
    slots[slot] = i + 1;
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
  // check_edges packs a node index and a direction bit into an int.
  if (mesh.nodes.size() >= (std::size_t{1} << 30)) {
    return "the mesh has " + std::to_string(mesh.nodes.size()) + " nodes, more than this check takes (2^30)";
  }
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
