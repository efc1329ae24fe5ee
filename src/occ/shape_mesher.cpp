#include "occ/model/edge_contraction.h"
#include "occ/model/strip_absorption.h"
#include "occ/shape_mesher.h"

#include "occ/intervals/band_alignment.h"

#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/cancellation.h"
#include "core/elapsed.h"
#include "core/input_error.h"
#include "core/mesh/shell_orientation.h"
#include "core/templates/count_fitting.h"
#include "occ/face/cusp_ends.h"
#include "occ/intervals/edge_discretization.h"
#include "occ/model/face_sewing.h"
#include "occ/face/mid_edge_nodes.h"
#include "occ/face/face_boundary.h"
#include "occ/face/face_corners.h"
#include "occ/face/face_route.h"
#include "occ/model/shape_index.h"

namespace tquad {

namespace {

// Beyond this many units across, a shape's coordinates are taken for damage (1e12
// mm is a million km): the sizes and counts derived from them would be meaningless.
constexpr double kMaxShapeExtent = 1e12;

// The shape's bounding box (BRepBndLib); throws InputError when it is absurd. A shape
// without any (no face, no edge) gets a box 25 across, so that the default size is 1.
Box3 checked_shape_box(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  if (box.IsVoid()) return {{0, 0, 0}, {25.0, 0, 0}};
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const Box3 result{{x0, y0, z0}, {x1, y1, z1}};
  const double diagonal = result.diagonal();
  if (!(diagonal <= kMaxShapeExtent)) {
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", diagonal);
    throw InputError(std::string("the shape is ") + text + " units across: its coordinates are absurd (a damaged file?)");
  }
  return result;
}

// The area estimate mostly undercounts (edges refined for curvature and small faces
// give more quads than area / size^2) and overcounts little (a face's quads cover
// its area with sides near the size): a shape whose estimate is over the limit is refused before meshing, since meshing
// it would take minutes and gigabytes only to be refused by the exact running total.
constexpr double kEstimateOverLimit = 1.0;

// About how many quads the faces take at `size`: each face's area / size^2 (a square
// grid of that size). A face whose area OpenCASCADE cannot integrate counts 0 here.
// `face_sizes`: per face, its own size where local sizes set one (or empty: `size`).
double estimated_quads(const ShapeIndex& index, const std::vector<char>& faces, double size,
                       const std::vector<double>& face_sizes) {
  double quads = 0;
  for (int f = 0; f < index.face_count(); ++f) {
    if (!faces[f]) continue;
    try {
      GProp_GProps properties;
      BRepGProp::SurfaceProperties(index.face(f), properties);
      const double h = face_sizes.empty() ? size : face_sizes[f];
      if (std::isfinite(properties.Mass())) quads += std::abs(properties.Mass()) / (h * h);
    } catch (const Standard_Failure&) {
    }
  }
  return quads;
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

// Removes the nodes no quad uses (vertices and edge nodes of faces not meshed or
// refused, seam nodes of refused faces), keeping the others in order; returns each
// old node's new index (-1: removed).
std::vector<NodeId> drop_unused_nodes(ShapeMesh& mesh) {
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
  return new_id;
}

// Runs job(i) for i in [0, count) on `threads` workers. An exception in a job stops
// the workers at their next job and is rethrown here once all have joined (an
// exception leaving a std::thread would end the process).
template <typename Job>
void run_parallel(int count, int threads, const Job& job) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::min(threads, std::max(1, count));
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_failure;
  std::mutex failure_mutex;
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) {
    workers.emplace_back([&] {
      for (int i = next++; i < count && !failed; i = next++) {
        try {
          job(i);
        } catch (...) {
          const std::lock_guard<std::mutex> lock(failure_mutex);
          if (!first_failure) first_failure = std::current_exception();
          failed = true;
        }
      }
    });
  }
  for (std::thread& w : workers) w.join();
  if (first_failure) std::rethrow_exception(first_failure);
}

// The pipeline's state, stage after stage (as OpenCASCADE's IMeshTools context):
// each stage reads what the ones before it left and fills its own part.
class ShapeMeshContext {
 public:
  ShapeMeshContext(const TopoDS_Shape& shape, const ShapeMeshOptions& options)
      : shape_(shape), options_(options), index_(shape) {}

