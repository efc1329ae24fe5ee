#include "occ/face/face_route.h"

#include "core/cancellation.h"

#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>

#include <algorithm>
#include <iterator>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <unordered_map>

#include "core/elapsed.h"
#include "core/face_refusal.h"
#include "core/input_error.h"
#include "core/templates/mesher.h"
#include "core/mesh/quality.h"
#include "occ/intervals/crossing_chords.h"
#include "occ/intervals/edge_discretization.h"
#include "occ/face/face_corners.h"
#include "occ/face/face_decomposed.h"
#include "occ/face/face_mesh_closure.h"
#include "occ/face/pole_to_pole.h"
#include "occ/face/surface_smoothing.h"

namespace tquad {

namespace {

// A face whose quads stay inverted.
struct InvertedQuadsError : FaceRefusalError {
  InvertedQuadsError(const std::string& message, std::size_t quads, bool coarse_for_curvature)
      : FaceRefusalError(RefusalCode::inverted_quads, message), quads(quads),
        coarse_for_curvature(coarse_for_curvature) {}
  std::size_t quads;  // in the face's best mesh
  bool coarse_for_curvature;  // has_quad_over_curvature of that mesh
};

// Whether some quad of `mesh` spans more of its surface's turning than a segment may
// stand for (segments_for_turn, the edges' rule): the surface normals at two of its
// corners more than 45 degrees apart. Such a face is coarse for its curvature, and
// finer edges may cure its inverted quads however many it has: a narrow fillet band
// twisting along its length, meshed with segments several times its width, had
// quads inverted, their corners' normals well over 45 degrees apart.
bool has_quad_over_curvature(const FaceMeshResult& mesh) {
  if (mesh.normal.size() != mesh.boundary_nodes.size() + mesh.interior.size()) return false;
  for (const Quad& q : mesh.quads) {
    poll_cancellation(4);
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        const Vec3 &a = mesh.normal[q[i]], &b = mesh.normal[q[j]];
        if (norm(a) == 0 || norm(b) == 0) continue;  // singular there (a pole)
        if (segments_for_turn(angle_between(a, b)) > 1) return true;
      }
    }
  }
  return false;
}

// The refusal code of what a meshing route threw: the code it carries, cannot_mesh for
// any other wrong input, internal for anything else (the mesher's own failure).
RefusalCode refusal_code_of(const std::exception& e) {
  if (const auto* known = dynamic_cast<const FaceRefusalError*>(&e)) return known->code();
  return dynamic_cast<const InputError*>(&e) ? RefusalCode::cannot_mesh : RefusalCode::internal;
}

// Finer edges may cure a face meshed with at most this many quads: a small curved face
// of a few segments cannot be meshed on its surface however its nodes move. Larger
// faces keep their counts (doubling them did not help in the parts measured, and it
// grows the neighbours' meshes too) unless they are coarse for their curvature
// (has_quad_over_curvature).
constexpr std::size_t kRefinableQuads = 16;

// A face meshed whole (templates on its own corners, or the one-hole O-grid) whose
// worst corner reaches this keeps that mesh; below it, the face decomposition is
// tried too and the better mesh kept.
constexpr double kGoodEnoughCorner = 0.3;
// The decomposition's other variants are smoothed too only where the smoothed best
// stays under this. Smoothing them all doubled the smoothing time on parts with many
// decomposed faces for means barely higher on faces already fair; the worst quads it
// is for (where the variant ranked first before smoothing ends below another after
// it) are lower.
constexpr double kSmoothVariantsBelow = 0.25;
// ... first with this many passes each (fewer than SmoothingOptions::passes), and
// only the best of them in full: smoothing every variant of a large decomposed face in
// full took many times its meshing.
constexpr SmoothingOptions kVariantLook{2};

// --corners best screens its corner sets on the face's (u, v) loop, where a template
// mesh costs microseconds, and meshes on the surface only the kSurfaceCandidates best
// of them (fewest inverted quads, then the best worst and mean scaled Jacobian in
// (u, v)): a set meshed on the surface costs far more, and meshing every set made
// runs on faces with many candidate sets an order of magnitude slower.
constexpr std::size_t kSurfaceCandidates = 4;

