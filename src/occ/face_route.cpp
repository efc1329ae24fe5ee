#include "occ/face_route.h"

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
#include "core/mesher.h"
#include "core/quality.h"
#include "occ/crossing_chords.h"
#include "occ/edge_discretization.h"
#include "occ/face_corners.h"
#include "occ/face_decomposed.h"
#include "occ/face_mesh_closure.h"
#include "occ/pole_to_pole.h"
#include "occ/surface_smoothing.h"

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
// ... first with this many passes each (the smoother's default is 8), and only the
// best of them in full: smoothing every variant of a large decomposed face in full
// took many times its meshing.
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
};

// The natural choice smoothed (when `smooth`): its best mesh, or, where smoothing
// reorders them, another variant or the searched patches (the worst corner, then the
// mean).
FaceMeshResult settle_natural_choice(const TopoDS_Face& face, bool seam, const std::vector<Vec3>& nodes, bool smooth,
                                     NaturalChoice& choice) {
  FaceMeshResult& best = choice.best;
  if (!smooth) {
    if (choice.patches_searched && better_worst_then_mean(*choice.patches_searched, best)) {
      return std::move(*choice.patches_searched);
    }
    return std::move(best);
  }
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
    if (better_worst_then_mean(other, best)) best = std::move(other);
  }
  // Ranked before smoothing, searched patches can win and then end lower once
  // smoothed: they are judged smoothed.
  if (choice.patches_searched) {
    smooth_face_mesh(face, seam, nodes, *choice.patches_searched);
    if (better_worst_then_mean(*choice.patches_searched, best)) best = std::move(*choice.patches_searched);
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

// The face's mesh, the one place where the algorithm per face is chosen:
//   - no hole: the templates on each corner choice (face_corners.h), and for a disk
//     (one smooth loop) the disk's O-grid (disk_o_grid.h);
//   - one hole: a structured ring when both loops have the same count
//     (mapped_ring.h), and the O-grid of two halves (o_grid.h, face_decomposed.h);
//   - more holes, or when the above leave inverted quads or a worst corner under
//     kGoodEnoughCorner: the face decomposition (face_decomposed.h), any outline;
//   - a disk around a pole: polar templates (no decomposition), and a cone's tip as
//     the apex of its flattened sector (pole_sector);
//   - closed around two poles (a full sphere): the cube sphere (pole_to_pole.h).
// The best mesh is kept and smoothed on the surface; bad quads that remain (inverted,
// degenerate or folded: is_bad_quad) refuse the face unless allow_inverted
// (never a silent bad mesh).
// A route says it cannot mesh the face by throwing InputError (FaceRefusalError with
// its code); any other exception is a broken invariant, caught by no route here:
// mesh_one_face refuses the face as an internal failure, named in the report, rather
// than another route hiding it.
FaceMeshResult best_face_mesh(const ShapeIndex& index, int f, const FaceBoundary& boundary, const PoleSector* sector,
                              const std::vector<Vec3>& nodes, const ShapeMeshOptions& options, double size) {
  const auto start = std::chrono::steady_clock::now();
  const std::string name = "face " + std::to_string(f);
  std::optional<FaceMeshResult> best;
  std::string refusal;  // the last route's refusal, and its kind (internal: the mesher failed)
  RefusalCode refusal_code = RefusalCode::cannot_mesh;
  const auto note_refusal = [&](const std::exception& e) {
    refusal = e.what();
    refusal_code = refusal_code_of(e);
  };
  if (closed_seam_edge(index, f) >= 0) {
    // Closed around two poles: the cube sphere, the one layout without a corner of
    // 180 degrees at a pole (pole_to_pole.h).
    FaceMeshResult sphere = mesh_pole_to_pole(index.face(f), f, boundary, nodes);
    sphere.meshing_seconds = seconds_since(start);
    refuse_bad_quads(sphere, name, options);
    return sphere;
  }
  const bool pole = boundary.has_degenerate_edge || boundary.polar;
  // Around a smooth pole (a sphere's) the face is decomposed in polar (x, y), holes
  // and all; a cone's tip must stay a node, which only the disk routes make sure of.
  const bool smooth_polar = boundary.polar && boundary.smooth_pole;
  if (boundary.inner_wires > 0 && pole && !smooth_polar) {
    throw FaceRefusalError(RefusalCode::not_supported, name + " has a hole and a pole (a cone's tip); not supported yet");
  }
  bool decompose = !pole || smooth_polar;
  const auto requested = options.corners.find(f);
  const bool user_corners = requested != options.corners.end();
  std::vector<std::vector<int>> natural_corners;
  auto keep = [&](FaceMeshResult&& r) {
    if (!best || better_face_mesh(r, *best)) best = std::move(r);
  };
  if (boundary.inner_wires == 1) {
    try {
      if (auto ring = mesh_face_ring(index.face(f), f, boundary, nodes, index.vertex_count())) keep(std::move(*ring));
      keep(mesh_face_o_grid(index.face(f), f, boundary, nodes, index.vertex_count(), size, options.templates));
    } catch (const InputError& e) {  // the decomposition below is the other route
      note_refusal(e);
    }
  } else if (boundary.inner_wires == 0) {
    natural_corners = corner_choices(boundary, f, user_corners ? requested->second : std::vector<int>{});
    for (const std::vector<int>& corners : natural_corners) {
      try {
        keep(mesh_face(index, f, boundary, corners, nodes, options.templates));
      } catch (const InputError& e) {  // a route that cannot mesh the face is noted; others follow
        note_refusal(e);
      }
    }
    decompose = decompose && !user_corners;  // the user's corners are an instruction
    if (boundary.polar && !user_corners) {
      try {
        if (auto disk = mesh_polar_disk(index.face(f), boundary, nodes, options.templates)) keep(std::move(*disk));
      } catch (const InputError& e) {  // the corner routes stand
        if (!best) note_refusal(e);
      }
      if (sector) {
        try {
          if (auto tip = mesh_pole_sector(index.face(f), *sector, nodes, options.templates)) keep(std::move(*tip));
        } catch (const InputError& e) {  // the disk routes stand
          if (!best) note_refusal(e);
        }
      }
    }
    // A face with a pole on its rim and no seam (a sphere's lune): the disk's O-grid
    // on the loop's mean plane, where corners on the smooth rim, or at the pole, make
    // quads of 180 degrees.
    if (boundary.has_degenerate_edge && !boundary.polar && !user_corners) {
      try {
        if (auto disk = mesh_disk_in_space(index.face(f), boundary, nodes, options.templates)) keep(std::move(*disk));
      } catch (const InputError& e) {  // the corner routes stand
        if (!best) note_refusal(e);
      }
    }
    // A disk's O-grid (a square and four patches around it) beats corners on a smooth
    // curve; offered when the face has no user corners and no pole (a polar disk had
    // its own above).
    if (decompose && !boundary.polar) {
      try {
        if (auto disk = mesh_face_disk(index.face(f), f, boundary, nodes, index.vertex_count(), options.templates)) {
          keep(std::move(*disk));
        }
      } catch (const InputError& e) {  // the other routes stand
        if (!best) note_refusal(e);
      }
    }
  }
  // The decomposition's other variants, when its best was kept: smoothed, one of them
  // may end better (below).
  std::vector<FaceMeshResult> other_decompositions;
  // The decomposition with its poor patches' corners searched (corner_search.h), where
  // the decomposition is tried (and, with --corners best, on every face it can mesh):
  // smoothed too, and kept when it then ends better (below).
  std::optional<FaceMeshResult> patches_searched;
  bool patches_tried = false;
  const auto search_patches = [&] {
    patches_tried = true;
    MeshOptions searching = options.templates;
    searching.search_patch_corners = true;
    try {
      patches_searched = std::move(
          mesh_face_decomposed(index.face(f), f, boundary, nodes, index.vertex_count(), size, searching).front());
    } catch (const InputError&) {  // the decomposition without the search stands
    }
  };
  if (decompose && (!best || best->bad > 0 || best->collapsed > 0 || best->worst_corner < kGoodEnoughCorner)) {
    try {
      std::vector<FaceMeshResult> decomposed =
          mesh_face_decomposed(index.face(f), f, boundary, nodes, index.vertex_count(), size, options.templates);
      const bool kept = !best || better_face_mesh(decomposed.front(), *best);
      const std::vector<Quad> plain_quads = decomposed.front().quads;
      keep(std::move(decomposed.front()));
      if (kept) other_decompositions.assign(std::make_move_iterator(decomposed.begin() + 1),
                                            std::make_move_iterator(decomposed.end()));
      search_patches();
      // No patch poor enough, or none bettered: the same mesh again.
      if (patches_searched && patches_searched->quads == plain_quads) patches_searched.reset();
    } catch (const InputError& e) {  // a mesh already found stays
      if (!best) note_refusal(e);
    }
  }
  if (!best) {
    if (refusal_code == RefusalCode::internal) throw std::runtime_error(refusal);
    throw FaceRefusalError(refusal_code, refusal);
  }
  // --corners best: more corner sets compete with the routes above (the natural
  // choice): the one that beats it before smoothing is smoothed and kept if it beats
  // the natural choice smoothed too, so no face ends worse than without the search.
  std::optional<FaceMeshResult> searched;
  CornerSearch search;
  const bool search_corners = options.best_corners && !pole && !user_corners;
  if (search_corners) {
    const auto compete = [&](FaceMeshResult&& candidate) {
      if (better_worst_then_mean(candidate, searched ? *searched : *best)) searched = std::move(candidate);
    };
    if (boundary.inner_wires == 0) {
      const std::vector<std::vector<int>> sets = searched_corner_choices(boundary, natural_corners);
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
    if (decompose && !patches_tried) {
      search_patches();
      if (patches_searched) compete(std::move(*patches_searched));
      patches_searched.reset();
    }
    if (patches_tried) ++search.tried;
  }
  // Every candidate route counts, the rejected ones too.
  const double meshing_seconds = seconds_since(start);
  const bool seam = std::find(boundary.is_seam.begin(), boundary.is_seam.end(), 1) != boundary.is_seam.end();
  const auto smoothing = std::chrono::steady_clock::now();
  NaturalChoice natural{std::move(*best), std::move(other_decompositions), std::move(patches_searched)};
  best = settle_natural_choice(index.face(f), seam, nodes, options.smooth, natural);
  if (search_corners) {
    search.natural_worst = best->worst_corner;
    search.natural_mean = mean_scaled_jacobian(*best);
    if (searched) {
      if (options.smooth) smooth_face_mesh(index.face(f), seam, nodes, *searched);
      search.changed = better_worst_then_mean(*searched, *best);
      if (search.changed) best = std::move(searched);
    }
    search.chosen_worst = best->worst_corner;
    search.chosen_mean = mean_scaled_jacobian(*best);
    best->corner_search = search;
  }
  best->meshing_seconds = meshing_seconds;
  if (options.smooth) best->smoothing_seconds = seconds_since(smoothing);
  refuse_bad_quads(*best, name, options);
  return std::move(*best);
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
    outcome.mesh = best_face_mesh(index, f, outcome.boundary, sector ? &*sector : nullptr, nodes, options, size);
    const std::string open = face_mesh_closure_problem(index, f, edges, outcome.mesh);
    if (!open.empty()) throw std::logic_error(open);  // a route's bug: an internal failure
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
  std::vector<NodeId> loop, mesh_nodes;
  std::vector<std::vector<NodeId>> holes(outcome.boundary.holes.size());
  if (!renumbered_ids(outcome.boundary.nodes, loop) || !renumbered_ids(outcome.mesh.boundary_nodes, mesh_nodes)) {
    return false;
  }
  for (std::size_t h = 0; h < holes.size(); ++h) {
    if (!renumbered_ids(outcome.boundary.holes[h].nodes, holes[h])) return false;
  }
  outcome.boundary.nodes = std::move(loop);
  outcome.mesh.boundary_nodes = std::move(mesh_nodes);
  for (std::size_t h = 0; h < holes.size(); ++h) outcome.boundary.holes[h].nodes = std::move(holes[h]);
  return true;
}

}  // namespace tquad