  ShapeMeshResult run() {
    // Long loops of the stages on this thread look at the cancel flag too; their
    // heartbeat repeats the stage's start (the faces' workers have their own).
    const CancellationScope scope(options_.cancel, [this] { report(current_stage_, 0, 1); });
    stage("index", [&] { index_faces(); });
    // Small faces whose quads stay inverted get their edges' counts doubled, and
    // refused faces whose boundary crosses itself only by its chords their crossing
    // curves' (crossing_chords.h); then the shape is meshed again (at most
    // kRefinements times: doubling one face's edges changes its neighbours' counts,
    // which may need their own round).
    constexpr int kRefinements = 4;
    // A round is kept only when it leaves fewer faces refused than every round before
    // it: doubling counts changes the neighbours' counts too, and on some shapes the
    // later rounds refuse more faces than the first. Two rounds in a row that refuse no
    // fewer than the best before them end the refinement: a face may need its edges
    // doubled twice, but doubling again the edges of faces that two finer counts did
    // not repair repeats the same layouts at twice the cost each time.
    constexpr int kStalledRounds = 2;
    int stalled = 0;
    std::optional<RoundState> best;
    for (int round = 0;; ++round) {
      stage("assign intervals", [&] { assign_intervals(); });
      stage("discretize edges", [&] { discretize(round == 0); });
      stage("mesh faces", [&] { mesh_faces(); });
      const int refused = refused_faces();
      result_.refused_per_round.push_back(refused);
      result_.kept_round = round;
      stalled = best && refused >= best->refused ? stalled + 1 : 0;
      if (stalled >= kStalledRounds) break;
      if (round >= kRefinements || !refine_edges_of_inverted_faces()) break;
      if (!best || refused < best->refused) best = save_round(refused, round);
      ++result_.refinement_rounds;
    }
    if (best && result_.refused_per_round.back() >= best->refused) {
      result_.kept_round = best->round;
      restore_round(std::move(*best));
    }
    // Once every face is meshed (the part's worst corner known), in face order: the
    // same for any number of threads.
    result_.higher_mean_faces = take_higher_means(outcomes_, meshed_);
    report_intervals();
    stage("assemble", [&] { assemble(); });
    if (options_.order == 2) stage("mid-edge nodes", [&] { add_middles(); });
    return std::move(result_);
  }

 private:
  template <typename Work>
  void stage(const char* name, const Work& work) {
    throw_if_cancelled();
    current_stage_ = name;
    report(name, 0, 1);
    const auto start = std::chrono::steady_clock::now();
    try {
      work();
    } catch (const OperationCancelled&) {
      throw MeshCancelled("meshing cancelled");
    } catch (const Standard_Failure& failure) {  // OpenCASCADE on a damaged shape; no std::exception
      const std::string what = *failure.GetMessageString() ? failure.GetMessageString() : failure.DynamicType()->Name();
      throw InputError(std::string("OpenCASCADE failed on the shape in stage '") + name + "': " + what +
                       " (a damaged file?)");
    }
    result_.stage_seconds[name] += seconds_since(start);
    throw_if_cancelled();
    report(name, 1, 1);
  }
  void report(const char* name, int done, int total) {
    if (!options_.progress) return;
    const std::lock_guard<std::mutex> lock(progress_mutex_);
    options_.progress(MeshProgress{name, done, total});
  }
  bool cancelled() const { return options_.cancel && options_.cancel->load(); }
  void throw_if_cancelled() const {
    if (cancelled()) throw MeshCancelled("meshing cancelled");
  }

