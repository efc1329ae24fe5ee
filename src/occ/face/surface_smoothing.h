// smooth_face_mesh: a face's chosen mesh cleaned (doublets merged, core/repair/doublets.h)
// and smoothed on its surface (core/repair/smoothing.h).
//
// Interior nodes move in the mesh's own coordinates ((u, v), or polar (x, y) around a
// pole) and are evaluated on the surface; shared boundary nodes stay. The smoothed
// mesh is measured again (check_on_surface) and kept unless it is worse by that
// measure, so smoothing never costs a face its validity.
#pragma once

#include <vector>

#include <TopoDS_Face.hxx>

#include "core/repair/smoothing.h"
#include "occ/face/face_mesher.h"

namespace tquad {

// `nodes`: the shared nodes (the boundary's positions). A mesh from the 3D route
// (used_projection) on a face with a seam is left as it is: its (u, v) come from
// projections and may jump across the seam.
// `options`: the smoother's (fewer passes for a quick look at a candidate).
// `layouts`: whether layouts changed around boundary corners (flat corners turned,
// lopsided sharp ones flipped) are tried too; a quick look keeps the mesh's own.
enum class LayoutChanges { tried, none };
void smooth_face_mesh(const TopoDS_Face& face, bool has_seam, const std::vector<Vec3>& nodes, FaceMeshResult& mesh,
                      const SmoothingOptions& options = {}, LayoutChanges layouts = LayoutChanges::tried);

}  // namespace tquad
