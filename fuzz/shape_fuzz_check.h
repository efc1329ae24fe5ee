// What the shape fuzz targets (fuzz_brep, fuzz_step) demand of a shape that was read:
// meshed with the CLI's defaults on one thread (every refused face listed, as with
// --keep-going) at a coarse size (the bounding-box diagonal / 8, so that a run takes
// milliseconds) and at second order (the mid-edge nodes too), it ends in an
// InputError or in a mesh that passes check_shape_mesh with finite node coordinates,
// no inverted quad (a scaled Jacobian below -kSurfaceInvertedBelow: those faces are
// refused unless allowed) and one middle node per quad edge, shared by the quads on
// both sides (check_shape_mesh checks that). Anything else, another exception, a crash, a hang or a sanitizer
// report, is a bug.
#pragma once

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>

#include <cmath>
#include <cstdlib>

#include "core/input_error.h"
#include "core/mesh/quality.h"
#include "io/shape_mesh_check.h"
#include "occ/read/isolated_reader.h"
#include "occ/shape_mesher.h"

namespace tquad::fuzz {

// A short deadline: the seeds read in milliseconds, and an edit that makes
// OpenCASCADE's reader spin costs the whole deadline before the child is killed.
inline ReadLimits fuzz_read_limits() {
  ReadLimits limits;
  limits.seconds = 1;
  limits.memory_bytes = 2ULL << 30;
  return limits;
}

inline void mesh_and_check(const ReadShape& read) {
  ShapeMeshOptions options;
  try {
    Bnd_Box box;
    BRepBndLib::Add(read.shape, box);
    const double diagonal = box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
    if (std::isfinite(diagonal) && diagonal > 0) options.size = diagonal / 8;
  } catch (const Standard_Failure&) {
    return;  // mesh_shape refuses such a shape with an InputError
  }
  options.threads = 1;
  options.keep_going = true;
  options.order = 2;
  options.templates.max_quads = 200'000;
  for (int f : read.invalid_faces) options.damaged_faces[f] = kInvalidFaceReason;
  ShapeMeshResult result;
  try {
    result = mesh_shape(read.shape, options);
  } catch (const InputError&) {
    return;
  }
  const ShapeMesh& mesh = result.mesh;
  check_shape_mesh(mesh);  // throws std::invalid_argument: a bug
  if (mesh.quads.empty()) std::abort();  // "nothing meshed" must be an InputError
  for (const Vec3& p : mesh.nodes) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
  }
  for (double sj : mesh.scaled_jacobian) {
    if (!(sj >= -kSurfaceInvertedBelow)) std::abort();
  }
  if (mesh.mid_nodes.size() != mesh.quads.size()) std::abort();  // shared middles: check_shape_mesh
}

}  // namespace tquad::fuzz
