#include "core/repair/hex_smoothing.h"

#include <algorithm>
#include <limits>

namespace tquad {

namespace {

double worst_of(const std::vector<Vec3>& nodes, const std::vector<Hex>& hexes, const std::vector<std::int64_t>& around) {
  double worst = std::numeric_limits<double>::infinity();
  for (std::int64_t k : around) {
    std::array<Vec3, 8> p;
    for (int i = 0; i < 8; ++i) p[i] = nodes[hexes[k][i]];
    worst = std::min(worst, hex_scaled_jacobian(p));
  }
  return worst;
}

}  // namespace

long long smooth_hexahedra(std::vector<Vec3>& nodes, const std::vector<Hex>& hexes,
                           const std::vector<HexSmoothingNode>& free, int passes) {
  long long kept = 0;
  for (int pass = 0; pass < passes; ++pass) {
    long long moved = 0;
    for (const HexSmoothingNode& n : free) {
      if (n.neighbours.empty()) continue;
      Vec3 mean{0, 0, 0};
      for (NodeId m : n.neighbours) mean += nodes[m];
      mean = (1.0 / static_cast<double>(n.neighbours.size())) * mean;
      const Vec3 old = nodes[n.node];
      if (distance(old, mean) == 0) continue;
      const double before = worst_of(nodes, hexes, n.hexes);
      nodes[n.node] = mean;
      if (worst_of(nodes, hexes, n.hexes) >= before) {
        ++moved;
      } else {
        nodes[n.node] = old;
      }
    }
    kept += moved;
    if (moved == 0) break;
  }
  return kept;
}

}  // namespace tquad
