#include "occ/face/face_decomposed.h"
#include "core/cancellation.h"

#include <BRepAdaptor_Surface.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/decomposition/cut_intervals.h"
#include "core/decomposition/decomposed_mesher.h"
#include "core/templates/disk_o_grid.h"
#include "core/templates/mapped_ring.h"
#include "core/decomposition/face_decomposition.h"
#include "core/decomposition/hole_rings.h"
#include "core/decomposition/touching_loops.h"
#include "core/face_refusal.h"
#include "core/input_error.h"
#include "core/templates/o_grid.h"
#include "occ/intervals/edge_discretization.h"
#include "occ/model/occ_vec.h"

namespace tquad {

namespace {


// The face's own coordinates (its (u, v), or polar (x, y) around a smooth pole:
// FaceBoundary::polar) <-> chart: x = mirror * su * p.x, y = sv * p.y.
struct Chart {
  double su = 1, sv = 1, mirror = 1;
  std::optional<PolarMap> polar;
  Vec3 to_chart(const Vec3& p) const { return {mirror * su * p.x, sv * p.y, 0.0}; }
  Vec3 to_own(const Vec3& xy) const { return {xy.x / (mirror * su), xy.y / sv, 0.0}; }
  Vec3 surface_uv(const Vec3& own) const { return polar ? polar_to_uv(*polar, own) : own; }
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

// Polar (x, y) around a smooth pole scaled alike in x and y by the loop's length in
// space over its length in (x, y), so the rim keeps its length. On a sphere the map
// is its azimuthal equidistant projection, its radii uniform: a hemisphere's come out
// 2 / pi of their length on the surface, shallower caps' nearer their own.
Chart polar_chart(const FaceBoundary& b) {
  double along = 0;
  for (std::size_t i = 0; i < b.uv.size(); ++i) along += distance(b.uv[i], b.uv[(i + 1) % b.uv.size()]);
  Chart c;
  c.polar = b.polar;
  c.su = c.sv = along > 0 && b.arc_length.size() == b.uv.size() + 1 ? b.arc_length.back() / along : 1.0;
  if (!(c.su > 0) || !std::isfinite(c.su)) c.su = c.sv = 1;
  return c;
}

// A face's domain in its chart, with the shared node and (u, v) of each domain point.
class FaceChart {
 public:
  FaceChart(const TopoDS_Face& face, int face_index, const FaceBoundary& b, const std::vector<Vec3>& nodes,
            int vertex_nodes)
      : face_(face), name_("face " + std::to_string(face_index)), b_(b), nodes_(nodes), surface_(face) {
    if (b.polar ? !b.smooth_pole : b.has_degenerate_edge) throw InputError(name_ + " has a pole; it is not decomposed");
    if (b.uv.size() < 3 || b.uv.size() != b.nodes.size()) {
      throw FaceRefusalError(RefusalCode::too_coarse, name_ + " has only " + std::to_string(b.nodes.size()) + " boundary segments");
    }
    for (const NodeLoop& hole : b.holes) {
      if (hole.uv.size() < 3 || hole.uv.size() != hole.nodes.size()) {
        throw FaceRefusalError(RefusalCode::too_coarse, name_ + " has a hole of only " + std::to_string(hole.nodes.size()) + " segments");
      }
    }
    chart_ = b.polar ? polar_chart(b) : chart_for(surface_, b.uv);
    if (signed_uv_area(b.uv) < 0) chart_.mirror = -1;
    add_loop(b.uv, b.nodes, vertex_nodes, false);
    for (const NodeLoop& hole : b.holes) add_loop(hole.uv, hole.nodes, vertex_nodes, true);
    splice_touching_holes();
    try {
      check_planar_domain(domain_);  // every route on this chart starts from a valid domain
    } catch (const InputError& e) {
      throw InputError(name_ + " in its (u, v) chart: " + e.what());
    }
    ringed_ = ring_holes(domain_);
  }

  // The domain the routes decompose: inside the rings around the holes.
  const PlanarDomain& domain() const { return ringed_.inner; }
  const std::string& name() const { return name_; }