  // Stage "index": faces to mesh, the target size, and the edges they need.
  void index_faces() {
    meshed_ = meshed_faces(index_, options_.faces);
    const Box3 box = checked_shape_box(shape_);  // checked even when the size is given
    const double diagonal = box.diagonal();
    result_.diagonal = diagonal;
    if (options_.size > 0 && options_.min_size > options_.size) {
      char text[96];
      std::snprintf(text, sizeof text, "the minimum element size (%g) is larger than the element size (%g)",
                    options_.min_size, options_.size);
      throw InputError(text);
    }
    result_.size = std::max(options_.size > 0 ? options_.size : diagonal / 25.0, options_.min_size);
    // Damaged faces (the reader's check, or an edge whose curve cannot be evaluated)
    // are refused before anything else looks at them; the rest is meshed without them.
    damaged_ = options_.damaged_faces;
    std::vector<char> usable(index_.edge_count(), 1);
    for (const auto& [e, why] : unusable_edges(index_, box)) {
      usable[e] = 0;
      for (int f : index_.faces_of_edge(e)) {
        if (!damaged_.count(f)) damaged_[f] = "its edge " + std::to_string(e) + " " + why + " (a damaged file?)";
      }
    }
    to_mesh_ = meshed_;
    for (const auto& [f, why] : damaged_) if (f >= 0 && f < index_.face_count()) to_mesh_[f] = 0;
    edge_floor_ = edge_turn_minimums(index_, usable, options_.curvature_segments);
    sized_ = edge_segment_counts(index_, result_.size, edge_floor_, lengths_, usable);
    // Local sizes only refine: each edge's count from its graded field, at least its
    // turning minimum; strips and short edges are then judged by the smallest size.
    check_growth_rate(options_.growth_rate);
    if (options_.curvature_segments < 8 || options_.curvature_segments > 1000) {
      throw InputError("the segments per full turn of a curve must be 8 (one per 45 degrees) to 1000, not " +
                       std::to_string(options_.curvature_segments));
    }
    double judged_size = result_.size;
    goal_lengths_ = lengths_;
    graded_floor_.assign(index_.edge_count(), 0);
    if (!options_.local_sizes.empty()) {
      const SizeField field = local_size_field(index_, result_.size, options_.min_size, options_.local_sizes,
                                               options_.growth_rate, lengths_);
      for (int e = 0; e < index_.edge_count(); ++e) {
        if (!usable[e] || !(lengths_[e] > 0)) continue;
        const double goal = graded_segments(field.edges[e], lengths_[e]);
        check_goal(goal, "edge " + std::to_string(e));
        const int graded = field.edges[e].graded() ? static_cast<int>(std::ceil(goal - 1e-9))
                                                   : static_cast<int>(std::lround(goal));
        sized_[e] = std::max(edge_floor_[e], std::max(1, graded));
        goal_lengths_[e] = std::max(1, graded) * result_.size;
        if (field.edges[e].graded()) graded_floor_[e] = graded;
      }
      spacings_.grading = field.edges;
      face_sizes_ = field.faces;
      judged_size = field.smallest;
    }
    // Faces narrower than the contraction bound are absorbed (strip_absorption.h) and
    // edges far shorter than the size become one node (edge_contraction.h), before
    // any face's sides are counted.
    // Strips are found among all undamaged faces, requested or not: one left meshed
    // would keep its neighbours' short end edges.
    std::vector<char> whole(index_.face_count(), 1);
    for (const auto& [f, why] : damaged_) if (f >= 0 && f < index_.face_count()) whole[f] = 0;
    result_.absorbed_strips = contract_and_absorb(index_, strips_to_absorb(index_, whole, lengths_, usable, judged_size),
                                                  lengths_, usable, judged_size, result_.contracted_edges);
    const std::vector<char> requested = to_mesh_;
    for (const AbsorbedStrip& strip : result_.absorbed_strips) meshed_[strip.face] = to_mesh_[strip.face] = 0;
    if (std::count(meshed_.begin(), meshed_.end(), 1) == 0) {
      // Every face asked for is absorbed: named, rather than an empty mesh.
      for (const AbsorbedStrip& strip : result_.absorbed_strips) {
        if (!requested[strip.face]) continue;
        char text[160];
        std::snprintf(text, sizeof text, "face %d is a strip %.3g wide, under %g of the size %g: it is absorbed "
                      "into its neighbours' edges and has no quads of its own", strip.face, strip.width,
                      kContractedEdgeRatio, result_.size);
        throw InputError(text);
      }
    }
    for (int e = 0; e < index_.edge_count(); ++e) {
      if (index_.contracted(e)) edge_floor_[e] = sized_[e] = 0;
    }
    raise_three_edge_face_floors(index_, to_mesh_, edge_floor_);
    raise_two_edge_loop_floors(index_, to_mesh_, edge_floor_);
    for (int e = 0; e < index_.edge_count(); ++e) sized_[e] = std::max(sized_[e], edge_floor_[e]);
    // A cusp end's first segment is as long as the size there allows: an edge's local
    // size where one applies, so that it grades like the edge's other segments, and
    // never longer than the edge's length over its least count, so that a curved edge
    // keeps at most the --curvature-segments angle per segment.
    std::vector<double> edge_sizes(index_.edge_count(), result_.size);
    for (int e = 0; e < static_cast<int>(spacings_.grading.size()); ++e) {
      const EdgeSizing& g = spacings_.grading[e];
      if (g.own > 0) edge_sizes[e] = std::min({g.own, g.first > 0 ? g.first : g.own, g.last > 0 ? g.last : g.own});
    }
    for (int e = 0; e < index_.edge_count(); ++e) {
      if (edge_floor_[e] > 0 && lengths_[e] > 0) edge_sizes[e] = std::min(edge_sizes[e], lengths_[e] / edge_floor_[e]);
    }
    spacings_.cusp_ends = cusp_ends(index_, edge_sizes, lengths_);
    needed_.assign(index_.edge_count(), 0);
    for (int f = 0; f < index_.face_count(); ++f) {
      if (!to_mesh_[f]) continue;
      for (TopExp_Explorer it(index_.face(f), TopAbs_EDGE); it.More(); it.Next()) needed_[index_.edge_index(it.Current())] = 1;
    }
    // A merged edge's nodes are those of the edge it is merged into.
    for (const AbsorbedStrip& strip : result_.absorbed_strips) {
      needed_[strip.kept] = needed_[strip.kept] || needed_[strip.merged];
    }
    minimum_.assign(index_.edge_count(), 0);
    for (const UnsewnEdgePair& pair : unsewn_edge_pairs(index_)) {
      if (meshed_[index_.faces_of_edge(pair.first).front()] && meshed_[index_.faces_of_edge(pair.second).front()]) {
        result_.unsewn_edges.push_back(pair);
      }
    }
  }

