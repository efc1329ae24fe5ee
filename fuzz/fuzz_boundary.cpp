// libFuzzer target: the boundary JSON reader and the template mesher.
//
// Any input must end in a mesh that passes the final check (check_disk_mesh: all
// quads, conforming, nodes = 1 + quads + boundary_edges / 2) or in an InputError.
// Anything else, an exception of another kind, a crash, a hang or a sanitizer
// report, is a bug. Meshes are capped at 200,000 quads to keep each run short.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/input_error.h"
#include "core/mesh_validation.h"
#include "core/mesher.h"
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
  if (!tquad::check_disk_mesh(mesh, static_cast<int>(loop.points.size())).empty()) std::abort();
  return 0;
}
