#include "occ/face_mesher.h"

#include <BRepAdaptor_Surface.hxx>
#include <Extrema_ExtPS.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <BRep_Tool.hxx>

#include <algorithm>

#include "core/input_error.h"
#include "core/planar_self_intersection.h"
#include "core/quality.h"

namespace tquad {

namespace {

Vec3 to_vec3(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

// The quads of a template mesh in the face's local numbering, reversed when the loop
// runs clockwise around the outer normal.
void take_quads(const QuadMesh& mesh, bool reverse, FaceMeshResult& out) {
  out.quads = mesh.quads;
  if (reverse) for (Quad& q : out.quads) std::swap(q[1], q[3]);
  out.template_tree = mesh.template_tree;
}

long long inverted_quads(const QuadMesh& mesh, const std::optional<Vec3>& normal) {
  return summarize_quality(mesh, normal).inverted;
}

FaceMeshResult mesh_in_parameter_space(const TopoDS_Face& face, const FaceBoundary& b,
                                       const std::vector<int>& corners, const MeshOptions& options) {
  const QuadMesh uv_mesh = mesh_boundary(BoundaryLoop{b.uv, corners}, options);
  FaceMeshResult out;
  take_quads(uv_mesh, !runs_counter_clockwise(b, face), out);
  out.inverted = inverted_quads(uv_mesh, Vec3{0, 0, signed_uv_area(b.uv) > 0 ? 1.0 : -1.0});
  const BRepAdaptor_Surface surface(face);
  const std::size_t n = b.nodes.size();
  out.interior.reserve(uv_mesh.nodes.size() - n);
  for (std::size_t i = n; i < uv_mesh.nodes.size(); ++i) {
    out.interior.push_back(to_vec3(surface.Value(uv_mesh.nodes[i].x, uv_mesh.nodes[i].y)));
  }
  return out;
}

FaceMeshResult mesh_in_space(const TopoDS_Face& face, const FaceBoundary& b, const std::vector<int>& corners,
                             const std::vector<Vec3>& nodes, const MeshOptions& options) {
  // A loop through a seam meets the seam's nodes twice: in space it folds onto itself.
  std::vector<NodeId> sorted = b.nodes;
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end()) {
    throw InputError("the boundary passes twice through node " + std::to_string(*twice) +
                     " (a seam); a face with both a seam and a pole is not supported yet");
  }
  std::vector<Vec3> loop;
  for (NodeId id : b.nodes) loop.push_back(nodes[id]);
  const QuadMesh mesh = mesh_boundary(BoundaryLoop{loop, corners}, options);
  FaceMeshResult out;
  out.used_projection = true;
  // The 3D loop's own orientation: compare with the outer normal at the first node.
  const Vec3 loop_normal = newell_normal(loop);
  const BRepAdaptor_Surface surface(face);
  gp_Pnt p;
  gp_Vec du, dv;
  surface.D1(b.uv[0].x, b.uv[0].y, p, du, dv);
  Vec3 outer{du.Crossed(dv).X(), du.Crossed(dv).Y(), du.Crossed(dv).Z()};
  if (face.Orientation() == TopAbs_REVERSED) outer = -1.0 * outer;
  take_quads(mesh, dot(loop_normal, outer) < 0, out);
  out.inverted = inverted_quads(mesh, std::nullopt);

  // Closest points on the surface, each search started from the previous node's
  // (u, v): neighbouring nodes are created one after the other.
  const Handle(Geom_Surface) geom = BRep_Tool::Surface(face);
  ShapeAnalysis_Surface analysis(geom);
  const double tolerance = BRep_Tool::Tolerance(face);
  gp_Pnt2d previous(b.uv[0].x, b.uv[0].y);
  const TopLoc_Location location = face.Location();
  const gp_Trsf to_local = location.Transformation().Inverted();
  const gp_Trsf to_global = location.Transformation();
  for (std::size_t i = loop.size(); i < mesh.nodes.size(); ++i) {
    const Vec3& q = mesh.nodes[i];
    const gp_Pnt local = gp_Pnt(q.x, q.y, q.z).Transformed(to_local);
    previous = analysis.NextValueOfUV(previous, local, tolerance);
    out.interior.push_back(to_vec3(geom->Value(previous.X(), previous.Y()).Transformed(to_global)));
  }
  return out;
}

}  // namespace

FaceMeshResult mesh_face(const ShapeIndex& index, int face_index, const FaceBoundary& boundary,
                         const std::vector<int>& corners, const std::vector<Vec3>& nodes,
                         const MeshOptions& options) {
  const TopoDS_Face& face = index.face(face_index);
  const std::string name = "face " + std::to_string(face_index);
  if (boundary.inner_wires > 0) {
    throw InputError(name + " has " + std::to_string(boundary.inner_wires) +
                     " inner wire(s) (holes); faces with holes are not supported yet");
  }
  if (boundary.nodes.size() < 4) {
    throw InputError(name + " has only " + std::to_string(boundary.nodes.size()) +
                     " boundary segments; use a smaller --size");
  }
  // A degenerate edge (a pole) is one point in space but a segment in (u, v): the
  // parameter-space mesh would collapse quads there, so such a face takes the 3D route,
  // where the pole is a single loop node.
  std::string uv_problem = "a degenerate edge (pole) collapses quads in (u, v)";
  if (!boundary.has_degenerate_edge) {
    try {
      return mesh_in_parameter_space(face, boundary, corners, options);
    } catch (const InputError& e) {
      uv_problem = e.what();
    }
  }
  try {
    return mesh_in_space(face, boundary, corners, nodes, options);
  } catch (const InputError& e) {
    throw InputError(name + " cannot be meshed: in (u, v): " + uv_problem + "; in 3D: " + e.what());
  }
}

}  // namespace tquad