  std::string over_limit_text() const {
    return ", over the limit of " + std::to_string(options_.templates.max_quads) + " (--max-quads); use a larger --size";
  }

  // Stage "assign intervals": every edge's count (size, curvature, refinement), then
  // every meshed face's total made even. Cuts inside faces get theirs with the face.
  void assign_intervals() {
    segments_ = sized_;
    for (int e = 0; e < index_.edge_count(); ++e) {
      segments_[e] = needed_[e] && !index_.contracted(e) ? std::max(segments_[e], minimum_[e]) : 0;
    }
    // No change goes below the curvature and three-edge-face bounds or a refinement,
    // nor below a graded edge's ceil(F): fewer segments than the integral F of 1 / size
    // would make neighbours differ by more than the growth rate (local_sizes.h).
    std::vector<int> floor = edge_floor_;
    for (int e = 0; e < index_.edge_count(); ++e) {
      floor[e] = std::max({floor[e], minimum_[e], index_.contracted(e) ? 0 : graded_floor_[e]});
    }
    intervals_ = assign_shape_intervals(index_, to_mesh_, goal_lengths_, result_.size, segments_, floor, wires_,
                                        &spacings_);
    // Before anything is allocated: a face of E boundary segments has at least
    // E / 2 - 1 quads (nodes = 1 + quads + E / 2 - holes, and its E boundary nodes).
    long long at_least = 0;
    for (int f = 0; f < index_.face_count(); ++f) {
      if (to_mesh_[f]) at_least += std::max(0, face_boundary_total(index_, f, segments_) / 2 - 1);
    }
    if (at_least > options_.templates.max_quads) {
      throw InputError("the edge counts alone give at least " + std::to_string(at_least) + " quads" +
                       over_limit_text());
    }
    // And at most about sum(E^2) / (4 pi) (a face of perimeter P has at most the area
    // P^2 / (4 pi) of a disk): when that is well under the limit, as in any ordinary
    // run, the faces' areas (a surface integral each, a large share of the run's time
    // on parts of many curved faces) need not be computed.
    double at_most = 0;
    for (int f = 0; f < index_.face_count(); ++f) {
      if (!to_mesh_[f]) continue;
      const double e = face_boundary_total(index_, f, segments_);
      at_most += e * e / (4 * M_PI);
    }
    const double refused_above = kEstimateOverLimit * static_cast<double>(options_.templates.max_quads);
    if (at_most > refused_above) {
      const double estimate = estimated_quads(index_, to_mesh_, result_.size, face_sizes_);
      if (estimate > refused_above) {
        char text[96];
        std::snprintf(text, sizeof text, "the faces' area at size %.3g gives about %.3g quads", result_.size, estimate);
        throw InputError(text + over_limit_text());
      }
    }
  }

