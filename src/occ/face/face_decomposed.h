// Faces meshed by a decomposition into patches (core's face_decomposition.h and
// o_grid.h) in a chart of their (u, v) space.
//
// The chart is (u, v) scaled by the surface's mean first derivatives |S_u| and |S_v|
// over the face (and mirrored when the outer loop runs clockwise in (u, v)), so that
// lengths and angles there are close to the surface's on cylinders, cones and
// unevenly parametrized B-splines: the decomposition measures angles and lengths. The
// mesh's interior nodes are the surface evaluated at their (u, v). The CAD vertices
// are the boundary points the decomposition may keep as sharp corners.
#pragma once

#include <TopoDS_Face.hxx>

#include <optional>

#include "core/templates/mesher.h"
#include "occ/face/face_boundary.h"
#include "occ/face/face_mesher.h"

namespace tquad {

// Any outline, any number of holes: the general decomposition. `vertex_nodes`: shared
// nodes below this id are CAD vertices. Returns the meshes of the plain decomposition
// and of its variants (mesh_variants: DecompositionOptions that may mesh a face
// better), the best first (better_face_mesh); the caller may smooth them all and
// choose again. Throws InputError (naming the face) for a face with a pole, or when
// no decomposition can be made.
std::vector<FaceMeshResult> mesh_face_decomposed(const TopoDS_Face& face, int face_index, const FaceBoundary& boundary,
                                    const std::vector<Vec3>& nodes, int vertex_nodes, double edge_size,
                                    const MeshOptions& options);

// One hole: the O-grid of two four-sided halves (o_grid.h). Eight places for the
// first cut are tried around the rim; the mesh with the fewest inverted, then
// collapsed quads, then the best worst corner is kept. The tree reads "D2[...]".
// Throws InputError (naming the face) when no place gives a valid mesh.
FaceMeshResult mesh_face_o_grid(const TopoDS_Face& face, int face_index, const FaceBoundary& boundary,
                                const std::vector<Vec3>& nodes, int vertex_nodes, double edge_size,
                                const MeshOptions& options);

// A ring (one hole) whose loops have equal counts: one structured grid around the
// hole (mapped_ring.h), or nothing when the face is not such a ring.
std::optional<FaceMeshResult> mesh_face_ring(const TopoDS_Face& face, int face_index, const FaceBoundary& boundary,
                                             const std::vector<Vec3>& nodes, int vertex_nodes);

// A disk (one smooth loop, no hole): a square and four mapped patches around it
// (disk_o_grid.h), or nothing when the face is not such a disk. Throws InputError
// (naming the face) for a face with a pole or a broken chart.
std::optional<FaceMeshResult> mesh_face_disk(const TopoDS_Face& face, int face_index, const FaceBoundary& boundary,
                                             const std::vector<Vec3>& nodes, int vertex_nodes,
                                             const MeshOptions& options);

}  // namespace tquad