  // The mesh of a decomposition of the domain, placed on the surface and checked;
  // `memo`: the patches of other decompositions already meshed.
  FaceMeshResult mesh(const FaceDecomposition& decomposition, double edge_size, const MeshOptions& options,
                      PatchMeshMemo* memo = nullptr) const {
    const auto start = std::chrono::steady_clock::now();
    const PlanarDomain& inner = ringed_.inner;
    return place(join_rings(domain_, ringed_,
                            mesh_decomposed_domain(inner, decomposition,
                                                   assign_cut_intervals(inner, decomposition, edge_size,
                                                                        cut_turn_minimums(decomposition)),
                                                   options,
                                                   memo)),
                 start);
  }

  // A mesh of the whole domain in the chart (its points first), placed on the surface
  // and checked; `start`: when building it began.
  FaceMeshResult place(const QuadMesh& mesh, std::chrono::steady_clock::time_point start) const {
    FaceMeshResult out;
    out.boundary_nodes = boundary_nodes_;
    out.quads = mesh.quads;
    if (!runs_counter_clockwise(b_, face_)) for (Quad& q : out.quads) std::swap(q[1], q[3]);
    out.template_tree = mesh.template_tree;
    out.template_seconds = seconds_since(start);

    const auto placing = std::chrono::steady_clock::now();
    const std::size_t n = boundary_nodes_.size();
    std::vector<Vec3> own = own_;
    out.interior.reserve(mesh.nodes.size() - n);
    for (std::size_t i = n; i < mesh.nodes.size(); ++i) {
      poll_cancellation(8);
      own.push_back(chart_.to_own(mesh.nodes[i]));
      const Vec3 uv = chart_.surface_uv(own.back());
      out.interior.push_back(to_vec3(surface_.Value(uv.x, uv.y)));
    }
    out.placement_seconds = seconds_since(placing);
    std::vector<Vec3> xyz;
    xyz.reserve(mesh.nodes.size());
    for (NodeId id : boundary_nodes_) xyz.push_back(nodes_[id]);
    xyz.insert(xyz.end(), out.interior.begin(), out.interior.end());
    check_on_surface(face_, surface_, own, chart_.polar, xyz, out);
    return out;
  }

  // The whole domain, before its rings (a disk has none).
  const PlanarDomain& whole_domain() const { return domain_; }

 private:
  // Per cut of `decomposition`, the fewest segments that stand for its turning on the
  // surface (segments_for_turn, as edges get): a cut is straight in the chart, not in
  // space. A torus groove of a shaft cut by a milled flat had cuts across its tube
  // (up to a half circle) of fewer segments than edges of that turn get, and some of
  // its quads stayed inverted.
  // None on a plane. The face's decompositions share most cuts: each is measured once.
  std::vector<int> cut_turn_minimums(const FaceDecomposition& decomposition) const {
    if (surface_.GetType() == GeomAbs_Plane) return {};
    std::vector<int> minimums;
    for (const CutCurve& cut : decomposition.cuts) {
      const std::pair<int, int> ends = std::minmax(cut.from, cut.to);
      auto known = cut_minimums_.find(ends);
      if (known == cut_minimums_.end()) {
        const double turn = turn_along(inner_point(ends.first), inner_point(ends.second));
        known = cut_minimums_.emplace(ends, segments_for_turn(turn)).first;
      }
      minimums.push_back(known->second);
    }
    return minimums;
  }

  Vec3 inner_point(int id) const {
    for (const DomainLoop& loop : ringed_.inner.loops) {
      if (id < static_cast<int>(loop.points.size())) return loop.points[id];
      id -= static_cast<int>(loop.points.size());
    }
    throw std::logic_error("a cut ends at no point of the domain");
  }

