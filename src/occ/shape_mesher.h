// mesh_shape: all-quad meshes of the faces of a CAD shape, conforming across shared
// edges. A pipeline of named stages held by one context:
//   index            faces to mesh, target size, edge lengths and curvature;
//   assign intervals every edge's count, every face's total even (interval_assignment.h);
//   discretize edges every edge once, its nodes shared by its faces;
//   mesh faces       per face and in parallel, its route (face_route.h): templates on
//                    its corners, O-grid, decomposition into patches with their cuts,
//                    placed on the surface and checked;
//   assemble         the refusal policy, then the faces numbered in order, so the
//                    output is the same whatever the number of threads.
// Small faces refused for inverted quads send the pipeline back to "assign
// intervals" with finer edges (four times at most). Progress and cancel hooks are in the
// options.
#pragma once

#include <TopoDS_Shape.hxx>

#include <atomic>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.h"
#include "core/templates/mesher.h"
#include "core/mesh/shape_mesh.h"
#include "occ/intervals/interval_assignment.h"
#include "occ/intervals/local_sizes.h"
#include "occ/model/strip_absorption.h"
#include "occ/model/unsewn_edges.h"

namespace tquad {

// What the pipeline is doing: a stage's name ("index", "assign intervals",
// "discretize edges", "mesh faces", "assemble") and how far it is (done of total;
// for "mesh faces", faces done).
struct MeshProgress {
  std::string stage;
  int done = 0, total = 1;
};

// Thrown when the cancel flag is raised; nothing is returned or written.
class MeshCancelled : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Faces refused while keep_going is off: the job stops (exit 2, ValueError). The
// message lists the faces' reasons; each front end adds how to mesh the others
// (--keep-going, keep_going=True), and can read the records themselves.
class FacesRefusedError : public InputError {
 public:
  FacesRefusedError(const std::string& message, std::vector<RefusedFace> refused)
      : InputError(message), refused_(std::move(refused)) {}
  const std::vector<RefusedFace>& refused() const { return refused_; }

 private:
  std::vector<RefusedFace> refused_;
};

struct ShapeMeshOptions {
  // Target edge length; <= 0 uses the shape's bounding-box diagonal / 25.
  double size = 0.0;
  // The target edge length never goes below it (0: no floor), whether given or
  // automatic; curvature and short edges may still give shorter segments.
  double min_size = 0.0;
  // Target edge lengths per face, edge or vertex (local_sizes.h), under the global
  // one; neighbouring segments then differ by at most growth_rate.
  std::vector<LocalSize> local_sizes;
  double growth_rate = kDefaultGrowthRate;
  // Curved edges get at least this many segments per full turn (edge_discretization.h;
  // at least 8, one per 45 degrees).
  int curvature_segments = 8;
  // Faces to mesh (0-based); empty: all.
  std::vector<int> faces;
  // Per face, the shape vertices to use as corners (2 to 4).
  std::map<int, std::vector<int>> corners;
  MeshOptions templates;
  // Faces refused before meshing, with the reason (the reader's geometry check:
  // isolated_reader.h).
  std::map<int, std::string> damaged_faces;
  // Smooth each face's mesh on its surface (surface_smoothing.h).
  bool smooth = true;
  // Search more corner sets per face without holes (face_corners.h,
  // searched_corner_choices) and keep the best worst, then mean, scaled Jacobian.
  bool best_corners = false;
  // Worker threads for the faces; <= 0: all cores.
  int threads = 0;
  // 1: four-node quads; 2: eight-node quads, a node in the middle of each edge on the
  // curve or surface it stands for (mid_edge_nodes.h).
  int order = 1;
  // Mesh the other faces when one is refused (and list it); otherwise refuse all.
  bool keep_going = false;
  // Keep a face whose mesh still has bad quads after repair (inverted, degenerate or
  // folded: is_bad_quad; listed in ShapeMeshResult::bad_quad_faces) instead of
  // refusing it.
  bool allow_inverted = false;
  // Join faces that touch without sharing their edge before meshing (face_sewing.h),
  // so the mesh is connected there; face numbers stay the shape's.
  bool sew = false;
  // Called at each stage's start and end, and after each face (from worker threads,
  // one call at a time). May be empty.
  std::function<void(const MeshProgress&)> progress;
  // When set and raised (by another thread, or by `progress`), meshing stops at the
  // next face or stage with MeshCancelled.
  const std::atomic<bool>* cancel = nullptr;
};

struct ShapeMeshResult {
  ShapeMesh mesh;
  double size = 0.0;                     // the target size used
  double diagonal = 0.0;                 // the shape's bounding-box diagonal (the default size's D)
  std::vector<IntervalChange> changes;   // edge counts changed by the interval assignment
  long long projected_faces = 0;         // faces meshed by the 3D route
  long long inverted = 0;                // quads still inverted after repair
  // With allow_inverted: each face kept with bad quads (is_bad_quad: inverted,
  // degenerate or folded), as {face, bad quads}; without it such faces are refused.
  std::vector<std::pair<int, long long>> bad_quad_faces;
  std::map<std::string, double> stage_seconds;  // wall time per stage, summed over rounds
  long long off_surface = 0;             // quads cutting across their surface (face_mesher.h)
  int refinement_rounds = 0;            // times small faces' edges were doubled
  // Faces refused after each round (round 0 first), and the round whose meshes were
  // kept: the last one, unless an earlier one refused fewer faces (the earliest such).
  std::vector<int> refused_per_round;
  int kept_round = 0;
  // Faces given their higher-mean mesh, the part's worst corner holding
  // (take_higher_means, face_route.h).
  int higher_mean_faces = 0;
  long long straightened_mid_nodes = 0;  // second order: middles put on their chords (mid_edge_nodes.h)
  int interval_chains = 0;               // chains of opposite edges given one count
  int chained_edges = 0;                 // edges in those chains
  int balanced_bands = 0;                // faces one segment wide given equal long sides
  int aligned_bands = 0;                 // bands whose long sides' nodes face each other (band_alignment.h)
  int balanced_rings = 0;                // faces of two loops given equal totals
  int quartered_pole_rims = 0;           // disks around a pole given a multiple of 4 on their rim
  // Edges far shorter than the size, each made one node (edge_contraction.h).
  std::vector<int> contracted_edges;
  // Faces narrower than that bound everywhere, absorbed: no quads, their two long
  // sides one row of nodes (strip_absorption.h).
  std::vector<AbsorbedStrip> absorbed_strips;
  // Edges of meshed faces that lie on each other without being one edge (the file's
  // faces are not sewn there): the mesh has a crack along each (unsewn_edges.h).
  std::vector<UnsewnEdgePair> unsewn_edges;
  // With ShapeMeshOptions::sew: the edges sewing merged away (the shape's edge count
  // before, less after).
  int sewn_edges = 0;
  // Faces outside solids whose quads were turned to agree with their neighbours'
  // normals, and face pairs that meet with normals that cannot agree (a one-sided
  // shell, or solids' faces that disagree): shell_orientation.h.
  std::vector<int> turned_faces;
  std::vector<std::pair<int, int>> orientation_conflicts;
  double template_seconds = 0;           // summed over faces (all threads)
  double placement_seconds = 0;          // interior nodes onto the surfaces, summed
  double meshing_seconds = 0;            // every face's routes before smoothing, summed
  double smoothing_seconds = 0;          // the chosen meshes smoothed, summed
};

// Throws InputError (a face index out of range; without keep_going, a refused face,
// naming it and the reason).
ShapeMeshResult mesh_shape(const TopoDS_Shape& shape, const ShapeMeshOptions& options);

}  // namespace tquad
