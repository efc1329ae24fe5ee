#include "core/mesh/shell_orientation.h"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <map>

namespace tquad {

namespace {

// One quad edge between two boundary nodes: its undirected key, the face (index into
// mesh.faces) and whether the quad runs along it from the lower node to the higher.
struct EdgeUse {
  std::uint64_t key;
  int face;
  bool ascending;
};

// How two faces meet, summed over the edges they share: along how many their quads run
// the same way (they disagree there) and how many the opposite way (they agree).
struct Meeting {
  int same = 0, opposite = 0;
};

Quad reversed(const Quad& q) { return {q[0], q[3], q[2], q[1]}; }

}  // namespace

ShellOrientation orient_shells(ShapeMesh& mesh, NodeId boundary_nodes, const std::vector<char>& anchored) {
  ShellOrientation result;
  const int face_count = static_cast<int>(mesh.faces.size());
  if (face_count == 0) return result;

  std::vector<EdgeUse> uses;
  for (int k = 0; k < face_count; ++k) {
    const FaceMesh& f = mesh.faces[k];
    for (std::int64_t q = f.first_quad; q < f.first_quad + f.quad_count; ++q) {
      const Quad& quad = mesh.quads[q];
      for (int i = 0; i < 4; ++i) {
        const NodeId a = quad[i], b = quad[(i + 1) % 4];
        if (a >= boundary_nodes || b >= boundary_nodes || a == b) continue;
        const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
        uses.push_back({lo << 32 | hi, k, a < b});
      }
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.key != y.key ? x.key < y.key : x.face < y.face;
  });

  // Face pairs that meet, and faces with an edge no other quad has (an open boundary)
  // or one shared by three or more quads (a junction): both make a component open.
  std::map<std::pair<int, int>, Meeting> meetings;
  std::vector<char> open_edge(face_count, 0);
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i == 1) {
      open_edge[uses[i].face] = 1;
    } else if (j - i == 2) {
      const EdgeUse& a = uses[i];
      const EdgeUse& b = uses[i + 1];
      if (a.face != b.face) {  // within one face: a seam or a chord between two boundary nodes
        Meeting& m = meetings[{a.face, b.face}];
        (a.ascending == b.ascending ? m.same : m.opposite) += 1;
      }
    } else {
      for (std::size_t u = i; u < j; ++u) open_edge[uses[u].face] = 1;
    }
    i = j;
  }
  // For each face, its neighbours and whether it must take the opposite turn of theirs.
  std::vector<std::vector<std::pair<int, bool>>> neighbours(face_count);
  for (const auto& [pair, m] : meetings) {
    const bool disagree = m.same > m.opposite;
    neighbours[pair.first].push_back({pair.second, disagree});
    neighbours[pair.second].push_back({pair.first, disagree});
  }

  auto is_anchored = [&](int k) { return k < static_cast<int>(anchored.size()) && anchored[k]; };
  // turn[k]: 0 not yet reached, +1 kept, -1 reversed.
  std::vector<int> turn(face_count, 0);
  std::vector<std::pair<int, int>> conflicts;
  // Anchored faces seed first, so that a component holding one takes its turn.
  std::vector<int> seeds;
  for (int k = 0; k < face_count; ++k) if (is_anchored(k)) seeds.push_back(k);
  for (int k = 0; k < face_count; ++k) if (!is_anchored(k)) seeds.push_back(k);
  for (int seed : seeds) {
    if (turn[seed] != 0) continue;
    std::vector<int> component{seed};
    bool holds_anchor = false;
    turn[seed] = 1;
    std::deque<int> queue{seed};
    while (!queue.empty()) {
      const int k = queue.front();
      queue.pop_front();
      holds_anchor = holds_anchor || is_anchored(k);
      for (const auto& [n, disagree] : neighbours[k]) {
        const int wanted = disagree ? -turn[k] : turn[k];
        if (turn[n] == 0) {
          // An anchored face reached from another keeps its own turn (+1).
          turn[n] = is_anchored(n) ? 1 : wanted;
          if (turn[n] != wanted) conflicts.push_back({std::min(k, n), std::max(k, n)});
          component.push_back(n);
          queue.push_back(n);
        } else if (turn[n] != wanted) {
          conflicts.push_back({std::min(k, n), std::max(k, n)});
        }
      }
    }
    if (holds_anchor) continue;
    // No anchor: outward when closed, else as the larger area lies.
    bool closed = true;
    for (int k : component) closed = closed && !open_edge[k];
    double volume = 0, kept_area = 0, turned_area = 0;
    const Vec3 origin = mesh.nodes[mesh.quads[mesh.faces[seed].first_quad][0]];
    for (int k : component) {
      const FaceMesh& f = mesh.faces[k];
      for (std::int64_t q = f.first_quad; q < f.first_quad + f.quad_count; ++q) {
        const Quad& quad = mesh.quads[q];
        const Vec3 p0 = mesh.nodes[quad[0]] - origin, p1 = mesh.nodes[quad[1]] - origin;
        const Vec3 p2 = mesh.nodes[quad[2]] - origin, p3 = mesh.nodes[quad[3]] - origin;
        volume += turn[k] * (dot(p0, cross(p1, p2)) + dot(p0, cross(p2, p3))) / 6.0;
        const double area = 0.5 * norm(cross(p2 - p0, p3 - p1));
        (turn[k] > 0 ? kept_area : turned_area) += area;
      }
    }
    const bool flip_all = closed ? volume < 0 : turned_area > kept_area;
    if (flip_all) for (int k : component) turn[k] = -turn[k];
  }

  for (int k = 0; k < face_count; ++k) {
    if (turn[k] >= 0) continue;
    const FaceMesh& f = mesh.faces[k];
    for (std::int64_t q = f.first_quad; q < f.first_quad + f.quad_count; ++q) {
      mesh.quads[q] = reversed(mesh.quads[q]);
      if (mesh.second_order()) {
        // Middle i lies on edge i -> i + 1; reversed, edge i is the old edge 3 - i.
        const Quad& m = mesh.mid_nodes[q];
        mesh.mid_nodes[q] = {m[3], m[2], m[1], m[0]};
      }
    }
    result.turned_faces.push_back(f.face);
  }
  std::sort(result.turned_faces.begin(), result.turned_faces.end());
  for (auto& [a, b] : conflicts) {
    const int fa = mesh.faces[a].face, fb = mesh.faces[b].face;
    result.conflicts.push_back({std::min(fa, fb), std::max(fa, fb)});
  }
  std::sort(result.conflicts.begin(), result.conflicts.end());
  result.conflicts.erase(std::unique(result.conflicts.begin(), result.conflicts.end()), result.conflicts.end());
  return result;
}

}  // namespace tquad