  // The turning in space of the chart's straight line from a to b: the angles between
  // successive chords of kChords (it reads about 1/kChords low on a circle's arc).
  double turn_along(const Vec3& a, const Vec3& b) const {
    constexpr int kChords = 32;
    double turn = 0;
    Vec3 previous_point, previous_chord;
    for (int i = 0; i <= kChords; ++i) {
      const Vec3 uv = chart_.surface_uv(chart_.to_own(a + (static_cast<double>(i) / kChords) * (b - a)));
      const Vec3 point = to_vec3(surface_.Value(uv.x, uv.y));
      if (i > 0) {
        const Vec3 chord = point - previous_point;
        if (norm(chord) > 0) {
          if (norm(previous_chord) > 0) turn += angle_between(previous_chord, chord);
          previous_chord = chord;
        }
      }
      previous_point = point;
    }
    return turn;
  }

  // A hole through a vertex of the outer loop (or of another hole) is spliced into
  // that loop (core/decomposition/touching_loops.h); the vertex's node stands for both its copies.
  void splice_touching_holes() {
    const std::vector<long long> ids(boundary_nodes_.begin(), boundary_nodes_.end());
    SplicedDomain spliced = splice_touching_loops(domain_, ids);
    if (spliced.splices == 0) return;
    domain_ = std::move(spliced.domain);
    std::vector<NodeId> nodes;
    std::vector<Vec3> own;
    for (int i : spliced.source) {
      nodes.push_back(boundary_nodes_[i]);
      own.push_back(own_[i]);
    }
    boundary_nodes_ = std::move(nodes);
    own_ = std::move(own);
  }

  // Holes run clockwise in the chart, the outer loop counter-clockwise. `own`: the
  // loop's points in the face's own coordinates.
  void add_loop(std::vector<Vec3> own, std::vector<NodeId> ids, int vertex_nodes, bool hole) {
    DomainLoop loop;
    for (std::size_t i = 0; i < own.size(); ++i) {
      loop.points.push_back(chart_.to_chart(own[i]));
      loop.vertex.push_back(ids[i] < vertex_nodes);
    }
    if (hole && twice_signed_area(loop.points) > 0) {
      std::reverse(loop.points.begin(), loop.points.end());
      std::reverse(loop.vertex.begin(), loop.vertex.end());
      std::reverse(ids.begin(), ids.end());
      std::reverse(own.begin(), own.end());
    }
    domain_.loops.push_back(std::move(loop));
    boundary_nodes_.insert(boundary_nodes_.end(), ids.begin(), ids.end());
    own_.insert(own_.end(), own.begin(), own.end());
  }

