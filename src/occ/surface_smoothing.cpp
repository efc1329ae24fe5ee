#include "occ/surface_smoothing.h"

#include <BRepAdaptor_Surface.hxx>

#include "core/doublets.h"
#include "core/smoothing.h"
#include "occ/occ_vec.h"

namespace tquad {

void smooth_face_mesh(const TopoDS_Face& face, const std::vector<Vec3>& nodes, FaceMeshResult& mesh) {
  if (mesh.used_projection || mesh.interior.empty()) return;
  const std::size_t fixed = mesh.boundary_nodes.size();
  if (mesh.param.size() != fixed + mesh.interior.size()) return;  // not measured on the surface
  const BRepAdaptor_Surface surface(face);
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  const auto to_uv = [&](const Vec3& p) { return mesh.polar ? polar_to_uv(*mesh.polar, p) : p; };

  std::vector<Vec3> param = mesh.param, position, normal;
  position.reserve(param.size());
  for (NodeId id : mesh.boundary_nodes) position.push_back(nodes[id]);
  position.insert(position.end(), mesh.interior.begin(), mesh.interior.end());
  for (const Vec3& p : param) normal.push_back(outer_normal(surface, reversed, to_uv(p)));
  const PlaceNode place = [&](const Vec3& p, Vec3& at, Vec3& n) {
    const Vec3 uv = to_uv(p);
    at = to_vec3(surface.Value(uv.x, uv.y));
    n = outer_normal(surface, reversed, uv);
    return norm(n) > 0;
  };
  std::vector<Quad> quads = mesh.quads;
  const int merged = remove_doublets(quads, static_cast<int>(fixed), param, position, normal);
  const long long moves = smooth_mesh(quads, static_cast<int>(fixed), param, position, normal, place).moves;
  if (merged == 0 && moves == 0) return;

  FaceMeshResult smoothed = mesh;
  smoothed.quads = std::move(quads);
  smoothed.interior.assign(position.begin() + fixed, position.end());
  check_on_surface(face, param, mesh.polar, position, smoothed);
  if (!better_face_mesh(mesh, smoothed)) mesh = std::move(smoothed);
}

}  // namespace tquad
