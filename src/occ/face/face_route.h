// The algorithm per face, picked in one place: a registry of face routes (the
// templates on the face's own corners, ring and disk O-grids, polar templates, the
// cube sphere, the general decomposition), each with when it applies and how it
// proposes meshes; one chooser ranks every candidate by one order
// (better_face_mesh), smooths the best, and applies the refusal policy (never a
// silent bad mesh). FaceMeshResult::route names the route of the mesh kept.
#pragma once

#include <string>
#include <vector>

#include "core/face_refusal.h"
#include "occ/intervals/edge_discretization.h"
#include "occ/face/face_boundary.h"
#include "occ/face/face_mesher.h"
#include "occ/model/shape_index.h"
#include "occ/shape_mesher.h"

namespace tquad {

struct FaceOutcome {
  bool ok = false;
  // Refused for quads that stay inverted on a small mesh, or for a boundary whose
  // chords cross (crossing_chords.h): finer edges may help, on `refine_edges` (the
  // crossing curves), or on all the face's edges when that is empty.
  bool finer_edges_may_help = false;
  std::vector<int> refine_edges;
  // Why it was refused; RefusalCode::internal is a failure of the mesher itself (a
  // broken invariant, out of memory), not of the input: exit 1, not 2, when it stops
  // the job.
  RefusalCode code = RefusalCode::cannot_mesh;
  std::string reason;
  FaceBoundary boundary;
  FaceMeshResult mesh;
  // A smoothed candidate of higher mean than `mesh` and a lower worst corner, with no
  // quad unfit for analysis or off the surface (take_higher_means decides between them).
  std::optional<FaceMeshResult> higher_mean;
};

// The part's worst element is the lowest corner of its faces (lowest_corner: by the
// surface's normal or the quad's own). A face whose mesh won on its worst corner
// (better_worst_then_mean) takes its higher-mean alternative where that alternative's
// lowest corner is still at or above the part's and the part's
// mean over all its quads rises (a face's mean can rise with its quad count while the
// part's falls): the mesh's worst element stays the same, its mean rises. Faces are
// taken in order, each against the part's figures after the ones before it; every
// alternative is dropped after. Counts the faces that took theirs. `meshed[f]`: face f
// is part of the mesh (outcomes of other faces are left alone).
int take_higher_means(std::vector<FaceOutcome>& outcomes, const std::vector<char>& meshed);

// The registry's routes by name, in the order they are offered.
std::vector<std::string> face_route_names();

// Face f's mesh from the discretized edges; a refusal is returned with its reason,
// never thrown (an internal failure is named as such).
FaceOutcome mesh_one_face(const ShapeIndex& index, int f, const std::vector<EdgeNodes>& edges,
                          const std::vector<Vec3>& nodes, const ShapeMeshOptions& options, double size);

// A face meshed before the edges were discretized again (a refinement round) taken
// over as it is, where none of its edges changed: the same curve parameters and node
// positions, so mesh_one_face would give the same mesh. Its shared node ids are
// renumbered from `before_edges` to `edges`. False (outcome untouched) where an edge
// changed, the outcome was a refusal, or an id is not on the face's edges.
bool reuse_unchanged_face(const ShapeIndex& index, int f, const std::vector<EdgeNodes>& before_edges,
                          const std::vector<Vec3>& before_nodes, const std::vector<EdgeNodes>& edges,
                          const std::vector<Vec3>& nodes, FaceOutcome& outcome);

}  // namespace tquad
