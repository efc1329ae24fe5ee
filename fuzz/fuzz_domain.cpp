// libFuzzer target: the face decomposition, its patch meshing and smoothing, on planar
// domains built from the input bytes so that most of them are valid: an outline that
// is star-shaped around the origin (its radii from the bytes) and up to 6 holes,
// small star-shaped loops at positions from the bytes (which may overlap each other
// or the outline: those domains must be refused with an InputError).
//
// Every valid domain must give a mesh that passes check_domain_mesh (all quads,
// conforming, nodes = 1 + quads + boundary_edges / 2 - holes) before and after
// smoothing, with its boundary points kept; anything else is a bug.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "core/decomposition/decomposed_mesher.h"
#include "core/input_error.h"
#include "core/mesh/mesh_validation.h"
#include "core/repair/smoothing.h"

namespace {

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  int next() { return at_ < size_ ? data_[at_++] : 0; }
  bool done() const { return at_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
};

// A star-shaped loop around `centre`: `points` points, radii scale * (0.5 .. 1.5).
tquad::DomainLoop star(Bytes& in, tquad::Vec3 centre, double scale, int points, bool clockwise) {
  tquad::DomainLoop loop;
  for (int k = 0; k < points; ++k) {
    const double t = (clockwise ? -2 : 2) * M_PI * k / points;
    const double r = scale * (0.5 + in.next() / 255.0);
    loop.points.push_back({centre.x + r * std::cos(t), centre.y + r * std::sin(t), 0.0});
    loop.vertex.push_back(in.next() % 8 == 0 ? 1 : 0);
  }
  return loop;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  tquad::PlanarDomain domain;
  domain.loops.push_back(star(in, {0, 0, 0}, 10.0, 6 + in.next() % 40, false));
  const int holes = in.next() % 7;
  for (int h = 0; h < holes && !in.done(); ++h) {
    const tquad::Vec3 centre{(in.next() - 128) / 16.0, (in.next() - 128) / 16.0, 0.0};
    domain.loops.push_back(star(in, centre, 0.3 + in.next() / 100.0, 4 + in.next() % 24, true));
  }
  if (domain.point_count() % 2 != 0) domain.loops[0].points.pop_back(), domain.loops[0].vertex.pop_back();
  // Sizes from a tenth to half the outline's radius: meshes of tens to thousands of
  // quads, so that a run takes milliseconds.
  const double edge_size = 1.0 + in.next() / 64.0;
  tquad::QuadMesh mesh;
  try {
    mesh = tquad::mesh_planar_domain(domain, edge_size);
  } catch (const tquad::InputError&) {
    return 0;
  }
  std::vector<int> loops;
  for (const tquad::DomainLoop& l : domain.loops) loops.push_back(static_cast<int>(l.points.size()));
  if (!tquad::check_domain_mesh(mesh, loops).empty()) std::abort();
  int merged = 0;
  tquad::smooth_planar_mesh(mesh, domain.point_count(), merged);
  if (!tquad::check_domain_mesh(mesh, loops).empty()) std::abort();
  int k = 0;
  for (const tquad::DomainLoop& l : domain.loops) {
    for (const tquad::Vec3& p : l.points) {
      if (!(mesh.nodes[k].x == p.x && mesh.nodes[k].y == p.y)) std::abort();
      ++k;
    }
  }
  return 0;
}
