#include "occ/face/pole_to_pole.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/templates/cube_sphere.h"
#include "core/face_refusal.h"
#include "occ/face/face_boundary.h"
#include "occ/model/occ_vec.h"

namespace tquad {

int closed_seam_edge(const ShapeIndex& index, int f) {
  const TopoDS_Face& face = index.face(f);
  int wires = 0;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
  if (wires != 1) return -1;
  int seam = -1, poles = 0;
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    if (BRep_Tool::Degenerated(edge)) {
      if (is_pole_edge(edge, face)) ++poles;
    } else if (BRep_Tool::IsClosed(edge, face)) {
      const int e = index.edge_index(edge);
      if (seam >= 0 && seam != e) return -1;
      seam = e;
    } else {
      return -1;
    }
  }
  return poles > 0 ? seam : -1;
}

FaceMeshResult mesh_pole_to_pole(const TopoDS_Face& face, int face_index, const FaceBoundary& b,
                                 const std::vector<Vec3>& nodes) {
  const std::string name = "face " + std::to_string(face_index);
  const BRepAdaptor_Surface surface(face);
  if (!surface.IsUPeriodic()) {
    throw FaceRefusalError(RefusalCode::not_supported, name + " is closed around two poles but not periodic in u");
  }
  // The seam's nodes from one pole to the other: its first walk in the loop.
  const int n = static_cast<int>(b.nodes.size());
  const auto k = std::find(b.is_seam.begin(), b.is_seam.end(), 1) - b.is_seam.begin();
  if (k == static_cast<long>(b.is_seam.size())) throw FaceRefusalError(RefusalCode::cannot_mesh, name + " has no seam");
  const int first = b.edge_start[k];
  const int last = k + 1 < static_cast<long>(b.edge_start.size()) ? b.edge_start[k + 1] : n;
  std::vector<int> seam;  // loop positions
  for (int i = first; i <= last; ++i) seam.push_back(i % n);
  const int segments = static_cast<int>(seam.size()) - 1;
  if (segments < 4 || segments % 4 != 0 || b.nodes[seam.front()] == b.nodes[seam.back()]) {
    throw FaceRefusalError(RefusalCode::cannot_mesh,
                           name + " (closed around two poles): its seam has " + std::to_string(segments) +
                               " segments; the cube sphere needs a multiple of 4 from pole to pole");
  }
  const int m = segments / 2;
  const CubeSphere cube = cube_sphere(m);
  // Local numbering: the seam's nodes first (shared), then the others.
  std::vector<NodeId> local(cube.nodes.size(), -1);
  FaceMeshResult out;
  for (int t = 0; t <= segments; ++t) {
    local[cube.seam[t]] = t;
    out.boundary_nodes.push_back(b.nodes[seam[t]]);
  }
  const double period = surface.UPeriod();
  const double u_seam = b.uv[seam.front()].x;
  std::vector<Vec3> param(out.boundary_nodes.size()), xyz(out.boundary_nodes.size());
  for (int t = 0; t <= segments; ++t) {
    param[t] = b.uv[seam[t]];
    xyz[t] = nodes[b.nodes[seam[t]]];
  }
  // v at a latitude: the seam's nodes are at latitudes -90 + 90 t / m degrees.
  const auto v_at = [&](double latitude) {
    const double t = std::clamp((latitude + M_PI / 2) / (M_PI / segments), 0.0, static_cast<double>(segments));
    const int i = std::min(static_cast<int>(t), segments - 1);
    const double w = t - i;
    return (1 - w) * b.uv[seam[i]].y + w * b.uv[seam[i + 1]].y;
  };
  for (std::size_t c = 0; c < cube.nodes.size(); ++c) {
    if (local[c] >= 0) continue;
    const Vec3& d = cube.nodes[c];
    const double longitude = std::atan2(d.y, d.x), latitude = std::asin(std::clamp(d.z, -1.0, 1.0));
    const Vec3 uv{u_seam + longitude / (2 * M_PI) * period, v_at(latitude), 0};
    local[c] = static_cast<NodeId>(param.size());
    param.push_back(uv);
    const gp_Pnt p = surface.Value(uv.x, uv.y);
    xyz.push_back(to_vec3(p));
    out.interior.push_back(to_vec3(p));
  }
  for (const Quad& q : cube.quads) out.quads.push_back({local[q[0]], local[q[1]], local[q[2]], local[q[3]]});
  out.template_tree = "C6[T0,T0,T0,T0,T0,T0]";
  check_on_surface(face, surface, param, std::nullopt, xyz, out);
  // The cube's orientation against the face's outer normal depends on the direction
  // of u and v: quads turned the other way are reversed.
  long long negative = 0;
  for (double s : out.scaled_jacobian) negative += s < 0 ? 1 : 0;
  if (2 * negative > static_cast<long long>(out.quads.size())) {
    for (Quad& q : out.quads) q = {q[0], q[3], q[2], q[1]};
    check_on_surface(face, surface, param, std::nullopt, xyz, out);
  }
  return out;
}

}  // namespace tquad