  const TopoDS_Face& face_;
  std::string name_;
  const FaceBoundary& b_;
  const std::vector<Vec3>& nodes_;
  BRepAdaptor_Surface surface_;
  Chart chart_;
  PlanarDomain domain_;
  RingedDomain ringed_;
  std::vector<NodeId> boundary_nodes_;
  std::vector<Vec3> own_;  // each boundary node's own coordinates ((u, v) or polar)
  mutable std::map<std::pair<int, int>, int> cut_minimums_;  // cut_turn_minimums, by the cut's ends
};

// The variants of the plain decomposition that may mesh a face better
// (DecompositionOptions): decomposition_variants, and corner ears cleared (`plain`:
// nothing when it could not be made).
std::vector<FaceMeshResult> mesh_variants(const FaceChart& chart, const std::optional<FaceDecomposition>& plain,
                                          double edge_size, const MeshOptions& options, PatchMeshMemo& memo) {
  std::vector<DecompositionOptions> variants(1);
  variants[0].clear_corner_ears = true;
  for (const DecompositionOptions& v : decomposition_variants({}, plain ? &*plain : nullptr)) variants.push_back(v);
  std::vector<FaceMeshResult> out;
  for (std::size_t k = 0; k < variants.size(); ++k) {
    const DecompositionOptions variant = variants[k];  // (variants may grow below)
    try {
      const FaceDecomposition decomposition = decompose_domain(chart.domain(), variant);
      // Cleared corner ears that split no piece give the plain decomposition again.
      if (variant.clear_corner_ears && decomposition.corner_splits == 0) continue;
      // Corner ears cleared also as before reflex extensions and square pairs where
      // those acted, as they move cuts there too (the ears cleared alone can give a
      // better worst quad than with them).
      if (k == 0 && (decomposition.reflex_extensions > 0 || decomposition.square_pair_slivers > 0)) {
        DecompositionOptions& before = variants.emplace_back(variant);
        before.extend_reflex_corners = false;
        before.keep_square_pairs = false;
      }
      out.push_back(chart.mesh(decomposition, edge_size, options, &memo));
    } catch (const InputError&) {  // the plain decomposition's mesh stays, as in face_route
    }
  }
  return out;
}

}  // namespace

std::vector<FaceMeshResult> mesh_face_decomposed(const TopoDS_Face& face, int face_index, const FaceBoundary& b,
                                                 const std::vector<Vec3>& nodes, int vertex_nodes, double edge_size,
                                                 const MeshOptions& options) {
  const FaceChart chart(face, face_index, b, nodes, vertex_nodes);
  std::vector<FaceMeshResult> meshes;
  PatchMeshMemo patches;  // the decompositions differ only here and there
  std::string plain_problem;
  std::optional<FaceDecomposition> plain;
  try {
    plain = decompose_domain(chart.domain());
    meshes.push_back(chart.mesh(*plain, edge_size, options, &patches));
  } catch (const InputError& e) {
    plain_problem = e.what();  // a variant below may still mesh the face
  }
  for (FaceMeshResult& variant : mesh_variants(chart, plain, edge_size, options, patches)) {
    meshes.push_back(std::move(variant));
  }
  if (meshes.empty()) throw InputError(chart.name() + " (decomposed into patches): " + plain_problem);
  // The best first; the others keep their order (the plain decomposition first).
  std::stable_sort(meshes.begin(), meshes.end(),
                   [](const FaceMeshResult& x, const FaceMeshResult& y) { return better_face_mesh(x, y); });
  return meshes;
}

std::optional<FaceMeshResult> mesh_face_disk(const TopoDS_Face& face, int face_index, const FaceBoundary& b,
                                             const std::vector<Vec3>& nodes, int vertex_nodes,
                                             const MeshOptions& options) {
  const FaceChart chart(face, face_index, b, nodes, vertex_nodes);
  const auto start = std::chrono::steady_clock::now();
  const std::optional<QuadMesh> disk = mesh_disk_o_grid(chart.whole_domain(), options);
  if (!disk) return std::nullopt;
  return chart.place(*disk, start);
}

std::optional<FaceMeshResult> mesh_face_ring(const TopoDS_Face& face, int face_index, const FaceBoundary& b,
                                             const std::vector<Vec3>& nodes, int vertex_nodes) {
  const FaceChart chart(face, face_index, b, nodes, vertex_nodes);
  const auto start = std::chrono::steady_clock::now();
  const std::optional<QuadMesh> ring = mesh_mapped_ring(chart.whole_domain());
  if (!ring) return std::nullopt;
  return chart.place(*ring, start);
}

FaceMeshResult mesh_face_o_grid(const TopoDS_Face& face, int face_index, const FaceBoundary& b,
                                const std::vector<Vec3>& nodes, int vertex_nodes, double edge_size,
                                const MeshOptions& options) {
  constexpr int kPlaces = 8;
  const FaceChart chart(face, face_index, b, nodes, vertex_nodes);
  const int rim = chart.domain().loop_count() == 2 ? static_cast<int>(chart.domain().loops[1].points.size()) : 0;
  std::optional<FaceMeshResult> best;
  std::string problem = "no pair of cuts from the hole to the outer loop stays inside the face";
  PatchMeshMemo halves_meshed;  // places t and t + kPlaces / 2 give the same halves
  for (int t = 0; t < std::min(kPlaces, rim); ++t) {
    const std::optional<FaceDecomposition> halves = o_grid_decomposition(chart.domain(), t * rim / std::min(kPlaces, rim));
    if (!halves) continue;
    try {
      FaceMeshResult r = chart.mesh(*halves, edge_size, options, &halves_meshed);
      if (!best || better_face_mesh(r, *best)) best = std::move(r);
    } catch (const InputError& e) {  // the other places are still tried
      problem = e.what();
    }
  }
  if (!best) throw InputError(chart.name() + " (with a hole): " + problem);
  return std::move(*best);
}

}  // namespace tquad