std::vector<std::vector<int>> screened_corner_sets(const FaceBoundary& boundary,
                                                   const std::vector<std::vector<int>>& sets,
                                                   const MeshOptions& options) {
  const Vec3 up{0, 0, signed_uv_area(boundary.uv) > 0 ? 1.0 : -1.0};
  // Without the repair of folded quads: a fold counts against the set, and repairing
  // it took most of the screening's time.
  MeshOptions screening = options;
  screening.untangle = false;
  struct Screened {
    long long inverted;
    double worst, mean;
    const std::vector<int>* corners;
  };
  std::vector<Screened> screened;
  for (const std::vector<int>& corners : sets) {
    try {
      const QuadMesh mesh = mesh_boundary(BoundaryLoop{boundary.uv, corners}, screening);
      const QualitySummary q = summarize_quality(mesh, up);
      screened.push_back({q.inverted, q.scaled_jacobian.min, q.scaled_jacobian.avg, &corners});
    } catch (const InputError&) {  // a set the templates cannot mesh is no candidate
    }
  }
  std::stable_sort(screened.begin(), screened.end(), [](const Screened& a, const Screened& b) {
    if (a.inverted != b.inverted) return a.inverted < b.inverted;
    if (a.worst != b.worst) return a.worst > b.worst;
    return a.mean > b.mean;
  });
  std::vector<std::vector<int>> kept;
  for (std::size_t i = 0; i < screened.size() && i < kSurfaceCandidates; ++i) kept.push_back(*screened[i].corners);
  return kept;
}

// The natural choice's candidates: the best mesh of the routes, the other variants of
// its decomposition, and the decomposition with its poor patches' corners searched.
struct NaturalChoice {
  FaceMeshResult best;
  std::vector<FaceMeshResult> other_decompositions;
  std::optional<FaceMeshResult> patches_searched;
  std::vector<FaceMeshResult> judged_smoothed;  // RouteContext::judged_smoothed
  // Of the smoothed meshes that lost to `best`, the one of highest mean with no bad
  // quad (FaceOutcome::higher_mean).
  std::optional<FaceMeshResult> higher_mean;
};

// Whether `loser`, a smoothed mesh that did not win, is kept as the face's higher-mean
// alternative: no quad unfit for analysis (`bad` counts the inverted and collapsed ones
// too) or cutting across the surface, and a higher mean than the one kept so far.
void offer_higher_mean(FaceMeshResult&& loser, std::optional<FaceMeshResult>& kept) {
  if (loser.bad > 0 || loser.off_surface > 0 || loser.quads.empty()) return;
  if (kept && mean_scaled_jacobian(loser) <= mean_scaled_jacobian(*kept)) return;
  kept = std::move(loser);
}

// The natural choice smoothed (when `smooth`): its best mesh, or, where smoothing
// reorders them, another variant or the searched patches (better_worst_then_mean).
// The smoothed meshes that lose are offered as the higher-mean alternative.
FaceMeshResult settle_natural_choice(const TopoDS_Face& face, bool seam, const std::vector<Vec3>& nodes, bool smooth,
                                     NaturalChoice& choice) {
  FaceMeshResult& best = choice.best;
  if (!smooth) {
    if (choice.patches_searched && better_worst_then_mean(*choice.patches_searched, best)) {
      best = std::move(*choice.patches_searched);
    }
    for (FaceMeshResult& layout : choice.judged_smoothed) {
      if (better_worst_then_mean(layout, best)) best = std::move(layout);
    }
    return std::move(best);
  }
  // The challenger smoothed already; the better of it and `best` stays as `best`.
  const auto contest = [&](FaceMeshResult&& challenger) {
    if (better_worst_then_mean(challenger, best)) std::swap(challenger, best);
    offer_higher_mean(std::move(challenger), choice.higher_mean);
  };
  smooth_face_mesh(face, seam, nodes, best);
  // The variants are ranked on their meshes before smoothing, which smoothing can
  // reorder (the variant ranked second before smoothing can end the better one after
  // it): each is smoothed too (a quick look, then the most promising in full), and
  // the best after smoothing kept (the worst corner, then the mean: variants differ
  // here and there, and often share their worst quad).
  std::vector<FaceMeshResult>& others = choice.other_decompositions;
  if (best.bad == 0 && best.collapsed == 0 && best.worst_corner >= kSmoothVariantsBelow) others.clear();
  // Each looked at with a few passes, and the best of them smoothed in full.
  std::size_t promising = 0;
  std::optional<FaceMeshResult> promising_look;
  for (std::size_t k = 0; k < others.size(); ++k) {
    FaceMeshResult look = others[k];
    smooth_face_mesh(face, seam, nodes, look, kVariantLook, LayoutChanges::none);
    if (!promising_look || better_worst_then_mean(look, *promising_look)) {
      promising = k;
      promising_look = std::move(look);
    }
  }
  if (promising_look) {
    FaceMeshResult& other = others[promising];
    smooth_face_mesh(face, seam, nodes, other);
    contest(std::move(other));
  }
  // Ranked before smoothing, searched patches can win and then end lower once
  // smoothed: they are judged smoothed.
  if (choice.patches_searched) {
    smooth_face_mesh(face, seam, nodes, *choice.patches_searched);
    contest(std::move(*choice.patches_searched));
  }
  // Each judged layout as placed or smoothed, whichever ranks higher: where its worst
  // corner is the CAD's own (a tip), the smoother's max-min moves can only lower the mean.
  for (FaceMeshResult& layout : choice.judged_smoothed) {
    FaceMeshResult smoothed = layout;
    smooth_face_mesh(face, seam, nodes, smoothed);
    if (better_worst_then_mean(smoothed, layout)) layout = std::move(smoothed);
    contest(std::move(layout));
  }
  return std::move(best);
}

