#include "occ/shape_mesher.h"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>

#include <atomic>
#include <cmath>
#include <exception>
#include <optional>
#include <thread>

#include "core/input_error.h"
#include "occ/edge_discretization.h"
#include "occ/face_boundary.h"
#include "occ/face_corners.h"
#include "occ/face_decomposed.h"
#include "occ/face_mesher.h"
#include "occ/shape_index.h"

namespace tquad {

namespace {

double default_size(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  if (box.IsVoid()) return 1.0;
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  return std::sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0) + (z1 - z0) * (z1 - z0)) / 25.0;
}

std::vector<char> meshed_faces(const ShapeIndex& index, const std::vector<int>& faces) {
  std::vector<char> meshed(index.face_count(), faces.empty() ? 1 : 0);
  for (int f : faces) {
    if (f < 0 || f >= index.face_count()) {
      throw InputError("face " + std::to_string(f) + " does not exist; the shape has faces 0.." +
                       std::to_string(index.face_count() - 1));
    }
    meshed[f] = 1;
  }
  return meshed;
}

// --corners is the user's instruction, not a property of a face: a mistake in it
// stops the job even with keep_going (exit 2), before any face is meshed.
void check_requested_corners(const ShapeIndex& index, const std::vector<char>& meshed,
                             const std::map<int, std::vector<int>>& corners,
                             const std::vector<EdgeNodes>& edges, const std::vector<Vec3>& nodes) {
  for (const auto& [face, vertices] : corners) {
    const std::string where = "--corners for face " + std::to_string(face);
    if (face < 0 || face >= index.face_count()) {
      throw InputError(where + ": the shape has faces 0.." + std::to_string(index.face_count() - 1));
    }
    if (!meshed[face]) throw InputError(where + ": that face is not among the faces to mesh (--faces)");
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      if (vertices[i] < 0 || vertices[i] >= index.vertex_count()) {
        throw InputError(where + ": vertex " + std::to_string(vertices[i]) + " does not exist; the shape has vertices 0.." +
                         std::to_string(index.vertex_count() - 1));
      }
      for (std::size_t j = 0; j < i; ++j) {
        if (vertices[j] == vertices[i]) throw InputError(where + ": vertex " + std::to_string(vertices[i]) + " is given twice");
      }
    }
    FaceBoundary boundary = face_boundary(index, face, edges, nodes);
    if (boundary.inner_wires > 0) {
      throw InputError(where + ": a face with a hole takes its corners from the cut through the hole");
    }
    if (is_disk_around_pole(boundary)) boundary = around_pole(boundary, index.face(face), face, nodes);
    choose_face_corners(boundary, face, vertices, false);  // throws when a vertex is off the wire
  }
}

// A face whose quads stay inverted.
struct InvertedQuadsError : InputError {
  InvertedQuadsError(const std::string& message, std::size_t quads) : InputError(message), quads(quads) {}
  std::size_t quads;  // in the face's best mesh
};

// Finer edges may cure a face meshed with at most this many quads: a small curved face
// of a few segments cannot be meshed on its surface however its nodes move. Larger
// faces keep their counts (doubling them did not help in the parts measured, and it
// grows the neighbours' meshes too).
constexpr std::size_t kRefinableQuads = 16;

struct FaceOutcome {
  bool ok = false;
  bool finer_edges_may_help = false;
  std::string reason;
  FaceBoundary boundary;
  FaceMeshResult mesh;
};

// A face meshed whole (templates on its own corners, or the one-hole O-grid) whose
// worst corner reaches this keeps that mesh; below it, the face decomposition is
// tried too and the better mesh kept.
constexpr double kGoodEnoughCorner = 0.3;

