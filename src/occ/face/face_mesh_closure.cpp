#include "occ/face/face_mesh_closure.h"
#include "core/cancellation.h"

#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_map>

namespace tquad {

namespace {

// A mesh node as the shape knows it: a shared node's id, or an interior node's local
// index above every shared id (so a seam's two sides, one shared node twice in the
// face's loop, are one node here).
using GlobalNode = std::uint64_t;
constexpr GlobalNode kInterior = GlobalNode{1} << 40;

struct EdgeKey {
  GlobalNode low, high;
  bool operator==(const EdgeKey& o) const { return low == o.low && high == o.high; }
};
struct EdgeKeyHash {
  std::size_t operator()(const EdgeKey& k) const { return std::hash<GlobalNode>()(k.low * 0x9E3779B97F4A7C15ull ^ k.high); }
};
EdgeKey edge_key(GlobalNode a, GlobalNode b) { return a < b ? EdgeKey{a, b} : EdgeKey{b, a}; }

std::string node_text(GlobalNode n) {
  return n >= kInterior ? "interior node " + std::to_string(n - kInterior) : "node " + std::to_string(n);
}
std::string edge_text(const EdgeKey& k) { return node_text(k.low) + " to " + node_text(k.high); }

}  // namespace

std::string face_mesh_closure_problem(const ShapeIndex& index, int face, const std::vector<EdgeNodes>& edges,
                                      const FaceMeshResult& mesh) {
  const std::string name = "face " + std::to_string(face);
  // Segments the face's edges expect in one quad each. A seam is met twice, once each
  // way, and its segments lie inside the mesh. (Not BRep_Tool::IsClosed: an edge on
  // the closing line of a periodic surface has both pcurves on every face of that
  // surface, also on one that meets it once, as a boolean leaves a cylinder cut in two.)
  std::map<int, int> occurrences;
  const TopoDS_Face& f = index.face(face);
  for (TopExp_Explorer it(f, TopAbs_EDGE); it.More(); it.Next()) {
    if (!BRep_Tool::Degenerated(TopoDS::Edge(it.Current()))) ++occurrences[index.edge_index(it.Current())];
  }
  std::unordered_map<EdgeKey, int, EdgeKeyHash> expected;
  for (const auto& [e, count] : occurrences) {
    if (count != 1) continue;
    const EdgeNodes& en = edges[e];
    for (std::size_t i = 0; i + 1 < en.nodes.size(); ++i) ++expected[edge_key(en.nodes[i], en.nodes[i + 1])];
  }
  const std::size_t loop = mesh.boundary_nodes.size();
  const auto global = [&](NodeId local) {
    const auto i = static_cast<std::size_t>(local);
    return i < loop ? static_cast<GlobalNode>(mesh.boundary_nodes[i]) : kInterior + (i - loop);
  };
  // Every quad edge once per quad, sorted so that equal edges are neighbours (a sort of
  // one flat array: a hash map of millions of edges cost a sizeable share of a large
  // face's meshing, most of it allocating and freeing its nodes).
  std::vector<EdgeKey> uses;
  uses.reserve(4 * mesh.quads.size());
  for (const Quad& q : mesh.quads) {
    poll_cancellation(8);
    for (int k = 0; k < 4; ++k) uses.push_back(edge_key(global(q[k]), global(q[(k + 1) % 4])));
  }
  // The sort of a large face's edges takes seconds (20 million keys at 5 million
  // quads): it looks at the cancel flag through a count in the comparator, every
  // kSortPoll comparisons.
  constexpr std::size_t kSortPoll = 1 << 10;
  std::size_t compared = 0;
  const auto before = [&compared](const EdgeKey& a, const EdgeKey& b) {
    if (++compared % kSortPoll == 0) poll_cancellation(kSortPoll);
    return a.low != b.low ? a.low < b.low : a.high < b.high;
  };
  std::sort(uses.begin(), uses.end(), before);
  // Inside: two quads, no edge segment. On the boundary: one quad, one segment. Two
  // edges of one segment each between the same two nodes (a seam an IGES file gives
  // as two edges) are one mesh edge between two quads, like a seam.
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j] == uses[i]) ++j;
    const EdgeKey& key = uses[i];
    const int count = static_cast<int>(j - i);
    i = j;
    const auto it = expected.find(key);
    const int segments = it == expected.end() ? 0 : it->second;
    if (count > 2) return name + ": its mesh edge from " + edge_text(key) + " is in " + std::to_string(count) + " quads";
    if (count == 2 && (segments == 0 || segments == 2)) continue;
    if (count == 1 && segments == 1) continue;
    if (count == 1) {
      return name + ": its mesh edge from " + edge_text(key) + " is in one quad but on none of the face's edges (a crack)";
    }
    return name + ": its mesh edge from " + edge_text(key) + " on the face's edge is in two quads";
  }
  for (const auto& [key, segments] : expected) {
    if (!std::binary_search(uses.begin(), uses.end(), key, before)) {
      return name + ": its edge segment from " + edge_text(key) + " is in no quad of its mesh";
    }
  }
  return {};
}

}  // namespace tquad