// The one policy for bad quads (is_bad_quad): a face keeping any is refused, unless
// the user allows them.
void refuse_bad_quads(const FaceMeshResult& mesh, const std::string& name, const ShapeMeshOptions& options) {
  if (mesh.bad == 0 || options.allow_inverted) return;
  char worst[32];
  std::snprintf(worst, sizeof worst, "%.3g", mesh.worst_corner);
  const std::string collapsed =
      mesh.collapsed > 0 ? " (" + std::to_string(mesh.collapsed) +
                               " collapsed: a corner's Jacobian under 1/1000 of another's, a triangle in effect)"
                         : "";
  throw InvertedQuadsError(name + ": " + std::to_string(mesh.bad) + " of " + std::to_string(mesh.quads.size()) +
                               " quads stay inverted, degenerate, folded or collapsed after repair" + collapsed +
                               " (worst corner " + worst +
                               " against the surface; " + mesh.template_tree.substr(0, 60) + ")",
                           mesh.quads.size(), has_quad_over_curvature(mesh));
}

// What a route sees of the face, and what the routes leave for the chooser after
// them (the corner sets tried, the decomposition's other variants and its searched
// patches).
struct RouteContext {
  RouteContext(const ShapeIndex& index, int f, const FaceBoundary& boundary, const PoleSector* sector,
               const std::vector<Vec3>& nodes, const ShapeMeshOptions& options, double size)
      : index(index), f(f), boundary(boundary), sector(sector), nodes(nodes), options(options), size(size) {}
  const ShapeIndex& index;
  int f;
  const FaceBoundary& boundary;
  const PoleSector* sector;  // a cone's tip, when the face is a disk around it
  const std::vector<Vec3>& nodes;
  const ShapeMeshOptions& options;
  double size;
  bool pole = false;          // a degenerate edge or a polar chart
  bool user_corners = false;  // the user gave this face's corners: an instruction
  bool decompose = false;     // the decomposition may be tried
  std::vector<std::vector<int>> natural_corners;
  std::vector<FaceMeshResult> other_decompositions;
  std::optional<FaceMeshResult> patches_searched;
  bool patches_tried = false;
  // Layouts whose shape smoothing finishes (the tip strip's kites): ranked against the
  // natural choice once both are smoothed, not before.
  std::vector<FaceMeshResult> judged_smoothed;
};

// The candidates of the routes, ranked by one order (better_face_mesh: fewer bad
// quads, fewer inverted, fewer collapsed, then the better worst corner), and the last
// refusal with its code (internal: the mesher failed).
class Candidates {
 public:
  // The route whose meshes keep() takes now (FaceMeshResult::route).
  void proposing(const char* route) { route_ = route; }
  // Whether r became the best.
  bool keep(FaceMeshResult&& r) {
    if (r.route.empty()) r.route = route_;
    if (best_ && !better_face_mesh(r, *best_)) return false;
    best_ = std::move(r);
    return true;
  }
  void refused(const std::exception& e) {
    refusal_ = e.what();
    code_ = refusal_code_of(e);
  }
  std::optional<FaceMeshResult>& best() { return best_; }
  const std::optional<FaceMeshResult>& best() const { return best_; }
  const std::string& refusal() const { return refusal_; }
  RefusalCode code() const { return code_; }