// The face's mesh, the one place where the algorithm per face is chosen:
//   - no hole: the templates on each corner choice (face_corners.h);
//   - one hole: the O-grid of two halves (o_grid.h, face_decomposed.h);
//   - more holes, or when the above leave inverted quads or a worst corner under
//     kGoodEnoughCorner: the face decomposition (face_decomposed.h), any outline;
//   - a disk around a pole: polar templates (no decomposition).
// The best mesh is kept; inverted quads that remain refuse the face unless
// allow_inverted (never a silent bad mesh).
FaceMeshResult best_face_mesh(const ShapeIndex& index, int f, const FaceBoundary& boundary,
                              const std::vector<Vec3>& nodes, const ShapeMeshOptions& options, double size) {
  const std::string name = "face " + std::to_string(f);
  std::optional<FaceMeshResult> best;
  std::string refusal;
  const bool pole = boundary.has_degenerate_edge || boundary.polar;
  if (boundary.inner_wires > 0 && pole) throw InputError(name + " has a hole and a pole; not supported yet");
  bool decompose = !pole;
  auto keep = [&](FaceMeshResult&& r) {
    if (!best || better_face_mesh(r, *best)) best = std::move(r);
  };
  if (boundary.inner_wires == 1) {
    try {
      keep(mesh_face_o_grid(index.face(f), f, boundary, nodes, index.vertex_count(), size, options.templates));
    } catch (const std::exception& e) {  // the decomposition below is the other route
      refusal = e.what();
    }
  } else if (boundary.inner_wires == 0) {
    const auto requested = options.corners.find(f);
    const bool user_corners = requested != options.corners.end();
    for (const std::vector<int>& corners :
         corner_choices(boundary, f, user_corners ? requested->second : std::vector<int>{})) {
      try {
        keep(mesh_face(index, f, boundary, corners, nodes, options.templates));
      } catch (const std::exception& e) {  // an internal failure of one route is noted; others follow
        refusal = e.what();
      }
    }
    decompose = !user_corners;  // the user's corners are an instruction
  }
  if (decompose && (!best || best->inverted > 0 || best->collapsed > 0 || best->worst_corner < kGoodEnoughCorner)) {
    try {
      keep(mesh_face_decomposed(index.face(f), f, boundary, nodes, index.vertex_count(), size, options.templates));
    } catch (const InputError& e) {
      if (!best) refusal = e.what();
    }
  }
  if (!best) throw InputError(refusal);
  if (best->inverted > 0 && !options.allow_inverted) {
    throw InvertedQuadsError(name + ": " + std::to_string(best->inverted) + " quads stay inverted after repair (" +
                     best->template_tree.substr(0, 60) + ")", best->quads.size());
  }
  return std::move(*best);
}

FaceOutcome mesh_one_face(const ShapeIndex& index, int f, const std::vector<EdgeNodes>& edges,
                          const std::vector<Vec3>& nodes, const ShapeMeshOptions& options, double size) {
  FaceOutcome outcome;
  try {
    outcome.boundary = face_boundary(index, f, edges, nodes);
    if (is_disk_around_pole(outcome.boundary)) {
      outcome.boundary = around_pole(outcome.boundary, index.face(f), f, nodes);
    }
    outcome.mesh = best_face_mesh(index, f, outcome.boundary, nodes, options, size);
    outcome.ok = true;
  } catch (const InvertedQuadsError& e) {
    outcome.reason = e.what();
    outcome.finer_edges_may_help = e.quads <= kRefinableQuads;
  } catch (const InputError& e) {
    outcome.reason = e.what();
  } catch (const std::exception& e) {
    outcome.reason = std::string("face ") + std::to_string(f) + ": internal failure: " + e.what();
  }
  return outcome;
}

// Removes the nodes no quad uses (vertices and edge nodes of faces not meshed or
// refused, seam nodes of refused faces), keeping the others in order.
void drop_unused_nodes(ShapeMesh& mesh) {
  std::vector<NodeId> new_id(mesh.nodes.size(), -1);
  for (const Quad& q : mesh.quads) for (NodeId n : q) new_id[n] = 0;
  NodeId next = 0;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    if (new_id[i] < 0) continue;
    new_id[i] = next;
    mesh.nodes[next++] = mesh.nodes[i];
  }
  mesh.nodes.resize(next);
  for (Quad& q : mesh.quads) for (NodeId& n : q) n = new_id[n];
}

// Runs job(i) for i in [0, count) on `threads` workers.
template <typename Job>
void run_parallel(int count, int threads, const Job& job) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::min(threads, std::max(1, count));
  std::atomic<int> next{0};
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) {
    workers.emplace_back([&] {
      for (int i = next++; i < count; i = next++) job(i);
    });
  }
  for (std::thread& w : workers) w.join();
}

}  // namespace

