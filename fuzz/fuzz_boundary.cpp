// libFuzzer target: the boundary JSON reader and the template mesher, then the route
// the CLI and the Python module take by default (mesh_boundary_region: a planar
// region smoothed in its plane with reflex-point splits and untangling, a curved loop
// on the surface it spans, the corner search where an inverted quad stays), and for
// loops of at most 40 points the --corners best search.
//
// Any input must end in a mesh that passes the final check (check_disk_mesh: all
// quads, conforming, nodes = 1 + quads + boundary_edges / 2) or in an InputError.
// Anything else, an exception of another kind, a crash, a hang or a sanitizer
// report, is a bug. Meshes are capped at 200,000 quads, and smoothed only up to
// 20,000, to keep each run short.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

#include "core/boundary_region.h"
#include "core/decomposition/corner_search.h"
#include "core/input_error.h"
#include "core/mesh/mesh_validation.h"
#include "core/templates/mesher.h"
#include "core/geometry/planar_self_intersection.h"
#include "core/repair/smoothing.h"
#include "io/boundary_json_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  tquad::BoundaryLoop loop;
  try {
    loop = tquad::parse_boundary_json(text, "fuzz input");
  } catch (const tquad::InputError&) {
    return 0;
  }
  tquad::MeshOptions options;
  options.max_quads = 200'000;
  tquad::QuadMesh mesh;
  try {
    mesh = tquad::mesh_boundary(loop, options);
  } catch (const tquad::InputError&) {
    return 0;
  }
  const int n = static_cast<int>(loop.points.size());
  if (!tquad::check_disk_mesh(mesh, n).empty()) std::abort();
  tquad::Vec3 normal;
  const bool planar = tquad::planar_normal(loop.points, normal);
  const std::optional<tquad::Vec3> plane = planar ? std::optional<tquad::Vec3>(normal) : std::nullopt;
  if (mesh.quads.size() <= 20'000) {
    // The front ends' route (boundary_region.h): smoothed in its plane or, a curved
    // loop, on the surface it spans, and the corner search where an inverted quad
    // stays; it throws std::logic_error on an invalid result: a bug.
    try {
      tquad::mesh_boundary_region(loop, options, plane, true, false);
    } catch (const tquad::InputError&) {
      std::abort();  // the given corners meshed above, so the route must too
    }
  }
  if (n <= 40) {
    try {
      const tquad::CornerSearchResult found = tquad::mesh_boundary_best_corners(
          loop, options, plane, true);
      if (!tquad::check_disk_mesh(found.mesh, n).empty()) std::abort();
    } catch (const tquad::InputError&) {
      std::abort();  // the given corners meshed above, so the search must too
    }
  }
  return 0;
}