 private:
  std::optional<FaceMeshResult> best_;
  const char* route_ = "";
  std::string refusal_;
  RefusalCode code_ = RefusalCode::cannot_mesh;
};

// A route: when it applies, and how it proposes meshes (Candidates::keep). It says
// it cannot mesh the face by throwing InputError (FaceRefusalError with its code);
// its refusal is noted always, or only while no route has a mesh (the routes offered
// besides a mesh). Any other exception is a broken invariant, caught by no route:
// mesh_one_face refuses the face as an internal failure, named in the report. A route
// `alone` is the face's one route when it applies, its mesh kept as it is.
enum class Refusal { noted, noted_without_mesh };
struct FaceRoute {
  const char* name;
  bool (*applies)(const RouteContext&, const Candidates&);
  void (*propose)(RouteContext&, Candidates&);
  Refusal refusal;
  bool alone;
};

// The decomposition with its poor patches' corners searched (corner_search.h).
void search_patches(RouteContext& c) {
  c.patches_tried = true;
  MeshOptions searching = c.options.templates;
  searching.search_patch_corners = true;
  try {
    c.patches_searched = std::move(mesh_face_decomposed(c.index.face(c.f), c.f, c.boundary, c.nodes,
                                                        c.index.vertex_count(), c.size, searching)
                                       .front());
    c.patches_searched->route = "decomposition, patch corners searched";
  } catch (const InputError&) {  // the decomposition without the search stands
  }
}

