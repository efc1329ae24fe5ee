#include "core/templates/mapped_ring.h"

#include <cmath>
#include <limits>

namespace tquad {

namespace {

// Above this many points per loop the offset search looks only near the outer point
// nearest to hole point 0 (the full search is quadratic).
constexpr int kFullOffsetSearch = 2048;

double twice_quad_area(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (a.x * b.y - b.x * a.y) + (b.x * c.y - c.x * b.y) + (c.x * d.y - d.x * c.y) + (d.x * a.y - a.x * d.y);
}

}  // namespace

std::optional<QuadMesh> mesh_mapped_ring(const PlanarDomain& domain) {
  if (domain.loop_count() != 2) return std::nullopt;
  const std::vector<Vec3>& outer = domain.loops[0].points;  // counter-clockwise
  const std::vector<Vec3>& hole = domain.loops[1].points;   // clockwise
  const int n = static_cast<int>(hole.size());
  if (n < 4 || static_cast<int>(outer.size()) != n) return std::nullopt;
  // Outer point paired with hole point i: outer[(k - i) mod n], both then clockwise.
  const auto partner = [&](int i, int k) { return ((k - i) % n + n) % n; };
  std::vector<int> offsets;
  if (n <= kFullOffsetSearch) {
    for (int k = 0; k < n; ++k) offsets.push_back(k);
  } else {
    int nearest = 0;
    for (int j = 1; j < n; ++j) if (distance(outer[j], hole[0]) < distance(outer[nearest], hole[0])) nearest = j;
    for (int d = -8; d <= 8; ++d) offsets.push_back(((nearest + d) % n + n) % n);
  }
  int best = -1;
  double best_sum = std::numeric_limits<double>::infinity();
  for (int k : offsets) {
    double sum = 0;
    for (int i = 0; i < n && sum < best_sum; ++i) {
      const Vec3 d = outer[partner(i, k)] - hole[i];
      sum += dot(d, d);
    }
    if (sum < best_sum) { best_sum = sum; best = k; }
  }
  double gaps = 0, spacing = 0;
  for (int i = 0; i < n; ++i) {
    gaps += distance(outer[partner(i, best)], hole[i]);
    spacing += 0.5 * (distance(hole[i], hole[(i + 1) % n]) + distance(outer[i], outer[(i + 1) % n]));
  }
  const int layers = std::max(1, static_cast<int>(std::lround(gaps / spacing)));

  QuadMesh mesh;
  mesh.nodes = outer;
  mesh.nodes.insert(mesh.nodes.end(), hole.begin(), hole.end());
  // row[l][i]: node of layer l (0: the hole, layers: the outer loop) paired with hole point i.
  std::vector<std::vector<NodeId>> row(layers + 1, std::vector<NodeId>(n));
  for (int i = 0; i < n; ++i) {
    row[0][i] = n + i;
    row[layers][i] = partner(i, best);
  }
  for (int l = 1; l < layers; ++l) {
    const double t = static_cast<double>(l) / layers;
    for (int i = 0; i < n; ++i) {
      row[l][i] = static_cast<NodeId>(mesh.nodes.size());
      mesh.nodes.push_back(hole[i] + t * (outer[partner(i, best)] - hole[i]));
    }
  }
  double twice_area = 0;
  for (int l = 0; l < layers; ++l) {
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      const Quad q{row[l][i], row[l][j], row[l + 1][j], row[l + 1][i]};
      // Counter-clockwise at every corner, or this is no tiling.
      for (int c = 0; c < 4; ++c) {
        const Vec3& a = mesh.nodes[q[(c + 3) % 4]];
        const Vec3& b = mesh.nodes[q[c]];
        const Vec3& d = mesh.nodes[q[(c + 1) % 4]];
        if ((b.x - a.x) * (d.y - b.y) - (b.y - a.y) * (d.x - b.x) <= 0) return std::nullopt;
      }
      twice_area += twice_quad_area(mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]], mesh.nodes[q[3]]);
      mesh.quads.push_back(q);
    }
  }
  const double ring_area = twice_signed_area(outer) + twice_signed_area(hole);  // the hole's is negative
  if (std::abs(twice_area - ring_area) > 1e-9 * std::abs(twice_signed_area(outer))) return std::nullopt;
  mesh.template_tree = "R" + std::to_string(layers);
  return mesh;
}

}  // namespace tquad
