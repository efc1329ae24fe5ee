#include "core/repair/doublets.h"
#include "core/cancellation.h"

#include <algorithm>
#include <array>

#include "core/mesh/node_adjacency.h"
#include "core/mesh/quality.h"

namespace tquad {

namespace {

// Quad q rotated so that node n comes first.
Quad starting_at(const Quad& q, NodeId n) {
  const int i = static_cast<int>(std::find(q.begin(), q.end(), n) - q.begin());
  return {q[i], q[(i + 1) % 4], q[(i + 2) % 4], q[(i + 3) % 4]};
}

double worst_corner(const Quad& q, const std::vector<Vec3>& position, const std::vector<Vec3>& normal) {
  const std::array<Vec3, 4> p{position[q[0]], position[q[1]], position[q[2]], position[q[3]]};
  double worst = 1.0;
  for (int i = 0; i < 4; ++i) {
    Vec3 n = normal[q[i]];
    if (norm(n) == 0) n = cross(p[2] - p[0], p[3] - p[1]);
    worst = std::min(worst, corner_scaled_jacobian(p, i, n));
  }
  return worst;
}

// One sweep over the nodes: merges where it may; marks removed quads and nodes.
int merge_doublets(std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                   const std::vector<Vec3>& normal, bool even_if_worse, std::vector<char>& quad_gone,
                   std::vector<char>& node_gone, int& refused) {
  const NodeAdjacency adjacency(position.size(), quads);
  const CompressedLists& around = adjacency.quads_of;
  // Nodes of quads changed in this sweep: their lists above are stale until the next.
  std::vector<char> stale(position.size(), 0);
  int merged = 0;
  for (int n = fixed; n < static_cast<int>(position.size()); ++n) {
    if (node_gone[n] || stale[n]) continue;
    std::vector<int> live;
    for (int k = around.offsets[n]; k < around.offsets[n + 1]; ++k) {
      if (!quad_gone[around.items[k]]) live.push_back(around.items[k]);
    }
    if (live.size() != 2) continue;
    const Quad a = starting_at(quads[live[0]], n), b = starting_at(quads[live[1]], n);
    if (b[1] != a[3] || b[3] != a[1]) continue;  // not one fan of two quads around n
    const Quad joined{a[1], a[2], a[3], b[2]};
    if (!even_if_worse && worst_corner(joined, position, normal) <
                              std::min(worst_corner(a, position, normal), worst_corner(b, position, normal))) {
      ++refused;
      continue;
    }
    quads[live[0]] = joined;
    quad_gone[live[1]] = 1;
    node_gone[n] = 1;
    for (NodeId v : a) stale[v] = 1;
    for (NodeId v : b) stale[v] = 1;
    ++merged;
  }
  return merged;
}

}  // namespace

// One pass over the quads spares the sweeps' adjacency lists where there is no
// doublet (with the mesh copy smooth_mesh_in_plane no longer makes, those lists were
// a large share of the smoothing's time on large meshes).
bool has_doublet(const std::vector<Quad>& quads, int fixed, std::size_t nodes) {
  std::vector<unsigned char> quads_at(nodes, 0);
  for (const Quad& q : quads) {
    poll_cancellation(4);
    for (NodeId n : q) quads_at[n] = static_cast<unsigned char>(std::min(quads_at[n] + 1, 3));
  }
  return std::find(quads_at.begin() + std::min<std::size_t>(fixed, nodes), quads_at.end(), 2) != quads_at.end();
}

int remove_doublets(std::vector<Quad>& quads, int fixed, std::vector<Vec3>& param, std::vector<Vec3>& position,
                    std::vector<Vec3>& normal, bool even_if_worse, int* refused) {
  if (refused) *refused = 0;
  if (!has_doublet(quads, fixed, position.size())) return 0;
  std::vector<char> quad_gone(quads.size(), 0), node_gone(position.size(), 0);
  int removed = 0, refusals = 0, merged = 0;
  // A merge can leave a neighbour in two quads; a few sweeps reach them.
  for (int sweep = 0; sweep < 4; ++sweep) {
    refusals = 0;  // those of the last sweep: earlier ones may have merged since
    merged = merge_doublets(quads, fixed, position, normal, even_if_worse, quad_gone, node_gone, refusals);
    removed += merged;
    if (merged == 0) break;
  }
  // Sweeps that ran out while still merging skipped the nodes of their merges: at
  // least one refusal is then assumed.
  if (refused) *refused = merged > 0 ? std::max(refusals, 1) : refusals;
  if (removed == 0) return 0;
  std::vector<NodeId> renumber(position.size(), -1);
  NodeId next = 0;
  for (std::size_t i = 0; i < position.size(); ++i) {
    if (node_gone[i]) continue;
    renumber[i] = next;
    param[next] = param[i];
    position[next] = position[i];
    normal[next] = normal[i];
    ++next;
  }
  param.resize(next);
  position.resize(next);
  normal.resize(next);
  std::size_t kept = 0;
  for (std::size_t k = 0; k < quads.size(); ++k) {
    if (quad_gone[k]) continue;
    Quad q = quads[k];
    for (NodeId& v : q) v = renumber[v];
    quads[kept++] = q;
  }
  quads.resize(kept);
  return removed;
}

}  // namespace tquad