// The face routes in the order they are offered (a tie keeps the earlier mesh):
//   - closed around two poles (a full sphere): the cube sphere (pole_to_pole.h), the
//     one layout without a corner of 180 degrees at a pole; alone;
//   - one hole: a structured ring when both loops have the same count
//     (mapped_ring.h), and the O-grid of two halves (o_grid.h, face_decomposed.h);
//   - no hole: the templates on each corner choice (face_corners.h); a thin band
//     between two sharp tips, the tip strip (face_mesher.h); around a pole,
//     polar templates and a cone's tip as the apex of its flattened sector
//     (pole_sector); a pole on the rim (a sphere's lune), the disk's O-grid in space;
//     a disk (one smooth loop) the disk's O-grid (disk_o_grid.h);
//   - more holes, or when the above leave bad quads or a worst corner under
//     kGoodEnoughCorner: the face decomposition (face_decomposed.h), any outline.
// Adding a route is a function pair and a row here.
const std::vector<FaceRoute>& face_routes() {
  static const std::vector<FaceRoute> routes{
      {"cube sphere", [](const RouteContext& c, const Candidates&) { return closed_seam_edge(c.index, c.f) >= 0; },
       [](RouteContext& c, Candidates& out) {
         out.keep(mesh_pole_to_pole(c.index.face(c.f), c.f, c.boundary, c.nodes));
       },
       Refusal::noted, true},
      {"mapped ring and O-grid", [](const RouteContext& c, const Candidates&) { return c.boundary.inner_wires == 1; },
       [](RouteContext& c, Candidates& out) {
         const TopoDS_Face& face = c.index.face(c.f);
         if (auto ring = mesh_face_ring(face, c.f, c.boundary, c.nodes, c.index.vertex_count())) {
           out.keep(std::move(*ring));
         }
         out.keep(mesh_face_o_grid(face, c.f, c.boundary, c.nodes, c.index.vertex_count(), c.size,
                                   c.options.templates));
       },
       Refusal::noted, false},
      {"templates on corners", [](const RouteContext& c, const Candidates&) { return c.boundary.inner_wires == 0; },
       [](RouteContext& c, Candidates& out) {
         const auto requested = c.options.corners.find(c.f);
         c.natural_corners = corner_choices(c.boundary, c.f, c.user_corners ? requested->second : std::vector<int>{});
         for (const std::vector<int>& corners : c.natural_corners) {
           try {
             out.keep(mesh_face(c.index, c.f, c.boundary, corners, c.nodes, c.options.templates));
           } catch (const InputError& e) {  // a corner set that cannot mesh the face is noted; others follow
             out.refused(e);
           }
         }
       },
       Refusal::noted, false},
      {"tip strip",
       [](const RouteContext& c, const Candidates&) {
         return c.boundary.inner_wires == 0 && !c.boundary.polar && !c.boundary.has_degenerate_edge &&
                !c.user_corners;
       },
       [](RouteContext& c, Candidates&) {
         if (auto strip = mesh_face_tip_strip(c.index.face(c.f), c.boundary, c.nodes)) {
           c.judged_smoothed.push_back(std::move(*strip));
         }
       },
       Refusal::noted_without_mesh, false},
      {"polar disk",
       [](const RouteContext& c, const Candidates&) {
         return c.boundary.inner_wires == 0 && c.boundary.polar && !c.user_corners;
       },
       [](RouteContext& c, Candidates& out) {
         if (auto disk = mesh_polar_disk(c.index.face(c.f), c.boundary, c.nodes, c.options.templates)) {
           out.keep(std::move(*disk));
         }
       },
       Refusal::noted_without_mesh, false},
      {"pole sector",
       [](const RouteContext& c, const Candidates&) {
         return c.boundary.inner_wires == 0 && c.boundary.polar && !c.user_corners && c.sector;
       },
       [](RouteContext& c, Candidates& out) {
         if (auto tip = mesh_pole_sector(c.index.face(c.f), *c.sector, c.nodes, c.options.templates)) {
           out.keep(std::move(*tip));
         }
       },
       Refusal::noted_without_mesh, false},
      {"disk in space",
       [](const RouteContext& c, const Candidates&) {
         return c.boundary.inner_wires == 0 && c.boundary.has_degenerate_edge && !c.boundary.polar &&
                !c.user_corners;
       },
       [](RouteContext& c, Candidates& out) {
         if (auto disk = mesh_disk_in_space(c.index.face(c.f), c.boundary, c.nodes, c.options.templates)) {
           out.keep(std::move(*disk));
         }
       },
       Refusal::noted_without_mesh, false},
      {"disk O-grid",
       [](const RouteContext& c, const Candidates&) {
         return c.boundary.inner_wires == 0 && c.decompose && !c.boundary.polar;
       },
       [](RouteContext& c, Candidates& out) {
         if (auto disk = mesh_face_disk(c.index.face(c.f), c.f, c.boundary, c.nodes, c.index.vertex_count(),
                                        c.options.templates)) {
           out.keep(std::move(*disk));
         }
       },
       Refusal::noted_without_mesh, false},
      {"decomposition",
       [](const RouteContext& c, const Candidates& out) {
         const std::optional<FaceMeshResult>& best = out.best();
         return c.decompose &&
                (!best || best->bad > 0 || best->collapsed > 0 || best->worst_corner < kGoodEnoughCorner);
       },
       [](RouteContext& c, Candidates& out) {
         std::vector<FaceMeshResult> decomposed = mesh_face_decomposed(
             c.index.face(c.f), c.f, c.boundary, c.nodes, c.index.vertex_count(), c.size, c.options.templates);
         const std::vector<Quad> plain_quads = decomposed.front().quads;
         // Its other variants, when its best was kept: smoothed, one may end better.
         if (out.keep(std::move(decomposed.front()))) {
           for (auto it = decomposed.begin() + 1; it != decomposed.end(); ++it) it->route = "decomposition";
           c.other_decompositions.assign(std::make_move_iterator(decomposed.begin() + 1),
                                         std::make_move_iterator(decomposed.end()));
         }
         search_patches(c);
         // No patch poor enough, or none bettered: the same mesh again.
         if (c.patches_searched && c.patches_searched->quads == plain_quads) c.patches_searched.reset();
       },
       Refusal::noted_without_mesh, false},
  };
  return routes;
}

}  // namespace

std::vector<std::string> face_route_names() {
  std::vector<std::string> names;
  for (const FaceRoute& route : face_routes()) names.push_back(route.name);
  return names;
}