  // Stage "discretize edges": every edge once, shared by its faces.
  void discretize(bool first) {
    // The previous round's edges and nodes, to take over the faces none of whose
    // edges changed (mesh_faces).
    previous_edges_ = std::move(edges_);
    previous_nodes_ = std::move(result_.mesh.nodes);
    result_.mesh.nodes.clear();
    edges_ = discretize_edges(index_, segments_, result_.mesh.nodes, &spacings_);
    aligned_bands_ = align_narrow_bands(index_, meshed_, edges_, result_.mesh.nodes, &spacings_);
    if (first) check_requested_corners(index_, meshed_, options_.corners, edges_, result_.mesh.nodes);
  }

  // Stage "mesh faces": each face by its route (face_route.h), in parallel; progress
  // counts faces done, and a cancel stops the workers before their next face.
  void mesh_faces() {
    // In a refinement round, a face whose edges did not change keeps its mesh: each
    // round would otherwise mesh every face again.
    std::vector<FaceOutcome> previous = std::move(outcomes_);
    previous.resize(index_.face_count());
    outcomes_.assign(index_.face_count(), FaceOutcome{});
    const int total = static_cast<int>(std::count(meshed_.begin(), meshed_.end(), 1));
    int done = 0;  // counted under the progress lock, so reports never go backwards
    // Each face keeps under the limit by itself; the faces together are counted as
    // they finish, and the workers stop once their sum is over it.
    std::atomic<long long> quads{0};
    const long long limit = options_.templates.max_quads;
    run_parallel(index_.face_count(), options_.threads, [&](int f) {
      if (!meshed_[f] || cancelled() || quads.load() > limit) return;
      const auto damaged = damaged_.find(f);
      if (damaged != damaged_.end()) {
        outcomes_[f].reason = "face " + std::to_string(f) + ": " + damaged->second;
        outcomes_[f].code = RefusalCode::damaged;
      } else {
        if (reuse_unchanged_face(index_, f, previous_edges_, previous_nodes_, edges_, result_.mesh.nodes, previous[f])) {
          outcomes_[f] = std::move(previous[f]);
        } else {
          // Inside the face, long loops look at the cancel flag (cancellation.h); the
          // heartbeat repeats the faces' count, so that a front end whose progress
          // callback raises the flag is asked while a large face is meshed.
          const CancellationScope scope(options_.cancel, [&] {
            if (!options_.progress) return;
            const std::lock_guard<std::mutex> lock(progress_mutex_);
            options_.progress(MeshProgress{"mesh faces", done, total});
          });
          outcomes_[f] = mesh_one_face(index_, f, edges_, result_.mesh.nodes, options_, result_.size);
        }
        if (outcomes_[f].ok) quads += static_cast<long long>(outcomes_[f].mesh.quads.size());
      }
      if (!options_.progress) return;
      const std::lock_guard<std::mutex> lock(progress_mutex_);
      options_.progress(MeshProgress{"mesh faces", ++done, total});
    });
    if (quads.load() > limit) {
      // (How many were meshed before the workers stopped depends on the threads.)
      throw InputError("the faces together have more quads" + over_limit_text());
    }
  }

  // What a round leaves for assembly: counts, edges, nodes, face outcomes.
  struct RoundState {
    int refused = 0, round = 0;
    std::vector<int> segments;
    std::vector<EdgeNodes> edges;
    std::vector<Vec3> nodes;
    std::vector<FaceOutcome> outcomes;
    IntervalReport intervals;
    int aligned_bands = 0;
  };

  int refused_faces() const {
    int refused = 0;
    for (int f = 0; f < index_.face_count(); ++f) refused += meshed_[f] && !outcomes_[f].ok ? 1 : 0;
    return refused;
  }

  RoundState save_round(int refused, int round) const {
    return RoundState{refused, round, segments_, edges_, result_.mesh.nodes, outcomes_, intervals_, aligned_bands_};
  }

