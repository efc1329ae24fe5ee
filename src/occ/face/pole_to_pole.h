// mesh_pole_to_pole: a face closed around two poles, whose only edges are its seam
// and the two degenerate edges of its poles (a full sphere, a closed surface of
// revolution), meshed as the cube sphere (core/templates/cube_sphere.h) laid on it.
//
// The cube sphere's seam meridian takes the seam's own nodes; every other node
// keeps the cube sphere's longitude as the surface's u (a turn of u for a turn of
// longitude) and its latitude as v, interpolated between the seam nodes' v so that
// each parallel of nodes meets the seam at its node. On a sphere the seam's nodes,
// equally spaced by arc length, are the cube sphere's own, and the mesh is exact; on
// another surface of revolution its quads follow the surface's meridians and
// parallels.
#pragma once

#include <TopoDS_Face.hxx>

#include <vector>

#include "occ/face/face_boundary.h"
#include "occ/face/face_mesher.h"

namespace tquad {

// Whether the face has one wire, whose edges are one seam (closed on the face) and
// degenerate edges (its poles), nothing else. Returns the seam's shape edge index, or
// -1 for any other face.
int closed_seam_edge(const ShapeIndex& index, int face);

// The seam's segment count must be a multiple of 4 (2m, m even: the meridian through
// the centre of the cube's side faces); FaceRefusalError (cannot_mesh) otherwise, or
// when the face is not periodic in u or its seam does not run from pole to pole.
// The mesh is measured on the surface (check_on_surface), not smoothed.
FaceMeshResult mesh_pole_to_pole(const TopoDS_Face& face, int face_index, const FaceBoundary& boundary,
                                 const std::vector<Vec3>& nodes);

}  // namespace tquad