namespace {

// The face's mesh: every route of face_routes that applies proposes, the best by
// better_face_mesh is kept and smoothed on the surface (settle_natural_choice); with
// --corners best, more corner sets compete after them. Bad quads that remain
// (inverted, degenerate, folded or collapsed: is_bad_quad) refuse the face unless
// allow_inverted (never a silent bad mesh).
FaceMeshResult best_face_mesh(const ShapeIndex& index, int f, const FaceBoundary& boundary, const PoleSector* sector,
                              const std::vector<Vec3>& nodes, const ShapeMeshOptions& options, double size,
                              std::optional<FaceMeshResult>& higher_mean) {
  const auto start = std::chrono::steady_clock::now();
  const std::string name = "face " + std::to_string(f);
  RouteContext context(index, f, boundary, sector, nodes, options, size);
  Candidates candidates;
  for (const FaceRoute& route : face_routes()) {
    if (!route.alone || !route.applies(context, candidates)) continue;
    candidates.proposing(route.name);
    route.propose(context, candidates);
    FaceMeshResult only = std::move(*candidates.best());
    only.meshing_seconds = seconds_since(start);
    refuse_bad_quads(only, name, options);
    return only;
  }
  context.pole = boundary.has_degenerate_edge || boundary.polar;
  // Around a smooth pole (a sphere's) the face is decomposed in polar (x, y), holes
  // and all; a cone's tip must stay a node, which only the disk routes make sure of.
  const bool smooth_polar = boundary.polar && boundary.smooth_pole;
  if (boundary.inner_wires > 0 && context.pole && !smooth_polar) {
    throw FaceRefusalError(RefusalCode::not_supported, name + " has a hole and a pole (a cone's tip); not supported yet");
  }
  context.user_corners = options.corners.count(f) > 0;
  // The user's corners are an instruction: no other layout for a face without holes.
  context.decompose = (!context.pole || smooth_polar) && !(boundary.inner_wires == 0 && context.user_corners);
  for (const FaceRoute& route : face_routes()) {
    if (route.alone || !route.applies(context, candidates)) continue;
    candidates.proposing(route.name);
    try {
      route.propose(context, candidates);
    } catch (const InputError& e) {
      if (route.refusal == Refusal::noted || !candidates.best()) candidates.refused(e);
    }
    for (FaceMeshResult& layout : context.judged_smoothed) {
      if (layout.route.empty()) layout.route = route.name;
    }
  }
  if (!candidates.best() && !context.judged_smoothed.empty()) {
    candidates.keep(std::move(context.judged_smoothed.front()));
    context.judged_smoothed.erase(context.judged_smoothed.begin());
  }
  if (!candidates.best()) {
    if (candidates.code() == RefusalCode::internal) throw std::runtime_error(candidates.refusal());
    throw FaceRefusalError(candidates.code(), candidates.refusal());
  }
  FaceMeshResult best = std::move(*candidates.best());
  // --corners best: more corner sets compete with the routes above (the natural
  // choice): the one that beats it before smoothing is smoothed and kept if it beats
  // the natural choice smoothed too, so no face ends worse than without the search.
  std::optional<FaceMeshResult> searched;
  CornerSearch search;
  const bool search_corners = options.best_corners && !context.pole && !context.user_corners;
  if (search_corners) {
    const auto compete = [&](FaceMeshResult&& candidate) {
      if (!better_worst_then_mean(candidate, searched ? *searched : best)) return;
      if (candidate.route.empty()) candidate.route = "corner search";
      searched = std::move(candidate);
    };
    if (boundary.inner_wires == 0) {
      const std::vector<std::vector<int>> sets = searched_corner_choices(boundary, context.natural_corners);
      search.tried = static_cast<int>(sets.size());
      for (const std::vector<int>& corners : screened_corner_sets(boundary, sets, options.templates)) {
        try {
          compete(mesh_face(index, f, boundary, corners, nodes, options.templates));
        } catch (const InputError&) {  // a set the templates cannot mesh on the surface is one fewer
        }
      }
    }
    // And the decomposition with each poor patch's corners searched, holes or not:
    // where the natural choice has it already (a poor face), it stays there.
    if (context.decompose && !context.patches_tried) {
      search_patches(context);
      if (context.patches_searched) compete(std::move(*context.patches_searched));
      context.patches_searched.reset();
    }
    if (context.patches_tried) ++search.tried;
  }
  // Every candidate route counts, the rejected ones too.
  const double meshing_seconds = seconds_since(start);
  const bool seam = std::find(boundary.is_seam.begin(), boundary.is_seam.end(), 1) != boundary.is_seam.end();
  const auto smoothing = std::chrono::steady_clock::now();
  NaturalChoice natural{std::move(best), std::move(context.other_decompositions),
                        std::move(context.patches_searched), std::move(context.judged_smoothed), std::nullopt};
  best = settle_natural_choice(index.face(f), seam, nodes, options.smooth, natural);
  if (search_corners) {
    search.natural_worst = best.worst_corner;
    search.natural_mean = mean_scaled_jacobian(best);
    if (searched) {
      if (options.smooth) smooth_face_mesh(index.face(f), seam, nodes, *searched);
      search.changed = better_worst_then_mean(*searched, best);
      if (search.changed) best = std::move(*searched);
    }
    search.chosen_worst = best.worst_corner;
    search.chosen_mean = mean_scaled_jacobian(best);
    best.corner_search = search;
  }
  best.meshing_seconds = meshing_seconds;
  if (options.smooth) best.smoothing_seconds = seconds_since(smoothing);
  refuse_bad_quads(best, name, options);
  // The alternative only where it trades the worst corner for the mean (had it both,
  // it would have won).
  if (natural.higher_mean && lowest_corner(*natural.higher_mean) < lowest_corner(best) &&
      mean_scaled_jacobian(*natural.higher_mean) > mean_scaled_jacobian(best)) {
    higher_mean = std::move(natural.higher_mean);
  }
  return best;
}

}  // namespace