  void restore_round(RoundState&& kept) {
    segments_ = std::move(kept.segments);
    edges_ = std::move(kept.edges);
    result_.mesh.nodes = std::move(kept.nodes);
    outcomes_ = std::move(kept.outcomes);
    intervals_ = std::move(kept.intervals);
    aligned_bands_ = kept.aligned_bands;
  }

  // The kept round's interval assignment, for the report.
  void report_intervals() {
    result_.changes = intervals_.changes;
    result_.interval_chains = intervals_.chains;
    result_.chained_edges = intervals_.chained_edges;
    result_.balanced_bands = intervals_.balanced_bands;
    result_.balanced_rings = intervals_.balanced_rings;
    result_.quartered_pole_rims = intervals_.quartered_pole_rims;
    result_.aligned_bands = aligned_bands_;
  }

  bool refine_edges_of_inverted_faces() {
    bool refine = false;
    for (int f = 0; f < index_.face_count(); ++f) {
      if (!meshed_[f] || !outcomes_[f].finer_edges_may_help) continue;
      refine = true;
      const std::vector<int>& only = outcomes_[f].refine_edges;
      for (int e : only) minimum_[e] = std::max(minimum_[e], 2 * segments_[e]);
      if (!only.empty()) continue;
      for (TopExp_Explorer it(index_.face(f), TopAbs_EDGE); it.More(); it.Next()) {
        const int e = index_.edge_index(it.Current());
        minimum_[e] = std::max(minimum_[e], 2 * segments_[e]);
      }
    }
    return refine;
  }

  // Stage "assemble": the refusal policy, then the faces' quads and interior nodes in
  // face order (interior nodes after all edge nodes), whatever the thread count.
  void add_middles() {
    std::vector<const FaceMeshResult*> face_meshes;
    for (const FaceMesh& record : result_.mesh.faces) face_meshes.push_back(&outcomes_[record.face].mesh);
    result_.straightened_mid_nodes = add_mid_edge_nodes(index_, edges_, new_node_id_, face_meshes, result_.mesh);
  }

  void assemble() {
    ShapeMesh& mesh = result_.mesh;
    for (int f = 0; f < index_.face_count(); ++f) {
      if (meshed_[f] && !outcomes_[f].ok) {
        mesh.refused_faces.push_back({f, outcomes_[f].reason, outcomes_[f].code, index_.outer_wire_vertices(f)});
      }
    }
    if (!mesh.refused_faces.empty() && !options_.keep_going) {
      std::string text = std::to_string(mesh.refused_faces.size()) + " face(s) refused: ";
      bool internal = false;
      for (std::size_t i = 0; i < mesh.refused_faces.size(); ++i) {
        text += (i ? "; " : "") + mesh.refused_faces[i].reason;
        internal = internal || mesh.refused_faces[i].code == RefusalCode::internal;
      }
      if (internal) throw std::runtime_error(text);  // the mesher's fault: exit 1
      throw FacesRefusedError(text, mesh.refused_faces);
    }
    if (!mesh.refused_faces.empty() &&
        static_cast<std::size_t>(std::count(meshed_.begin(), meshed_.end(), 1)) == mesh.refused_faces.size()) {
      throw InputError("no face could be meshed; the first refused: " + mesh.refused_faces.front().reason);
    }
    const std::size_t edge_nodes = mesh.nodes.size();  // the shape's edge and vertex nodes come first
    for (int f = 0; f < index_.face_count(); ++f) {
      if (!meshed_[f] || !outcomes_[f].ok) continue;
      const FaceMeshResult& m = outcomes_[f].mesh;
      const std::vector<NodeId>& shared = m.boundary_nodes;
      const NodeId loop_size = static_cast<NodeId>(shared.size());
      const NodeId base = static_cast<NodeId>(mesh.nodes.size());
      mesh.nodes.insert(mesh.nodes.end(), m.interior.begin(), m.interior.end());
      const auto first = static_cast<std::int64_t>(mesh.quads.size());
      for (const Quad& q : m.quads) {
        Quad g;
        for (int k = 0; k < 4; ++k) g[k] = q[k] < loop_size ? shared[q[k]] : base + (q[k] - loop_size);
        mesh.quads.push_back(g);
      }
      mesh.scaled_jacobian.insert(mesh.scaled_jacobian.end(), m.scaled_jacobian.begin(), m.scaled_jacobian.end());
      mesh.faces.push_back(
          {f, m.template_tree, first, static_cast<std::int64_t>(m.quads.size()), m.corner_search, m.route});
      result_.projected_faces += m.used_projection ? 1 : 0;
      result_.inverted += m.inverted;
      if (m.bad > 0) result_.bad_quad_faces.emplace_back(f, m.bad);
      result_.off_surface += m.off_surface;
      result_.template_seconds += m.template_seconds;
      result_.placement_seconds += m.placement_seconds;
      result_.meshing_seconds += m.meshing_seconds;
      result_.smoothing_seconds += m.smoothing_seconds;
    }
    new_node_id_ = drop_unused_nodes(mesh);
    orient_faces(static_cast<NodeId>(
        std::count_if(new_node_id_.begin(), new_node_id_.begin() + static_cast<std::ptrdiff_t>(edge_nodes),
                      [](NodeId n) { return n >= 0; })));
  }

