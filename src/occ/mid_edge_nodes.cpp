#include "occ/mid_edge_nodes.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>

#include <cstdint>
#include <unordered_map>

#include "core/quadratic_quad.h"
#include "occ/occ_vec.h"

namespace tquad {

namespace {

std::uint64_t edge_key(NodeId a, NodeId b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// Where each CAD edge segment is, by its two end nodes (the mesh's ids): the edge
// and the segment's index along it.
struct Segment {
  int edge;
  std::size_t index;
};
std::unordered_map<std::uint64_t, Segment> curve_segments(const std::vector<EdgeNodes>& edges,
                                                           const std::vector<NodeId>& node_id) {
  std::unordered_map<std::uint64_t, Segment> segments;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const EdgeNodes& en = edges[e];
    if (en.degenerate) continue;
    for (std::size_t i = 0; i + 1 < en.nodes.size(); ++i) {
      const NodeId a = node_id[en.nodes[i]], b = node_id[en.nodes[i + 1]];
      if (a < 0 || b < 0) continue;  // an edge of faces not meshed
      segments.emplace(edge_key(a, b), Segment{static_cast<int>(e), i});  // two edges between two nodes: the first's
    }
  }
  return segments;
}

// The middle of a CAD edge segment: the edge's curve at the middle parameter.
Vec3 curve_middle(const ShapeIndex& index, const std::vector<EdgeNodes>& edges, const Segment& s) {
  const EdgeNodes& en = edges[static_cast<std::size_t>(s.edge)];
  return to_vec3(BRepAdaptor_Curve(index.edge(s.edge)).Value(0.5 * (en.params[s.index] + en.params[s.index + 1])));
}

// The surface point halfway between two nodes of a face in its mesh coordinates.
// Where that lands far from the chord's middle (the two coordinates on either side of
// a periodic surface's seam: the halfway point is on the far side), the chord's
// middle stands in: a straight edge there rather than a wrong one.
Vec3 surface_middle(const BRepAdaptor_Surface& surface, const FaceMeshResult& m, int a, int b, const Vec3& pa,
                    const Vec3& pb) {
  Vec3 param = 0.5 * (m.param[a] + m.param[b]);
  if (m.polar) param = polar_to_uv(*m.polar, param);
  const Vec3 on_surface = to_vec3(surface.Value(param.x, param.y));
  const Vec3 chord = 0.5 * (pa + pb);
  return distance(on_surface, chord) <= 0.5 * distance(pa, pb) ? on_surface : chord;
}

}  // namespace

long long add_mid_edge_nodes(const ShapeIndex& index, const std::vector<EdgeNodes>& edges,
                             const std::vector<NodeId>& node_id,
                             const std::vector<const FaceMeshResult*>& face_meshes, ShapeMesh& mesh) {
  const std::unordered_map<std::uint64_t, Segment> segments = curve_segments(edges, node_id);
  std::unordered_map<std::uint64_t, NodeId> middle;
  middle.reserve(2 * mesh.quads.size() + 16);
  mesh.mid_nodes.assign(mesh.quads.size(), Quad{});
  for (std::size_t r = 0; r < mesh.faces.size(); ++r) {
    const FaceMesh& record = mesh.faces[r];
    const FaceMeshResult& m = *face_meshes[r];
    const BRepAdaptor_Surface surface(index.face(record.face));
    for (std::int64_t k = 0; k < record.quad_count; ++k) {
      const std::size_t global = static_cast<std::size_t>(record.first_quad + k);
      const Quad& g = mesh.quads[global];
      const Quad& l = m.quads[static_cast<std::size_t>(k)];
      for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4;
        const std::uint64_t key = edge_key(g[i], g[j]);
        const auto [it, added] = middle.emplace(key, static_cast<NodeId>(mesh.nodes.size()));
        if (added) {
          const auto segment = segments.find(key);
          const Vec3 p = segment != segments.end()
                             ? curve_middle(index, edges, segment->second)
                             : surface_middle(surface, m, l[i], l[j], mesh.nodes[g[i]], mesh.nodes[g[j]]);
          mesh.nodes.push_back(p);
        }
        mesh.mid_nodes[global][i] = it->second;
      }
    }
  }
  return straighten_folded_quads(mesh);
}

}  // namespace tquad