FaceOutcome mesh_one_face(const ShapeIndex& index, int f, const std::vector<EdgeNodes>& edges,
                          const std::vector<Vec3>& nodes, const ShapeMeshOptions& options, double size) {
  FaceOutcome outcome;
  try {
    outcome.boundary = face_boundary(index, f, edges, nodes);
    std::optional<PoleSector> sector;
    if (is_disk_around_pole(outcome.boundary) && closed_seam_edge(index, f) < 0) {
      sector = pole_sector(outcome.boundary, index.face(f));
      outcome.boundary = around_pole(outcome.boundary, index.face(f), f, nodes);
    }
    std::optional<FaceMeshResult> higher_mean;
    outcome.mesh =
        best_face_mesh(index, f, outcome.boundary, sector ? &*sector : nullptr, nodes, options, size, higher_mean);
    const std::string open = face_mesh_closure_problem(index, f, edges, outcome.mesh);
    if (!open.empty()) throw std::logic_error(open);  // a route's bug: an internal failure
    if (higher_mean && face_mesh_closure_problem(index, f, edges, *higher_mean).empty()) {
      outcome.higher_mean = std::move(higher_mean);
    }
    outcome.ok = true;
  } catch (const InputError& e) {
    outcome.reason = e.what();
    outcome.code = refusal_code_of(e);
    const auto* inverted = dynamic_cast<const InvertedQuadsError*>(&e);
    outcome.finer_edges_may_help =
        inverted && (inverted->quads <= kRefinableQuads || inverted->coarse_for_curvature);
    if (!outcome.finer_edges_may_help) {
      outcome.refine_edges = edges_of_crossing_chords(index, f, outcome.boundary);
      outcome.finer_edges_may_help = !outcome.refine_edges.empty();
    }
  } catch (const OperationCancelled&) {
    throw;  // the user's: the stage ends the job
  } catch (const std::bad_alloc&) {
    outcome.reason = std::string("face ") + std::to_string(f) + ": internal failure: out of memory";
    outcome.code = RefusalCode::internal;
  } catch (const std::exception& e) {
    outcome.reason = std::string("face ") + std::to_string(f) + ": internal failure: " + e.what();
    outcome.code = RefusalCode::internal;
  } catch (const Standard_Failure& e) {  // OpenCASCADE's on the face's geometry; no std::exception
    outcome.reason = std::string("face ") + std::to_string(f) + ": OpenCASCADE failure: " + e.GetMessageString() +
                     " (a damaged face?)";
    outcome.code = RefusalCode::damaged;
  } catch (...) {
    outcome.reason = std::string("face ") + std::to_string(f) + ": internal failure";
    outcome.code = RefusalCode::internal;
  }
  return outcome;
}

