#include "occ/face/mid_edge_nodes.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>

#include <cstdint>
#include <optional>

#include "core/mesh/mesh_edges.h"
#include "core/mesh/quadratic_quad.h"
#include "occ/model/occ_vec.h"

namespace tquad {

namespace {

// For each mesh edge that is a segment of a CAD edge (found by its end nodes, in the
// mesh's ids), the curve at the segment's middle parameter; one curve adaptor per
// CAD edge. Two CAD edges between the same two nodes: the first one's.
std::vector<std::optional<Vec3>> curve_middles(const ShapeIndex& index, const std::vector<EdgeNodes>& edges,
                                               const std::vector<NodeId>& node_id, const MeshEdges& mesh_edges) {
  std::vector<std::optional<Vec3>> middles(mesh_edges.count());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const EdgeNodes& en = edges[e];
    if (en.degenerate || en.nodes.size() < 2) continue;
    std::optional<BRepAdaptor_Curve> curve;  // only for an edge the mesh has
    for (std::size_t i = 0; i + 1 < en.nodes.size(); ++i) {
      const NodeId a = node_id[en.nodes[i]], b = node_id[en.nodes[i + 1]];
      if (a < 0 || b < 0) continue;  // an edge of faces not meshed
      const std::size_t edge = mesh_edges.index(a, b);
      if (edge == MeshEdges::npos || middles[edge]) continue;
      if (!curve) curve.emplace(index.edge(static_cast<int>(e)));
      middles[edge] = to_vec3(curve->Value(0.5 * (en.params[i] + en.params[i + 1])));
    }
  }
  return middles;
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
  const MeshEdges mesh_edges(mesh.nodes.size(), mesh.quads);
  const std::vector<std::optional<Vec3>> on_curves = curve_middles(index, edges, node_id, mesh_edges);
  std::vector<NodeId> middle(mesh_edges.count(), -1);
  mesh.nodes.reserve(mesh.nodes.size() + mesh_edges.count());
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
        const std::size_t edge = mesh_edges.index(g[i], g[j]);
        if (middle[edge] < 0) {
          middle[edge] = static_cast<NodeId>(mesh.nodes.size());
          const Vec3 p = on_curves[edge] ? *on_curves[edge]
                                         : surface_middle(surface, m, l[i], l[j], mesh.nodes[g[i]], mesh.nodes[g[j]]);
          mesh.nodes.push_back(p);
        }
        mesh.mid_nodes[global][i] = middle[edge];
      }
    }
  }
  return straighten_folded_quads(mesh);
}

}  // namespace tquad
