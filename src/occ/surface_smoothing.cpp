#include "occ/surface_smoothing.h"

#include <BRepAdaptor_Surface.hxx>

#include "core/doublets.h"
#include "core/smoothing.h"
#include "occ/occ_vec.h"

namespace tquad {

void smooth_face_mesh(const TopoDS_Face& face, bool has_seam, const std::vector<Vec3>& nodes, FaceMeshResult& mesh) {
  if ((mesh.used_projection && has_seam) || mesh.interior.empty()) return;
  // Every corner already at good_enough: smooth_mesh would move no node (it starts
  // from the nodes with a corner under it), and there is no doublet (a doublet's
  // node has a corner of 180 degrees or more). Measured: each mapped face of 3,364
  // quads of box.brep at D/100 spent about 12 ms here for nothing.
  if (mesh.worst_corner >= SmoothingOptions{}.good_enough) return;
  const std::size_t fixed = mesh.boundary_nodes.size();
  if (mesh.param.size() != fixed + mesh.interior.size()) return;  // not measured on the surface
  const BRepAdaptor_Surface surface(face);
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  const auto to_uv = [&](const Vec3& p) { return mesh.polar ? polar_to_uv(*mesh.polar, p) : p; };

  std::vector<Vec3> position, normal;
  position.reserve(mesh.param.size());
  for (NodeId id : mesh.boundary_nodes) position.push_back(nodes[id]);
  position.insert(position.end(), mesh.interior.begin(), mesh.interior.end());
  for (const Vec3& p : mesh.param) normal.push_back(outer_normal(surface, reversed, to_uv(p)));
  const PlaceNode place = [&](int, const Vec3& p, Vec3& at, Vec3& n) {
    const Vec3 uv = to_uv(p);
    n = outer_normal(surface, reversed, uv, at);
    return norm(n) > 0;
  };
  // Doublets merged where the merged quad is no worse; where some are not, also with
  // every doublet merged and its reflex corner left to the smoothing, the better kept.
  const FaceMeshResult original = mesh;
  int strict_merges = -1;
  for (bool even_if_worse : {false, true}) {
    std::vector<Vec3> param = original.param, moved = position, normals = normal;
    std::vector<Quad> quads = original.quads;
    const int merged = remove_doublets(quads, static_cast<int>(fixed), param, moved, normals, even_if_worse);
    if (even_if_worse && merged == strict_merges) break;  // no doublet was refused
    if (!even_if_worse) strict_merges = merged;
    const long long moves = smooth_mesh(quads, static_cast<int>(fixed), param, moved, normals, place).moves;
    if (merged == 0 && moves == 0) continue;
    FaceMeshResult smoothed = original;
    smoothed.quads = std::move(quads);
    smoothed.interior.assign(moved.begin() + fixed, moved.end());
    check_on_surface(face, param, original.polar, moved, smoothed);
    if (!better_face_mesh(mesh, smoothed)) mesh = std::move(smoothed);
  }
}

}  // namespace tquad