int take_higher_means(std::vector<FaceOutcome>& outcomes, const std::vector<char>& meshed) {
  const auto in_part = [&](std::size_t f) { return f < meshed.size() && meshed[f] && outcomes[f].ok; };
  double part_worst = INFINITY, sum = 0;
  long long count = 0;
  for (std::size_t f = 0; f < outcomes.size(); ++f) {
    if (!in_part(f)) continue;
    part_worst = std::min(part_worst, lowest_corner(outcomes[f].mesh));
    sum += scaled_jacobian_sum(outcomes[f].mesh);
    count += static_cast<long long>(outcomes[f].mesh.scaled_jacobian.size());
  }
  int taken = 0;
  for (std::size_t f = 0; f < outcomes.size(); ++f) {
    FaceOutcome& outcome = outcomes[f];
    if (in_part(f) && outcome.higher_mean) {
      FaceMeshResult& alternative = *outcome.higher_mean;
      const double sum_after = sum - scaled_jacobian_sum(outcome.mesh) + scaled_jacobian_sum(alternative);
      const long long count_after = count - static_cast<long long>(outcome.mesh.scaled_jacobian.size()) +
                                    static_cast<long long>(alternative.scaled_jacobian.size());
      // sum_after / count_after > sum / count, both counts positive.
      if (lowest_corner(alternative) >= part_worst && count_after > 0 &&
          sum_after * static_cast<double>(count) > sum * static_cast<double>(count_after)) {
        alternative.meshing_seconds = outcome.mesh.meshing_seconds;
        alternative.smoothing_seconds = outcome.mesh.smoothing_seconds;
        alternative.corner_search = outcome.mesh.corner_search;
        outcome.mesh = std::move(alternative);
        sum = sum_after;
        count = count_after;
        ++taken;
      }
    }
    outcome.higher_mean.reset();
  }
  return taken;
}

bool reuse_unchanged_face(const ShapeIndex& index, int f, const std::vector<EdgeNodes>& before_edges,
                          const std::vector<Vec3>& before_nodes, const std::vector<EdgeNodes>& edges,
                          const std::vector<Vec3>& nodes, FaceOutcome& outcome) {
  if (!outcome.ok || before_edges.size() != edges.size()) return false;
  std::unordered_map<NodeId, NodeId> renumbered;
  for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) {
    const int e = index.edge_index(it.Current());
    const EdgeNodes &before = before_edges[e], &now = edges[e];
    if (before.degenerate != now.degenerate || before.params != now.params || before.nodes.size() != now.nodes.size()) {
      return false;
    }
    for (std::size_t i = 0; i < now.nodes.size(); ++i) {
      if (!(before_nodes[before.nodes[i]] == nodes[now.nodes[i]])) return false;
      renumbered[before.nodes[i]] = now.nodes[i];
    }
  }
  // The ids renumbered into copies first (not a copy of the whole outcome, its mesh
  // included), so that a missing id leaves the outcome as it was.
  const auto renumbered_ids = [&](std::vector<NodeId> ids, std::vector<NodeId>& out) {
    for (NodeId& id : ids) {
      const auto found = renumbered.find(id);
      if (found == renumbered.end()) return false;
      id = found->second;
    }
    out = std::move(ids);
    return true;
  };
  std::vector<NodeId> loop, mesh_nodes, alternative_nodes;
  std::vector<std::vector<NodeId>> holes(outcome.boundary.holes.size());
  if (!renumbered_ids(outcome.boundary.nodes, loop) || !renumbered_ids(outcome.mesh.boundary_nodes, mesh_nodes)) {
    return false;
  }
  if (outcome.higher_mean && !renumbered_ids(outcome.higher_mean->boundary_nodes, alternative_nodes)) return false;
  for (std::size_t h = 0; h < holes.size(); ++h) {
    if (!renumbered_ids(outcome.boundary.holes[h].nodes, holes[h])) return false;
  }
  outcome.boundary.nodes = std::move(loop);
  outcome.mesh.boundary_nodes = std::move(mesh_nodes);
  if (outcome.higher_mean) outcome.higher_mean->boundary_nodes = std::move(alternative_nodes);
  for (std::size_t h = 0; h < holes.size(); ++h) outcome.boundary.holes[h].nodes = std::move(holes[h]);
  return true;
}

}  // namespace tquad