  // Faces of a solid keep the outward orientation the solid gives them; the others
  // (shells, face sets, sewn faces) are turned to agree with their neighbours
  // (shell_orientation.h), and pairs that cannot agree are reported.
  void orient_faces(NodeId boundary_nodes) {
    ShapeMesh& mesh = result_.mesh;
    TopTools_IndexedDataMapOfShapeListOfShape solids_of_face;
    TopExp::MapShapesAndAncestors(shape_, TopAbs_FACE, TopAbs_SOLID, solids_of_face);
    std::vector<char> anchored(mesh.faces.size(), 0);
    for (std::size_t k = 0; k < mesh.faces.size(); ++k) {
      const int i = solids_of_face.FindIndex(index_.face(mesh.faces[k].face));
      anchored[k] = i > 0 && !solids_of_face(i).IsEmpty();
    }
    ShellOrientation orientation = orient_shells(mesh, boundary_nodes, anchored);
    result_.turned_faces = std::move(orientation.turned_faces);
    result_.orientation_conflicts = std::move(orientation.conflicts);
  }

  const TopoDS_Shape& shape_;
  const ShapeMeshOptions& options_;
  ShapeIndex index_;  // edges contracted once, in index_faces
  std::mutex progress_mutex_;
  ShapeMeshResult result_;
  std::vector<char> meshed_, needed_;
  std::vector<double> lengths_;
  // The lengths the interval assignment aims by (its goal is length / size): the
  // edges' own, or under local sizes each edge's graded count times the size.
  std::vector<double> goal_lengths_;
  std::vector<int> sized_, minimum_, segments_, edge_floor_, graded_floor_;
  std::map<int, std::string> damaged_;  // faces refused before meshing, with the reason
  std::vector<char> to_mesh_;           // meshed_ without the damaged faces
  std::vector<EdgeNodes> edges_;
  std::vector<EdgeNodes> previous_edges_;  // the last round's, while meshing the next
  std::vector<double> face_sizes_;         // per face, its own size under local sizes (or empty)
  const char* current_stage_ = "index";    // the stage running, for the heartbeat
  EdgeSpacings spacings_;                  // each edge's last spacing, for the next rounds
  IntervalReport intervals_;               // the round's interval assignment
  int aligned_bands_ = 0;                  // the round's aligned bands (band_alignment.h)
  FaceWireEdges wires_{index_};            // each face's wires, walked once
  std::vector<Vec3> previous_nodes_;
  std::vector<FaceOutcome> outcomes_;
  std::vector<NodeId> new_node_id_;  // assemble's renumbering: edges_' ids -> the mesh's (-1: dropped)
};

}  // namespace

ShapeMeshResult mesh_shape(const TopoDS_Shape& shape, const ShapeMeshOptions& options) {
  if (options.order != 1 && options.order != 2) {
    throw InputError("the element order must be 1 or 2, not " + std::to_string(options.order));
  }
  if (!options.sew) return ShapeMeshContext(shape, options).run();
  const SewnShape sewn = sew_faces(shape);
  ShapeMeshResult result = ShapeMeshContext(sewn.shape, options).run();
  result.sewn_edges = sewn.edges_before - sewn.edges_after;
  return result;
}

}  // namespace tquad
