#include "occ/face_decomposed.h"

#include <BRepAdaptor_Surface.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/decomposed_mesher.h"
#include "core/input_error.h"

namespace tquad {

namespace {

Vec3 to_vec3(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

// (u, v) <-> chart: x = mirror * su * u, y = sv * v.
struct Chart {
  double su = 1, sv = 1, mirror = 1;
  Vec3 to_chart(const Vec3& uv) const { return {mirror * su * uv.x, sv * uv.y, 0.0}; }
  Vec3 to_uv(const Vec3& xy) const { return {xy.x / (mirror * su), xy.y / sv, 0.0}; }
};

// Mean |S_u| and |S_v| on a 5 x 5 grid over the loop's (u, v) box.
Chart chart_for(const BRepAdaptor_Surface& surface, const std::vector<Vec3>& uv) {
  double u0 = uv[0].x, u1 = uv[0].x, v0 = uv[0].y, v1 = uv[0].y;
  for (const Vec3& p : uv) {
    u0 = std::min(u0, p.x); u1 = std::max(u1, p.x);
    v0 = std::min(v0, p.y); v1 = std::max(v1, p.y);
  }
  double su = 0, sv = 0;
  int samples = 0;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      gp_Pnt p;
      gp_Vec du, dv;
      surface.D1(u0 + (u1 - u0) * (i + 0.5) / 5, v0 + (v1 - v0) * (j + 0.5) / 5, p, du, dv);
      su += du.Magnitude();
      sv += dv.Magnitude();
      ++samples;
    }
  }
  Chart c;
  c.su = su / samples;
  c.sv = sv / samples;
  if (!(c.su > 0) || !(c.sv > 0) || !std::isfinite(c.su) || !std::isfinite(c.sv)) c.su = c.sv = 1;
  return c;
}

DomainLoop chart_loop(const Chart& chart, const std::vector<Vec3>& uv, const std::vector<NodeId>& ids,
                      int vertex_nodes) {
  DomainLoop loop;
  for (std::size_t i = 0; i < uv.size(); ++i) {
    loop.points.push_back(chart.to_chart(uv[i]));
    loop.vertex.push_back(ids[i] < vertex_nodes);
  }
  return loop;
}

}  // namespace

FaceMeshResult mesh_face_decomposed(const TopoDS_Face& face, int face_index, const FaceBoundary& b,
                                    const std::vector<Vec3>& nodes, int vertex_nodes, double edge_size,
                                    const MeshOptions& options) {
  const std::string name = "face " + std::to_string(face_index);
  if (b.has_degenerate_edge || b.polar) throw InputError(name + " has a pole; it is not decomposed");
  const auto start = std::chrono::steady_clock::now();
  const BRepAdaptor_Surface surface(face);
  Chart chart = chart_for(surface, b.uv);
  if (signed_uv_area(b.uv) < 0) chart.mirror = -1;

  FaceMeshResult out;
  PlanarDomain domain;
  std::vector<Vec3> uv = b.uv;
  domain.loops.push_back(chart_loop(chart, b.uv, b.nodes, vertex_nodes));
  out.boundary_nodes = b.nodes;
  for (const NodeLoop& hole : b.holes) {
    DomainLoop loop = chart_loop(chart, hole.uv, hole.nodes, vertex_nodes);
    std::vector<NodeId> ids = hole.nodes;
    std::vector<Vec3> hole_uv = hole.uv;
    if (twice_signed_area(loop.points) > 0) {  // holes run clockwise in the chart
      std::reverse(loop.points.begin(), loop.points.end());
      std::reverse(loop.vertex.begin(), loop.vertex.end());
      std::reverse(ids.begin(), ids.end());
      std::reverse(hole_uv.begin(), hole_uv.end());
    }
    domain.loops.push_back(std::move(loop));
    out.boundary_nodes.insert(out.boundary_nodes.end(), ids.begin(), ids.end());
    uv.insert(uv.end(), hole_uv.begin(), hole_uv.end());
  }

  QuadMesh mesh;
  try {
    mesh = mesh_planar_domain(domain, edge_size, options);
  } catch (const InputError& e) {
    throw InputError(name + " (decomposed into patches): " + e.what());
  }
  out.quads = mesh.quads;
  if (!runs_counter_clockwise(b, face)) for (Quad& q : out.quads) std::swap(q[1], q[3]);
  out.template_tree = mesh.template_tree;
  out.template_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const auto placing = std::chrono::steady_clock::now();
  const std::size_t n = out.boundary_nodes.size();
  out.interior.reserve(mesh.nodes.size() - n);
  for (std::size_t i = n; i < mesh.nodes.size(); ++i) {
    uv.push_back(chart.to_uv(mesh.nodes[i]));
    out.interior.push_back(to_vec3(surface.Value(uv.back().x, uv.back().y)));
  }
  out.placement_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - placing).count();
  std::vector<Vec3> xyz;
  xyz.reserve(mesh.nodes.size());
  for (NodeId id : out.boundary_nodes) xyz.push_back(nodes[id]);
  xyz.insert(xyz.end(), out.interior.begin(), out.interior.end());
  check_on_surface(face, uv, std::nullopt, xyz, out);
  return out;
}

}  // namespace tquad
