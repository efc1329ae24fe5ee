// bench_decomposition: wall time of the face decomposition and of the whole planar
// domain mesher (decomposition, cut counts, templates per patch) on a square plate
// with a grid of round holes, at growing sizes. Single-threaded; nothing is asserted.
//
//   bench_decomposition            # three sizes, the best of 3 runs each
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/decomposition/decomposed_mesher.h"

namespace tquad {
namespace {

// A 10 x 10 square of `per_side` segments a side with `holes` round holes of
// `per_hole` segments in a grid.
PlanarDomain plate_with_holes(int per_side, int holes, int per_hole) {
  PlanarDomain d;
  DomainLoop outer;
  const Vec3 corner[4] = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}};
  for (int s = 0; s < 4; ++s) {
    for (int k = 0; k < per_side; ++k) {
      const double t = static_cast<double>(k) / per_side;
      outer.points.push_back((1 - t) * corner[s] + t * corner[(s + 1) % 4]);
      outer.vertex.push_back(k == 0);
    }
  }
  d.loops.push_back(outer);
  const int grid = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(holes))));
  for (int h = 0; h < holes; ++h) {
    DomainLoop hole;
    const double cx = (h % grid + 0.5) * 10.0 / grid, cy = (h / grid + 0.5) * 10.0 / grid, r = 2.0 / grid;
    for (int k = 0; k < per_hole; ++k) {
      const double a = -2 * M_PI * k / per_hole;  // clockwise
      hole.points.push_back({cx + r * std::cos(a), cy + r * std::sin(a), 0});
      hole.vertex.push_back(0);
    }
    d.loops.push_back(hole);
  }
  return d;
}

template <typename Work>
double seconds_of(const Work& work) {
  double best = 1e300;
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    work();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

}  // namespace
}  // namespace tquad

int main() {
  using namespace tquad;
  std::printf("| boundary points | holes | patches | decomposition | whole mesh | quads |\n|---:|---:|---:|---:|---:|---:|\n");
  struct Case { int per_side, holes, per_hole; };
  for (const Case c : {Case{100, 16, 40}, Case{400, 25, 100}, Case{1000, 100, 100}}) {
    const PlanarDomain d = plate_with_holes(c.per_side, c.holes, c.per_hole);
    std::size_t patches = 0, quads = 0;
    const double decompose = seconds_of([&] { patches = decompose_domain(d).patches.size(); });
    const double whole = seconds_of([&] { quads = mesh_planar_domain(d, 10.0 / c.per_side).quads.size(); });
    std::printf("| %d | %d | %zu | %.3f s | %.3f s | %zu |\n", d.point_count(), c.holes, patches, decompose, whole, quads);
  }
  return 0;
}