ShapeMeshResult mesh_shape(const TopoDS_Shape& shape, const ShapeMeshOptions& options) {
  const ShapeIndex index(shape);
  const std::vector<char> meshed = meshed_faces(index, options.faces);
  ShapeMeshResult result;
  result.size = options.size > 0 ? options.size : default_size(shape);

  std::vector<double> lengths;
  const std::vector<int> sized = edge_segment_counts(index, result.size, lengths);
  // Only edges of meshed faces are discretized.
  std::vector<char> needed(index.edge_count(), 0);
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f]) continue;
    for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) needed[index.edge_index(it.Current())] = 1;
  }

  // Small faces whose quads stay inverted get their edges' counts doubled and the
  // shape is meshed again (at most kRefinements times).
  constexpr int kRefinements = 2;
  std::vector<int> minimum(index.edge_count(), 0);
  ShapeMesh& mesh = result.mesh;
  std::vector<FaceOutcome> outcomes;
  for (int round = 0;; ++round) {
    std::vector<int> segments = sized;
    for (int e = 0; e < index.edge_count(); ++e) segments[e] = needed[e] ? std::max(segments[e], minimum[e]) : 0;
    result.changes = assign_even_intervals(index, meshed, lengths, result.size, segments);
    mesh.nodes.clear();
    const std::vector<EdgeNodes> edges = discretize_edges(index, segments, mesh.nodes);
    if (round == 0) check_requested_corners(index, meshed, options.corners, edges, mesh.nodes);

    outcomes.assign(index.face_count(), FaceOutcome{});
    run_parallel(index.face_count(), options.threads, [&](int f) {
      if (meshed[f]) outcomes[f] = mesh_one_face(index, f, edges, mesh.nodes, options, result.size);
    });
    bool refine = false;
    for (int f = 0; f < index.face_count() && round < kRefinements; ++f) {
      if (!meshed[f] || !outcomes[f].finer_edges_may_help) continue;
      refine = true;
      for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) {
        const int e = index.edge_index(it.Current());
        minimum[e] = std::max(minimum[e], 2 * segments[e]);
      }
    }
    if (!refine) break;
    ++result.refinement_rounds;
  }

  for (int f = 0; f < index.face_count(); ++f) {
    if (meshed[f] && !outcomes[f].ok) mesh.refused_faces.push_back({f, outcomes[f].reason});
  }
  if (!mesh.refused_faces.empty() && !options.keep_going) {
    std::string text = std::to_string(mesh.refused_faces.size()) + " face(s) refused: ";
    for (std::size_t i = 0; i < mesh.refused_faces.size(); ++i) {
      text += (i ? "; " : "") + mesh.refused_faces[i].reason;
    }
    throw InputError(text + " (--keep-going meshes the other faces)");
  }

  // Assembly in face order: interior nodes after all edge nodes.
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f] || !outcomes[f].ok) continue;
    const FaceOutcome& o = outcomes[f];
    const std::vector<NodeId>& shared = o.mesh.boundary_nodes;
    const NodeId loop_size = static_cast<NodeId>(shared.size());
    const NodeId base = static_cast<NodeId>(mesh.nodes.size());
    mesh.nodes.insert(mesh.nodes.end(), o.mesh.interior.begin(), o.mesh.interior.end());
    const auto first = static_cast<std::int64_t>(mesh.quads.size());
    for (const Quad& q : o.mesh.quads) {
      Quad g;
      for (int k = 0; k < 4; ++k) g[k] = q[k] < loop_size ? shared[q[k]] : base + (q[k] - loop_size);
      mesh.quads.push_back(g);
    }
    mesh.scaled_jacobian.insert(mesh.scaled_jacobian.end(), o.mesh.scaled_jacobian.begin(), o.mesh.scaled_jacobian.end());
    mesh.faces.push_back({f, o.mesh.template_tree, first, static_cast<std::int64_t>(o.mesh.quads.size())});
    result.projected_faces += o.mesh.used_projection ? 1 : 0;
    result.inverted += o.mesh.inverted;
    result.template_seconds += o.mesh.template_seconds;
    result.placement_seconds += o.mesh.placement_seconds;
  }
  drop_unused_nodes(mesh);
  return result;
}

}  // namespace tquad
